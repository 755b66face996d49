#include <deal.II/base/exceptions.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <hati/time/hati_coupling.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

namespace hati
{
namespace
{
/** The unit vector e_l of size n. */
Vector<double> unit_vector(const unsigned int n, const unsigned int l)
{
  Vector<double> e(n);
  e[l] = 1.;
  return e;
}

using Clock = std::chrono::steady_clock;

double seconds_since(const Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/** The row applied to the integer-time velocity of CD-Lagrange (G2). */
double integer_velocity(const SparseRow &row, CDLagrange &integrator)
{
  double s = 0.;
  for (unsigned int i = 0; i < row.dofs.size(); ++i)
    s += row.coefficients[i] * integrator.coupling_view().integer_velocity(row.dofs[i]);
  return s;
}

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

void HATIParameters::declare_parameters(ParameterHandler &prm)
{
  prm.declare_entry("Time step ratio",
                    "10",
                    Patterns::Integer(0),
                    "m = DT / dt (-), an integer >= 1: the implicit subdomain steps "
                    "with DT = m dt, the explicit one with Time integration/Time step "
                    "dt.");
  prm.declare_entry(
      "Coupling method",
      "macro-linear",
      Patterns::Selection("macro-linear"),
      "Interface problem of the coupling. macro-linear (G3'): velocity continuity at "
      "the macro-step ends, the interface force linear in time over the macro step; "
      "stable (spectral radius of a macro step <= 1) and energy-consistent.");
}

void HATIParameters::parse_parameters(ParameterHandler &prm)
{
  const long ratio = prm.get_integer("Time step ratio");
  AssertThrow(ratio >= 1,
              ExcMessage("Time integration/HATI/Time step ratio must be an integer >= 1 "
                         "(DT = m dt), got " +
                         std::to_string(ratio)));
  time_step_ratio = ratio;
  coupling_method = prm.get("Coupling method");
}

void SparseColumns::add_column(const Vector<double> &v)
{
  for (unsigned int i = 0; i < v.size(); ++i)
    if (v[i] != 0.)
    {
      row.push_back(i);
      value.push_back(v[i]);
    }
  start.push_back(row.size());
}

SparseColumns::SparseColumns(const FullMatrix<double> &matrix)
{
  for (unsigned int k = 0; k < matrix.n(); ++k)
  {
    for (unsigned int i = 0; i < matrix.m(); ++i)
      if (matrix(i, k) != 0.)
      {
        row.push_back(i);
        value.push_back(matrix(i, k));
      }
    start.push_back(row.size());
  }
}

void SparseColumns::add_multiply(Vector<double> &y, const Vector<double> &x) const
{
  for (unsigned int k = 0; k + 1 < start.size(); ++k)
    if (x[k] != 0.)
      for (std::size_t e = start[k]; e < start[k + 1]; ++e)
        y[row[e]] += value[e] * x[k];
}

void DenseColumns::vmult(Vector<double> &y, const Vector<double> &x) const
{
  AssertDimension(y.size(), n_rows);
  AssertDimension(x.size(), n_columns);
  double *__restrict a = y.data();
  std::fill(a, a + n_rows, 0.);
  const double *const columns = value.data();
  unsigned int l = 0;
  for (; l + 4 <= n_columns; l += 4)
  {
    const double x0 = x[l], x1 = x[l + 1], x2 = x[l + 2], x3 = x[l + 3];
    const double *__restrict c0 = columns + std::size_t(l) * n_rows,
                             *__restrict c1 = c0 + n_rows, *__restrict c2 = c1 + n_rows,
                             *__restrict c3 = c2 + n_rows;
    for (unsigned int i = 0; i < n_rows; ++i)
      a[i] += c0[i] * x0 + c1[i] * x1 + c2[i] * x2 + c3[i] * x3;
  }
  for (; l < n_columns; ++l)
  {
    const double xl = x[l];
    const double *__restrict column = columns + std::size_t(l) * n_rows;
    for (unsigned int i = 0; i < n_rows; ++i)
      a[i] += column[i] * xl;
  }
}

void SparseColumns::Tvmult_add(Vector<double> &g, const double *c) const
{
  for (unsigned int k = 0; k + 1 < start.size(); ++k)
  {
    double s = 0.;
    for (std::size_t e = start[k]; e < start[k + 1]; ++e)
      s += value[e] * c[row[e]];
    g[k] += s;
  }
}

std::vector<unsigned int> SparseColumns::rows() const
{
  std::vector<unsigned int> r(row);
  std::sort(r.begin(), r.end());
  r.erase(std::unique(r.begin(), r.end()), r.end());
  return r;
}

HATICoupling::HATICoupling(const Decomposition &decomposition,
                           const unsigned int n_global_dofs,
                           const double dt,
                           const double safety_factor,
                           const HATIParameters &parameters,
                           const NewmarkParameters &newmark_parameters,
                           const RayleighDamping &damping)
    : decomposition(decomposition), m(parameters.time_step_ratio), damping(damping),
      explicit_integrator(decomposition.parts[0].system, dt, safety_factor, damping),
      implicit(decomposition.parts[1].system, m * dt, newmark_parameters, damping),
      gamma(newmark_parameters.gamma)
{
  const auto start = Clock::now();
  AssertThrow(
      m >= 1,
      ExcMessage("Time integration/HATI/Time step ratio must be an integer >= 1"));
  const unsigned int n_gamma = decomposition.n_interface_dofs();
  for (unsigned int k = 0; k < n_gamma; ++k)
  {
    SparseRow e, i;
    e.dofs = {decomposition.interface[0][k]};
    e.coefficients = {1.};
    i.dofs = {decomposition.interface[1][k]};
    i.coefficients = {-1.};
    rows_E.push_back(e);
    rows_I.push_back(i);
  }
  dofs_E = decomposition.interface[0];
  for (auto *v : {&lambda_n,
                  &lambda_m,
                  &delta_lambda,
                  &v_end,
                  &increment_sum,
                  &increment_weighted,
                  &free_jump,
                  &implicit_guess,
                  &solve_work,
                  &u_old})
    v->reinit(n_gamma);
  link_force.reinit(decomposition.parts[1].system.n_dofs());
  global_U.reinit(n_global_dofs);
  global_V.reinit(n_global_dofs);

  precompute_ramp_response();
  initial_multiplier();
  setup = seconds_since(start);
}

void HATICoupling::precompute_ramp_response()
{
  const DiscreteSystem &system = decomposition.parts[0].system;
  const unsigned int n_gamma = rows_E.size();
  const double dt = explicit_integrator.time_step(), DT = m * dt;

  // (G3') the implicit part gamma DT C_I M_eff^-1 C_I^T of the interface
  // matrix, and the link columns
  const unsigned int n_I = decomposition.parts[1].system.n_dofs();
  Vector<double> b(n_I), x(n_I);
  H_I.reinit(n_gamma, n_gamma);
  // dense link columns up to 2e7 entries (160 MB)
  const bool keep_columns = double(n_I) * n_gamma <= 2e7;
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
      H_I(k, l) = gamma * DT * rows_I[k].apply(x);
    if (keep_columns)
      for (unsigned int i = 0; i < n_I; ++i)
        link_columns(i, l) = x[i];
  }

  // the explicit integrator's own code path, from rest, without loads
  ramp_integrator = std::make_unique<CDLagrange>(system, dt, 1., damping);
  reach_contacts.clear();
  reach_dofs.clear();
  compute_ramp({}, open_ramp, false);

  // contacts within reach of the ramp response
  std::vector<bool> reach(system.n_dofs(), false);
  for (const auto &columns : open_ramp.state)
    for (const auto i : columns.rows())
      reach[i] = true;
  for (unsigned int c = 0; c < system.contacts.size(); ++c)
    for (const auto d : system.contacts[c].dofs)
      if (reach[d])
      {
        reach_contacts.push_back(c);
        break;
      }
  contacts_in_reach = !reach_contacts.empty();

  // damped: the ramp's velocities and damping forces on the reach, per step
  // (every explicit DoF when contacts are within reach: a bilateral contact
  // carries the response from one body to the other)
  if (explicit_integrator.damped())
  {
    for (unsigned int i = 0; i < reach.size(); ++i)
      if (reach[i] || contacts_in_reach)
        reach_dofs.push_back(i);
    const unsigned int nR = reach_dofs.size();
    reach_is_all = nR == system.n_dofs();
    reach_mass.reinit(nR);
    for (unsigned int r = 0; r < nR; ++r)
      reach_mass[r] = system.lumped_mass[reach_dofs[r]];
    pass_velocity_reach.assign(m + 1, Vector<double>(nR));
    pass_damping_reach.assign(m + 1, Vector<double>(nR));
    pass_stiffness_reach.assign(m + 1, Vector<double>(nR));
    if (!reach_is_all)
      stiffness_velocity_full.reinit(system.n_dofs());
    std::vector<int> index(system.n_dofs(), -1);
    for (unsigned int r = 0; r < nR; ++r)
      index[reach_dofs[r]] = r;
    interface_reach_index.clear();
    for (const unsigned int d : dofs_E)
    {
      AssertThrow(index[d] >= 0, ExcInternalError());
      interface_reach_index.push_back(index[d]);
    }
    for (auto *v : {&dissipation_p, &dissipation_p_prev, &dissipation_c})
      v->reinit(nR);
    dissipation_g.reinit(dofs_E.size());
    dissipation_q.reinit(dofs_E.size());
  }
  if (contacts_in_reach || explicit_integrator.damped())
    compute_ramp({}, open_ramp, explicit_integrator.damped());
  const unsigned int nrc = reach_contacts.size();
  pass_impulse.resize((m + 1) * nrc);
  pass_gap.resize((m + 1) * nrc);
  pass_normal.resize((m + 2) * nrc);
  pass_active.resize(m * nrc);
  pattern.resize(nrc);
}

void HATICoupling::compute_ramp(const std::vector<bool> &active_set,
                                RampResponse &r,
                                const bool with_damping)
{
  const DiscreteSystem &system = decomposition.parts[0].system;
  const unsigned int n_gamma = rows_E.size(), nrc = reach_contacts.size(),
                     nR = reach_dofs.size();
  const double dt = explicit_integrator.time_step();
  CDLagrange &ramp = *ramp_integrator;
  const auto &shapes = ramp.coupling_view().applied_load_shapes();
  const bool with_contacts = !active_set.empty();
  std::vector<bool> prescribed(system.contacts.size(), false);
  for (unsigned int c = 0; c < active_set.size(); ++c)
    prescribed[reach_contacts[c]] = active_set[c];
  ramp.coupling_view().prescribe_active_set(with_contacts ? &prescribed : nullptr);

  r.state.assign(ramp.linear_state().size(), SparseColumns());
  FullMatrix<double> increment_sum(n_gamma, n_gamma),
      increment_weighted(n_gamma, n_gamma);
  FullMatrix<double> H_E(n_gamma, n_gamma);
  r.load_work.assign(shapes.size(),
                     std::vector<Vector<double>>(m, Vector<double>(n_gamma)));
  // filled as dense per micro step, stored sparse
  std::vector<FullMatrix<double>> impulse(m + 1, FullMatrix<double>(nrc, n_gamma)),
      gap(m + 1, FullMatrix<double>(nrc, n_gamma)),
      normal_velocity(m + 2, FullMatrix<double>(nrc, n_gamma)),
      velocity_reach(with_damping ? m + 1 : 0, FullMatrix<double>(nR, n_gamma)),
      damping_reach(with_damping ? m + 1 : 0, FullMatrix<double>(nR, n_gamma));
  for (unsigned int l = 0; l < n_gamma; ++l)
  {
    for (auto *v : ramp.linear_state())
      *v = 0.;
    for (const unsigned int c : reach_contacts)
      ramp.coupling_view().set_contact_state(c, 0., 0.);
    for (unsigned int j = 1; j <= m; ++j)
    {
      const Vector<double> &V = *ramp.linear_state()[1]; // V_{j-1/2}
      for (unsigned int s = 0; s < shapes.size(); ++s)
        r.load_work[s][j - 1][l] = dt * (shapes[s] * V);
      for (unsigned int k = 0; k < n_gamma; ++k)
      {
        const double du = dt * rows_E[k].apply(V);
        increment_sum(k, l) += du;
        increment_weighted(k, l) += (2. * j - 1.) / (2. * m) * du;
      }
      for (unsigned int c = 0; c < nrc; ++c)
        normal_velocity[j](c, l) = system.contacts[reach_contacts[c]].apply(V);
      if (with_damping)
        for (unsigned int i = 0; i < nR; ++i)
          velocity_reach[j](i, l) = V[reach_dofs[i]];
      ramp.coupling_view().predict();
      ramp.coupling_view().free_velocity(false);
      ramp.coupling_view().add_force(rows_E[l], double(j) / m); // unit ramp (j/m) e_l
      if (j == m)
        for (unsigned int k = 0; k < n_gamma; ++k)
          H_E(k, l) = integer_velocity(rows_E[k], ramp);
      ramp.coupling_view().finish_step(with_contacts);
      for (unsigned int c = 0; c < nrc; ++c)
      {
        const auto &row = system.contacts[reach_contacts[c]];
        impulse[j](c, l) = with_contacts ? ramp.impulses()[reach_contacts[c]] : 0.;
        gap[j](c, l) = row.apply(ramp.displacement());
      }
      if (with_damping)
      {
        const Vector<double> &d = *ramp.linear_state()[3];
        for (unsigned int i = 0; i < nR; ++i)
          damping_reach[j](i, l) = d[reach_dofs[i]];
      }
    }
    for (unsigned int c = 0; c < nrc; ++c)
      normal_velocity[m + 1](c, l) =
          system.contacts[reach_contacts[c]].apply(ramp.velocity());
    const auto state = ramp.linear_state();
    for (unsigned int s = 0; s < state.size(); ++s)
      r.state[s].add_column(*state[s]);
  }
  ramp.coupling_view().prescribe_active_set(nullptr);
  // stored sparse with the micro steps stacked, row j nrc + c
  const auto store = [nrc, n_gamma](const std::vector<FullMatrix<double>> &dense)
  {
    FullMatrix<double> stacked(dense.size() * nrc, n_gamma);
    for (unsigned int j = 0; j < dense.size(); ++j)
      for (unsigned int c = 0; c < nrc; ++c)
        for (unsigned int l = 0; l < n_gamma; ++l)
          stacked(j * nrc + c, l) = dense[j](c, l);
    return SparseColumns(stacked);
  };
  r.impulse = store(impulse);
  r.gap = store(gap);
  r.normal_velocity = store(normal_velocity);
  r.velocity_on_reach.clear();
  r.dissipation_quadratic = DenseColumns();
  if (with_damping)
  {
    // V_j on the reach for j = 1 .. m, then V_{m+1/2} (the final state)
    r.velocity_on_reach.resize(m + 2);
    for (unsigned int j = 1; j <= m; ++j)
      r.velocity_on_reach[j] = SparseColumns(velocity_reach[j]);
    FullMatrix<double> final_velocity(nR, n_gamma);
    for (unsigned int l = 0; l < n_gamma; ++l)
    {
      Vector<double> column(system.n_dofs());
      for (unsigned int i = 0; i < system.n_dofs(); ++i)
        column[i] = 0.;
      r.state[1].add_multiply(column, unit_vector(n_gamma, l));
      for (unsigned int i = 0; i < nR; ++i)
        final_velocity(i, l) = column[reach_dofs[i]];
    }
    r.velocity_on_reach[m + 1] = SparseColumns(final_velocity);
    // Q = sum_j V_j^T M (D_{j-1} + D_j), D_0 = 0 (the ramp starts at rest)
    r.dissipation_quadratic.reinit(n_gamma, n_gamma);
    for (unsigned int j = 1; j <= m; ++j)
      for (unsigned int i = 0; i < nR; ++i)
        for (unsigned int l = 0; l < n_gamma; ++l)
        {
          const double v = velocity_reach[j](i, l);
          if (v == 0.)
            continue;
          for (unsigned int k = 0; k < n_gamma; ++k)
            r.dissipation_quadratic(l, k) +=
                reach_mass[i] * v * (damping_reach[j - 1](i, k) + damping_reach[j](i, k));
        }
  }
  r.increment_sum = SparseColumns(increment_sum);
  r.increment_weighted = SparseColumns(increment_weighted);
  r.H_E = SparseColumns(H_E);

  // (G3') H = C_E V_ramp + gamma DT C_I M_eff^-1 C_I^T, inverted once
  LAPACKFullMatrix<double> H(n_gamma, n_gamma);
  for (unsigned int k = 0; k < n_gamma; ++k)
    for (unsigned int l = 0; l < n_gamma; ++l)
      H(k, l) = H_E(k, l) + H_I(k, l);
  H.invert();
  r.H_inverse.reinit(n_gamma, n_gamma);
  for (unsigned int k = 0; k < n_gamma; ++k)
    for (unsigned int l = 0; l < n_gamma; ++l)
      r.H_inverse(k, l) = H(k, l);
}

const HATICoupling::RampResponse &
HATICoupling::ramp_for(const std::vector<bool> &active_set)
{
  if (std::find(active_set.begin(), active_set.end(), true) == active_set.end())
    return open_ramp;
  auto it = pattern_ramps.find(active_set);
  if (it != pattern_ramps.end())
    return it->second;
  // a bounded cache: each response holds m (contacts + reach) x n_gamma entries
  if (pattern_ramps.size() >= 64)
    pattern_ramps.clear();
  ++n_patterns;
  RampResponse &r = pattern_ramps[active_set];
  compute_ramp(active_set, r, explicit_integrator.damped());
  return r;
}

void HATICoupling::initial_multiplier()
{
  // acceleration continuity at t = 0:
  // (C_E M_E^-1 C_E^T + C_I M_I^-1 C_I^T) Lambda_0 = -(C_E a_E + C_I a_I)
  const unsigned int n_gamma = rows_E.size();
  const double dt = explicit_integrator.time_step();
  auto state_E = explicit_integrator.linear_state();
  auto state_I = implicit.linear_state();
  Vector<double> rhs(n_gamma);
  for (unsigned int k = 0; k < n_gamma; ++k)
    rhs[k] = -((rows_E[k].apply(*state_E[1]) - rows_E[k].apply(*state_E[2])) / dt +
               rows_I[k].apply(*state_I[2]));
  if (rhs.linfty_norm() == 0.)
    return;
  const unsigned int n_I = decomposition.parts[1].system.n_dofs();
  const Vector<double> &minv = explicit_integrator.inverse_mass();
  std::vector<Vector<double>> columns(n_gamma, Vector<double>(n_I));
  LAPACKFullMatrix<double> B(n_gamma, n_gamma);
  Vector<double> b(n_I), e(n_gamma);
  for (unsigned int l = 0; l < n_gamma; ++l)
  {
    b = 0.;
    e = 0.;
    e[l] = 1.;
    add_transpose(rows_I, e, b);
    implicit.solve_with_mass(columns[l], b);
    for (unsigned int k = 0; k < n_gamma; ++k)
      B(k, l) = rows_I[k].apply(columns[l]) +
                (k == l ? minv[rows_E[k].dofs[0]] * rows_E[k].coefficients[0] *
                              rows_E[k].coefficients[0]
                        : 0.);
  }
  B.compute_lu_factorization();
  B.solve(rhs);
  lambda_n = rhs;
  for (unsigned int k = 0; k < n_gamma; ++k)
  {
    rows_E[k].add_transpose(0.5 * dt * lambda_n[k], minv, *state_E[1]);
    rows_E[k].add_transpose(-0.5 * dt * lambda_n[k], minv, *state_E[2]);
    state_I[2]->add(lambda_n[k], columns[k]);
  }
}

void HATICoupling::micro_steps(const Vector<double> &lambda_end, const bool pass)
{
  const unsigned int n_gamma = rows_E.size();
  const double dt = explicit_integrator.time_step();
  increment_sum = 0.;
  increment_weighted = 0.;
  const bool record_damping = !reach_dofs.empty() && pass;
  const auto &contacts = decomposition.parts[0].system.contacts;
  const unsigned int nrc = reach_contacts.size();
  const unsigned int n_loads = decomposition.parts[0].system.time_dependent_loads.size();
  pass_load_weight.resize(n_loads * m);
  // the normal velocities L V_{j-1/2} before each micro step: the first
  // here, the others from the sample after the step before (take_sample)
  if (record_contacts)
    for (unsigned int c = 0; c < nrc; ++c)
    {
      pass_impulse[c] = explicit_integrator.impulses()[reach_contacts[c]];
      pass_gap[c] = explicit_integrator.gaps()[reach_contacts[c]];
      pass_normal[nrc + c] =
          contacts[reach_contacts[c]].apply(explicit_integrator.velocity());
    }
  if (record_damping)
  {
    const Vector<double> &d = *explicit_integrator.linear_state()[3];
    gather_reach(d, pass_damping_reach[0]);
  }
  for (unsigned int j = 1; j <= m; ++j)
  {
    if (record_damping)
    {
      const Vector<double> &V = *explicit_integrator.linear_state()[1];
      gather_reach(V, pass_velocity_reach[j]);
    }
    // interface displacement increment of this step, dt C_E V_{j-1/2}
    // (C_E: +1 on the explicit DoF of each interface pair)
    const double *const V = explicit_integrator.linear_state()[1]->data();
    const double weight = (2. * j - 1.) / (2. * m);
    for (unsigned int k = 0; k < n_gamma; ++k)
    {
      const double du = dt * V[dofs_E[k]];
      increment_sum[k] += du;
      increment_weighted[k] += weight * du;
    }
    // (G2) Lambda_j = (1 - j/m) Lambda_n [+ (j/m) Lambda_{n+m}] over the step
    explicit_integrator.coupling_view().predict();
    if (record_damping)
      explicit_integrator.coupling_view().record_stiffness_velocity(
          reach_is_all ? pass_stiffness_reach[j].data() : stiffness_velocity_full.data());
    explicit_integrator.coupling_view().free_velocity();
    if (record_damping)
    {
      explicit_integrator.coupling_view().record_stiffness_velocity(nullptr);
      if (!reach_is_all)
        for (unsigned int r = 0; r < reach_dofs.size(); ++r)
          pass_stiffness_reach[j][r] = stiffness_velocity_full[reach_dofs[r]];
    }
    const double w0 = 1. - double(j) / m, w1 = double(j) / m;
    for (unsigned int k = 0; k < n_gamma; ++k)
    {
      const double lambda = w0 * lambda_n[k] + w1 * lambda_end[k];
      if (lambda != 0.)
        explicit_integrator.coupling_view().add_dof_force(dofs_E[k], lambda);
    }
    if (j == m)
      for (unsigned int k = 0; k < n_gamma; ++k)
        v_end[k] = explicit_integrator.coupling_view().integer_velocity(dofs_E[k]);
    explicit_integrator.coupling_view().finish_step();
    if (pass)
      for (unsigned int s = 0; s < n_loads; ++s)
        pass_load_weight[s * m + j - 1] =
            explicit_integrator.coupling_view().load_step_weight(s);
    if (record_damping)
    {
      const Vector<double> &d = *explicit_integrator.linear_state()[3];
      gather_reach(d, pass_damping_reach[j]);
    }
    if (record_contacts)
    {
      if (n_recorded == contact_record.size())
        contact_record.emplace_back();
      ContactSample &s = contact_record[n_recorded++];
      take_sample(s);
      for (unsigned int c = 0; c < nrc; ++c)
      {
        const unsigned int k = reach_contacts[c];
        pass_impulse[j * nrc + c] = explicit_integrator.impulses()[k];
        pass_gap[j * nrc + c] = explicit_integrator.gaps()[k];
        pass_normal[(j + 1) * nrc + c] = s.normal_velocities[k];
      }
    }
    else if (after_micro_step)
    {
      take_sample(sample);
      after_micro_step(sample);
    }
  }
}

void HATICoupling::step()
{
  const unsigned int n_gamma = rows_E.size();

  // (G1) the free implicit step
  auto start = Clock::now();
  implicit.free_step();
  seconds[1] += seconds_since(start);

  // (G2) the micro steps with the known part of the multiplier; with
  // contacts within reach of the ramp response, keep the state to redo them
  start = Clock::now();
  record_contacts = contacts_in_reach;
  n_recorded = 0;
  if (record_contacts)
    explicit_integrator.save(snapshot);
  micro_steps(lambda_n, true);
  seconds[0] += seconds_since(start);

  // (G3') Lambda_{n+m} from the velocity continuity at t_{n+m}, with the
  // ramp response of the active set of the contacts within reach when it
  // stayed the same over the pass
  start = Clock::now();
  const RampResponse *ramp = &open_ramp;
  bool same_active_set = true;
  if (contacts_in_reach)
  {
    // the pushing set of every micro step: the contacts with an impulse
    // above round-off (A5) and the bilateral ones
    const unsigned int nrc = reach_contacts.size();
    const auto &system_E_contacts = decomposition.parts[0].system.contacts;
    double impulse_scale = 0.;
    for (const double l : pass_impulse)
      impulse_scale = std::max(impulse_scale, std::abs(l));
    for (unsigned int j = 1; j <= m; ++j)
      for (unsigned int c = 0; c < nrc; ++c)
        pass_active[(j - 1) * nrc + c] =
            system_E_contacts[reach_contacts[c]].bilateral ||
            pass_impulse[j * nrc + c] > 1e-10 * impulse_scale;
    for (unsigned int c = 0; c < nrc; ++c)
      pattern[c] = pass_active[c];
    for (unsigned int j = 1; j < m && same_active_set; ++j)
      for (unsigned int c = 0; c < nrc; ++c)
        if (pass_active[j * nrc + c] != pattern[c])
        {
          same_active_set = false;
          break;
        }
    if (same_active_set)
      ramp = &ramp_for(pattern);
  }
  for (unsigned int k = 0; k < n_gamma; ++k)
    free_jump[k] = rows_I[k].apply(implicit.new_velocity());
  for (unsigned int k = 0; k < n_gamma; ++k)
    delta_lambda[k] = -(v_end[k] + free_jump[k]);
  // the pass ran with the guess Lambda_{n+m} = Lambda_n, whose implicit
  // link part is H_I Lambda_n; the correction solves
  // H dLambda = -(C_E V_pass + C_I V_free + H_I Lambda_n)
  H_I.vmult(implicit_guess, lambda_n);
  delta_lambda -= implicit_guess;
  ramp->H_inverse.vmult(solve_work, delta_lambda);
  delta_lambda.swap(solve_work);
  lambda_m = lambda_n;
  lambda_m += delta_lambda;
  seconds[2] += seconds_since(start);

  start = Clock::now();
  if (!(same_active_set && superpose(*ramp, delta_lambda)))
  {
    // the active set changed within the macro step: redo the micro steps
    // with the full multiplier and correct Lambda_{n+m} until the macro-end
    // continuity holds
    ++n_redone;
    unsigned int iterations = 0;
    Vector<double> residual(n_gamma);
    for (;; ++iterations)
    {
      explicit_integrator.restore(snapshot);
      record_contacts = true;
      n_recorded = 0;
      micro_steps(lambda_m, false);
      Vector<double> implicit_part(n_gamma);
      H_I.vmult(implicit_part, lambda_m);
      double norm = 0., scale = 0.;
      for (unsigned int k = 0; k < n_gamma; ++k)
      {
        residual[k] = -(v_end[k] + free_jump[k] + implicit_part[k]);
        norm = std::max(norm, std::abs(residual[k]));
        scale = std::max({scale, std::abs(v_end[k]), std::abs(free_jump[k])});
      }
      if (norm <= 1e-8 * std::max(scale, 1e-300) || norm == 0.)
        break;
      if (iterations >= 50)
      {
        std::ostringstream message;
        message << "HATI: the interface velocity continuity with contacts within "
                   "reach of the interface did not converge in 50 corrections at t = "
                << explicit_integrator.time() << " s (residual " << norm
                << " m/s, velocity scale " << scale
                << " m/s): move the interface further from the contacts or reduce the "
                   "Time step ratio";
        AssertThrow(false, ExcMessage(message.str()));
      }
      ramp->H_inverse.vmult(solve_work, residual);
      residual.swap(solve_work);
      lambda_m += residual;
    }
    max_iterations = std::max(max_iterations, iterations + 1);
    if (after_micro_step)
      for (unsigned int j = 0; j < n_recorded; ++j)
        after_micro_step(contact_record[j]);
  }
  record_contacts = false;
  seconds[0] += seconds_since(start);

  // (G5) interface work of the explicit side: the trapezoid of each micro
  // step, sum_j 1/2 dU_j . C_E^T (Lambda_{j-1} + Lambda_j)
  start = Clock::now();
  for (unsigned int k = 0; k < n_gamma; ++k)
    interface_work += increment_sum[k] * lambda_n[k] +
                      increment_weighted[k] * (lambda_m[k] - lambda_n[k]);
  seconds[2] += seconds_since(start);

  // (G4) the implicit link with Lambda_{n+m}, its interface work
  // 1/2 dU_I . C_I^T (Lambda_n + Lambda_{n+m}) and the continuity check
  start = Clock::now();
  for (unsigned int k = 0; k < n_gamma; ++k)
    u_old[k] = rows_I[k].apply(implicit.displacement());
  if (!link_columns.empty())
  {
    link_columns.vmult(link_acceleration, lambda_m);
    implicit.add_link_acceleration(link_acceleration);
  }
  else
  {
    link_force = 0.;
    add_transpose(rows_I, lambda_m, link_force);
    implicit.add_link(link_force);
  }
  for (unsigned int k = 0; k < n_gamma; ++k)
  {
    interface_work += 0.5 * (rows_I[k].apply(implicit.new_displacement()) - u_old[k]) *
                      (lambda_n[k] + lambda_m[k]);
    max_jump =
        std::max(max_jump, std::abs(v_end[k] + rows_I[k].apply(implicit.new_velocity())));
  }
  implicit.finish_step();
  lambda_n = lambda_m;
  seconds[1] += seconds_since(start);
}

bool HATICoupling::superpose(const RampResponse &r, const Vector<double> &lambda)
{
  const unsigned int nrc = reach_contacts.size();
  const DiscreteSystem &system_E = decomposition.parts[0].system;
  const bool contacts = record_contacts && nrc > 0;
  if (contacts)
  {
    // the contact quantities of pass + ramp, and the check that the active
    // set of the pass still holds
    total_impulse.resize((m + 1) * nrc);
    total_gap.resize((m + 1) * nrc);
    total_normal.resize((m + 2) * nrc);
    // the ramp's part of the impulses, gaps and normal velocities of all
    // micro steps, one product each
    for (auto *y : {&ramp_impulse, &ramp_gap})
      if (y->size() != (m + 1) * nrc)
        y->reinit((m + 1) * nrc);
    if (ramp_normal.size() != (m + 2) * nrc)
      ramp_normal.reinit((m + 2) * nrc);
    r.impulse.vmult(ramp_impulse, lambda);
    r.gap.vmult(ramp_gap, lambda);
    r.normal_velocity.vmult(ramp_normal, lambda);
    double scale = 0.;
    for (unsigned int c = 0; c < nrc; ++c)
    {
      total_impulse[c] = pass_impulse[c];
      total_gap[c] = pass_gap[c];
    }
    for (unsigned int i = nrc; i < (m + 1) * nrc; ++i)
    {
      total_impulse[i] = pass_impulse[i] + ramp_impulse[i];
      scale = std::max({scale, std::abs(pass_impulse[i]), std::abs(ramp_impulse[i])});
      total_gap[i] = pass_gap[i] + ramp_gap[i];
    }
    for (unsigned int i = nrc; i < (m + 2) * nrc; ++i)
      total_normal[i] = pass_normal[i] + ramp_normal[i];
    // the LCP (A5) of every micro step keeps the pushing set of the pass:
    // impulses >= 0 on it; elsewhere the contact is open (gap > 0) or its
    // velocity after the step satisfies the law without impulse, w >= 0
    double velocity_scale = 0.;
    for (const double v : total_normal)
      velocity_scale = std::max(velocity_scale, std::abs(v));
    const double impulse_tolerance = 1e-9 * scale,
                 velocity_tolerance = 1e-9 * velocity_scale + 1e-15;
    for (unsigned int j = 1; j <= m; ++j)
      for (unsigned int c = 0; c < nrc; ++c)
      {
        const unsigned int i = j * nrc + c;
        if (pass_active[(j - 1) * nrc + c])
        {
          if (!system_E.contacts[reach_contacts[c]].bilateral &&
              total_impulse[i] < -impulse_tolerance)
            return false;
        }
        else if (total_gap[i] <= 0.)
        {
          const double e = system_E.contacts[reach_contacts[c]].restitution,
                       w = total_normal[i + nrc] + e * total_normal[i];
          if (w < -velocity_tolerance)
            return false;
        }
      }

    // contact work of the total, sum_j 1/2 (L V_{j-1/2}) (lambda_{j-1} +
    // lambda_j), minus what the pass booked
    double work = 0.;
    for (unsigned int j = 1; j <= m; ++j)
      for (unsigned int c = 0; c < nrc; ++c)
      {
        const unsigned int i = j * nrc + c, h = (j - 1) * nrc + c;
        work += 0.5 * (total_normal[i] * (total_impulse[h] + total_impulse[i]) -
                       pass_normal[i] * (pass_impulse[h] + pass_impulse[i]));
      }
    explicit_integrator.coupling_view().add_contact_work(work);
    for (unsigned int c = 0; c < nrc; ++c)
      explicit_integrator.coupling_view().set_contact_state(
          reach_contacts[c], total_gap[m * nrc + c], total_impulse[m * nrc + c]);
    for (unsigned int j = 1; j <= m && j <= n_recorded; ++j)
    {
      ContactSample &s = contact_record[j - 1];
      for (unsigned int c = 0; c < nrc; ++c)
      {
        const unsigned int k = reach_contacts[c];
        s.gaps[k] = total_gap[j * nrc + c];
        s.impulses[k] = total_impulse[j * nrc + c];
        s.normal_velocities[k] = total_normal[(j + 1) * nrc + c];
      }
    }
  }

  // superposition of the ramp response: the state, the interface
  // increments and the work of the time-dependent loads
  const auto state = explicit_integrator.linear_state();
  for (unsigned int s = 0; s < state.size(); ++s)
    r.state[s].add_multiply(*state[s], lambda);
  r.increment_sum.add_multiply(increment_sum, lambda);
  r.increment_weighted.add_multiply(increment_weighted, lambda);
  r.H_E.add_multiply(v_end, lambda);
  // with the amplitudes of the pass's micro steps
  const unsigned int n_gamma = lambda.size();
  double work = 0.;
  for (unsigned int s = 0; s < r.load_work.size(); ++s)
    for (unsigned int j = 1; j <= m; ++j)
    {
      const double *const w = r.load_work[s][j - 1].data();
      double p = 0.;
      for (unsigned int l = 0; l < n_gamma; ++l)
        p += w[l] * lambda[l];
      work += pass_load_weight[s * m + j - 1] * p;
    }
  explicit_integrator.coupling_view().add_external_work(work);
  if (!reach_dofs.empty())
    explicit_integrator.add_dissipated(ramp_dissipation(r, lambda));
  if (after_micro_step)
    for (unsigned int j = 0; j < n_recorded; ++j)
      after_micro_step(contact_record[j]);
  return true;
}

void HATICoupling::gather_reach(const Vector<double> &source, Vector<double> &reach) const
{
  if (reach_is_all)
    std::copy(source.begin(), source.begin() + reach.size(), reach.begin());
  else
    for (unsigned int r = 0; r < reach_dofs.size(); ++r)
      reach[r] = source[reach_dofs[r]];
}

void HATICoupling::take_sample(ContactSample &s) const
{
  s.time = explicit_integrator.time();
  s.gaps = explicit_integrator.gaps();
  s.impulses = explicit_integrator.impulses();
  s.active = explicit_integrator.active();
  const auto &contacts = decomposition.parts[0].system.contacts;
  const Vector<double> &V = explicit_integrator.velocity();
  s.normal_velocities.resize(contacts.size());
  for (unsigned int k = 0; k < contacts.size(); ++k)
    s.normal_velocities[k] = contacts[k].apply(V);
}

double HATICoupling::ramp_dissipation(const RampResponse &ramp,
                                      const Vector<double> &lambda) const
{
  // With a = V_r Lambda (the ramp's velocities V_{j-1/2}) the ramp's damping
  // force is d_r,j = alpha (a_j + a_{j+1} - f_j) + a1 S a_j (A7, alpha =
  // a0 dt / 2, f_j: the velocity jumps of its interface ramp and contact
  // impulses, M f_j = dt (j/m) C_E^T Lambda + L^T lambda_j), and K is
  // symmetric, so the part of the pass and the ramp
  //   1/2 sum_j [v_a,j . M (d_r,j-1 + d_r,j) + a_j . M (D_a,j + d_r,j-1 + d_r,j)]
  // is 1/2 [sum_{j=1}^{m+1} c_j . a_j - alpha sum_j p_j . M f_j + Lambda^T Q
  // Lambda] with p_j = v_a,j + v_a,j+1 (p_m = v_a,m), D_a,j = d_a,j-1 +
  // d_a,j, c_j = alpha M (p_j + p_{j-1}) + a1 M S p_j + M D_a,j (p_0 = 0),
  // c_{m+1} = alpha M p_m: one pass over the ramp's velocities only
  const unsigned int nR = reach_dofs.size(), n_gamma = dofs_E.size();
  const double dt = explicit_integrator.time_step();
  const double alpha = 0.5 * explicit_integrator.mass_damping_coefficient() * dt,
               a1 = explicit_integrator.stiffness_damping_coefficient();
  const double *__restrict const mass = reach_mass.data();
  double *__restrict const cj = dissipation_c.data();
  dissipation_p_prev = 0.;
  dissipation_g = 0.;
  double impulse_term = 0.;
  const unsigned int nrc = reach_contacts.size();
  const bool with_impulses =
      nrc > 0 && ramp_impulse.size() == (m + 1) * nrc && record_contacts;
  const auto &contacts = decomposition.parts[0].system.contacts;
  for (unsigned int j = 1; j <= m; ++j)
  {
    const double *__restrict const v0 = pass_velocity_reach[j].data(),
                                   *__restrict const k0 = pass_stiffness_reach[j].data(),
                                   *__restrict const d0 =
                                       pass_damping_reach[j - 1].data(),
                                   *__restrict const d1 = pass_damping_reach[j].data();
    const double *__restrict const v1 =
        j < m ? pass_velocity_reach[j + 1].data() : nullptr,
                                   *__restrict const k1 =
                                       j < m ? pass_stiffness_reach[j + 1].data()
                                             : nullptr;
    double *__restrict const p = dissipation_p.data();
    const double *__restrict const p_prev = dissipation_p_prev.data();
    for (unsigned int r = 0; r < nR; ++r)
    {
      const double pr = v0[r] + (v1 ? v1[r] : 0.);
      const double spr = k0[r] + (k1 ? k1[r] : 0.);
      cj[r] = mass[r] * (alpha * (pr + p_prev[r]) + a1 * spr + d0[r] + d1[r]);
      p[r] = pr;
    }
    ramp.velocity_on_reach[j].Tvmult_add(dissipation_g, cj);
    // the interface ramp's and the contacts' velocity jumps in the ramp's
    // free velocity
    const double s = dt * double(j) / m;
    for (unsigned int l = 0; l < n_gamma; ++l)
      impulse_term += p[interface_reach_index[l]] * s * lambda[l];
    if (with_impulses)
      for (unsigned int c = 0; c < nrc; ++c)
      {
        const double impulse = ramp_impulse[j * nrc + c];
        if (impulse != 0.)
          impulse_term += contacts[reach_contacts[c]].apply(dissipation_p) * impulse;
      }
    dissipation_p_prev.swap(dissipation_p);
  }
  // c_{m+1} = alpha M p_m (p_m is now in dissipation_p_prev)
  for (unsigned int r = 0; r < nR; ++r)
    cj[r] = mass[r] * alpha * dissipation_p_prev[r];
  ramp.velocity_on_reach[m + 1].Tvmult_add(dissipation_g, cj);
  ramp.dissipation_quadratic.vmult(dissipation_q, lambda); // Q Lambda
  return 0.5 * (dissipation_g * lambda - alpha * impulse_term + lambda * dissipation_q);
}

const Vector<double> &HATICoupling::displacement() const
{
  const auto &E = decomposition.parts[0], &I = decomposition.parts[1];
  global_U = 0.;
  for (unsigned int i = 0; i < I.global_dofs.size(); ++i)
    global_U[I.global_dofs[i]] = implicit.displacement()[i];
  for (unsigned int i = 0; i < E.global_dofs.size(); ++i)
    global_U[E.global_dofs[i]] = explicit_integrator.displacement()[i];
  return global_U;
}

const Vector<double> &HATICoupling::velocity() const
{
  const auto &E = decomposition.parts[0], &I = decomposition.parts[1];
  global_V = 0.;
  for (unsigned int i = 0; i < I.global_dofs.size(); ++i)
    global_V[I.global_dofs[i]] = implicit.velocity()[i];
  for (unsigned int i = 0; i < E.global_dofs.size(); ++i)
    global_V[E.global_dofs[i]] = explicit_integrator.velocity()[i];
  return global_V;
}

Energies HATICoupling::energies() const
{
  const Energies e = explicit_integrator.energies(), i = implicit.energies();
  Energies r;
  r.kinetic = e.kinetic + i.kinetic;
  r.internal = e.internal + i.internal;
  r.external_work = e.external_work + i.external_work;
  r.contact_work = e.contact_work;
  r.dissipated = e.dissipated + i.dissipated;
  r.interface_work = interface_work;
  r.kinetic_explicit = e.kinetic;
  r.kinetic_implicit = i.kinetic;
  r.internal_explicit = e.internal;
  r.internal_implicit = i.internal;
  return r;
}

unsigned int HATICoupling::state_size() const
{
  return 2 * decomposition.parts[0].system.n_dofs() +
         3 * decomposition.parts[1].system.n_dofs() + rows_E.size();
}

void HATICoupling::get_state(Vector<double> &x) const
{
  const unsigned int nE = decomposition.parts[0].system.n_dofs(),
                     nI = decomposition.parts[1].system.n_dofs();
  const double dt = explicit_integrator.time_step(), DT = m * dt;
  x.reinit(state_size());
  unsigned int o = 0;
  for (unsigned int i = 0; i < nE; ++i)
    x[o++] = explicit_integrator.displacement()[i];
  for (unsigned int i = 0; i < nE; ++i)
    x[o++] = dt * explicit_integrator.velocity()[i];
  for (unsigned int i = 0; i < nI; ++i)
    x[o++] = implicit.displacement()[i];
  for (unsigned int i = 0; i < nI; ++i)
    x[o++] = DT * implicit.velocity()[i];
  for (unsigned int i = 0; i < nI; ++i)
    x[o++] = DT * DT * implicit.acceleration()[i];
  for (unsigned int k = 0; k < rows_E.size(); ++k)
    x[o++] = lambda_n[k];
}

void HATICoupling::set_state(const Vector<double> &x)
{
  AssertThrow(x.size() == state_size(), ExcDimensionMismatch(x.size(), state_size()));
  const unsigned int nE = decomposition.parts[0].system.n_dofs(),
                     nI = decomposition.parts[1].system.n_dofs();
  const double dt = explicit_integrator.time_step(), DT = m * dt;
  auto E = explicit_integrator.linear_state();
  auto I = implicit.linear_state();
  for (auto *v : E)
    *v = 0.;
  unsigned int o = 0;
  for (unsigned int i = 0; i < nE; ++i)
    (*E[0])[i] = x[o++];
  for (unsigned int i = 0; i < nE; ++i)
    (*E[1])[i] = (*E[2])[i] = x[o++] / dt;
  for (unsigned int i = 0; i < nI; ++i)
    (*I[0])[i] = x[o++];
  for (unsigned int i = 0; i < nI; ++i)
    (*I[1])[i] = x[o++] / DT;
  for (unsigned int i = 0; i < nI; ++i)
    (*I[2])[i] = x[o++] / (DT * DT);
  for (unsigned int k = 0; k < rows_E.size(); ++k)
    lambda_n[k] = x[o++];
}
} // namespace hati
