// Modal analysis: the lowest modes of K phi = omega^2 M phi.
//
// Why ARPACK: deal.II 9.4 on this machine is built with ARPACK, whose
// ArpackSolver is serial and works directly on deal.II vectors and on any
// operator with a vmult(); the shift-invert operator (K - sigma M)^-1 is then
// applied with the same Amesos_Klu factorisation (Trilinos) that the static
// analysis and the Newmark integrator use. SLEPc (also installed) would need
// copies of K and M as PETSc matrices and a PETSc linear solver for the
// spectral transformation, for no gain on the serial problems hati solves.
// Small problems where ARPACK's constraint 2 nev + 1 < ncv <= n_free cannot
// be met go to dense LAPACK (dsygv) on the free DoFs.
//
// Closed contacts: the zero-gap contact rows are bilateral constraints
// L_c U = 0, eliminated as U = T q (one slave DoF per independent row,
// Gaussian elimination with partial pivoting on the sparse rows) so that
// K_r = T^T K T and M_r = T^T M T stay sparse and both solvers above apply
// unchanged, the slaves being held like fixed DoFs. A dense null-space basis
// Z = null(L_c) would be exact too but dense, n x (n - m).

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/arpack_solver.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <hati/analysis/modal_analysis.h>
#include <hati/analysis/row_elimination.h>
#include <hati/linear_algebra/column_major.h>
#include <hati/linear_algebra/direct_solver.h>
#include <hati/linear_algebra/sparse_nonzeros.h>
#include <hati/linear_algebra/symmetric_mumps.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <map>
#include <memory>
#include <numeric>
#include <random>
#include <sstream>

namespace hati
{
// named, not anonymous: ModalProblem::Data (declared in the header) holds
// ModalMatrices and ShiftedInverse (-Wsubobject-linkage)
namespace modal_internal
{
/**
 * The shift-invert operator (K - sigma M)^-1 of ARPACK's mode 3: one
 * factorisation of `K - sigma M` with the Amesos @p package (Amesos_Klu or
 * Amesos_Mumps), one forward/backward substitution per vmult(). A positive
 * shift (inside the spectrum: the factorisation is indefinite) is nudged
 * upwards by 1e-6 relative, at most twice, if the factorisation fails (the
 * shift on an eigenvalue).
 */
class ShiftedInverse
{
public:
  ShiftedInverse(const SparseMatrix<double> &K,
                 const SparseMatrix<double> &M,
                 const double shift,
                 const std::string &package)
      : sigma(shift), solver(package)
  {
    // fixed rows: K keeps a positive diagonal, M is zero there
    SparseMatrix<double> shifted(K.get_sparsity_pattern());
    for (unsigned int attempt = 0;; ++attempt)
    {
      shifted.copy_from(K);
      shifted.add(-sigma, M);
      try
      {
        solver.factorize(shifted,
                         "modal analysis: " + package +
                             " found a zero pivot in the shifted stiffness K - sigma M "
                             "(a free DoF without stiffness and without mass?).");
        return;
      }
      catch (const std::exception &)
      {
        if (sigma <= 0. || attempt == 2)
          throw;
        sigma *= 1. + 1e-6;
      }
    }
  }

  /** The shift factorised (1/s^2). */
  double shift() const { return sigma; }

  /** dst = (K - sigma M)^-1 src. */
  void vmult(Vector<double> &dst, const Vector<double> &src) const
  {
    solver.solve(dst, src);
  }

private:
  double sigma;
  DirectSolver solver;
};

/**
 * The shift-invert operator deflated of the M-orthonormal vectors Z:
 * `P (K - sigma M)^-1 P^T` with `P = I - Z Z^T M`, applied to `b = M x` as
 * ARPACK does: `P (K - sigma M)^-1 M P x`, whose eigenvalues are those of
 * the shift-invert operator but 0 on span(Z). (@p MZ: the products M Z.)
 */
class DeflatedInverse
{
public:
  /**
   * @p Z and @p MZ: the deflated modes and their M products, column-major
   * (n x n_z, contiguous: the projections are BLAS dgemv, one pass of each
   * through memory, not 2 n_z vector operations).
   */
  DeflatedInverse(const ShiftedInverse &inverse,
                  const std::vector<double> &Z,
                  const std::vector<double> &MZ,
                  const unsigned int n_z)
      : inverse(inverse), Z(Z), MZ(MZ), n_z(n_z), coefficients(n_z)
  {
  }

