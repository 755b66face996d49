#include <hati/linear_algebra/amg_preconditioner.h>

#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

namespace hati
{
namespace
{
/**
 * While it lives: the standard output and error go to /dev/null and the
 * working directory is a new private temporary folder; the destructor
 * restores both and removes the folder with what was written there.
 */
class Quiet
{
public:
  Quiet()
  {
    std::cout.flush();
    std::cerr.flush();
    std::fflush(nullptr);
    const int null = ::open("/dev/null", O_WRONLY);
    if (null >= 0)
    {
      for (const int fd : {1, 2})
      {
        saved[fd - 1] = ::dup(fd);
        if (saved[fd - 1] >= 0)
          ::dup2(null, fd);
      }
      ::close(null);
    }
    // (the error_code overload: nothing may throw once the streams moved)
    std::error_code error;
    std::filesystem::path folder = std::filesystem::temp_directory_path(error);
    if (error)
      folder = "/tmp";
    std::string pattern = (folder / "hati-quiet-XXXXXX").string();
    cwd = ::open(".", O_RDONLY | O_DIRECTORY);
    if (cwd >= 0 && ::mkdtemp(pattern.data()) != nullptr)
    {
      scratch = pattern;
      moved = ::chdir(scratch.c_str()) == 0;
    }
  }

  ~Quiet()
  {
    std::cout.flush();
    std::cerr.flush();
    std::fflush(nullptr);
    for (const int fd : {1, 2})
      if (saved[fd - 1] >= 0)
      {
        ::dup2(saved[fd - 1], fd);
        ::close(saved[fd - 1]);
      }
    if (moved && ::fchdir(cwd) != 0)
    { // nothing better to do: the folder was there a moment ago
    }
    if (cwd >= 0)
      ::close(cwd);
    if (!scratch.empty())
    {
      std::error_code ignored;
      std::filesystem::remove_all(scratch, ignored);
    }
  }

  Quiet(const Quiet &) = delete;
  Quiet &operator=(const Quiet &) = delete;

private:
  int saved[2] = {-1, -1};
  int cwd = -1;
  bool moved = false;
  std::string scratch;
};
} // namespace

void initialize_quietly(TrilinosWrappers::PreconditionAMG &amg,
                        const TrilinosWrappers::SparseMatrix &matrix,
                        const TrilinosWrappers::PreconditionAMG::AdditionalData &data)
{
  const Quiet quiet;
  amg.initialize(matrix, data);
}

TrilinosWrappers::PreconditionAMG::AdditionalData
structural_amg_data(const std::array<Vector<double>, 3> &translations,
                    const unsigned int n)
{
  TrilinosWrappers::PreconditionAMG::AdditionalData data;
  data.elliptic = true;
  data.smoother_sweeps = 2;
  // near null space: the rigid translations of the model, where it has any
  for (const auto &r : translations)
    if (r.size() == n && r.linfty_norm() > 0.)
    {
      std::vector<bool> mode(n);
      for (unsigned int i = 0; i < n; ++i)
        mode[i] = (r[i] != 0.);
      data.constant_modes.push_back(mode);
    }
  return data;
}
} // namespace hati
