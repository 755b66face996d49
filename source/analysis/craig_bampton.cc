// Craig-Bampton reduction of a linear implicit part (C1, doc/theory.md 12.1).

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>

#include <hati/analysis/craig_bampton.h>
#include <hati/analysis/modal_analysis.h>
#include <hati/analysis/row_elimination.h>
#include <hati/linear_algebra/column_major.h>
#include <hati/linear_algebra/direct_solver.h>
#include <hati/linear_algebra/sparse_nonzeros.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>
#include <tuple>

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
namespace
{

/** f = omega / (2 pi) (Hz) of an eigenvalue lambda = omega^2 (0 below 0). */
double frequency_of(const double lambda)
{
  return std::sqrt(std::max(lambda, 0.)) / (2. * M_PI);
}

/**
 * Merge the slice @p found into the ascending @p kept modes, keeping the
 * new ones: Gram-Schmidt in the M inner product against the kept modes
 * (the modes where a slice overlaps the previous ones come again, those of
 * a multiple eigenvalue in another basis of its eigenspace). A candidate is
 * new if at least half of its M-norm is left; the candidates with most left
 * go first, so that of the two copies of a double eigenvalue found again,
 * the one with the missing direction is kept and the other is then a
 * repeat. The new modes are M-orthogonal to the kept ones to round-off, as
 * those of one Lanczos run are; those of a multiple eigenvalue are then
 * mass-normalised again, their eigenvalue the Rayleigh quotient. Returns
 * the number of modes added.
 */
unsigned int merge_slice(const DiscreteSystem &system,
                         std::vector<Eigenpair> &found,
                         std::vector<Eigenpair> &kept)
{
  const unsigned int n = system.n_dofs();
  const std::size_t n_kept = kept.size();
  // the candidates' M-products with the kept modes and the part of their
  // M-norm^2 left
  std::vector<std::vector<double>> coefficients(found.size());
  std::vector<double> left(found.size(), 1.);
  for (unsigned int c = 0; c < found.size(); ++c)
    for (std::size_t k = 0; k < n_kept; ++k)
    {
      coefficients[c].push_back(kept[k].phi * found[c].Mphi);
      left[c] -= coefficients[c].back() * coefficients[c].back();
    }
  std::vector<unsigned int> order(found.size());
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(),
                   order.end(),
                   [&left](const unsigned int a, const unsigned int b)
                   { return left[a] > left[b]; });

  std::vector<Eigenpair> added;
  for (const unsigned int c : order)
  {
    if (left[c] < 0.25)
      continue; // a repeat of kept modes
    Eigenpair pair = std::move(found[c]);
    // this slice's modes kept meanwhile too
    for (const Eigenpair &other : added)
      coefficients[c].push_back(other.phi * pair.Mphi);
    double removed = 0.;
    for (std::size_t k = 0; k < coefficients[c].size(); ++k)
    {
      const Eigenpair &other = k < n_kept ? kept[k] : added[k - n_kept];
      pair.phi.add(-coefficients[c][k], other.phi);
      pair.Mphi.add(-coefficients[c][k], other.Mphi);
      removed += coefficients[c][k] * coefficients[c][k];
    }
    if (removed > 1e-8)
    {
      // a new direction of a multiple eigenvalue
      const double mass = pair.phi * pair.Mphi;
      if (!(mass >= 0.25))
        continue;
      pair.phi /= std::sqrt(mass);
      pair.Mphi /= std::sqrt(mass);
      Vector<double> Kv(n);
      system.stiffness.vmult(Kv, pair.phi);
      pair.lambda = pair.phi * Kv;
      unsigned int largest = 0;
      for (unsigned int i = 0; i < n; ++i)
        if (std::abs(pair.phi[i]) > std::abs(pair.phi[largest]))
          largest = i;
      if (pair.phi[largest] < 0.)
      {
        pair.phi *= -1.;
        pair.Mphi *= -1.;
      }
    }
    added.push_back(std::move(pair));
  }
  for (Eigenpair &pair : added)
    kept.push_back(std::move(pair));
  std::stable_sort(kept.begin(),
                   kept.end(),
                   [](const Eigenpair &a, const Eigenpair &b)
                   { return a.lambda < b.lambda; });
  return added.size();
}

