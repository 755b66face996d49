#include <deal.II/base/exceptions.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <hati/analysis/settled_friction.h>
#include <hati/analysis/static_analysis.h>
#include <hati/analysis/static_contacts.h>
#include <hati/linear_algebra/amg_preconditioner.h>
#include <hati/linear_algebra/direct_solver.h>
#include <hati/model/rope_diagnostics.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <map>
#include <sstream>

namespace hati
{
namespace
{
const std::string singular_message =
    "static analysis: the stiffness matrix is singular: the model can move as a "
    "rigid body (check the supports)";

/**
 * The largest residual `||K U - F|| / ||F||` accepted: a mechanism leaves
 * one of order 1; round-off in a stiff thin-plate solid 3e-8 (doc/theory.md 6).
 */
constexpr double residual_tolerance = 1e-6;

/** ||x||_2 over the free DoFs. */
double free_norm(const Vector<double> &x, const std::vector<bool> &fixed)
{
  double s = 0.;
  for (unsigned int i = 0; i < x.size(); ++i)
    if (!fixed[i])
      s += x[i] * x[i];
  return std::sqrt(s);
}

/** r = F - K U on the free DoFs, zero on the fixed ones. */
void residual(const SparseMatrix<double> &K,
              const Vector<double> &U,
              const Vector<double> &F,
              const std::vector<bool> &fixed,
              Vector<double> &r)
{
  K.vmult(r, U);
  r.sadd(-1., F);
  for (unsigned int i = 0; i < r.size(); ++i)
    if (fixed[i])
      r[i] = 0.;
}

/**
 * Rigid translations: if an influence vector r_d (1 on the translations along
 * d) satisfies K r_d = 0 to round-off, the model can translate along d
 * without straining. Round-off scale: sum_j |K_ij| |r_j| per row.
 */
void check_rigid_translations(const DiscreteSystem &system,
                              const std::vector<const SparseRow *> &closed)
{
  const char *direction[3] = {"x", "y", "z"};
  const unsigned int n = system.n_dofs();
  for (unsigned int d = 0; d < 3; ++d)
  {
    const Vector<double> &r = system.influence[d];
    if (r.size() != n)
      continue;
    bool moves = false;
    for (unsigned int i = 0; i < n; ++i)
      moves = moves || (!system.fixed[i] && r[i] != 0.);
    if (!moves)
      continue;
    double kr = 0., scale = 0.;
    for (unsigned int i = 0; i < n; ++i)
    {
      if (system.fixed[i])
        continue;
      double row = 0., row_abs = 0.;
      for (auto it = system.stiffness.begin(i); it != system.stiffness.end(i); ++it)
        if (!system.fixed[it->column()])
        {
          row += it->value() * r[it->column()];
          row_abs += std::abs(it->value() * r[it->column()]);
        }
      kr = std::max(kr, std::abs(row));
      scale = std::max(scale, row_abs);
    }
    if (kr > 1e-10 * scale)
      continue;
    // a closed contact whose row sees the translation holds it
    bool held = false;
    for (const SparseRow *row : closed)
    {
      const SparseRow &c = *row;
      double lr = 0.;
      for (unsigned int j = 0; j < c.dofs.size(); ++j)
        if (!system.fixed[c.dofs[j]])
          lr += c.coefficients[j] * r[c.dofs[j]];
      held = held || std::abs(lr) > 1e-12;
    }
    // a rope whose ends the translation moves differently (e.g. a load hanging
    // from a fixed hook point) holds it once taut: axially, or laterally by
    // its tension's geometric stiffness (R1); a slack one is found by the
    // Newton iteration of solve_with_ropes()
    const auto moved = [&](const types::global_dof_index i)
    { return i != numbers::invalid_dof_index && !system.fixed[i] ? r[i] : 0.; };
    for (const Rope &rope : system.ropes)
      held = held || moved(rope.hook_dofs[d]) != moved(rope.load_dofs[d]);
    AssertThrow(held,
                ExcMessage(singular_message + ": a rigid translation along " +
                           direction[d] + " costs no strain energy" +
                           (closed.empty() ? "" : " and no closed contact holds it") +
                           "."));
  }
}

/**
 * The static problem with the closed contact rows @p closed as bilateral
 * constraints: `[K L^T; L 0] [U; mu] = [F; -g0]`, `lambda = -mu` (so that
 * `K U = F + L^T lambda`), factorised with the Amesos @p package (KLU or
 * MUMPS, pivoting) with up to two refinement steps. Returns lambda per
 * closed row (N).
 */
std::vector<double> solve_closed(const DiscreteSystem &system,
                                 const std::string &package,
                                 const SparseMatrix<double> &K,
                                 const Vector<double> &F,
                                 const std::vector<const SparseRow *> &closed,
                                 const std::vector<double> &closed_rhs,
                                 Vector<double> &U,
                                 const std::vector<unsigned int> &centred,
                                 const std::vector<unsigned int> &tangent_rows,
                                 PlayProbe &probe,
                                 DirectSolver *reusable)
{
  const unsigned int n = system.n_dofs(), m = closed.size(), N = n + m;
  const std::vector<bool> &fixed = system.fixed;
  DynamicSparsityPattern dsp(N, N);
  for (unsigned int i = 0; i < n; ++i)
    for (auto it = K.begin(i); it != K.end(i); ++it)
      dsp.add(i, it->column());
  for (unsigned int r = 0; r < m; ++r)
  {
    const SparseRow &c = *closed[r];
    dsp.add(n + r, n + r);
    for (const auto dof : c.dofs)
      if (!fixed[dof])
      {
        dsp.add(n + r, dof);
        dsp.add(dof, n + r);
      }
  }
  SparsityPattern pattern;
  pattern.copy_from(dsp);
  SparseMatrix<double> A(pattern);
  for (unsigned int i = 0; i < n; ++i)
    for (auto it = K.begin(i); it != K.end(i); ++it)
      A.add(i, it->column(), it->value());
  Vector<double> b(N), x(N), r(N), dx(N);
  for (unsigned int i = 0; i < n; ++i)
    b[i] = F[i];
  for (unsigned int k = 0; k < m; ++k)
  {
    const SparseRow &c = *closed[k];
    for (unsigned int j = 0; j < c.dofs.size(); ++j)
      if (!fixed[c.dofs[j]])
      {
        A.add(n + k, c.dofs[j], c.coefficients[j]);
        A.add(c.dofs[j], n + k, c.coefficients[j]);
      }
    b[n + k] = closed_rhs[k];
  }
  DirectSolver local(package);
  DirectSolver &solver = reusable ? *reusable : local;
  const std::string failure = singular_message + " with its closed contacts (" + package +
                              " found a zero pivot in [K L^T; L 0]).";
  if (reusable)
    solver.factorize_or_update(A, failure);
  else
    solver.factorize(A, failure);
  solver.solve(x, b);
  const double norm_b = b.l2_norm();
  for (unsigned int refinement = 0; refinement < 2; ++refinement)
  {
    A.residual(r, x, b);
    if (!std::isfinite(r.l2_norm()) || r.l2_norm() <= 1e-14 * norm_b)
      break;
    solver.solve(dx, r);
    x += dx;
  }
  AssertThrow(std::isfinite(x.l2_norm()),
              ExcMessage(singular_message + " (the solution is not finite)."));
  settle_sticking_tangents(solver, A, n, tangent_rows, x, b);
  const double norm_r = A.residual(r, x, b);
  if (!(norm_r <= residual_tolerance * norm_b))
  {
    std::ostringstream message;
    message << singular_message << " with its closed contacts (residual " << norm_r
            << " > " << residual_tolerance << " ||F|| = " << residual_tolerance * norm_b
            << ").";
    AssertThrow(false, ExcMessage(message.str()));
  }
  U.reinit(n);
  for (unsigned int i = 0; i < n; ++i)
    U[i] = fixed[i] ? 0. : x[i];
  std::vector<double> lambda(m);
  for (unsigned int k = 0; k < m; ++k)
    lambda[k] = -x[n + k];
  // the pushed centred rows: the block of A^-1 on them (PlayProbe), one
  // back-substitution each
  double largest = 0., load = 0.;
  for (const double l : lambda)
    largest = std::max(largest, std::abs(l));
  for (unsigned int i = 0; i < n; ++i)
    load = std::max(load, std::abs(F[i]));
  probe.rows.clear();
  for (const unsigned int r : centred)
    if (pushes(lambda[r], largest, load))
      probe.rows.push_back(r);
  const unsigned int np = probe.rows.size();
  probe.block.assign(np * np, 0.);
  // all the unit right-hand sides at once (one pass through the factor)
  std::vector<double> columns(std::size_t(N) * np, 0.);
  for (unsigned int j = 0; j < np; ++j)
    columns[std::size_t(j) * N + n + probe.rows[j]] = 1.;
  solver.solve_many(columns.data(), np);
  for (unsigned int j = 0; j < np; ++j)
    for (unsigned int i = 0; i < np; ++i)
      probe.block[i * np + j] = columns[std::size_t(j) * N + n + probe.rows[i]];
  return lambda;
}

/**
 * K U = F by one factorisation with the Amesos @p package (KLU stops at an
 * exactly zero pivot), then the solve and up to two steps of iterative
 * refinement with it.
 */
void solve_direct(const std::string &package,
                  const SparseMatrix<double> &K,
                  const Vector<double> &F,
                  const std::vector<bool> &fixed,
                  Vector<double> &U,
                  DirectSolver *reusable)
{
  const double norm_F = F.l2_norm();
  Vector<double> r(U.size());
  DirectSolver local(package);
  DirectSolver &solver = reusable ? *reusable : local;
  const std::string failure =
      singular_message + " (" + package + " found a zero pivot in K).";
  if (reusable)
    solver.factorize_or_update(K, failure);
  else
    solver.factorize(K, failure);
  solver.solve(U, F);
  for (unsigned int refinement = 0; refinement < 2; ++refinement)
  {
    residual(K, U, F, fixed, r);
    if (!std::isfinite(r.l2_norm()) || free_norm(r, fixed) <= 1e-14 * norm_F)
      break;
    Vector<double> x(U.size());
    solver.solve(x, r);
    U += x;
  }
}

/**
 * K U = F by CG with Trilinos ML AMG (the rigid translations of the model as
 * its near null space) to `1e-12 ||F||`; throws if CG does not converge.
 * Returns false if CG breaks down (a zero curvature p.K p = 0), which a
 * singular K gives but also a solvable one whose AMG hierarchy is
 * singular (solids tied to beams): the caller then asks the direct solver.
 */
bool solve_iterative(const DiscreteSystem &system,
                     const SparseMatrix<double> &K,
                     const Vector<double> &F,
                     Vector<double> &U)
{
  const unsigned int n = system.n_dofs();
  const double norm_F = F.l2_norm();
  TrilinosWrappers::PreconditionAMG amg;
  TrilinosWrappers::SparseMatrix trilinos_K;
  trilinos_K.reinit(K, 0.);
  // quiet: ML writes amesos-failure.dat and an ERROR line for a singular K
  initialize_quietly(amg, trilinos_K, structural_amg_data(system.influence, n));
  SolverControl control(std::max(1000u, n), 1e-12 * norm_F);
  TrilinosWrappers::SolverCG cg(control);
  try
  {
    cg.solve(trilinos_K, U, F, amg);
  }
  catch (const SolverControl::NoConvergence &e)
  {
    std::ostringstream message;
    message << singular_message << " or badly conditioned: CG + AMG did not "
            << "converge in " << e.last_step << " iterations (residual "
            << e.last_residual << ", target " << 1e-12 * norm_F << ").";
    AssertThrow(false, ExcMessage(message.str()));
  }
  catch (const std::exception &)
  {
    // AztecOO reports a breakdown of CG (a zero curvature p.K p = 0)
    return false;
  }
  return true;
}

/**
 * The rows a static solve holds: the closed contacts, then the tangent rows
 * of the closed contacts with friction, which stick (A9), with their
 * right-hand sides, and where each sticking contact's tangents are.
 */
struct HeldRows
{
  std::vector<const SparseRow *> rows;
  std::vector<double> rhs;
  std::vector<std::array<unsigned int, 3>> sticking;

