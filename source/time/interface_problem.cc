#include <deal.II/base/exceptions.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <hati/analysis/reduced_part.h>
#include <hati/time/interface_problem.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace hati
{
namespace
{
/** b = sum_k rows[k]^T x[k] (an interface force as a DoF vector). */
void add_transpose(const std::vector<SparseRow> &rows,
                   const Vector<double> &x,
                   Vector<double> &b)
{
  for (unsigned int k = 0; k < rows.size(); ++k)
    for (unsigned int i = 0; i < rows[k].dofs.size(); ++i)
      b[rows[k].dofs[i]] += rows[k].coefficients[i] * x[k];
}
} // namespace

InterfaceProblem::InterfaceProblem(const Decomposition &decomposition,
                                   const Newmark &implicit,
                                   const double gamma)
    : decomposition(decomposition)
{
  // (G3'') C_E and C_I sparse rows (Decomposition)
  const unsigned int n_gamma = decomposition.n_interface_dofs();
  rows_E = decomposition.rows[0];
  rows_I = implicit_rows(decomposition);
  for (auto *v : {&free_jump, &implicit_guess, &solve_work, &u_old, &implicit_part})
    v->reinit(n_gamma);
  const unsigned int n_I = implicit_system(decomposition).n_dofs();
  link_force.reinit(n_I);

  // (G3') the implicit part gamma DT C_I M_eff^-1 C_I^T of the interface
  // matrix, and the link columns
  const double DT = implicit.time_step();
  Vector<double> b(n_I), x(n_I);
  H_I.reinit(n_gamma, n_gamma);
  const bool keep_columns = double(n_I) * n_gamma <= max_link_column_entries;
  if (keep_columns)
  {
    link_columns.reinit(n_I, n_gamma);
    link_acceleration.reinit(n_I);
  }
  for (unsigned int l = 0; l < n_gamma; ++l)
  {
    b = 0.;
    x = 0.;
    Vector<double> e(n_gamma);
    e[l] = 1.;
    add_transpose(rows_I, e, b);
    implicit.solve_with_effective_matrix(x, b);
    for (unsigned int k = 0; k < n_gamma; ++k)
      H_I.set(k, l, gamma * DT * rows_I[k].apply(x));
    if (keep_columns)
      for (unsigned int i = 0; i < n_I; ++i)
        link_columns.set(i, l, x[i]);
  }
  H_I.skip_zero_rows();
  if (keep_columns)
    link_columns.skip_zero_rows();
}

void InterfaceProblem::invert(const FullMatrix<double> &H_E,
                              DenseColumns &H_inverse) const
{
  // (G3') H = C_E V_ramp + gamma DT C_I M_eff^-1 C_I^T, inverted once
  const unsigned int n_gamma = size();
  LAPACKFullMatrix<double> H(n_gamma, n_gamma);
  for (unsigned int k = 0; k < n_gamma; ++k)
    for (unsigned int l = 0; l < n_gamma; ++l)
      H(k, l) = H_E(k, l) + H_I(k, l);
  H.invert();
  H_inverse.reinit(n_gamma, n_gamma);
  for (unsigned int k = 0; k < n_gamma; ++k)
    for (unsigned int l = 0; l < n_gamma; ++l)
      H_inverse.set(k, l, H(k, l));
  H_inverse.skip_zero_rows();
}

void InterfaceProblem::initial_multiplier(CDLagrange &explicit_integrator,
                                          Newmark &implicit,
                                          Vector<double> &lambda,
                                          const Vector<double> *given) const
{
  // acceleration continuity at t = 0:
  // (C_E M_E^-1 C_E^T + C_I M_I^-1 C_I^T) Lambda_0 = -(C_E a_E + C_I a_I)
  const unsigned int n_gamma = size();
  const double dt = explicit_integrator.time_step();
  auto state_E = explicit_integrator.linear_state();
  auto state_I = implicit.linear_state();
  Vector<double> rhs(n_gamma);
  for (unsigned int k = 0; k < n_gamma; ++k)
    rhs[k] = -((rows_E[k].apply(*state_E[1]) - rows_E[k].apply(*state_E[2])) / dt +
               rows_I[k].apply(*state_I[2]));
  if (given != nullptr)
    rhs = *given;
  if (rhs.linfty_norm() == 0.)
    return;
  const unsigned int n_I = implicit_system(decomposition).n_dofs();
  const Vector<double> &minv = explicit_integrator.inverse_mass();
  std::vector<Vector<double>> columns(n_gamma, Vector<double>(n_I));
  LAPACKFullMatrix<double> B(n_gamma, n_gamma);
  Vector<double> b(n_I), e(n_gamma);
  // C_E M_E^-1 C_E^T: diagonal for the rows of single DoFs
  std::vector<const SparseRow *> explicit_rows;
  for (const SparseRow &row : rows_E)
    explicit_rows.push_back(&row);
  const FullMatrix<double> W_E = delassus(explicit_rows, minv);
  for (unsigned int l = 0; l < n_gamma; ++l)
  {
    b = 0.;
    e = 0.;
    e[l] = 1.;
    add_transpose(rows_I, e, b);
    implicit.solve_with_mass(columns[l], b);
    for (unsigned int k = 0; k < n_gamma; ++k)
      B(k, l) = rows_I[k].apply(columns[l]) + W_E(k, l);
  }
  if (given == nullptr)
  {
    B.compute_lu_factorization();
    B.solve(rhs);
  }
  lambda = rhs;
  for (unsigned int k = 0; k < n_gamma; ++k)
  {
    rows_E[k].add_transpose(0.5 * dt * lambda[k], minv, *state_E[1]);
    rows_E[k].add_transpose(-0.5 * dt * lambda[k], minv, *state_E[2]);
    state_I[2]->add(lambda[k], columns[k]);
  }
}

void InterfaceProblem::set_free_implicit_velocity(const Newmark &implicit)
{
  for (unsigned int k = 0; k < size(); ++k)
    free_jump[k] = rows_I[k].apply(implicit.new_velocity());
}

void InterfaceProblem::correction(const DenseColumns &H_inverse,
                                  const Vector<double> &v_end,
                                  const Vector<double> &lambda_guess,
                                  Vector<double> &delta)
{
  for (unsigned int k = 0; k < size(); ++k)
    delta[k] = -(v_end[k] + free_jump[k]);
  // the guess's implicit link part is H_I lambda_guess
  H_I.vmult(implicit_guess, lambda_guess);
  delta -= implicit_guess;
  solve(H_inverse, delta);
}

double InterfaceProblem::residual(const Vector<double> &v_end,
                                  const Vector<double> &lambda,
                                  Vector<double> &r,
                                  double &scale) const
{
  H_I.vmult(implicit_part, lambda);
  double norm = 0.;
  scale = 0.;
  for (unsigned int k = 0; k < size(); ++k)
  {
    r[k] = -(v_end[k] + free_jump[k] + implicit_part[k]);
    norm = std::isfinite(r[k]) ? std::max(norm, std::abs(r[k]))
                               : std::numeric_limits<double>::quiet_NaN();
    scale = std::max({scale, std::abs(v_end[k]), std::abs(free_jump[k])});
  }
  return norm;
}

void InterfaceProblem::solve(const DenseColumns &H_inverse, Vector<double> &x)
{
  H_inverse.vmult(solve_work, x);
  x.swap(solve_work);
}

void InterfaceProblem::link(Newmark &implicit,
                            const Vector<double> &lambda_start,
                            const Vector<double> &lambda_end,
                            const Vector<double> &v_end,
                            double &work,
                            double &max_jump)
{
  const unsigned int n_gamma = size();
  for (unsigned int k = 0; k < n_gamma; ++k)
    u_old[k] = rows_I[k].apply(implicit.displacement());
  if (!link_columns.has_no_entries())
  {
    link_columns.vmult(link_acceleration, lambda_end);
    implicit.add_link_acceleration(link_acceleration);
  }
  else
  {
    link_force = 0.;
    add_transpose(rows_I, lambda_end, link_force);
    implicit.add_link(link_force);
  }
  for (unsigned int k = 0; k < n_gamma; ++k)
  {
    work += 0.5 * (rows_I[k].apply(implicit.new_displacement()) - u_old[k]) *
            (lambda_start[k] + lambda_end[k]);
    max_jump =
        std::max(max_jump, std::abs(v_end[k] + rows_I[k].apply(implicit.new_velocity())));
  }
}
} // namespace hati
