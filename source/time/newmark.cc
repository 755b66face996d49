#include <deal.II/base/exceptions.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <hati/base/cpu_clones.h>
#include <hati/linear_algebra/amg_preconditioner.h>
#include <hati/linear_algebra/column_major.h>
#include <hati/time/newmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

// Energy balance of the average acceleration scheme (beta = 1/4, gamma = 1/2)
// -------------------------------------------------------------------------
// N1 and N3 together give
//   U_{n+1} = U_n + DT V_n + DT^2/4 (A_n + A_{n+1}),
//   V_{n+1} = V_n + DT/2 (A_n + A_{n+1}),
// hence  dU := U_{n+1} - U_n = DT/2 (V_n + V_{n+1})  and
//        A_n + A_{n+1} = 2 (V_{n+1} - V_n) / DT.
// N2 is the equation of motion at t_{n+1}: with N3,
//   M A_{n+1} + C V_{n+1} + K U_{n+1}
//     = M_eff A_{n+1} + C V* + K U* = F_{n+1},
// and set_initial_state() makes it hold at t_0. Average the equations at t_n
// and t_{n+1} and take the dot product with dU (M, C, K symmetric):
//   dU.M (A_n + A_{n+1})/2 = (V_n + V_{n+1}).M (V_{n+1} - V_n)/2
//                          = 1/2 V_{n+1}.M V_{n+1} - 1/2 V_n.M V_n,
//   dU.K (U_n + U_{n+1})/2 = 1/2 U_{n+1}.K U_{n+1} - 1/2 U_n.K U_n,
//   dU.C (V_n + V_{n+1})/2 = increment of `dissipated`,
//   dU.(F_n + F_{n+1})/2   = increment of `external_work`.
// So  d(kinetic) + d(internal) + d(dissipated) - d(external_work) = 0  in
// every step: Energies::total() is constant up to the round-off of the
// solves (and the tolerance of CG with the iterative solver). Rows of fixed
// DoFs do not satisfy the equation of motion (their reactions are not
// computed), but dU = 0 there, so they add nothing. For other (beta, gamma)
// the balance holds only to O(DT) (gamma > 1/2 dissipates numerically).
//
// Frequency-range damping (N4) adds K S to the internal force on both
// sides: its term is dU.K (S_n + S_{n+1})/2, the work the branches take,
// booked as MaxwellMemory::add_work(). With the memory update
// q_l,n+1 = e_l q_l,n + tau_l (1 - e_l) dU / DT, that work is the change of
// the stored 1/2 sum_l alpha_l q_l.K q_l plus a dissipation; energies()
// reports the stored part as damping_stored and the rest in dissipated.