/**
 * The fixed-interface modes of @p problem up to @p cutoff (Hz), or at least
 * @p limit of them, by spectrum slicing: shift-invert Lanczos runs of
 * @p per_run modes nearest a shift, from the lowest ones up, the operator
 * deflated of the kept modes near the shift (from `deflated_from` up), so
 * that a slice holds modes not kept yet (merge_slice() drops the repeats).
 * Every eigenvalue within a slice's radius of its shift (the distance to the
 * farthest one found) is then kept; once a slice reaches strictly below
 * `covered` (a multiple eigenvalue at `covered`, perhaps cut by the last
 * slice, then lies inside it), every eigenvalue up to its shift + radius is.
 * The next shift lies 0.4 of the slice's width above `covered`, so that the
 * next slice, at a similar modal density, reaches below it; if it does not
 * (the density grew), again at the same shift (the factorisation is kept),
 * these modes deflated too. A slice has fewer modes when the modal density
 * of the kept ones says that fewer remain below the cut-off. Counts the runs
 * in @p runs; returns the kept modes, ascending.
 */
std::vector<Eigenpair> slice_spectrum(const DiscreteSystem &system,
                                      const ModalProblem &problem,
                                      const unsigned int per_run,
                                      const unsigned int limit,
                                      const double cutoff,
                                      unsigned int &runs)
{
  std::vector<Eigenpair> kept;
  double shift = problem.lowest_shift(), covered = -std::numeric_limits<double>::max();
  double deflated_from = covered;
  unsigned int n_run = per_run, repeats = 0;
  while (true)
  {
    std::vector<const Eigenpair *> deflated;
    for (auto pair = kept.rbegin(); pair != kept.rend() && pair->lambda >= deflated_from;
         ++pair)
      deflated.push_back(&*pair);
    while (!deflated.empty() && !problem.lanczos_applies(n_run, deflated.size()))
      deflated.pop_back(); // (a small system) the farthest ones may come again
    std::vector<Eigenpair> found = problem.modes_near(shift, n_run, deflated);
    ++runs;
    const double lowest = found.front().lambda, highest = found.back().lambda;
    const double radius = std::max(highest - shift, shift - lowest);
    merge_slice(system, found, kept);
    if (covered > -std::numeric_limits<double>::max() &&
        shift - radius >= covered - 1e-8 * std::abs(covered))
    {
      AssertThrow(++repeats < 8,
                  ExcMessage(where +
                             "Implicit reduction = Craig-Bampton: the "
                             "fixed-interface modes above " +
                             std::to_string(frequency_of(covered)) +
                             " Hz are not contiguous across 8 Lanczos runs."));
      continue;
    }
    repeats = 0;
    covered = std::max(covered, shift + radius);
    if (frequency_of(covered) > cutoff || kept.size() >= limit)
      return kept;
    std::vector<double> frequencies;
    for (const Eigenpair &pair : kept)
      frequencies.push_back(frequency_of(pair.lambda));
    const double remaining = estimated_mode_count(frequencies, cutoff) - kept.size();
    const unsigned int next = static_cast<unsigned int>(std::min<double>(
        per_run,
        std::max<double>(std::min(per_run, 8u), std::ceil(1.25 * remaining) + 4.)));
    deflated_from = covered - 2. * (highest - lowest);
    shift = covered + 0.4 * (highest - lowest) * next / n_run;
    n_run = next;
  }
}
} // namespace

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
                       direct_solver_package(settings.linear_solver,
                                             system.n_dofs(),
                                             system.stiffness_row_length()));
  phase_seconds[0] = since(start);
  add_fixed_interface_modes(system, settings);
  phase_seconds[1] = since(start) - phase_seconds[0];
  store_basis();
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
  // the particular parts U_p (g = e_k, masters 0), then T_0^T K T_0 v =
  // -T_0^T K U_p, all boundary rows' right-hand sides at once (MUMPS: one
  // pass through the factor for a block of them)
  std::vector<double> rhs(std::size_t(n) * nb), v(std::size_t(n) * nb);
  Vector<double> x(n + nb), U_p(n), column(n), product(n);
  for (unsigned int k = 0; k < nb; ++k)
  {
    x = 0.;
    x[n + k] = 1.;
    elimination.distribute(x);
    for (unsigned int i = 0; i < n; ++i)
      U_p[i] = x[i];
    system.stiffness.vmult(column, U_p);
    column *= -1.;
    elimination.transpose_apply(column);
    for (unsigned int i = 0; i < n; ++i)
      rhs[std::size_t(k) * n + i] = system.fixed[i] ? 0. : column[i];
  }
  v = rhs;
  solver.solve_many(v.data(), nb);
  // one step of iterative refinement: thin plates make K ill conditioned
  std::vector<double> residuals(std::size_t(n) * nb);
  for (unsigned int k = 0; k < nb; ++k)
  {
    std::copy(v.begin() + std::size_t(k) * n,
              v.begin() + std::size_t(k + 1) * n,
              column.begin());
    K_0.vmult(product, column);
    for (unsigned int i = 0; i < n; ++i)
      residuals[std::size_t(k) * n + i] = rhs[std::size_t(k) * n + i] - product[i];
  }
  solver.solve_many(residuals.data(), nb);
  for (unsigned int k = 0; k < nb; ++k)
  {
    x = 0.;
    for (unsigned int i = 0; i < n; ++i)
      x[i] = v[std::size_t(k) * n + i] + residuals[std::size_t(k) * n + i];
    for (const auto &entry : elimination.slaves)
      x[entry.first] = 0.;
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
  const ModalProblem problem(system, false, nullptr, settings.linear_solver, &boundary);
  const unsigned int per_run = std::min(std::max(settings.modes_per_run, 4u), limit);
  std::vector<Eigenpair> kept;
  if (problem.lanczos_applies(per_run))
    kept = slice_spectrum(
        system, problem, per_run, limit, settings.cutoff_frequency, n_lanczos_runs);
  else
  {
    // a small system: one dense solve gives every mode up to the limit
    kept = problem.modes_near(problem.lowest_shift(), limit);
    ++n_lanczos_runs;
  }
  if (kept.size() >= limit &&
      frequency_of(kept[limit - 1].lambda) <= settings.cutoff_frequency &&
      limit < n_free_interior)
  {
    std::vector<double> frequencies;
    for (unsigned int k = 0; k < limit; ++k)
      frequencies.push_back(frequency_of(kept[k].lambda));
    const double needed = estimated_mode_count(frequencies, settings.cutoff_frequency);
    std::ostringstream m;
    m << where << "Reduction cutoff frequency = " << settings.cutoff_frequency
      << " Hz needs more than Reduction maximum modes = " << settings.maximum_modes
      << " fixed-interface modes (mode " << limit << " is at " << frequencies.back()
      << " Hz): about " << static_cast<unsigned long>(std::ceil(needed))
      << " by the modal density; raise Reduction maximum modes or lower the cut-off";
    AssertThrow(false, ExcMessage(m.str()));
  }
  for (Eigenpair &pair : kept)
    if (frequency_of(pair.lambda) <= settings.cutoff_frequency)
    {
      modal_frequencies.push_back(frequency_of(pair.lambda));
      columns.push_back(std::move(pair.phi));
    }
}