  /** dst = P (K - sigma M)^-1 P^T src, P = I - Z (M Z)^T. */
  void vmult(Vector<double> &dst, const Vector<double> &src) const
  {
    const std::size_t n = src.size();
    double *const c = coefficients.data();
    // projected = src - M Z (Z^T src)
    Vector<double> projected(src);
    column_major_vmult(true, n, n_z, 1., Z.data(), src.data(), 0., c);
    column_major_vmult(false, n, n_z, -1., MZ.data(), c, 1., projected.data());
    inverse.vmult(dst, projected);
    // dst -= Z (M Z)^T dst
    column_major_vmult(true, n, n_z, 1., MZ.data(), dst.data(), 0., c);
    column_major_vmult(false, n, n_z, -1., Z.data(), c, 1., dst.data());
  }

private:
  const ShiftedInverse &inverse;
  const std::vector<double> &Z, &MZ;
  const unsigned int n_z;
  mutable std::vector<double> coefficients;
};

/** Dense generalized eigenproblem on the free DoFs (LAPACK dsygv). */
std::vector<Eigenpair> dense_modes(const SparseMatrix<double> &K,
                                   const SparseMatrix<double> &M,
                                   const std::vector<bool> &fixed)
{
  const unsigned int n = K.m();
  std::vector<unsigned int> free_index(n, numbers::invalid_unsigned_int), free_dofs;
  for (unsigned int i = 0; i < n; ++i)
    if (!fixed[i])
    {
      free_index[i] = free_dofs.size();
      free_dofs.push_back(i);
    }
  const unsigned int nf = free_dofs.size();
  LAPACKFullMatrix<double> A(nf, nf), B(nf, nf);
  for (unsigned int i = 0; i < n; ++i)
  {
    if (fixed[i])
      continue;
    for (auto it = K.begin(i); it != K.end(i); ++it)
      if (!fixed[it->column()])
        A(free_index[i], free_index[it->column()]) += it->value();
    for (auto it = M.begin(i); it != M.end(i); ++it)
      if (!fixed[it->column()])
        B(free_index[i], free_index[it->column()]) += it->value();
  }
  std::vector<Vector<double>> vectors(nf, Vector<double>(nf));
  try
  {
    A.compute_generalized_eigenvalues_symmetric(B, vectors);
  }
  catch (const std::exception &)
  {
    AssertThrow(false,
                ExcMessage("modal analysis (dense LAPACK): the mass matrix is not "
                           "positive definite on the free DoFs (a free DoF without "
                           "mass?)."));
  }
  std::vector<Eigenpair> pairs(nf);
  for (unsigned int k = 0; k < nf; ++k)
  {
    pairs[k].lambda = A.eigenvalue(k).real();
    pairs[k].phi.reinit(n);
    for (unsigned int j = 0; j < nf; ++j)
      pairs[k].phi[free_dofs[j]] = vectors[k][j];
  }
  return pairs;
}

/**
 * The shift of the lowest modes: sigma = -s < 0, so that K - sigma M = K +
 * s M is positive definite even if the model has rigid-body modes (K only
 * semi-definite), and the wanted eigenvalues lambda >= 0 > sigma are the
 * largest nu = 1/(lambda - sigma) in magnitude. s is tiny next to the
 * stiffness scale: the accuracy of the elastic eigenvalues does not depend
 * on it (round-off eps ||K||).
 */
double shift_below_spectrum(const SparseMatrix<double> &K,
                            const SparseMatrix<double> &M,
                            const std::vector<bool> &fixed)
{
  double ratio = std::numeric_limits<double>::max();
  for (unsigned int i = 0; i < K.m(); ++i)
    if (!fixed[i] && M.diag_element(i) > 0. && K.diag_element(i) > 0.)
      ratio = std::min(ratio, K.diag_element(i) / M.diag_element(i));
  return -(ratio < std::numeric_limits<double>::max() ? 1e-8 * ratio : 1e-8);
}

/**
 * ARPACK shift-invert Lanczos with ncv Lanczos vectors: the @p n_modes
 * eigenpairs nearest the shift @p sigma of @p inverse (its shift-invert operator,
 * ShiftedInverse, or deflated, DeflatedInverse).
 */
template <typename Inverse>
std::vector<Eigenpair> arpack_modes(const SparseMatrix<double> &K,
                                    const SparseMatrix<double> &M,
                                    const std::vector<bool> &fixed,
                                    const Inverse &inverse,
                                    const double sigma,
                                    const unsigned int n_modes,
                                    const unsigned int ncv)
{
  const unsigned int n = K.m();
  SolverControl control(10000, 1e-13);
  ArpackSolver::AdditionalData data(ncv, ArpackSolver::largest_magnitude, true);
  ArpackSolver eigensolver(control, data);
  eigensolver.set_shift(sigma);
  // deterministic pseudo-random start vector (all ones would miss the
  // antisymmetric modes of symmetric structures), zero on fixed DoFs
  Vector<double> start(n);
  std::mt19937 generator(20240501);
  std::uniform_real_distribution<double> uniform(0.5, 1.5);
  for (unsigned int i = 0; i < n; ++i)
    start[i] = fixed[i] ? 0. : uniform(generator);
  eigensolver.set_initial_vector(start);

  std::vector<std::complex<double>> lambda(n_modes);
  std::vector<Vector<double>> vectors(n_modes, Vector<double>(n));
  eigensolver.solve(K, M, inverse, lambda, vectors, n_modes);

  std::vector<Eigenpair> pairs(n_modes);
  for (unsigned int k = 0; k < n_modes; ++k)
  {
    pairs[k].lambda = lambda[k].real();
    pairs[k].phi = vectors[k];
  }
  return pairs;
}

/**
 * K and M of the eigenproblem on one pattern (a diagonal one for a model
 * without stiffness; M the consistent mass if the system has one, else the
 * lumped diagonal). Fixed DoFs: K keeps a positive diagonal, M rows and
 * columns are zero, so that their eigenvalues are infinite and never found.
 */
struct ModalMatrices
{
  SparsityPattern diagonal_pattern;
  SparseMatrix<double> K, M;

