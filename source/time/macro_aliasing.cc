#include <deal.II/lac/lapack_full_matrix.h>

#include <hati/time/macro_aliasing.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace hati
{
std::vector<FreeInterfaceMode> free_interface_modes(const DiscreteSystem &explicit_part,
                                                    const std::vector<SparseRow> &rows,
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
  FullMatrix<double> y; // columns: M^1/2 phi, phi mass-normalised
  a.compute_eigenvalues_symmetric(
      -1., std::numeric_limits<double>::max(), 0., eigenvalues, y);
  std::vector<FreeInterfaceMode> modes(eigenvalues.size());
  double largest = 0.;
  for (unsigned int j = 0; j < modes.size(); ++j)
  {
    modes[j].omega = std::sqrt(std::max(eigenvalues[j], 0.));
    largest = std::max(largest, modes[j].omega);
  }
  // the interface flexibility of each flexible mode, (C_E phi)^2 / Omega^2
  double total = 0.;
  for (unsigned int j = 0; j < modes.size(); ++j)
  {
    if (modes[j].omega <= 1e-6 * largest)
      continue;
    double c2 = 0.;
    for (const SparseRow &row : rows)
    {
      double c = 0.;
      for (unsigned int k = 0; k < row.dofs.size(); ++k)
        if (local[row.dofs[k]] >= 0)
          c += row.coefficients[k] * y(local[row.dofs[k]], j) /
               std::sqrt(explicit_part.lumped_mass[row.dofs[k]]);
      c2 += c * c;
    }
    modes[j].share = c2 / (modes[j].omega * modes[j].omega);
    total += modes[j].share;
  }
  for (auto &mode : modes)
    mode.share = total > 0. ? mode.share / total : 0.;
  std::sort(modes.begin(),
            modes.end(),
            [](const FreeInterfaceMode &a, const FreeInterfaceMode &b)
            { return a.omega < b.omega; });
  return modes;
}

std::vector<AliasingMode> aliasing_modes(const std::vector<FreeInterfaceMode> &modes,
                                         const double dt,
                                         const unsigned int m,
                                         const double folded_phase,
                                         const double min_share)
{
  const double DT = m * dt, two_pi = 2. * M_PI;
  std::vector<AliasingMode> aliased;
  for (unsigned int i = 0; i < modes.size(); ++i)
  {
    const double phase = modes[i].omega * DT;
    const double k = std::round(phase / two_pi);
    if (phase <= M_PI || k < 1. || modes[i].share < min_share)
      continue;
    const double folded = std::abs(phase - two_pi * k);
    if (folded < folded_phase)
      aliased.push_back(
          {i + 1, modes[i].share, modes[i].omega / two_pi, folded / DT / two_pi});
  }
  return aliased;
}

std::string aliasing_warning(const std::vector<AliasingMode> &aliased,
                             const std::vector<FreeInterfaceMode> &modes,
                             const double dt,
                             const unsigned int m,
                             const double folded_phase,
                             const double min_share)
{
  if (aliased.empty())
    return "";
  // the mode folded closest to zero frequency
  const AliasingMode &worst =
      *std::min_element(aliased.begin(),
                        aliased.end(),
                        [](const AliasingMode &a, const AliasingMode &b)
                        { return a.folded_frequency < b.folded_frequency; });
  std::vector<unsigned int> clean;
  for (unsigned int r = (m > 4 ? m - 4 : 1); r <= m + 4; ++r)
    if (r != m && aliasing_modes(modes, dt, r, folded_phase, min_share).empty())
      clean.push_back(r);
  std::ostringstream s;
  s << "Time integration/HATI/Time step ratio = " << m
    << ": macro-step aliasing (doc/theory.md 11.3): the explicit subdomain's "
       "free-interface mode "
    << worst.number << " (" << worst.frequency << " Hz, " << 100. * worst.share
    << " % of the interface's flexibility) sampled once per macro step "
    << "folds to " << worst.folded_frequency << " Hz, onto the coupled structure's low "
    << "modes";
  if (aliased.size() > 1)
    s << " (" << aliased.size() - 1 << " more such mode"
      << (aliased.size() > 2 ? "s" : "") << ")";
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