void CraigBamptonReduction::assemble_reduced_matrices(const DiscreteSystem &system)
{
  const std::size_t r = size(), n = n_rows, nb = n_boundary();
  reduced_mass.reinit(r, r);
  reduced_stiffness.reinit(r, r);
  if (r == 0 || n == 0)
    return;
  // T^T (M T) and T^T (K Psi) by blocks of columns, BLAS dgemm (the products
  // column by column, 38,000 dot products on the 3D crane, took 11 s)
  constexpr std::size_t width = 32;
  // the consistent mass without its zero entries (a third of them for solids)
  SparsityPattern mass_pattern;
  SparseMatrix<double> mass;
  if (system.has_consistent_mass())
    copy_nonzeros(system.consistent_mass, mass_pattern, mass);
  std::vector<double> MT(n * width), KT(n * width), R(r * width);
  Vector<double> t(n), Mt(n), Kt(n);
  for (std::size_t b0 = 0; b0 < r; b0 += width)
  {
    const std::size_t w = std::min(width, r - b0);
    // the stiffness products of the constraint modes only (below)
    const std::size_t w_K = b0 < nb ? std::min(w, nb - b0) : 0;
    for (std::size_t j = 0; j < w; ++j)
    {
      const ArrayView<const double> column_j = column(b0 + j);
      std::copy(column_j.begin(), column_j.end(), t.begin());
      if (system.has_consistent_mass())
        mass.vmult(Mt, t);
      else
        reduction_mass_vmult(system, t, Mt);
      std::copy(Mt.begin(), Mt.end(), MT.begin() + j * n);
      if (j < w_K)
      {
        system.stiffness.vmult(Kt, t);
        std::copy(Kt.begin(), Kt.end(), KT.begin() + j * n);
      }
    }
    for (auto [product, reduced, columns] :
         {std::make_tuple(&MT, &reduced_mass, w),
          std::make_tuple(&KT, &reduced_stiffness, w_K)})
    {
      if (columns == 0)
        continue;
      column_major_mmult(true, r, columns, n, basis.data(), product->data(), R.data());
      for (std::size_t j = 0; j < columns; ++j)
        for (std::size_t a = 0; a < r; ++a)
          (*reduced)(a, b0 + j) = R[j * r + a];
    }
  }
  // the modes' columns of T^T K T without products: Psi^T K phi_j =
  // (K Psi)^T phi_j (computed), and K phi_j = lambda_j M phi_j + L^T mu_j
  // (the interface and support reactions, where phi_i vanishes), so that
  // phi_i^T K phi_j = lambda_j phi_i^T M phi_j (doc/theory.md 12.1)
  for (std::size_t j = nb; j < r; ++j)
  {
    const double omega = 2. * M_PI * modal_frequencies[j - nb];
    for (std::size_t a = 0; a < nb; ++a)
      reduced_stiffness(a, j) = reduced_stiffness(j, a);
    for (std::size_t a = nb; a < r; ++a)
      reduced_stiffness(a, j) = omega * omega * reduced_mass(a, j);
  }
  // symmetric to round-off: the mean of the two triangles
  for (auto *reduced : {&reduced_mass, &reduced_stiffness})
    for (std::size_t a = 0; a < r; ++a)
      for (std::size_t b = 0; b < a; ++b)
        (*reduced)(a, b) = (*reduced)(b, a) = 0.5 * ((*reduced)(a, b) + (*reduced)(b, a));
}

