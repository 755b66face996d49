// Craig-Bampton reduction of a linear implicit part (C1, doc/theory.md 12.1).

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>

#include <hati/analysis/craig_bampton.h>
#include <hati/analysis/modal_analysis.h>
#include <hati/analysis/row_elimination.h>
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

/**
 * The number of modes up to @p cutoff (Hz) that the local modal density
 * `N ~ f^p` of the ascending @p frequencies predicts (p from the last one
 * and the middle one).
 */
double estimated_mode_count(const std::vector<double> &frequencies, const double cutoff)
{
  const unsigned int n = frequencies.size(), half = std::max(1u, n / 2);
  const double last = frequencies.back(), f_half = frequencies[half - 1];
  const double p = (last > f_half && f_half > 0. && n > half)
                       ? std::log(double(n) / half) / std::log(last / f_half)
                       : 1.;
  return n * std::pow(cutoff / std::max(last, 1e-300), p);
}

} // namespace

void reduction_mass_vmult(const DiscreteSystem &system,
                          const Vector<double> &x,
                          Vector<double> &y)
{
  if (system.has_consistent_mass())
    system.consistent_mass.vmult(y, x);
  else
    for (unsigned int i = 0; i < x.size(); ++i)
      y[i] = system.lumped_mass[i] * x[i];
}

std::vector<SparseRow> unit_rows(const std::vector<unsigned int> &dofs)
{
  std::vector<SparseRow> rows(dofs.size());
  for (unsigned int k = 0; k < dofs.size(); ++k)
  {
    rows[k].dofs = {dofs[k]};
    rows[k].coefficients = {1.};
  }
  return rows;
}

CraigBamptonReduction::CraigBamptonReduction(const DiscreteSystem &system,
                                             const std::vector<SparseRow> &boundary_rows,
                                             const CraigBamptonSettings &settings)
    : boundary(boundary_rows)
{
  const auto start = std::chrono::steady_clock::now();
  AssertThrow(system.has_stiffness(),
              ExcMessage(where + "Implicit reduction = Craig-Bampton: the implicit part "
                                 "has no stiffness matrix to reduce."));
  AssertThrow(system.ropes.empty() && system.contacts.empty(),
              ExcMessage(where + "Implicit reduction = Craig-Bampton reduces a linear "
                                 "part: the implicit part holds ropes or contacts."));
  auto since = [](const std::chrono::steady_clock::time_point t)
  { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count(); };
  add_constraint_modes(system,
                       direct_solver_package(settings.linear_solver, system.n_dofs()));
  phase_seconds[0] = since(start);
  add_fixed_interface_modes(system, settings);
  phase_seconds[1] = since(start) - phase_seconds[0];
  assemble_reduced_matrices(system);
  seconds = since(start);
  phase_seconds[2] = seconds - phase_seconds[0] - phase_seconds[1];
}

void CraigBamptonReduction::add_constraint_modes(const DiscreteSystem &system,
                                                 const std::string &package)
{
  const unsigned int n = system.n_dofs(), nb = boundary.size();
  // L U = g with g_k a virtual DoF n + k (RowElimination): U = U_p(g) + T_0 v
  RowElimination elimination;
  for (unsigned int k = 0; k < nb; ++k)
  {
    SparseRow row = boundary[k];
    for (const auto i : row.dofs)
      AssertThrow(i < n,
                  ExcMessage(where + "Implicit reduction: a boundary row refers to DoF " +
                             std::to_string(i) + " of a part with " + std::to_string(n)));
    row.dofs.push_back(n + k);
    row.coefficients.push_back(-1.);
    const std::size_t before = elimination.slaves.size();
    elimination.eliminate(system.fixed, row, false, n);
    AssertThrow(elimination.slaves.size() == before + 1,
                ExcMessage(where + "Implicit reduction: boundary row " +
                           std::to_string(k) +
                           " depends on the others or only on fixed DoFs: the interface "
                           "of the implicit part holds a DoF twice."));
  }
  // the stiffness on L U = 0, the slaves held like fixed DoFs
  std::vector<double> diagonal(n, 1.);
  for (const auto &entry : elimination.slaves)
    if (system.stiffness.diag_element(entry.first) > 0.)
      diagonal[entry.first] = system.stiffness.diag_element(entry.first);
  SparsityPattern pattern;
  SparseMatrix<double> K_0;
  elimination.condense(system.stiffness, diagonal, pattern, K_0);
  DirectSolver solver(package);
  solver.factorize(K_0,
                   where + "Implicit reduction = Craig-Bampton: " + package +
                       " found a zero pivot in the stiffness held at the boundary (the "
                       "implicit part moves as a rigid body with its interface held: "
                       "add supports or interface rows).");
  for (unsigned int k = 0; k < nb; ++k)
  {
    // the particular part U_p (g = e_k, masters 0), then T_0^T K T_0 v = -T_0^T K U_p
    Vector<double> x(n + nb);
    x[n + k] = 1.;
    elimination.distribute(x);
    Vector<double> U_p(n), rhs(n), v(n), residual(n), correction(n);
    for (unsigned int i = 0; i < n; ++i)
      U_p[i] = x[i];
    system.stiffness.vmult(rhs, U_p);
    rhs *= -1.;
    elimination.transpose_apply(rhs);
    for (unsigned int i = 0; i < n; ++i)
      if (system.fixed[i])
        rhs[i] = 0.;
    solver.solve(v, rhs);
    // one step of iterative refinement: thin plates make K ill conditioned
    K_0.vmult(residual, v);
    residual.sadd(-1., rhs);
    solver.solve(correction, residual);
    v += correction;
    for (const auto &entry : elimination.slaves)
      v[entry.first] = 0.;
    x = 0.;
    for (unsigned int i = 0; i < n; ++i)
      x[i] = v[i];
    x[n + k] = 1.;
    elimination.distribute(x);
    Vector<double> psi(n);
    for (unsigned int i = 0; i < n; ++i)
      psi[i] = x[i];
    columns.push_back(std::move(psi));
  }
}

void CraigBamptonReduction::add_fixed_interface_modes(
    const DiscreteSystem &system, const CraigBamptonSettings &settings)
{
  const unsigned int n_free_interior =
      std::count(system.fixed.begin(), system.fixed.end(), false) - boundary.size();
  // the rows were found independent (add_constraint_modes()): each holds one DoF
  const unsigned int limit = std::min(settings.maximum_modes, n_free_interior);
  if (limit == 0)
    return;
  // more modes until the last one is above the cut-off (or the limit): the
  // next count from the modal density of the modes found, with a margin
  // (each count is a new Lanczos run), at least twice the last
  unsigned int wanted = std::min(limit, 12u);
  ModalResult modes;
  while (true)
  {
    modes =
        compute_modes(system, wanted, false, nullptr, settings.linear_solver, &boundary);
    ++n_lanczos_runs;
    if (modes.frequencies.back() > settings.cutoff_frequency || wanted == limit)
      break;
    const double needed =
        estimated_mode_count(modes.frequencies, settings.cutoff_frequency);
    wanted = static_cast<unsigned int>(
        std::min<double>(limit, std::max(2. * wanted, std::ceil(1.2 * needed) + 4.)));
  }
  const double last = modes.frequencies.back();
  if (last <= settings.cutoff_frequency && wanted < n_free_interior)
  {
    const double needed =
        estimated_mode_count(modes.frequencies, settings.cutoff_frequency);
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
    reduction_mass_vmult(system, columns[b], Mt);
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
  if (size() > 0 && u.size() != columns[0].size())
    u.reinit(columns[0].size());
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