  ModalMatrices(const DiscreteSystem &system, const Vector<double> *rope_state)
  {
    const unsigned int n = system.n_dofs();
    if (!system.has_stiffness())
    {
      diagonal_pattern.reinit(n, n, 1);
      diagonal_pattern.compress();
    }
    const SparsityPattern &pattern =
        system.has_stiffness() ? system.stiffness_pattern : diagonal_pattern;
    K.reinit(pattern);
    M.reinit(pattern);
    if (system.has_stiffness())
      K.copy_from(system.stiffness);
    // the ropes' tangent at their state (R1, doc/theory.md 10.4)
    if (system.has_stiffness() && !system.ropes.empty())
    {
      Vector<double> zero(n);
      add_rope_tangents(system.ropes, rope_state ? *rope_state : zero, K);
    }
    if (system.has_consistent_mass())
    {
      for (unsigned int i = 0; i < n; ++i)
        for (auto it = system.consistent_mass.begin(i);
             it != system.consistent_mass.end(i);
             ++it)
          if (it->value() != 0.)
          {
            AssertThrow(pattern.exists(i, it->column()),
                        ExcMessage("modal analysis: the consistent mass has an entry "
                                   "outside the sparsity pattern of the stiffness."));
            M.add(i, it->column(), it->value());
          }
    }
    else
      for (unsigned int i = 0; i < n; ++i)
        M.set(i, i, system.lumped_mass[i]);
    decouple_fixed_dofs(K, system.fixed);
    // fixed DoFs get no mass: their spurious eigenvalues go to infinity
    for (unsigned int i = 0; i < n; ++i)
      for (auto it = M.begin(i); it != M.end(i); ++it)
        if (system.fixed[i] || system.fixed[it->column()])
          it->value() = 0.;
  }
};

/** The largest absolute row sum of @p A (its infinity norm). */
double max_row_sum(const SparseMatrix<double> &A)
{
  double norm = 0.;
  for (unsigned int i = 0; i < A.m(); ++i)
  {
    double row = 0.;
    for (auto it = A.begin(i); it != A.end(i); ++it)
      row += std::abs(it->value());
    norm = std::max(norm, row);
  }
  return norm;
}

/**
 * Zero mode @p k (counted from 0) on the @p fixed DoFs, mass-normalise it
 * and check `K phi = lambda M phi` on the free DoFs (relative 1e-6, plus
 * 1e-10 `||K||_inf ||phi||`, @p norm_K); throws if it has no kinetic energy
 * or is not an eigenpair. @p Mphi: M phi of the normalised mode.
 */
void normalise_and_check(const unsigned int k,
                         const double lambda,
                         const SparseMatrix<double> &K,
                         const SparseMatrix<double> &M,
                         const std::vector<bool> &fixed,
                         const double norm_K,
                         Vector<double> &phi,
                         Vector<double> &Mphi)
{
  const unsigned int n = phi.size();
  Vector<double> Kphi(n), r(n);
  Mphi.reinit(n);
  for (unsigned int i = 0; i < n; ++i)
    if (fixed[i])
      phi[i] = 0.;
  M.vmult(Mphi, phi);
  const double mass = phi * Mphi;
  AssertThrow(mass > 0. && std::isfinite(mass),
              ExcMessage("modal analysis: mode " + std::to_string(k + 1) +
                         " has no kinetic energy (ARPACK did not converge or the "
                         "mass matrix is singular)."));
  phi /= std::sqrt(mass);
  Mphi /= std::sqrt(mass);

  K.vmult(Kphi, phi);
  r = Kphi;
  r.add(-lambda, Mphi);
  for (unsigned int i = 0; i < n; ++i)
    if (fixed[i])
      r[i] = 0.;
  const double tolerance = 1e-6 * (Kphi.l2_norm() + std::abs(lambda) * Mphi.l2_norm()) +
                           1e-10 * norm_K * phi.l2_norm();
  if (!(r.l2_norm() <= tolerance))
  {
    std::ostringstream message;
    message << "modal analysis: mode " << k + 1 << " (lambda = " << lambda
            << " 1/s^2) is not an eigenpair: ||K phi - lambda M phi|| = " << r.l2_norm()
            << " > " << tolerance << " (the eigensolver did not converge).";
    AssertThrow(false, ExcMessage(message.str()));
  }
}
} // namespace modal_internal
using namespace modal_internal;

std::array<Vector<double>, 3> influence_masses(const DiscreteSystem &system,
                                               const SparseMatrix<double> &M,
                                               std::array<double, 3> &total_mass)
{
  const unsigned int n = system.n_dofs();
  std::array<Vector<double>, 3> Mr;
  for (unsigned int d = 0; d < 3; ++d)
    if (system.mass_influence[d].size() == n)
    {
      // M r with the inertia coupled to the supports (DiscreteSystem)
      Mr[d] = system.mass_influence[d];
      for (unsigned int i = 0; i < n; ++i)
        if (system.fixed[i])
          Mr[d][i] = 0.;
      total_mass[d] = system.influence[d].size() == n ? system.influence[d] * Mr[d] : 0.;
    }
    else if (system.influence[d].size() == n)
    {
      Mr[d].reinit(n);
      M.vmult(Mr[d], system.influence[d]);
      total_mass[d] = system.influence[d] * Mr[d];
    }
  return Mr;
}

/**
 * The eigenproblem on the free DoFs: K and M, and with closed contacts or
 * held rows `K_r = T^T K T`, `M_r = T^T M T` on the full numbering, the
 * eliminated (slave) DoFs held like fixed ones (doc/theory.md 7.3).
 */
struct ModalProblem::Data
{
  const unsigned int n;
  const std::string package;
  const ModalMatrices matrices;
  RowElimination elimination;
  unsigned int n_closed_contacts = 0, n_constraints = 0;
  std::vector<bool> fixed;
  SparsityPattern condensed_pattern;
  SparseMatrix<double> K_condensed, M_condensed;
  /** M() without its zero entries: the products of the Lanczos runs. */
  SparsityPattern product_pattern;
  SparseMatrix<double> M_products;
  unsigned int n_free = 0;
  /** The factorisation of the condensed stiffness (solve_static()). */
  mutable std::unique_ptr<DirectSolver> static_solver;
  /** The last factorisation, of the shift @p factorised_shift asked for. */
  mutable std::unique_ptr<ShiftedInverse> inverse;
  mutable double factorised_shift = 0.;

