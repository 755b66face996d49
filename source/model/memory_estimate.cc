#include <deal.II/base/exceptions.h>

#include <hati/model/memory_estimate.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace hati
{
double
estimated_memory(const double n_cells, const double n_dofs, const double n_nonzeros)
{
  return 400. * n_cells + 40. * 8. * n_dofs + 28. * n_nonzeros;
}

double available_memory()
{
  double available = 0.;
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  double kb;
  std::string unit;
  while (meminfo >> key >> kb >> unit)
    if (key == "MemAvailable:")
      available = 1024. * kb;
  std::ifstream cgroup("/sys/fs/cgroup/memory.max");
  double limit;
  if (cgroup >> limit && limit > 0.)
    available = available > 0. ? std::min(available, limit) : limit;
  return available;
}

void check_memory_estimate(const std::string &entry,
                           const double n_cells,
                           const double n_dofs,
                           const double n_nonzeros)
{
  const double needed = estimated_memory(n_cells, n_dofs, n_nonzeros);
  const double available = available_memory();
  if (available <= 0. || needed <= available)
    return;
  char text[512];
  std::snprintf(text,
                sizeof(text),
                "%s: the model would need about %.3g GB of memory (%.3g DoFs, %.3g "
                "matrix nonzeros, %.3g cells), more than the %.3g GB available on this "
                "machine; reduce %s",
                entry.c_str(),
                needed / 1e9,
                n_dofs,
                n_nonzeros,
                n_cells,
                available / 1e9,
                entry.c_str());
  AssertThrow(false, dealii::ExcMessage(text));
}
} // namespace hati