namespace hati
{
namespace
{
using Clock = std::chrono::steady_clock;

double seconds_since(const Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/**
 * dst += factor * src for two deal.II matrices whose patterns may differ;
 * every entry of src must exist in the pattern of dst.
 */
void add_matrix(SparseMatrix<double> &dst,
                const double factor,
                const SparseMatrix<double> &src)
{
  if (&dst.get_sparsity_pattern() == &src.get_sparsity_pattern())
  {
    dst.add(factor, src);
    return;
  }
  const SparsityPattern &pattern = dst.get_sparsity_pattern();
  for (unsigned int i = 0; i < src.m(); ++i)
    for (auto it = src.begin(i); it != src.end(i); ++it)
    {
      if (it->value() == 0.)
        continue;
      AssertThrow(pattern.exists(i, it->column()),
                  ExcMessage("Newmark: the mass matrix has an entry outside the "
                             "sparsity pattern of the stiffness matrix."));
      dst.add(i, it->column(), factor * it->value());
    }
}

/**
 * Throw if @p x is not finite, naming @p what and, if given, the time of
 * the step (the message is formed only then: every step calls this).
 */
void check_finite(const Vector<double> &x,
                  const char *what,
                  const double step_time = std::numeric_limits<double>::quiet_NaN())
{
  if (std::isfinite(x.l2_norm()))
    return;
  std::ostringstream message;
  message << what;
  if (!std::isnan(step_time))
    message << " (the step from t = " << step_time << " s)";
  message << ": the solution is not finite (NaN or infinity): the model is singular or "
             "ill-conditioned (check the supports, the masses and the time step).";
  AssertThrow(false, ExcMessage(message.str()));
}
} // namespace

void NewmarkParameters::declare_parameters(ParameterHandler &prm)
{
  prm.declare_entry("Beta",
                    "0.25",
                    Patterns::Double(0.),
                    "Newmark beta (-). 0.25 with Gamma = 0.5 is the average "
                    "acceleration scheme: unconditionally stable, second order, "
                    "energy conserving. Unconditional stability needs "
                    "Beta >= Gamma / 2.");
  prm.declare_entry("Gamma",
                    "0.5",
                    Patterns::Double(0.),
                    "Newmark gamma (-), >= 0.5. Gamma > 0.5 adds numerical "
                    "damping and makes the scheme first order.");
  prm.declare_entry(
      "Linear solver",
      "auto",
      Patterns::Selection("auto|KLU|MUMPS|direct|iterative"),
      "KLU: the effective matrix M + gamma DT C + beta DT^2 K is "
      "factorised once (Amesos_Klu) and each step is one "
      "forward/backward substitution. MUMPS: the same with "
      "Amesos_Mumps (multifrontal; large models). auto: KLU below "
      "20000 DoFs, MUMPS at and above (the DoFs of the system solved: "
      "with HATI the implicit subdomain's), and MUMPS from 2000 DoFs "
      "for 3D continua (60 or more stiffness entries per row). direct: the same as auto "
      "(kept for older parameter files). iterative: conjugate gradients "
      "preconditioned by ML algebraic multigrid. Also the solver of the "
      "static analysis, of Initial state = static and of the modal "
      "analysis (with iterative, the matrices that are always "
      "factorised, e.g. the shifted stiffness of the modal analysis, "
      "use auto's choice).");
  prm.declare_entry("Solver tolerance",
                    "1e-10",
                    Patterns::Double(0.),
                    "iterative: relative residual ||b - M_eff A|| <= tol ||b|| of "
                    "each step (-).");
  prm.declare_entry("Mass",
                    "consistent",
                    Patterns::Selection("consistent|lumped"),
                    "Mass matrix of the implicit scheme: the model's consistent mass "
                    "(the lumped one for models without it) or the lumped (diagonal) "
                    "mass of the explicit scheme.");
}

void NewmarkParameters::parse_parameters(ParameterHandler &prm)
{
  beta = prm.get_double("Beta");
  gamma = prm.get_double("Gamma");
  linear_solver = prm.get("Linear solver");
  solver_tolerance = prm.get_double("Solver tolerance");
  mass = prm.get("Mass");
  AssertThrow(gamma >= 0.5,
              ExcMessage("Time integration/Newmark/Gamma = " + prm.get("Gamma") +
                         ": Newmark: Gamma must be >= 0.5: with Gamma < 1/2 the scheme "
                         "has negative numerical damping and the solution grows."));
  AssertThrow(solver_tolerance > 0.,
              ExcMessage("Time integration/Newmark/Solver tolerance: must be > 0."));
}

void NewmarkParameters::check_unconditional_stability() const
{
  if (!(2. * beta >= gamma - 1e-12))
  {
    std::ostringstream s;
    s << "Time integration/Newmark/Beta = " << beta << " with Gamma = " << gamma
      << ": Beta must be >= Gamma / 2 for unconditional stability (2 Beta >= Gamma >= "
         "1/2; Beta = 1/4, Gamma = 1/2 is the average acceleration scheme).";
    AssertThrow(false, ExcMessage(s.str()));
  }
}

/** The Trilinos effective matrix with its Amesos factorisation or AMG. */
struct Newmark::EffectiveSolver
{
  explicit EffectiveSolver(const std::string &package) : direct(package) {}

