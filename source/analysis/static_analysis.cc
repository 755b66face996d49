#include <deal.II/base/exceptions.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <hati/analysis/static_analysis.h>
#include <hati/linear_algebra/amg_preconditioner.h>
#include <hati/linear_algebra/direct_solver.h>
#include <hati/model/rope_diagnostics.h>

#include <algorithm>
#include <array>
#include <cmath>
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

/** Whether contact rows @p a and @p b are exact opposites (two-sided, no clearance). */
bool opposite_rows(const ContactRow &a, const ContactRow &b)
{
  if (a.dofs != b.dofs || a.initial_gap != b.initial_gap)
    return false;
  for (unsigned int j = 0; j < a.dofs.size(); ++j)
    if (a.coefficients[j] != -b.coefficients[j])
      return false;
  return true;
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
                                 Vector<double> &U)
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
  DirectSolver solver(package);
  solver.factorize(A,
                   singular_message + " with its closed contacts (" + package +
                       " found a zero pivot in [K L^T; L 0]).");
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
  return lambda;
}

/**
 * The contact rows the static state holds closed: zero initial gap and a
 * free DoF in the row; the second of two opposite rows (two-sided without
 * clearance) is left to the first.
 */
struct ClosedContacts
{
  /** The closed rows, in the order of the contacts. */
  std::vector<unsigned int> closed;
  /** The first rows of two-sided pairs with a clearance, held where they are. */
  std::vector<unsigned int> centred;
  /** Per contact row: the closed row it is the opposite of, or -1. */
  std::vector<int> opposite;

  explicit ClosedContacts(const DiscreteSystem &system)
      : opposite(system.contacts.size(), -1)
  {
    for (unsigned int k = 0; k < system.contacts.size(); ++k)
    {
      const ContactRow &c = system.contacts[k];
      bool free_dof = false;
      for (const auto dof : c.dofs)
        free_dof = free_dof || !system.fixed[dof];
      if (!free_dof)
        continue;
      // a row with a gap is held only as the second of a two-sided pair whose
      // first row (the same gap, the opposite normal) precedes it
      if (c.initial_gap != 0.)
      {
        for (unsigned int j = 0; j < k; ++j)
          if (opposite_rows(system.contacts[j], c))
          {
            centred.push_back(j);
            closed.push_back(j);
            opposite[k] = j;
            break;
          }
        continue;
      }
      for (const unsigned int j : closed)
        if (opposite_rows(system.contacts[j], c))
          opposite[k] = j;
      if (opposite[k] < 0)
        closed.push_back(k);
    }
  }

  /** Whether the closed row @p k is the first of a pair with a clearance. */
  bool is_centred(const unsigned int k) const
  {
    return std::find(centred.begin(), centred.end(), k) != centred.end();
  }
};

/**
 * The contact force per contact row (N) from the multipliers @p lambda of
 * the closed rows (solve_closed()): a bilateral pair in tension is carried
 * by its second row; throws if a unilateral contact is in tension or if
 * the load @p F pushes a two-sided contact across its clearance.
 */
std::vector<double> closed_contact_forces(const DiscreteSystem &system,
                                          const ClosedContacts &contacts,
                                          const std::vector<double> &lambda,
                                          const Vector<double> &F)
{
  const std::vector<unsigned int> &closed = contacts.closed;
  const std::vector<int> &opposite = contacts.opposite;
  double largest = 0.;
  for (const double l : lambda)
    largest = std::max(largest, std::abs(l));
  std::vector<double> forces(system.contacts.size(), 0.);
  for (unsigned int r = 0; r < closed.size(); ++r)
    forces[closed[r]] = lambda[r];
  for (unsigned int k = 0; k < system.contacts.size(); ++k)
    if (opposite[k] >= 0 && forces[opposite[k]] < 0.) // bilateral pair
    {
      forces[k] = -forces[opposite[k]];
      forces[opposite[k]] = 0.;
    }
  for (unsigned int r = 0; r < closed.size(); ++r)
  {
    const unsigned int k = closed[r];
    bool bilateral = system.contacts[k].bilateral; // and the centred pairs
    for (unsigned int j = 0; j < opposite.size(); ++j)
      bilateral = bilateral || opposite[j] == static_cast<int>(k);
    if (!bilateral && lambda[r] < -1e-9 * largest)
    {
      std::ostringstream message;
      message << "static analysis: the closed contact '" << system.contacts[k].name
              << "' is in tension (" << lambda[r]
              << " N): the structure would lift off there (give it a gap > 0 or a "
                 "support)";
      AssertThrow(false, ExcMessage(message.str()));
    }
  }
  // a two-sided contact with a clearance only stands in for the play: the
  // static load must not push the node to a side
  double load = 0.;
  for (unsigned int i = 0; i < F.size(); ++i)
    load = std::max(load, std::abs(F[i]));
  for (unsigned int r = 0; r < closed.size(); ++r)
    if (contacts.is_centred(closed[r]))
    {
      if (std::abs(lambda[r]) > 1e-9 * std::max(largest, load))
      {
        std::ostringstream message;
        message << "static analysis: the static load pushes the two-sided contact '"
                << system.contacts[closed[r]].name << "' across its clearance ("
                << lambda[r]
                << " N): there is no static state within the play (support it)";
        AssertThrow(false, ExcMessage(message.str()));
      }
      forces[closed[r]] = 0.;
      for (unsigned int k = 0; k < opposite.size(); ++k)
        if (opposite[k] == static_cast<int>(closed[r]))
          forces[k] = 0.;
    }
  return forces;
}

