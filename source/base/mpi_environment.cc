#include <hati/base/mpi_environment.h>

#include <cstdlib>
#include <filesystem>
#include <vector>

namespace hati
{
namespace
{
/** True if a launcher (mpirun, srun) started this process as a rank. */
bool started_by_launcher()
{
  for (const char *name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"})
    if (std::getenv(name) != nullptr)
      return true;
  return false;
}
} // namespace

MpiEnvironment::MpiEnvironment()
{
  if (started_by_launcher())
    return;
  // no orted daemon forked (0.2 s less per start); a user's value wins
  setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
  // one process talks to no other: the ob1 messaging layer and no UCX
  // one-sided component, instead of initialising UCX (0.2 s of each start:
  // hati --help 0.55 -> 0.33 s); a user's value wins
  setenv("OMPI_MCA_pml", "ob1", 0);
  setenv("OMPI_MCA_osc", "^ucx", 0);
  if (std::getenv("OMPI_MCA_orte_tmpdir_base") != nullptr)
    return;
  const char *tmp = std::getenv("TMPDIR");
  std::string templ =
      std::string(tmp != nullptr && *tmp != '\0' ? tmp : "/tmp") + "/hati-mpi-XXXXXX";
  std::vector<char> buffer(templ.begin(), templ.end());
  buffer.push_back('\0');
  if (mkdtemp(buffer.data()) == nullptr)
    return; // Open MPI's default session folder, as before
  session_base = buffer.data();
  setenv("OMPI_MCA_orte_tmpdir_base", session_base.c_str(), 1);
}

MpiEnvironment::~MpiEnvironment()
{
  if (session_base.empty())
    return;
  std::error_code ignored;
  std::filesystem::remove_all(session_base, ignored);
}
} // namespace hati
