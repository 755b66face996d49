#include <deal.II/base/exceptions.h>

#include <hati/model/memory_estimate.h>

#include <algorithm>
#include <cmath>
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
                           const double n_nonzeros,
                           const double factorization,
                           const std::string &remedy)
{
  const double needed = estimated_memory(n_cells, n_dofs, n_nonzeros) + factorization;
  const double available = available_memory();
  if (available <= 0. || needed <= available)
    return;
  char text[640];
  char factor[96] = "";
  if (factorization > 0.)
    std::snprintf(factor,
                  sizeof(factor),
                  ", %.3g GB of them the factorisation",
                  factorization / 1e9);
  std::snprintf(text,
                sizeof(text),
                "%s: the model would need about %.3g GB of memory (%.3g DoFs, %.3g "
                "matrix nonzeros, %.3g cells%s), more than the %.3g GB available on this "
                "machine; reduce %s",
                entry.c_str(),
                needed / 1e9,
                n_dofs,
                n_nonzeros,
                n_cells,
                factor,
                available / 1e9,
                remedy.empty() ? entry.c_str() : remedy.c_str());
  AssertThrow(false, dealii::ExcMessage(text));
}

HexahedraSize box_size(const std::array<double, 3> &cells, const unsigned int degree)
{
  const double p = degree;
  HexahedraSize size;
  size.n_dofs = 3.;
  double pairs = 1.;
  for (const double n : cells)
  {
    size.n_dofs *= p * n + 1.;
    pairs *= n * (p * p + 2. * p) + 1.;
  }
  size.n_nonzeros = 9. * pairs;
  return size;
}

HexahedraSize hexahedra_size(const double n_cells, const unsigned int degree)
{
  const double p = degree, q = p * p + 2. * p;
  return {3. * p * p * (p + 1.) * n_cells, 2. * 9. * q * q * q * n_cells};
}

double factorization_memory(const double n_dofs, const unsigned int degree)
{
  // measured peaks less the matrices (static analyses of boxes of 28,611
  // and 91,875 DoFs at degrees 2, 3 and 4): 8 B x 30 n^(4/3) (p + 1) / 2
  // within 0.7 to 1.05 of it
  return 8. * 30. * std::pow(n_dofs, 4. / 3.) * (degree + 1.) / 2.;
}
} // namespace hati