/** Whether rows @p a and @p b are parallel on the free DoFs (the same constraint). */
bool parallel_rows(const SparseRow &a, const SparseRow &b, const std::vector<bool> &fixed)
{
  std::map<types::global_dof_index, double> ca, cb;
  for (unsigned int j = 0; j < a.dofs.size(); ++j)
    if (!fixed[a.dofs[j]] && a.coefficients[j] != 0.)
      ca[a.dofs[j]] += a.coefficients[j];
  for (unsigned int j = 0; j < b.dofs.size(); ++j)
    if (!fixed[b.dofs[j]] && b.coefficients[j] != 0.)
      cb[b.dofs[j]] += b.coefficients[j];
  if (ca.empty() || ca.size() != cb.size())
    return false;
  const double ratio = cb.begin()->second / ca.begin()->second;
  for (auto ia = ca.begin(), ib = cb.begin(); ia != ca.end(); ++ia, ++ib)
    if (ia->first != ib->first ||
        std::abs(ib->second - ratio * ia->second) > 1e-12 * std::abs(ib->second))
      return false;
  return true;
}

/**
 * The tangent rows of the closed contacts with friction (not the pairs with
 * a clearance, which do not touch), appended to @p held with a zero
 * right-hand side: per closed row with friction, its index in `closed`,
 * the index of its first tangent row in @p held and their number (tangent
 * rows on fixed DoFs only, or parallel to a row held already, are left
 * out).
 */
std::vector<std::array<unsigned int, 3>>
sticking_tangents(const DiscreteSystem &system,
                  const ClosedContacts &contacts,
                  std::vector<const SparseRow *> &held,
                  std::vector<double> &held_rhs)
{
  std::vector<std::array<unsigned int, 3>> sticking;
  for (unsigned int r = 0; r < contacts.closed.size(); ++r)
  {
    const ContactRow &c = system.contacts[contacts.closed[r]];
    if (!c.frictional() || contacts.is_centred(contacts.closed[r]))
      continue;
    const unsigned int first = held.size();
    for (const SparseRow &t : c.tangents)
    {
      bool free_dof = false;
      for (const auto dof : t.dofs)
        free_dof = free_dof || !system.fixed[dof];
      if (!free_dof)
        continue; // a tangent direction a support holds already
      bool parallel = false;
      for (const SparseRow *h : held)
        parallel = parallel || parallel_rows(*h, t, system.fixed);
      if (parallel)
        continue; // held already, e.g. by a wheel's centred flange pair
      held.push_back(&t);
      held_rhs.push_back(0.);
    }
    sticking.push_back({{r, first, static_cast<unsigned int>(held.size()) - first}});
  }
  return sticking;
}

/**
 * Coulomb's cone at the sticking closed contacts (A9): `||lambda_t|| <= mu
 * |lambda_n|` with the multipliers @p lambda of solve_closed(); throws a
 * one-line error naming the first contact where the static state would
 * slide.
 */
void check_static_friction(const DiscreteSystem &system,
                           const ClosedContacts &contacts,
                           const std::vector<std::array<unsigned int, 3>> &sticking,
                           const std::vector<double> &lambda)
{
  double largest = 0.;
  for (const double l : lambda)
    largest = std::max(largest, std::abs(l));
  for (const auto &[r, first, count] : sticking)
  {
    const ContactRow &c = system.contacts[contacts.closed[r]];
    double t2 = 0.;
    for (unsigned int t = 0; t < count; ++t)
      t2 += lambda[first + t] * lambda[first + t];
    const double tangential = std::sqrt(t2), normal = std::abs(lambda[r]);
    if (tangential > c.friction * normal + 1e-12 * largest)
    {
      std::ostringstream message;
      message << "static analysis: the closed contact '" << c.name
              << "' does not stick: its tangential force " << tangential
              << " N exceeds mu times its normal force, " << c.friction << " x " << normal
              << " = " << c.friction * normal
              << " N (Coulomb friction, mu = " << c.friction
              << "): there is no static state on it (support it or raise mu)";
      AssertThrow(false, ExcMessage(message.str()));
    }
  }
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
                  Vector<double> &U)
{
  const double norm_F = F.l2_norm();
  Vector<double> r(U.size());
  DirectSolver solver(package);
  solver.factorize(K, singular_message + " (" + package + " found a zero pivot in K).");
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
 * its near null space) to `1e-12 ||F||`; throws if CG breaks down or does
 * not converge.
 */