  /** The held rows that are sticking tangents (settle_sticking_tangents()). */
  std::vector<unsigned int> tangent_rows() const
  {
    std::vector<unsigned int> t;
    for (const auto &[r, first, count] : sticking)
      for (unsigned int i = 0; i < count; ++i)
        t.push_back(first + i);
    return t;
  }
};

/**
 * What every static solve of one model takes: the model, its closed
 * contacts, the rows held, the linear solver (resolve_linear_solver(): KLU,
 * MUMPS or iterative), the Amesos package of its factorisations and where
 * the contact forces go (N; nullptr: nowhere).
 */
struct StaticSolve
{
  const DiscreteSystem &system;
  const ClosedContacts &contacts;
  const HeldRows &held;
  const std::string linear_solver, package;
  std::vector<double> *contact_forces;
  /** Where the sticking tangents' forces go (nullptr: nowhere). */
  std::vector<std::array<double, 2>> *tangent_forces;
  /** The centred pairs the load pushes to a side (closed_contact_forces()). */
  std::vector<PushedPair> *pushed;
  /** Their block of the inverse saddle matrix (solve_closed()). */
  PlayProbe *probe;
  /**
   * A factorisation kept between the solves of the rope iteration
   * (solve_with_ropes(): DirectSolver::factorize_or_update()), or nullptr.
   */
  DirectSolver *reusable = nullptr;
};

/**
 * K U = F with the held rows of @p s (solve_closed(), Coulomb's cone checked
 * at the sticking contacts) or without (direct or iterative), the residual
 * checked; @p K has its fixed DoFs decoupled.
 */
void solve_linear(const StaticSolve &s,
                  const SparseMatrix<double> &K,
                  const Vector<double> &F,
                  Vector<double> &U)
{
  const unsigned int n = s.system.n_dofs();
  const std::vector<bool> &fixed = s.system.fixed;
  const double norm_F = F.l2_norm();
  if (!s.contacts.closed.empty())
  {
    std::vector<unsigned int> centred;
    for (unsigned int r = 0; r < s.contacts.closed.size(); ++r)
      if (s.contacts.is_centred(s.contacts.closed[r]))
        centred.push_back(r);
    s.pushed->clear();
    const std::vector<double> lambda = solve_closed(s.system,
                                                    s.package,
                                                    K,
                                                    F,
                                                    s.held.rows,
                                                    s.held.rhs,
                                                    U,
                                                    centred,
                                                    s.held.tangent_rows(),
                                                    *s.probe,
                                                    s.reusable);
    s.pushed->clear();
    const std::vector<double> forces =
        closed_contact_forces(s.system, s.contacts, lambda, F, s.pushed);
    check_static_friction(s.system, s.contacts, s.held.sticking, lambda);
    if (s.contact_forces != nullptr)
      *s.contact_forces = forces;
    if (s.tangent_forces == nullptr)
      return;
    // the sticking tangents' multipliers; the held rows point into the
    // contact's own tangents (sticking_tangents() skips the held ones)
    s.tangent_forces->assign(s.system.contacts.size(), {{0., 0.}});
    for (const auto &[r, first, count] : s.held.sticking)
    {
      const ContactRow &c = s.system.contacts[s.contacts.closed[r]];
      for (unsigned int t = 0; t < count; ++t)
        for (unsigned int i = 0; i < c.tangents.size() && i < 2; ++i)
          if (s.held.rows[first + t] == &c.tangents[i])
            (*s.tangent_forces)[s.contacts.closed[r]][i] = lambda[first + t];
    }
    return;
  }

  if (s.linear_solver != "iterative")
    solve_direct(s.package, K, F, fixed, U, s.reusable);
  else if (norm_F > 0. && !solve_iterative(s.system, K, F, U))
  {
    // a breakdown is not a proof of singularity: the direct solver decides
    // (its zero pivot is), and a solvable model is solved and said so
    U = 0.;
    solve_direct(s.package, K, F, fixed, U, nullptr);
    std::cout << "  Linear solver = iterative: CG + AMG broke down (p.K p = 0) on a "
                 "stiffness that is not singular; solved with "
              << s.package << " instead" << std::endl;
  }

  AssertThrow(std::isfinite(U.l2_norm()),
              ExcMessage(singular_message + " (the solution is not finite)."));
  Vector<double> r(n);
  residual(K, U, F, fixed, r);
  const double norm_r = free_norm(r, fixed);
  if (!(norm_r <= residual_tolerance * norm_F))
  {
    std::ostringstream message;
    message << singular_message << " (residual ||K U - F|| = " << norm_r << " > "
            << residual_tolerance << " ||F|| = " << residual_tolerance * norm_F << ").";
    AssertThrow(false, ExcMessage(message.str()));
  }
  for (unsigned int i = 0; i < n; ++i)
    if (fixed[i])
      U[i] = 0.;
}

/** Newton iterations of the static state with ropes (R1) at most. */
constexpr unsigned int max_rope_iterations = 50;

/**
 * Relative correction below which the rope Newton iteration is also taken
 * as converged once it stops shrinking (by half per iteration): the linear
 * solves' round-off, about 2e-9 on the solid-girder crane of 54,000 DoFs.
 */
constexpr double rope_round_off_floor = 1e-8;

/**
 * The static state with ropes (R1, doc/theory.md 10.3): Newton on the rope
 * forces, the rest of the model linear,
 * `(K + K_r(U_k)) U_{k+1} = F + F_r(U_k) + K_r(U_k) U_k` from `U_0 = 0`,
 * until `||U_{k+1} - U_k|| <= 1e-10 ||U_{k+1}||` (free DoFs), or until it
 * stalls at the solves' round-off (rope_round_off_floor). A slack rope
 * gets a small isotropic stiffness in the iteration matrix (1e-6 k), which
 * does not change the solution.
 */
void solve_with_ropes(const StaticSolve &s, const Vector<double> &F, Vector<double> &U)
{
  const DiscreteSystem &system = s.system;
  const unsigned int n = system.n_dofs();
  const std::vector<bool> &fixed = system.fixed;
  U.reinit(n);
  Vector<double> U_next(n), Ft(n), rope_u(n);
  double du = 0., un = 0.;
  // the ropes' tangent changes only their ends' rows: one factorisation,
  // then low-rank updates of it (DirectSolver::factorize_or_update())
  DirectSolver factorisation(s.package);
  StaticSolve with_reuse = s;
  if (s.linear_solver != "iterative")
    with_reuse.reusable = &factorisation;
  for (unsigned int iteration = 0; iteration < max_rope_iterations; ++iteration)
  {
    SparseMatrix<double> K(system.stiffness_pattern);
    K.copy_from(system.stiffness);
    SparseMatrix<double> Kr(system.stiffness_pattern);
    for (const Rope &rope : system.ropes)
      add_rope_tangents({rope}, U, Kr, 1e-6 * rope.stiffness * rope.rest_length);
    K.add(1., Kr);
    decouple_fixed_dofs(K, fixed);
    // F + F_r(U_k) + K_r(U_k) U_k
    Ft = F;
    for (const Rope &rope : system.ropes)
      rope.add_force(U, Ft);
    Kr.vmult(rope_u, U);
    Ft += rope_u;
    for (unsigned int i = 0; i < n; ++i)
      if (fixed[i])
        Ft[i] = 0.;
    solve_linear(with_reuse, K, Ft, U_next);
    const double du_previous = iteration > 0 ? du : 0.;
    du = 0.;
    for (unsigned int i = 0; i < n; ++i)
      du += fixed[i] ? 0. : (U_next[i] - U[i]) * (U_next[i] - U[i]);
    du = std::sqrt(du);
    un = free_norm(U_next, fixed);
    U = U_next;
    if (du <= 1e-10 * un)
      return;
    // the solver's round-off floor (a large thin-plate solid: 2e-9 of ||U||):
    // the corrections stop shrinking below 1e-8 ||U||
    if (iteration > 0 && du <= rope_round_off_floor * un && du >= 0.5 * du_previous)
      return;
  }
  std::ostringstream message;
  message << "static analysis: the equilibrium with the ropes did not converge in "
          << max_rope_iterations << " Newton iterations (last correction " << du
          << " m of " << un << " m)";
  for (const Rope &rope : system.ropes)
    if (rope.chord(U).norm() < (1. - 1e-9) * rope.rest_length)
    {
      message << "; the rope '" << rope.name
              << "' is slack: a load held only by a slack rope has no static state";
      break;
    }
  AssertThrow(false, ExcMessage(message.str()));
}
/** Rounds of releasing pushed pairs at most (solve_static()). */
constexpr unsigned int max_release_rounds = 4;

/**
 * The rows a static solve holds: the closed contacts, `L U = -g0` (a
 * two-sided pair with a clearance held where it is, L U = 0), then the
 * tangent rows of the closed contacts with friction, which stick (A9):
 * `T U = 0`.
 */
HeldRows held_rows(const DiscreteSystem &system, const ClosedContacts &contacts)
{
  HeldRows held;
  for (const unsigned int k : contacts.closed)
  {
    held.rows.push_back(&system.contacts[k]);
    held.rhs.push_back(contacts.is_centred(k) ? 0. : -system.contacts[k].initial_gap);
  }
  held.sticking = sticking_tangents(system, contacts, held.rows, held.rhs);
  return held;
}

/** The static solve of @p s: with the ropes' Newton iteration, or linear. */
void solve_held(const StaticSolve &s, const Vector<double> &F, Vector<double> &U)
{
  if (!s.system.ropes.empty())
  {
    try
    {
      solve_with_ropes(s, F, U);
    }
    catch (const ExceptionBase &e)
    {
      rethrow_naming_slack_rope(e, singular_message, s.system.ropes, U);
      throw;
    }
    return;
  }
  // K with the fixed DoFs decoupled (positive diagonal, no couplings)
  SparseMatrix<double> K(s.system.stiffness_pattern);
  K.copy_from(s.system.stiffness);
  decouple_fixed_dofs(K, s.system.fixed);
  solve_linear(s, K, F, U);
}

/**
 * The released pairs of @p contacts (ClosedContacts::release()) at @p U:
 * each node within its play, `|L U| <= c / 2`; a one-line error otherwise.
 */
void check_within_play(const DiscreteSystem &system,
                       const ClosedContacts &contacts,
                       const Vector<double> &U)
{
  for (const unsigned int k : contacts.released)
  {
    const ContactRow &c = system.contacts[k];
    const double moved = c.apply(U);
    if (std::abs(moved) > c.initial_gap)
    {
      std::ostringstream message;
      message << "static analysis: the static load moves the two-sided contact '"
              << c.name << "' by " << moved << " m within a play of +-" << c.initial_gap
              << " m: there is no static state within the play (support it)";
      AssertThrow(false, ExcMessage(message.str()));
    }
  }
}
} // namespace

void solve_static(const DiscreteSystem &system,
                  const double time,
                  Vector<double> &U,
                  const std::string &linear_solver,
                  const bool constant_loads_only,
                  std::vector<double> *contact_forces,
                  std::vector<std::array<double, 2>> *tangent_forces)
{
  const unsigned int n = system.n_dofs();
  const double row_length = system.stiffness_row_length();
  const std::string solver = resolve_linear_solver(linear_solver, n, row_length),
                    package = direct_solver_package(linear_solver, n, row_length);
  const std::vector<bool> &fixed = system.fixed;
  U.reinit(n);
  if (contact_forces != nullptr)
    contact_forces->assign(system.contacts.size(), 0.);
  if (tangent_forces != nullptr)
    tangent_forces->assign(system.contacts.size(), {{0., 0.}});
  unsigned int n_free = 0;
  for (unsigned int i = 0; i < n; ++i)
    n_free += fixed[i] ? 0 : 1;
  if (n_free == 0)
    return;
  AssertThrow(system.has_stiffness(),
              ExcMessage(singular_message + ": the model has no stiffness."));

  ClosedContacts contacts(system);
  Vector<double> F(n);
  if (constant_loads_only)
    F = system.constant_force;
  else
    system.external_force(time, F);
  for (unsigned int i = 0; i < n; ++i)
    if (fixed[i])
      F[i] = 0.;

  std::vector<PushedPair> pushed;
  PlayProbe probe;
  HeldRows held = held_rows(system, contacts);
  check_rigid_translations(system, held.rows);
  // the solve of the closed contacts and held rows; the rounds below update
  // both in place
  const StaticSolve solve{system,
                          contacts,
                          held,
                          solver,
                          package,
                          contact_forces,
                          tangent_forces,
                          &pushed,
                          &probe};
  solve_held(solve, F, U);
  if (pushed.empty())
    return;
  // pairs pushed to a side of their play: free those whose release leaves
  // the saddle matrix regular (PlayProbe), solve again; their nodes must
  // stay within the play (doc/theory.md 6)
  // (rounds: a released pair's place may be taken by a friction tangent
  // that was parallel to it, sticking_tangents(), freeing another pair)
  // (a release that leaves a mechanism the probe's round-off hid, e.g. of
  // pairs pushed by a net load, ends with the pair's refusal)
  const std::string refusal = push_message(system, pushed.front());
  for (unsigned int round = 0; !pushed.empty(); ++round)
  {
    const std::vector<unsigned int> releasable = probe.releasable(contacts);
    AssertThrow(!releasable.empty() && round < max_release_rounds,
                ExcMessage(push_message(system, pushed.front())));
    for (const unsigned int k : releasable)
      contacts.release(k);
    held = held_rows(system, contacts);
    try
    {
      solve_held(solve, F, U);
    }
    catch (const ExceptionBase &)
    {
      AssertThrow(false, ExcMessage(refusal));
    }
  }
  check_within_play(system, contacts, U);
}
} // namespace hati
