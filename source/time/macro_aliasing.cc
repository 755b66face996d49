#include <deal.II/lac/lapack_full_matrix.h>

#include <hati/time/macro_aliasing.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace hati
{
std::vector<double> free_interface_frequencies(const DiscreteSystem &explicit_part,
                                               const unsigned int max_dofs)
{
  std::vector<unsigned int> free;
  for (unsigned int i = 0; i < explicit_part.n_dofs(); ++i)
    if (!explicit_part.fixed[i] && explicit_part.lumped_mass[i] > 0.)
      free.push_back(i);
  const unsigned int n = free.size();
  if (n == 0 || n > max_dofs || !explicit_part.has_stiffness())
    return {};
  std::vector<int> local(explicit_part.n_dofs(), -1);
  for (unsigned int i = 0; i < n; ++i)
    local[free[i]] = i;
  // M^-1/2 K M^-1/2 on the free DoFs
  LAPACKFullMatrix<double> a(n, n);
  for (unsigned int i = 0; i < n; ++i)
    for (auto it = explicit_part.stiffness.begin(free[i]);
         it != explicit_part.stiffness.end(free[i]);
         ++it)
      if (local[it->column()] >= 0)
        a(i, local[it->column()]) =
            it->value() / std::sqrt(explicit_part.lumped_mass[free[i]] *
                                    explicit_part.lumped_mass[it->column()]);
  Vector<double> eigenvalues;
  FullMatrix<double> eigenvectors;
  a.compute_eigenvalues_symmetric(
      -1., std::numeric_limits<double>::max(), 0., eigenvalues, eigenvectors);
  std::vector<double> omegas;
  for (unsigned int i = 0; i < eigenvalues.size(); ++i)
    omegas.push_back(std::sqrt(std::max(eigenvalues[i], 0.)));
  std::sort(omegas.begin(), omegas.end());
  return omegas;
}

std::vector<AliasingMode> aliasing_modes(const std::vector<double> &omegas,
                                         const double dt,
                                         const unsigned int m,
                                         const double folded_phase)
{
  const double DT = m * dt, two_pi = 2. * M_PI;
  std::vector<AliasingMode> modes;
  for (unsigned int i = 0; i < omegas.size(); ++i)
  {
    const double phase = omegas[i] * DT;
    const double k = std::round(phase / two_pi);
    if (phase <= M_PI || k < 1.)
      continue;
    const double folded = std::abs(phase - two_pi * k);
    if (folded < folded_phase)
      modes.push_back({i + 1, omegas[i] / two_pi, folded / DT / two_pi});
  }
  return modes;
}

std::string aliasing_warning(const std::vector<AliasingMode> &modes,
                             const std::vector<double> &omegas,
                             const double dt,
                             const unsigned int m,
                             const double folded_phase)
{
  if (modes.empty())
    return "";
  // the mode folded closest to zero frequency
  const AliasingMode &worst =
      *std::min_element(modes.begin(),
                        modes.end(),
                        [](const AliasingMode &a, const AliasingMode &b)
                        { return a.folded_frequency < b.folded_frequency; });
  std::vector<unsigned int> clean;
  for (unsigned int r = (m > 4 ? m - 4 : 1); r <= m + 4; ++r)
    if (r != m && aliasing_modes(omegas, dt, r, folded_phase).empty())
      clean.push_back(r);
  std::ostringstream s;
  s << "Time integration/HATI/Time step ratio = " << m
    << ": macro-step aliasing (doc/theory.md 11.3): the explicit subdomain's "
       "free-interface mode "
    << worst.number << " (" << worst.frequency << " Hz) sampled once per macro step "
    << "folds to " << worst.folded_frequency << " Hz, onto the coupled structure's low "
    << "modes";
  if (modes.size() > 1)
    s << " (" << modes.size() - 1 << " more such mode" << (modes.size() > 2 ? "s" : "")
      << ")";
  s << "; the coupling's error there does not shrink with the time step";
  if (!clean.empty())
  {
    s << "; ratios near it without such a mode:";
    for (unsigned int i = 0; i < clean.size(); ++i)
      s << (i == 0 ? " " : ", ") << clean[i];
  }
  return s.str();
}
} // namespace hati
