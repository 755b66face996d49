// Craig-Bampton reduction of a linear implicit part (C1, doc/theory.md 12.1).

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>

#include <hati/analysis/craig_bampton.h>
#include <hati/analysis/modal_analysis.h>
#include <hati/linear_algebra/direct_solver.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

namespace hati
{
namespace
{
const std::string where = "Model/Decomposition/";

/** The mass used: the consistent one if assembled, else the lumped diagonal. */
void apply_mass(const DiscreteSystem &system, const Vector<double> &x, Vector<double> &y)
{
  if (system.has_consistent_mass())
    system.consistent_mass.vmult(y, x);
  else
    for (unsigned int i = 0; i < x.size(); ++i)
      y[i] = system.lumped_mass[i] * x[i];
}
} // namespace

CraigBamptonReduction::CraigBamptonReduction(
    const DiscreteSystem &system,
    const std::vector<unsigned int> &boundary_dofs,
    const CraigBamptonSettings &settings)
    : boundary(boundary_dofs)
{
  const auto start = std::chrono::steady_clock::now();
  const unsigned int n = system.n_dofs();
  AssertThrow(system.has_stiffness(),
              ExcMessage(where + "Implicit reduction = Craig-Bampton: the implicit part "
                                 "has no stiffness matrix to reduce."));
  AssertThrow(system.ropes.empty() && system.contacts.empty(),
              ExcMessage(where + "Implicit reduction = Craig-Bampton reduces a linear "
                                 "part: the implicit part holds ropes or contacts."));
  std::vector<bool> seen(n, false);
  for (const unsigned int b : boundary)
  {
    AssertThrow(b < n && !system.fixed[b] && !seen[b],
                ExcMessage(where + "Implicit reduction: the boundary DoF " +
                           std::to_string(b) + " is out of range, fixed or repeated."));
    seen[b] = true;
  }
  add_constraint_modes(system, direct_solver_package(settings.linear_solver, n));
  add_fixed_interface_modes(system, settings);
  assemble_reduced_matrices(system);
  seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void CraigBamptonReduction::add_constraint_modes(const DiscreteSystem &system,
                                                 const std::string &package)
{
  const unsigned int n = system.n_dofs();
  std::vector<bool> is_boundary(n, false);
  for (const unsigned int b : boundary)
    is_boundary[b] = true;
  // K_ii on the full numbering: boundary rows and columns keep only their
  // diagonal (like the fixed DoFs, which the system holds so already)
  SparseMatrix<double> K_ii(system.stiffness_pattern);
  K_ii.copy_from(system.stiffness);
  for (unsigned int i = 0; i < n; ++i)
    for (auto it = K_ii.begin(i); it != K_ii.end(i); ++it)
      if ((is_boundary[i] || is_boundary[it->column()]) && it->column() != i)
        it->value() = 0.;
  DirectSolver solver(package);
  solver.factorize(
      K_ii,
      where + "Implicit reduction = Craig-Bampton: " + package +
          " found a zero pivot in K_ii (the implicit part without its "
          "boundary DoFs moves as a rigid body: hold it or add boundary DoFs).");
  // Psi_j = -K_ii^-1 K_ib e_j, and 1 at the boundary DoF itself (K symmetric:
  // column j of K is its row j)
  for (const unsigned int j : boundary)
  {
    Vector<double> rhs(n), psi(n);
    for (auto it = system.stiffness.begin(j); it != system.stiffness.end(j); ++it)
      if (!is_boundary[it->column()] && !system.fixed[it->column()])
        rhs[it->column()] = -it->value();
    solver.solve(psi, rhs);
    // one step of iterative refinement: the thin plates' K_ii is ill
    // conditioned (round-off ~ cond(K_ii) eps after one solve)
    Vector<double> residual(n), correction(n);
    K_ii.vmult(residual, psi);
    residual.sadd(-1., rhs);
    solver.solve(correction, residual);
    psi += correction;
    for (const unsigned int b : boundary)
      psi[b] = 0.;
    psi[j] = 1.;
    columns.push_back(std::move(psi));
  }
}

void CraigBamptonReduction::add_fixed_interface_modes(
    const DiscreteSystem &system, const CraigBamptonSettings &settings)
{
  const unsigned int n_free_interior =
      std::count(system.fixed.begin(), system.fixed.end(), false) - boundary.size();
  const unsigned int limit = std::min(settings.maximum_modes, n_free_interior);
  if (limit == 0)
    return;
  // more modes until the last one is above the cut-off (or the limit)
  unsigned int wanted = std::min(limit, 12u);
  ModalResult modes;
  while (true)
  {
    modes =
        compute_modes(system, wanted, false, nullptr, settings.linear_solver, &boundary);
    if (modes.frequencies.back() > settings.cutoff_frequency || wanted == limit)
      break;
    wanted = std::min(limit, 2 * wanted);
  }
  const double last = modes.frequencies.back();
  if (last <= settings.cutoff_frequency && wanted < n_free_interior)
  {
    // the count needed, from the local modal density N ~ f^p of the modes
    // found (p from the last and the middle one)
    const unsigned int half = std::max(1u, wanted / 2);
    const double f_half = modes.frequencies[half - 1];
    const double p = (last > f_half && f_half > 0.)
                         ? std::log(double(wanted) / half) / std::log(last / f_half)
                         : 1.;
    const double needed = wanted * std::pow(settings.cutoff_frequency / last, p);
    std::ostringstream m;
    m << where << "Reduction cutoff frequency = " << settings.cutoff_frequency
      << " Hz needs more than Reduction maximum modes = " << settings.maximum_modes
      << " fixed-interface modes (mode " << wanted << " is at " << last << " Hz): about "
      << static_cast<unsigned long>(std::ceil(needed))
      << " by the modal density; raise Reduction maximum modes or lower the cut-off";
    AssertThrow(false, ExcMessage(m.str()));
  }
  for (unsigned int k = 0; k < modes.frequencies.size(); ++k)
    if (modes.frequencies[k] <= settings.cutoff_frequency)
    {
      modal_frequencies.push_back(modes.frequencies[k]);
      columns.push_back(std::move(modes.modes[k]));
    }
}

void CraigBamptonReduction::assemble_reduced_matrices(const DiscreteSystem &system)
{
  const unsigned int r = columns.size(), n = system.n_dofs();
  reduced_mass.reinit(r, r);
  reduced_stiffness.reinit(r, r);
  Vector<double> Mt(n), Kt(n);
  for (unsigned int b = 0; b < r; ++b)
  {
    apply_mass(system, columns[b], Mt);
    system.stiffness.vmult(Kt, columns[b]);
    for (unsigned int a = 0; a <= b; ++a)
    {
      reduced_mass(a, b) = reduced_mass(b, a) = columns[a] * Mt;
      reduced_stiffness(a, b) = reduced_stiffness(b, a) = columns[a] * Kt;
    }
  }
}

void CraigBamptonReduction::expand(const Vector<double> &q, Vector<double> &u) const
{
  AssertThrow(q.size() == size(), ExcMessage("CraigBamptonReduction::expand: size"));
  u = 0.;
  for (unsigned int k = 0; k < size(); ++k)
    if (q[k] != 0.)
      u.add(q[k], columns[k]);
}

void CraigBamptonReduction::project(const Vector<double> &f, Vector<double> &r) const
{
  r.reinit(size());
  for (unsigned int k = 0; k < size(); ++k)
    r[k] = columns[k] * f;
}

std::vector<double> CraigBamptonReduction::frequencies(const unsigned int n) const
{
  const unsigned int r = size();
  LAPACKFullMatrix<double> K(r, r), M(r, r);
  K = reduced_stiffness;
  M = reduced_mass;
  std::vector<Vector<double>> vectors(r, Vector<double>(r));
  K.compute_generalized_eigenvalues_symmetric(M, vectors);
  std::vector<double> f;
  for (unsigned int k = 0; k < r; ++k)
    f.push_back(std::sqrt(std::max(K.eigenvalue(k).real(), 0.)) / (2. * M_PI));
  std::sort(f.begin(), f.end());
  f.resize(std::min(n, r));
  return f;
}
} // namespace hati