  DirectSolver direct;
  // iterative solver: the Trilinos matrix and its AMG preconditioner
  TrilinosWrappers::SparseMatrix matrix;
  TrilinosWrappers::PreconditionAMG amg;
};

Newmark::Newmark(const DiscreteSystem &system,
                 const double DT,
                 const NewmarkParameters &parameters,
                 const RayleighDamping &damping,
                 const MaxwellBranches &maxwell)
    : system(system), dt(DT), beta(parameters.beta), gamma(parameters.gamma),
      a0(damping.a0), a1(damping.a1),
      solver_name(resolve_linear_solver(
          parameters.linear_solver, system.n_dofs(), system.stiffness_row_length())),
      package(direct_solver_package(
          parameters.linear_solver, system.n_dofs(), system.stiffness_row_length())),
      direct(solver_name != "iterative"), tolerance(parameters.solver_tolerance),
      use_consistent_mass(system.has_consistent_mass() && parameters.mass != "lumped"),
      solver(std::make_unique<EffectiveSolver>(package)),
      branches(maxwell, DT, system.n_dofs())
{
  AssertThrow(!branches.active() || (a0 == 0. && a1 == 0.),
              ExcMessage("Newmark: Rayleigh and frequency-range damping cannot be "
                         "combined (Time integration/Damping/Type selects one)."));
  AssertThrow(dt > 0., ExcMessage("Newmark: the time step must be > 0 (s)."));
  AssertThrow(gamma >= 0.5, ExcMessage("Newmark: Gamma must be >= 0.5."));
  AssertThrow(
      2. * beta >= gamma - 1e-12,
      ExcMessage("Newmark: Beta must be >= Gamma / 2 (Time integration/Newmark/Beta, "
                 "Gamma) for unconditional stability "
                 "(2 Beta >= Gamma >= 1/2; Beta = 1/4, Gamma = 1/2 is the average "
                 "acceleration scheme)."));
  const unsigned int n = system.n_dofs();
  AssertThrow(system.fixed.size() == n,
              ExcMessage("Newmark: the DiscreteSystem has no fixed flags."));

  // (N2) M_eff = M + gamma DT C + beta DT^2 K
  //            = (1 + gamma DT a0) M + (beta DT^2 + gamma DT a1) K
  //              (+ gamma DT C_s with the system's own damping matrix C_s),
  // with frequency-range damping (N4) beta DT^2 (1 + beta_s) K
  const double mass_factor = 1. + gamma * dt * a0;
  const double stiffness_factor =
      branches.active() ? beta * dt * dt * (1. + branches.stiffness_factor())
                        : beta * dt * dt + gamma * dt * a1;
  SparsityPattern diagonal_pattern;
  if (!system.has_stiffness())
  {
    diagonal_pattern.reinit(n, n, 1);
    diagonal_pattern.compress();
  }
  SparseMatrix<double> m_eff(system.has_stiffness() ? system.stiffness_pattern
                                                    : diagonal_pattern);
  if (system.has_stiffness())
    add_matrix(m_eff, stiffness_factor, system.stiffness);
  if (system.has_damping_matrix())
    add_matrix(m_eff, gamma * dt, system.damping_matrix);
  if (use_consistent_mass)
    add_matrix(m_eff, mass_factor, system.consistent_mass);
  else
    for (unsigned int i = 0; i < n; ++i)
      m_eff.add(i, i, mass_factor * system.lumped_mass[i]);
  decouple_fixed_dofs(m_eff, system.fixed);
  for (unsigned int i = 0; i < n; ++i)
    AssertThrow(m_eff.diag_element(i) > 0.,
                ExcMessage("Newmark: the effective matrix has a zero or negative "
                           "diagonal at DoF " +
                           std::to_string(i) +
                           " (a DoF without mass and without stiffness): the model "
                           "is singular."));

  const auto start = Clock::now();
  if (direct)
    solver->direct.factorize(
        m_eff,
        "Newmark: the factorisation (" + package +
            ") of the effective matrix M + gamma DT C + beta DT^2 K found a zero pivot: "
            "the model is singular (check the masses and the supports).");
  else
  {
    solver->matrix.reinit(m_eff, 0.);
    TrilinosWrappers::PreconditionAMG::AdditionalData data;
    data.elliptic = true;
    data.smoother_sweeps = 2;
    // near null space: the rigid translations of the model, where it has any
    for (const auto &r : system.influence)
      if (r.size() == n && r.linfty_norm() > 0.)
      {
        std::vector<bool> mode(n);
        for (unsigned int i = 0; i < n; ++i)
          mode[i] = (r[i] != 0.);
        data.constant_modes.push_back(mode);
      }
    initialize_quietly(solver->amg, solver->matrix, data);
  }
  factorization_seconds = seconds_since(start);
  build_row_operators();

  for (auto *v :
       {&U, &V, &A, &F, &CV, &U_star, &V_star, &rhs, &tmp, &F_new, &A_new, &CV_new})
    v->reinit(n);
  if (branches.active())
    for (auto *v : {&KS, &KS_new, &W})
      v->reinit(n);
  t = system.start_time;
  set_initial_state(system.initial_displacement, system.initial_velocity);
}

Newmark::~Newmark() = default;

void Newmark::zero_fixed(Vector<double> &x) const
{
  for (unsigned int i = 0; i < x.size(); ++i)
    if (system.fixed[i])
      x[i] = 0.;
}

void Newmark::mass_vmult(Vector<double> &dst, const Vector<double> &src) const
{
  if (use_consistent_mass)
    system.consistent_mass.vmult(dst, src);
  else
    for (unsigned int i = 0; i < dst.size(); ++i)
      dst[i] = system.lumped_mass[i] * src[i];
}

void Newmark::build_row_operators()
{
  const unsigned int n = system.n_dofs();
  row_start.assign(1, 0);
  row_column.clear();
  row_stiffness.clear();
  row_damping.clear();
  // per row: column -> (K_ij, C_ij), the diagonal always present
  std::map<unsigned int, std::pair<double, double>> row;
  for (unsigned int i = 0; i < n; ++i)
  {
    row.clear();
    row[i];
    if (system.has_stiffness())
      for (auto it = system.stiffness.begin(i); it != system.stiffness.end(i); ++it)
      {
        auto &entry = row[it->column()];
        entry.first += it->value();
        entry.second += a1 * it->value();
      }
    if (system.has_damping_matrix())
      for (auto it = system.damping_matrix.begin(i); it != system.damping_matrix.end(i);
           ++it)
        row[it->column()].second += it->value();
    if (use_consistent_mass)
      for (auto it = system.consistent_mass.begin(i); it != system.consistent_mass.end(i);
           ++it)
        row[it->column()].second += a0 * it->value();
    else
      row[i].second += a0 * system.lumped_mass[i];
    for (const auto &[column, entry] : row)
      if (entry.first != 0. || entry.second != 0. || column == i)
      {
        row_column.push_back(column);
        row_stiffness.push_back(entry.first);
        row_damping.push_back(entry.second);
      }
    row_start.push_back(row_column.size());
  }
  // a dense operator (a reduced part, 12.2 of doc/theory.md): its rows are a
  // row-major matrix, whose products go to BLAS dgemv
  dense_rows = n >= dense_rows_from && row_column.size() == std::size_t(n) * n;
}

void Newmark::row_vmult(const std::vector<double> &values,
                        Vector<double> &dst,
                        const Vector<double> &src) const
{
  const unsigned int n = dst.size();
  if (dense_rows)
  {
    // row-major n x n: the transpose of a column-major one
    column_major_vmult(true, n, n, 1., values.data(), src.data(), 0., dst.data());
    return;
  }
  for (unsigned int i = 0; i < n; ++i)
  {
    double s = 0.;
    for (std::size_t e = row_start[i]; e < row_start[i + 1]; ++e)
      s += values[e] * src[row_column[e]];
    dst[i] = s;
  }
}

void Newmark::stiffness_vmult(Vector<double> &dst, const Vector<double> &src) const
{
  row_vmult(row_stiffness, dst, src);
}

void Newmark::damping_vmult(Vector<double> &dst, const Vector<double> &src) const
{
  if (!viscous_damping())
  {
    dst = 0.;
    return;
  }
  // C = a0 M + a1 K (+ the system's own), stored (build_row_operators())
  row_vmult(row_damping, dst, src);
}

void Newmark::set_initial_state(const Vector<double> &U0, const Vector<double> &V0)
{
  const unsigned int n = system.n_dofs();
  AssertThrow(U0.size() == n && V0.size() == n,
              ExcMessage("Newmark: the initial displacement and velocity must have " +
                         std::to_string(n) + " entries."));
  U = U0;
  V = V0;
  zero_fixed(U);
  zero_fixed(V);

  // M A_0 = F_ext(t) - C V_0 - K U_0 (algorithms.md section 2)
  system.external_force(t, F);
  rhs = F;
  stiffness_vmult(CV_new, U);
  rhs -= CV_new;
  damping_vmult(CV, V);
  rhs -= CV;
  zero_fixed(rhs);
  if (rhs.linfty_norm() == 0.)
    A = 0.;
  else if (use_consistent_mass)
    solve_with_mass(A, rhs);
  else
    // a free DoF without lumped mass has no inertia: its equation is static
    // and it gets A_0 = 0
    for (unsigned int i = 0; i < n; ++i)
      A[i] = system.lumped_mass[i] > 0. ? rhs[i] / system.lumped_mass[i] : 0.;
  zero_fixed(A);

  external_work = 0.;
  dissipated = 0.;
  // the branches start relaxed, S_0 = 0 (N4)
  branches.reset();
  KS = 0.;
}

void Newmark::solve_with_mass(Vector<double> &x, const Vector<double> &b) const
{
  if (!use_consistent_mass)
  {
    for (unsigned int i = 0; i < x.size(); ++i)
      x[i] = (system.fixed[i] || !(system.lumped_mass[i] > 0.))
                 ? 0.
                 : b[i] / system.lumped_mass[i];
    return;
  }
  if (!mass_solver)
  {
    SparseMatrix<double> mass(system.consistent_mass.get_sparsity_pattern());
    mass.copy_from(system.consistent_mass);
    decouple_fixed_dofs(mass, system.fixed);
    mass_solver = std::make_unique<DirectSolver>(package);
    mass_solver->factorize(
        mass,
        "Newmark: the consistent mass matrix is singular (" + package +
            " found a zero pivot): the initial acceleration M A_0 = F_0 - "
            "C V_0 - K U_0 cannot be computed (a free DoF without mass?).");
  }
  Vector<double> rhs_free(b);
  zero_fixed(rhs_free);
  mass_solver->solve(x, rhs_free);
  check_finite(x, "Newmark: initial acceleration");
}

void Newmark::step()
{
  free_step();
  finish_step();
}

HATI_AVX2_CLONES void Newmark::free_step()
{
  const unsigned int n = U.size();
  // (N1) predictors U* = U_n + DT V_n + DT^2 (1/2 - beta) A_n,
  // V* = V_n + DT (1 - gamma) A_n, in one pass
  {
    const double cu1 = dt, cu2 = dt * dt * (0.5 - beta), cv = dt * (1. - gamma);
    const double *__restrict u = U.data(), *__restrict v = V.data(),
                             *__restrict a = A.data();
    double *__restrict us = U_star.data(), *__restrict vs = V_star.data();
    for (unsigned int i = 0; i < n; ++i)
    {
      us[i] = u[i] + cu1 * v[i] + cu2 * a[i];
      vs[i] = v[i] + cv * a[i];
    }
  }

  // (N4) K acts on W = (1 + beta_s) U* - beta_s U_n + sum_l alpha_l e_l q_l,n
  const double *displacement = U_star.data();
  if (branches.active())
  {
    const double bs = branches.stiffness_factor();
    branches.history(W);
    for (unsigned int i = 0; i < n; ++i)
      W[i] += U_star[i] + bs * (U_star[i] - U[i]);
    displacement = W.data();
  }

  // (N2) M_eff A_{n+1} = F_{n+1} - C V* - K U*, K and C in one pass
  const double t_new = system.start_time + (n_steps + 1) * dt;
  system.external_force(t_new, F_new);
  if (dense_rows)
  {
    // r = F - K U* - C V* (row-major: the transposes of column-major matrices)
    double *const r = rhs.data();
    column_major_vmult(true, n, n, -1., row_stiffness.data(), displacement, 0., r);
    column_major_vmult(true, n, n, -1., row_damping.data(), V_star.data(), 1., r);
    for (unsigned int i = 0; i < n; ++i)
      r[i] = system.fixed[i] ? 0. : F_new[i] + r[i];
  }
  else
  {
    const double *__restrict f = F_new.data(), *__restrict us = displacement,
                             *__restrict vs = V_star.data(),
                             *__restrict k = row_stiffness.data(),
                             *__restrict c = row_damping.data();
    const unsigned int *__restrict column = row_column.data();
    double *__restrict r = rhs.data();
    // without viscous damping C = 0 (its rows hold zeros): K alone, the same
    // sums (k u + 0 = k u exactly) at half the loads
    const bool damped = viscous_damping();
    for (unsigned int i = 0; i < n; ++i)
    {
      double s = 0.;
      if (damped)
        for (std::size_t e = row_start[i]; e < row_start[i + 1]; ++e)
          s += k[e] * us[column[e]] + c[e] * vs[column[e]];
      else
        for (std::size_t e = row_start[i]; e < row_start[i + 1]; ++e)
          s += k[e] * us[column[e]];
      r[i] = system.fixed[i] ? 0. : f[i] - s;
    }
  }
  // A_n is the initial guess of CG; A_new becomes A_{n+1}
  if (!direct)
    A_new = A;
  solve_with_effective_matrix(A_new, rhs);

  // (N3) correctors: U_star becomes U_{n+1}, V_star V_{n+1}
  {
    const double cu = beta * dt * dt, cv = gamma * dt;
    double *__restrict a = A_new.data(), *__restrict us = U_star.data(),
                       *__restrict vs = V_star.data();
    for (unsigned int i = 0; i < n; ++i)
    {
      if (system.fixed[i])
        a[i] = 0.;
      us[i] += cu * a[i];
      vs[i] += cv * a[i];
    }
  }
}

void Newmark::add_link(const Vector<double> &force)
{
  // (G4) A_link = M_eff^-1 force
  rhs = force;
  zero_fixed(rhs);
  tmp = 0.;
  solve_with_effective_matrix(tmp, rhs);
  zero_fixed(tmp);
  add_link_acceleration(tmp);
}

HATI_AVX2_CLONES void Newmark::add_link_acceleration(const Vector<double> &a_link)
{
  // A_new += a, U* += beta DT^2 a, V* += gamma DT a in one serial pass (the
  // deal.II vector operations each go through the task scheduler)
  const unsigned int n = a_link.size();
  const double cu = beta * dt * dt, cv = gamma * dt;
  const double *__restrict a = a_link.data();
  double *__restrict an = A_new.data(), *__restrict us = U_star.data(),
                     *__restrict vs = V_star.data();
  for (unsigned int i = 0; i < n; ++i)
  {
    an[i] += a[i];
    us[i] += cu * a[i];
    vs[i] += cv * a[i];
  }
}

HATI_AVX2_CLONES void Newmark::finish_step()
{
  // energies: 1/2 (U_{n+1} - U_n) . (F_n + F_{n+1}) (and the damping's work)
  const unsigned int n = U.size();
  const bool damped = viscous_damping();
  if (damped)
    damping_vmult(CV_new, V_star);
  double work = 0., damping = 0.;
  {
    const double *__restrict u = U.data(), *__restrict us = U_star.data(),
                             *__restrict f = F.data(), *__restrict fn = F_new.data(),
                             *__restrict cv = CV.data(), *__restrict cvn = CV_new.data();
    for (unsigned int i = 0; i < n; ++i)
    {
      const double du = us[i] - u[i];
      work += du * (f[i] + fn[i]);
      damping += du * (cv[i] + cvn[i]);
    }
  }
  external_work += 0.5 * work;
  if (damped)
  {
    dissipated += 0.5 * damping;
    CV.swap(CV_new);
  }
  if (branches.active())
  {
    // (N4) q_l,n+1 = e_l q_l,n + tau_l (1 - e_l) (U_{n+1} - U_n) / DT, and the
    // branch work 1/2 dU . K (S_n + S_{n+1})
    // (W = U*, W -= U, W /= DT in one pass: the same products by 1/DT)
    const double inv_dt = 1. / dt;
    for (unsigned int i = 0; i < n; ++i)
      W[i] = (U_star[i] - U[i]) * inv_dt;
    branches.update(W);
    stiffness_vmult(KS_new, branches.sum());
    double branch = 0.;
    for (unsigned int i = 0; i < n; ++i)
      branch += (U_star[i] - U[i]) * (KS[i] + KS_new[i]);
    branches.add_work(0.5 * branch);
    KS.swap(KS_new);
  }

  U.swap(U_star);
  V.swap(V_star);
  A.swap(A_new);
  F.swap(F_new);
  ++n_steps;
  t = system.start_time + n_steps * dt;
}

void Newmark::set_memory(const std::vector<Vector<double>> &q)
{
  if (!branches.active())
    return;
  branches.set_memory(q, branches.work());
  stiffness_vmult(KS, branches.sum());
}

Energies Newmark::energies() const
{
  Energies e;
  mass_vmult(tmp, V);
  e.kinetic = 0.5 * (V * tmp);
  stiffness_vmult(tmp, U);
  e.internal = 0.5 * (U * tmp);
  e.external_work = external_work;
  e.dissipated = dissipated;
  branches.add_energies(e, system.stiffness);
  e.kinetic_implicit = e.kinetic;
  e.internal_implicit = e.internal;
  return e;
}

void Newmark::solve_with_effective_matrix(Vector<double> &x,
                                          const Vector<double> &b) const
{
  if (direct)
    solver->direct.solve(x, b);
  else
  {
    const double norm_b = b.l2_norm();
    if (norm_b == 0.)
      x = 0.;
    else
    {
      SolverControl control(std::max<unsigned int>(1000, b.size()), tolerance * norm_b);
      TrilinosWrappers::SolverCG cg(control);
      try
      {
        cg.solve(solver->matrix, x, b, solver->amg);
      }
      catch (const SolverControl::NoConvergence &e)
      {
        std::ostringstream message;
        message << "Newmark: CG + AMG did not converge on the effective matrix in "
                << e.last_step << " iterations (residual " << e.last_residual
                << ", target " << tolerance * norm_b
                << "): the model is singular or badly conditioned (check the "
                   "supports), or use Linear solver = auto.";
        AssertThrow(false, ExcMessage(message.str()));
      }
      catch (const std::exception &)
      {
        AssertThrow(false,
                    ExcMessage("Newmark: CG + AMG broke down on the effective matrix "
                               "(p.M_eff p <= 0): the model is singular (check the "
                               "masses and the supports), or use Linear solver = "
                               "auto."));
      }
    }
  }
  check_finite(x, "Newmark", t);
}
} // namespace hati