  Data(const DiscreteSystem &system,
       const bool close_contacts,
       const Vector<double> *rope_state,
       const std::string &linear_solver,
       const std::vector<SparseRow> *held)
      : n(system.n_dofs()),
        package(direct_solver_package(linear_solver, n, system.stiffness_row_length())),
        matrices(system, rope_state),
        elimination(close_contacts ? RowElimination(system) : RowElimination())
  {
    n_closed_contacts = elimination.n_closed;
    n_constraints = elimination.slaves.size();
    if (held)
      for (const SparseRow &row : *held)
        elimination.eliminate(system.fixed, row, false);
    fixed = system.fixed;
    if (!elimination.slaves.empty())
    {
      std::vector<double> diagonal(n, 1.), zero(n, 0.);
      for (const auto &entry : elimination.slaves)
      {
        fixed[entry.first] = true;
        if (matrices.K.diag_element(entry.first) > 0.)
          diagonal[entry.first] = matrices.K.diag_element(entry.first);
      }
      elimination.condense(matrices.K, diagonal, condensed_pattern, K_condensed);
      elimination.condense(matrices.M, zero, condensed_pattern, M_condensed);
    }
    n_free = std::count(fixed.begin(), fixed.end(), false);
    copy_nonzeros(M(), product_pattern, M_products);
  }