void CraigBamptonReduction::store_basis()
{
  n_columns = columns.size();
  n_rows = n_columns > 0 ? columns[0].size() : 0;
  basis.resize(n_rows * n_columns);
  for (std::size_t k = 0; k < n_columns; ++k)
  {
    std::copy(columns[k].begin(), columns[k].end(), basis.begin() + k * n_rows);
    columns[k].reinit(0); // one copy of T at a time
  }
  columns.clear();
  columns.shrink_to_fit();
}

void CraigBamptonReduction::expand(const Vector<double> &q, Vector<double> &u) const
{
  AssertThrow(q.size() == size(), ExcMessage("CraigBamptonReduction::expand: size"));
  if (u.size() != n_rows)
    u.reinit(n_rows);
  if (size() == 0 || n_rows == 0)
  {
    u = 0.;
    return;
  }
  // BLAS dgemv on the column-major T: one stream of T through memory (10 ms
  // a product on the 3D crane, 120 MB at the memory bandwidth of one core)
  column_major_vmult(false, n_rows, n_columns, 1., basis.data(), q.data(), 0., u.data());
}

void CraigBamptonReduction::expand_many(const std::vector<double> &Q,
                                        const unsigned int m,
                                        std::vector<double> &U) const
{
  AssertThrow(Q.size() == std::size_t(size()) * m,
              ExcMessage("CraigBamptonReduction::expand_many: size"));
  if (size() == 0 || n_rows == 0 || m == 0)
  {
    U.assign(n_rows * m, 0.);
    return;
  }
  U.resize(n_rows * m); // dgemm with beta = 0 writes every entry
  column_major_mmult(false, n_rows, m, n_columns, basis.data(), Q.data(), U.data());
}

FullMatrix<double>
CraigBamptonReduction::basis_rows(const std::vector<unsigned int> &rows) const
{
  FullMatrix<double> B(rows.size(), size());
  for (unsigned int k = 0; k < size(); ++k)
    for (unsigned int i = 0; i < rows.size(); ++i)
      B(i, k) = basis[k * n_rows + rows[i]];
  return B;
}

void CraigBamptonReduction::project(const Vector<double> &f, Vector<double> &r) const
{
  r.reinit(size());
  if (size() == 0 || n_rows == 0)
    return;
  AssertThrow(f.size() == n_rows, ExcMessage("CraigBamptonReduction::project: size"));
  column_major_vmult(true, n_rows, n_columns, 1., basis.data(), f.data(), 0., r.data());
}

void CraigBamptonReduction::free_interface_modes(
    std::vector<double> &omega_squared, std::vector<Vector<double>> &vectors) const
{
  const unsigned int r = size();
  LAPACKFullMatrix<double> K(r, r), M(r, r);
  K = reduced_stiffness;
  M = reduced_mass;
  vectors.assign(r, Vector<double>(r));
  K.compute_generalized_eigenvalues_symmetric(M, vectors);
  omega_squared.resize(r);
  for (unsigned int k = 0; k < r; ++k)
    omega_squared[k] = K.eigenvalue(k).real();
}

std::vector<double> CraigBamptonReduction::frequencies(const unsigned int n) const
{
  std::vector<double> omega_squared;
  std::vector<Vector<double>> vectors;
  free_interface_modes(omega_squared, vectors);
  std::vector<double> f;
  for (const double w2 : omega_squared)
    f.push_back(std::sqrt(std::max(w2, 0.)) / (2. * M_PI));
  std::sort(f.begin(), f.end());
  f.resize(std::min<std::size_t>(n, f.size()));
  return f;
}
} // namespace hati