void solve_iterative(const DiscreteSystem &system,
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
    AssertThrow(false,
                ExcMessage(singular_message + " (CG + AMG broke down: p.K p = 0)."));
  }
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
    const std::vector<double> lambda =
        solve_closed(s.system, s.package, K, F, s.held.rows, s.held.rhs, U);
    const std::vector<double> forces =
        closed_contact_forces(s.system, s.contacts, lambda, F);
    check_static_friction(s.system, s.contacts, s.held.sticking, lambda);
    if (s.contact_forces != nullptr)
      *s.contact_forces = forces;
    return;
  }

  if (s.linear_solver != "iterative")
    solve_direct(s.package, K, F, fixed, U);
  else if (norm_F > 0.)
    solve_iterative(s.system, K, F, U);

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
 * The static state with ropes (R1, doc/theory.md 10.3): Newton on the rope
 * forces, the rest of the model linear,
 * `(K + K_r(U_k)) U_{k+1} = F + F_r(U_k) + K_r(U_k) U_k` from `U_0 = 0`,
 * until `||U_{k+1} - U_k|| <= 1e-10 ||U_{k+1}||` (free DoFs). A slack rope
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
    solve_linear(s, K, Ft, U_next);
    du = 0.;
    for (unsigned int i = 0; i < n; ++i)
      du += fixed[i] ? 0. : (U_next[i] - U[i]) * (U_next[i] - U[i]);
    du = std::sqrt(du);
    un = free_norm(U_next, fixed);
    U = U_next;
    if (du <= 1e-10 * un)
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
} // namespace

void solve_static(const DiscreteSystem &system,
                  const double time,
                  Vector<double> &U,
                  const std::string &linear_solver,
                  const bool constant_loads_only,
                  std::vector<double> *contact_forces)
{
  const unsigned int n = system.n_dofs();
  const std::string solver = resolve_linear_solver(linear_solver, n),
                    package = direct_solver_package(linear_solver, n);
  const std::vector<bool> &fixed = system.fixed;
  U.reinit(n);
  if (contact_forces != nullptr)
    contact_forces->assign(system.contacts.size(), 0.);
  unsigned int n_free = 0;
  for (unsigned int i = 0; i < n; ++i)
    n_free += fixed[i] ? 0 : 1;
  if (n_free == 0)
    return;
  AssertThrow(system.has_stiffness(),
              ExcMessage(singular_message + ": the model has no stiffness."));

  const ClosedContacts contacts(system);
  // the rows held: the closed contacts, `L U = -g0` (a two-sided pair with a
  // clearance held where it is, L U = 0), then the tangent rows of the
  // closed contacts with friction, which stick (A9): `T U = 0`
  HeldRows held;
  for (const unsigned int k : contacts.closed)
  {
    held.rows.push_back(&system.contacts[k]);
    held.rhs.push_back(contacts.is_centred(k) ? 0. : -system.contacts[k].initial_gap);
  }
  held.sticking = sticking_tangents(system, contacts, held.rows, held.rhs);
  check_rigid_translations(system, held.rows);

  Vector<double> F(n);
  if (constant_loads_only)
    F = system.constant_force;
  else
    system.external_force(time, F);
  for (unsigned int i = 0; i < n; ++i)
    if (fixed[i])
      F[i] = 0.;

  const StaticSolve s{system, contacts, held, solver, package, contact_forces};
  if (!system.ropes.empty())
  {
    try
    {
      solve_with_ropes(s, F, U);
    }
    catch (const ExceptionBase &e)
    {
      rethrow_naming_slack_rope(e, singular_message, system.ropes, U);
      throw;
    }
    return;
  }
  // K with the fixed DoFs decoupled (positive diagonal, no couplings)
  SparseMatrix<double> K(system.stiffness_pattern);
  K.copy_from(system.stiffness);
  decouple_fixed_dofs(K, fixed);
  solve_linear(s, K, F, U);
}
} // namespace hati