  /** K of the eigenproblem solved (condensed if rows are eliminated). */
  const SparseMatrix<double> &K() const
  {
    return elimination.slaves.empty() ? matrices.K : K_condensed;
  }
  /** M of the eigenproblem solved (condensed if rows are eliminated). */
  const SparseMatrix<double> &M() const
  {
    return elimination.slaves.empty() ? matrices.M : M_condensed;
  }
  /**
   * ARPACK's ncv for @p n_modes with @p n_deflated vectors deflated: 2
   * n_modes + 1 < ncv < n and ncv <= n_free - n_deflated.
   */
  unsigned int ncv(const unsigned int n_modes, const unsigned int n_deflated) const
  {
    // ncv <= n_free keeps the Lanczos basis inside the space of the free DoFs
    return std::min({n_free - std::min(n_deflated, n_free),
                     n - 1,
                     std::max(2 * n_modes + 2, n_modes + 20)});
  }
};

ModalProblem::ModalProblem(const DiscreteSystem &system,
                           const bool close_contacts,
                           const Vector<double> *rope_state,
                           const std::string &linear_solver,
                           const std::vector<SparseRow> *held)
{
  AssertThrow(system.fixed.size() == system.n_dofs(),
              ExcMessage("modal analysis: the DiscreteSystem has no fixed flags."));
  data = std::make_unique<Data>(system, close_contacts, rope_state, linear_solver, held);
}

ModalProblem::~ModalProblem() = default;

unsigned int ModalProblem::n_free() const { return data->n_free; }

unsigned int ModalProblem::n_closed_contacts() const { return data->n_closed_contacts; }

unsigned int ModalProblem::n_constraints() const { return data->n_constraints; }

const SparseMatrix<double> &ModalProblem::mass() const { return data->matrices.M; }

const SparseMatrix<double> &ModalProblem::stiffness() const { return data->matrices.K; }

unsigned int ModalProblem::count_below(const double lambda) const
{
  const SparseMatrix<double> &K = data->K(), &M = data->M();
  SparseMatrix<double> shifted(K.get_sparsity_pattern());
  shifted.copy_from(K);
  shifted.add(-lambda, M);
  SymmetricMumps solver;
  std::ostringstream message;
  message << "modal analysis: the factorisation of K - lambda M at lambda = " << lambda
          << " 1/s^2 (" << std::sqrt(std::max(lambda, 0.)) / (2. * M_PI)
          << " Hz) failed (MUMPS INFOG(1) = ";
  AssertThrow(solver.factorize(shifted),
              ExcMessage(message.str() + std::to_string(solver.error()) +
                         "): is the frequency an eigenfrequency of the model?"));
  // fixed and eliminated DoFs: a positive diagonal of K, no mass, a positive pivot
  return static_cast<unsigned int>(solver.negative_pivots());
}

void ModalProblem::condense_load(Vector<double> &f) const
{
  AssertThrow(f.size() == data->n, ExcInternalError());
  if (!data->elimination.slaves.empty())
    data->elimination.transpose_apply(f);
  for (unsigned int i = 0; i < data->n; ++i)
    if (data->fixed[i])
      f[i] = 0.;
}

Vector<double> ModalProblem::solve_static(const Vector<double> &f) const
{
  AssertThrow(f.size() == data->n, ExcInternalError());
  if (!data->static_solver)
  {
    auto solver = std::make_unique<DirectSolver>(data->package);
    solver->factorize(data->K(),
                      "static solve of the modal problem: " + data->package +
                          " found a zero pivot in the condensed stiffness (a mechanism: "
                          "a free DoF that nothing holds).");
    data->static_solver = std::move(solver);
  }
  Vector<double> U(data->n);
  data->static_solver->solve(U, f);
  for (unsigned int i = 0; i < data->n; ++i)
    if (data->fixed[i])
      U[i] = 0.;
  data->elimination.distribute(U);
  return U;
}

double ModalProblem::lowest_shift() const
{
  return shift_below_spectrum(data->K(), data->M(), data->fixed);
}

bool ModalProblem::lanczos_applies(const unsigned int n_modes,
                                   const unsigned int n_deflated) const
{
  return data->ncv(n_modes, n_deflated) >= 2 * n_modes + 2;
}

std::vector<Eigenpair>
ModalProblem::modes_near(const double shift,
                         const unsigned int n_modes,
                         const std::vector<const Eigenpair *> &deflated) const
{
  AssertThrow(n_modes <= data->n_free,
              ExcMessage("modal analysis: " + std::to_string(n_modes) +
                         " modes requested, but the model has only " +
                         std::to_string(data->n_free) + " free degrees of freedom" +
                         (data->elimination.slaves.empty()
                              ? std::string()
                              : " once its closed contacts hold " +
                                    std::to_string(data->elimination.slaves.size())) +
                         " (the number of modes)."));
  if (n_modes == 0)
    return {};
  // M on the pattern of K (shifted: K - sigma M) and without its zeros (products)
  const SparseMatrix<double> &K = data->K(), &M = data->M(),
                             &M_products = data->M_products;
  const std::vector<bool> &fixed = data->fixed;
  const unsigned int ncv = data->ncv(n_modes, deflated.size());
  const bool lanczos = lanczos_applies(n_modes, deflated.size());
  AssertThrow(lanczos || deflated.empty(),
              ExcMessage("modal analysis: " + std::to_string(deflated.size()) +
                         " modes deflated leave too few free DoFs for " +
                         std::to_string(n_modes) + " modes with ARPACK."));
  std::vector<Eigenpair> pairs;
  if (lanczos)
  {
    if (!data->inverse || data->factorised_shift != shift)
    {
      data->inverse.reset();
      data->inverse = std::make_unique<ShiftedInverse>(K, M, shift, data->package);
      data->factorised_shift = shift;
    }
    const ShiftedInverse &inverse = *data->inverse;
    if (deflated.empty())
      pairs = arpack_modes(K, M_products, fixed, inverse, inverse.shift(), n_modes, ncv);
    else
    {
      // the deflated modes on the condensed problem: zero on its fixed DoFs
      const std::size_t n = K.m(), n_z = deflated.size();
      std::vector<double> Z(n * n_z), MZ(n * n_z);
      for (std::size_t k = 0; k < n_z; ++k)
      {
        const Vector<double> &phi = deflated[k]->phi, &Mphi = deflated[k]->Mphi;
        AssertThrow(phi.size() == n && Mphi.size() == n, ExcInternalError());
        for (std::size_t i = 0; i < n; ++i)
        {
          Z[k * n + i] = fixed[i] ? 0. : phi[i];
          MZ[k * n + i] = Mphi[i];
        }
      }
      pairs = arpack_modes(K,
                           M_products,
                           fixed,
                           DeflatedInverse(inverse, Z, MZ, n_z),
                           inverse.shift(),
                           n_modes,
                           ncv);
    }
  }
  else
    pairs = dense_modes(K, M, fixed);
  std::sort(pairs.begin(),
            pairs.end(),
            [](const Eigenpair &a, const Eigenpair &b) { return a.lambda < b.lambda; });
  // the n_modes nearest the shift: a window of the ascending eigenvalues
  // (the lowest ones for a shift below the spectrum)
  std::size_t first = 0;
  while (first + n_modes < pairs.size() &&
         std::abs(pairs[first + n_modes].lambda - shift) <
             std::abs(pairs[first].lambda - shift))
    ++first;
  pairs.erase(pairs.begin(), pairs.begin() + first);
  pairs.resize(n_modes);

  // mass-normalise and check (on the free DoFs of the condensed problem),
  // back-substitute the slaves, fix the sign (largest entry positive)
  const double norm_K = max_row_sum(K);
  for (unsigned int k = 0; k < n_modes; ++k)
  {
    Vector<double> &phi = pairs[k].phi;
    normalise_and_check(
        k, pairs[k].lambda, K, M_products, fixed, norm_K, phi, pairs[k].Mphi);
    data->elimination.distribute(phi);
    unsigned int largest = 0;
    for (unsigned int i = 0; i < phi.size(); ++i)
      if (std::abs(phi[i]) > std::abs(phi[largest]))
        largest = i;
    if (phi[largest] < 0.)
    {
      phi *= -1.;
      pairs[k].Mphi *= -1.;
    }
  }
  return pairs;
}

ModalResult compute_modes(const DiscreteSystem &system,
                          const unsigned int n_modes,
                          const bool close_contacts,
                          const Vector<double> *rope_state,
                          const std::string &linear_solver,
                          const std::vector<SparseRow> *held)
{
  const unsigned int n = system.n_dofs();
  const ModalProblem problem(system, close_contacts, rope_state, linear_solver, held);
  ModalResult result;
  const std::array<Vector<double>, 3> Mr =
      influence_masses(system, problem.mass(), result.total_mass);
  result.n_closed_contacts = problem.n_closed_contacts();
  result.n_constraints = problem.n_constraints();

  std::vector<Eigenpair> pairs = problem.modes_near(problem.lowest_shift(), n_modes);
  for (Eigenpair &pair : pairs)
  {
    result.frequencies.push_back(std::sqrt(std::max(pair.lambda, 0.)) / (2. * M_PI));
    std::array<double, 3> gamma{{0., 0., 0.}}, effective{{0., 0., 0.}};
    for (unsigned int d = 0; d < 3; ++d)
      if (Mr[d].size() == n)
      {
        gamma[d] = pair.phi * Mr[d];
        effective[d] = gamma[d] * gamma[d];
      }
    result.participation.push_back(gamma);
    result.effective_mass.push_back(effective);
    result.modes.push_back(std::move(pair.phi));
  }
  return result;
}
} // namespace hati
