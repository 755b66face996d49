#include <deal.II/base/exceptions.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <hati/analysis/static_analysis.h>
#include <hati/linear_algebra/direct_solver.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace hati
{
namespace
{
const std::string singular_message =
    "static analysis: the stiffness matrix is singular: the model can move as a "
    "rigid body (check the supports)";

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
void check_rigid_translations(const DiscreteSystem &system)
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
    AssertThrow(kr > 1e-10 * scale,
                ExcMessage(singular_message + ": a rigid translation along " +
                           direction[d] + " costs no strain energy."));
  }
}
} // namespace

void solve_static(const DiscreteSystem &system,
                  const double time,
                  Vector<double> &U,
                  const std::string &linear_solver,
                  const bool constant_loads_only)
{
  AssertThrow(linear_solver == "direct" || linear_solver == "iterative",
              ExcMessage("static analysis: unknown linear solver <" + linear_solver +
                         ">: use direct or iterative."));
  const unsigned int n = system.n_dofs();
  const std::vector<bool> &fixed = system.fixed;
  U.reinit(n);
  unsigned int n_free = 0;
  for (unsigned int i = 0; i < n; ++i)
    n_free += fixed[i] ? 0 : 1;
  if (n_free == 0)
    return;
  AssertThrow(system.has_stiffness(),
              ExcMessage(singular_message + ": the model has no stiffness."));
  check_rigid_translations(system);

  Vector<double> F(n);
  if (constant_loads_only)
    F = system.constant_force;
  else
    system.external_force(time, F);
  for (unsigned int i = 0; i < n; ++i)
    if (fixed[i])
      F[i] = 0.;
  const double norm_F = F.l2_norm();

  // K with the fixed DoFs decoupled (positive diagonal, no couplings)
  SparseMatrix<double> K(system.stiffness_pattern);
  K.copy_from(system.stiffness);
  decouple_fixed_dofs(K, fixed);

  Vector<double> r(n);
  if (linear_solver == "direct")
  {
    // one factorisation (Amesos_Klu stops at an exactly zero pivot), then the
    // solve and up to two steps of iterative refinement with it
    DirectSolver solver;
    solver.factorize(K, singular_message + " (Amesos_Klu found a zero pivot in K).");
    solver.solve(U, F);
    for (unsigned int refinement = 0; refinement < 2; ++refinement)
    {
      residual(K, U, F, fixed, r);
      if (!std::isfinite(r.l2_norm()) || free_norm(r, fixed) <= 1e-14 * norm_F)
        break;
      Vector<double> x(n);
      solver.solve(x, r);
      U += x;
    }
  }
  else if (norm_F > 0.)
  {
    TrilinosWrappers::PreconditionAMG amg;
    TrilinosWrappers::PreconditionAMG::AdditionalData data;
    data.elliptic = true;
    for (const auto &rd : system.influence)
      if (rd.size() == n && rd.linfty_norm() > 0.)
      {
        std::vector<bool> mode(n);
        for (unsigned int i = 0; i < n; ++i)
          mode[i] = (rd[i] != 0.);
        data.constant_modes.push_back(mode);
      }
    TrilinosWrappers::SparseMatrix trilinos_K;
    trilinos_K.reinit(K, 0.);
    amg.initialize(trilinos_K, data);
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

  AssertThrow(std::isfinite(U.l2_norm()),
              ExcMessage(singular_message + " (the solution is not finite)."));
  residual(K, U, F, fixed, r);
  const double norm_r = free_norm(r, fixed);
  if (!(norm_r <= 1e-8 * norm_F))
  {
    std::ostringstream message;
    message << singular_message << " (residual ||K U - F|| = " << norm_r
            << " > 1e-8 ||F|| = " << 1e-8 * norm_F << ").";
    AssertThrow(false, ExcMessage(message.str()));
  }
  for (unsigned int i = 0; i < n; ++i)
    if (fixed[i])
      U[i] = 0.;
}
} // namespace hati
