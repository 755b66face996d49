#include <deal.II/base/exceptions.h>

#include <hati/time/ramp_superposition.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace hati
{
namespace
{
/** The row applied to the integer-time velocity of CD-Lagrange (G2). */
double integer_velocity(const SparseRow &row, const CDLagrange::CouplingView &integrator)
{
  double s = 0.;
  for (unsigned int i = 0; i < row.dofs.size(); ++i)
    s += row.coefficients[i] * integrator.integer_velocity(row.dofs[i]);
  return s;
}
} // namespace

RampSuperposition::RampSuperposition(const DiscreteSystem &system,
                                     const double dt,
                                     const unsigned int m,
                                     const RayleighDamping &damping,
                                     const MaxwellBranches &branches,
                                     const InterfaceProblem &interface)
    : system(system), dt(dt), m(m), interface(interface),
      damped(damping.a0 != 0. || damping.a1 != 0. || !branches.alpha.empty()),
      with_memory(!branches.alpha.empty()),
      // the explicit integrator's own code path, from rest, without loads;
      // the coupling's explicit integrator has checked the step against
      // its safety factor (the stability test goes beyond it)
      ramp_integrator(std::make_unique<CDLagrange>(
          system, dt, std::numeric_limits<double>::infinity(), damping, branches))
{
  const auto &laws = ramp_integrator->force_laws();
  for (unsigned int i = 0; i < laws.size(); ++i)
  {
    const auto dofs = laws[i]->nonlinear_dofs();
    if (dofs.empty())
      continue;
    nonlinear_laws.push_back(i);
    nonlinear_first.push_back(nonlinear_dofs.size());
    nonlinear_dofs.insert(nonlinear_dofs.end(), dofs.begin(), dofs.end());
  }
  nonlinear_first.push_back(nonlinear_dofs.size());
  pass_law_force.assign((m + 1) * nonlinear_dofs.size(), 0.);
  compute_ramp({}, open_ramp, false);
  find_reach();
  if (contacts_in_reach() || damped)
    compute_ramp({}, open_ramp, damped);
  const unsigned int nrc = reach_contacts.size();
  pass_impulse.resize((m + 1) * nrc);
  pass_gap.resize((m + 1) * nrc);
  pass_normal.resize((m + 2) * nrc);
  pass_active.resize(m * nrc);
  pattern.assign(reach_friction ? 2 * nrc : nrc, false);
  if (reach_friction)
  {
    pass_tangential.assign(2 * (m + 1) * nrc, 0.);
    pass_tangential_velocity.assign(2 * (m + 2) * nrc, 0.);
    pass_stick.assign(m * nrc, false);
  }
}

void RampSuperposition::find_reach()
{
  // contacts within reach of the ramp response
  std::vector<bool> reach(system.n_dofs(), false);
  for (const auto &columns : open_ramp.state)
    for (const auto i : columns.rows())
      reach[i] = true;
  // a bilateral row (a rigid link, a tie) moves all its DoFs within the
  // micro step that reaches one of them: its other DoFs are within reach
  // too, and so on along chains of such rows
  for (bool grown = true; grown;)
  {
    grown = false;
    for (const auto &c : system.contacts)
    {
      if (!c.bilateral)
        continue;
      bool touched = false;
      for (const auto d : c.dofs)
        touched = touched || reach[d];
      if (touched)
        for (const auto d : c.dofs)
          if (!reach[d])
            reach[d] = grown = true;
    }
  }
  for (unsigned int c = 0; c < system.contacts.size(); ++c)
  {
    // the normal row, and with friction its tangent rows (A9)
    bool in_reach = false;
    for (const auto d : system.contacts[c].dofs)
      in_reach = in_reach || reach[d];
    for (const auto &t : system.contacts[c].tangents)
      for (const auto d : t.dofs)
        in_reach = in_reach || reach[d];
    if (in_reach)
    {
      reach_contacts.push_back(c);
      reach_frictional.push_back(system.contacts[c].frictional());
      reach_friction = reach_friction || system.contacts[c].frictional();
    }
  }
  if (!damped)
    return;

  // damped: the ramp's velocities and damping forces on the reach, per step
  // (every explicit DoF when contacts are within reach: a bilateral contact
  // carries the response from one body to the other)
  for (unsigned int i = 0; i < reach.size(); ++i)
    if (reach[i] || contacts_in_reach())
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
  interface_reach_rows.clear();
  for (const SparseRow &row : interface.explicit_rows())
  {
    interface_reach_rows.emplace_back();
    for (unsigned int i = 0; i < row.dofs.size(); ++i)
    {
      AssertThrow(index[row.dofs[i]] >= 0, ExcInternalError());
      interface_reach_rows.back().emplace_back(index[row.dofs[i]], row.coefficients[i]);
    }
  }
  for (auto *v : {&dissipation_p, &dissipation_p_prev, &dissipation_c})
    v->reinit(nR);
  dissipation_g.reinit(interface.size());
  dissipation_q.reinit(interface.size());
}

void RampSuperposition::compute_ramp(const std::vector<bool> &active_set,
                                     Response &r,
                                     const bool with_damping)
{
  const std::vector<SparseRow> &rows_E = interface.explicit_rows();
  const unsigned int n_gamma = rows_E.size(), nrc = reach_contacts.size(),
                     nR = reach_dofs.size();
  CDLagrange &integrator = *ramp_integrator;
  CDLagrange::CouplingView ramp = integrator.coupling_view();
  const auto &shapes = ramp.applied_load_shapes();
  const bool with_contacts = !active_set.empty();
  // the pattern: the active flags of the contacts within reach, then
  // (with friction) their sliding flags
  std::vector<bool> prescribed(system.contacts.size(), false),
      sliding(system.contacts.size(), false);
  for (unsigned int c = 0; c < nrc && with_contacts; ++c)
  {
    prescribed[reach_contacts[c]] = active_set[c];
    sliding[reach_contacts[c]] = active_set.size() == 2 * nrc && active_set[nrc + c];
  }
  ramp.prescribe_active_set(with_contacts ? &prescribed : nullptr,
                            with_contacts ? &sliding : nullptr);

  r.state.assign(integrator.linear_state().size(), SparseColumns());
  FullMatrix<double> increment_sum(n_gamma, n_gamma),
      increment_weighted(n_gamma, n_gamma);
  FullMatrix<double> H_E(n_gamma, n_gamma);
  // the displacements on the nonlinear laws' DoFs after each micro step, and
  // their velocities V_{j-1/2} before it (a held DoF: 0)
  const unsigned int n_nonlinear = nonlinear_dofs.size();
  FullMatrix<double> nonlinear_displacement(m * n_nonlinear, n_gamma),
      nonlinear_velocity(m * n_nonlinear, n_gamma);
  const auto at = [](const Vector<double> &x, const types::global_dof_index dof)
  { return dof == numbers::invalid_dof_index ? 0. : x[dof]; };
  r.load_work.assign(shapes.size(),
                     std::vector<Vector<double>>(m, Vector<double>(n_gamma)));
  // filled as dense per micro step, stored sparse
  std::vector<FullMatrix<double>> impulse(m + 1, FullMatrix<double>(nrc, n_gamma)),
      gap(m + 1, FullMatrix<double>(nrc, n_gamma)),
      normal_velocity(m + 2, FullMatrix<double>(nrc, n_gamma)),
      tangential_impulse(reach_friction ? m + 1 : 0,
                         FullMatrix<double>(2 * nrc, n_gamma)),
      tangential_velocity(reach_friction ? m + 2 : 0,
                          FullMatrix<double>(2 * nrc, n_gamma)),
      velocity_reach(with_damping ? m + 1 : 0, FullMatrix<double>(nR, n_gamma)),
      damping_reach(with_damping ? m + 1 : 0, FullMatrix<double>(nR, n_gamma));
  r.memory.assign(ramp.memory().n_branches(), SparseColumns());
  for (unsigned int l = 0; l < n_gamma; ++l)
  {
    for (auto *v : integrator.linear_state())
      *v = 0.;
    ramp.memory().reset();
    for (const unsigned int c : reach_contacts)
      ramp.set_contact_state(c, 0., 0.);
    for (unsigned int j = 1; j <= m; ++j)
    {
      const Vector<double> &V = integrator.velocity(); // V_{j-1/2}
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
      if (reach_friction)
        record_tangential(V, tangential_velocity[j], l);
      if (with_damping)
        for (unsigned int i = 0; i < nR; ++i)
          velocity_reach[j](i, l) = V[reach_dofs[i]];
      for (unsigned int i = 0; i < n_nonlinear; ++i)
        nonlinear_velocity((j - 1) * n_nonlinear + i, l) = at(V, nonlinear_dofs[i]);
      ramp.predict();
      ramp.free_velocity(false);
      ramp.add_force(rows_E[l], double(j) / m); // unit ramp (j/m) e_l
      ramp.finish_step(with_contacts);
      // (G3') with the impulses of the pushing set's rows of the last step
      if (j == m)
        for (unsigned int k = 0; k < n_gamma; ++k)
          H_E(k, l) = integer_velocity(rows_E[k], ramp);
      for (unsigned int i = 0; i < n_nonlinear; ++i)
        nonlinear_displacement((j - 1) * n_nonlinear + i, l) =
            at(integrator.displacement(), nonlinear_dofs[i]);
      for (unsigned int c = 0; c < nrc; ++c)
      {
        const auto &row = system.contacts[reach_contacts[c]];
        impulse[j](c, l) = with_contacts ? integrator.impulses()[reach_contacts[c]] : 0.;
        gap[j](c, l) = row.apply(integrator.displacement());
        if (with_contacts && reach_frictional[c])
          for (unsigned int t = 0; t < row.tangents.size(); ++t)
            tangential_impulse[j](2 * c + t, l) =
                integrator.friction().tangential_impulse(reach_contacts[c], t);
      }
      if (with_damping)
      {
        const Vector<double> &d = ramp.damping_force();
        for (unsigned int i = 0; i < nR; ++i)
          damping_reach[j](i, l) = d[reach_dofs[i]];
      }
    }
    for (unsigned int c = 0; c < nrc; ++c)
      normal_velocity[m + 1](c, l) =
          system.contacts[reach_contacts[c]].apply(integrator.velocity());
    if (reach_friction)
      record_tangential(integrator.velocity(), tangential_velocity[m + 1], l);
    const auto state = integrator.linear_state();
    for (unsigned int s = 0; s < state.size(); ++s)
      r.state[s].add_column(*state[s]);
    for (unsigned int b = 0; b < r.memory.size(); ++b)
      r.memory[b].add_column(ramp.memory().memory()[b]);
  }
  ramp.prescribe_active_set(nullptr);
  // stored sparse with the micro steps stacked, row j nrc + c
  const auto store = [n_gamma](const std::vector<FullMatrix<double>> &dense)
  {
    const unsigned int n = dense.empty() ? 0 : dense[0].m();
    FullMatrix<double> stacked(dense.size() * n, n_gamma);
    for (unsigned int j = 0; j < dense.size(); ++j)
      for (unsigned int c = 0; c < n; ++c)
        for (unsigned int l = 0; l < n_gamma; ++l)
          stacked(j * n + c, l) = dense[j](c, l);
    return SparseColumns(stacked);
  };
  r.impulse = store(impulse);
  r.gap = store(gap);
  r.normal_velocity = store(normal_velocity);
  r.tangential_impulse = store(tangential_impulse);
  r.tangential_velocity = store(tangential_velocity);
  r.velocity_on_reach.clear();
  r.damping_on_reach.clear();
  r.dissipation_quadratic = DenseColumns();
  if (with_damping)
    store_dissipation(velocity_reach, damping_reach, r);
  r.nonlinear_displacement = SparseColumns(nonlinear_displacement);
  r.nonlinear_velocity = SparseColumns(nonlinear_velocity);
  r.increment_sum = SparseColumns(increment_sum);
  r.increment_weighted = SparseColumns(increment_weighted);
  r.H_E = SparseColumns(H_E);
  interface.invert(H_E, r.H_inverse);
  // whether the response moves a DoF of a nonlinear force law (e.g. a rope's,
  // R1): then superpose() checks how much
  r.moves_nonlinear_law = false;
  for (const auto &columns : r.state)
    for (const auto i : columns.rows())
      for (const auto dof : nonlinear_dofs)
        r.moves_nonlinear_law = r.moves_nonlinear_law || dof == i;
}

void RampSuperposition::record_tangential(const Vector<double> &V,
                                          FullMatrix<double> &rows,
                                          const unsigned int l) const
{
  for (unsigned int c = 0; c < reach_contacts.size(); ++c)
  {
    const auto &tangents = system.contacts[reach_contacts[c]].tangents;
    if (reach_frictional[c])
      for (unsigned int t = 0; t < tangents.size(); ++t)
        rows(2 * c + t, l) = tangents[t].apply(V);
  }
}

const RampSuperposition::Response &
RampSuperposition::ramp_for(const std::vector<bool> &active_set)
{
  if (std::find(active_set.begin(), active_set.begin() + reach_contacts.size(), true) ==
      active_set.begin() + reach_contacts.size())
    return open_ramp;
  auto it = pattern_ramps.find(active_set);
  if (it != pattern_ramps.end())
    return it->second;
  if (pattern_ramps.size() >= max_cached_patterns)
    pattern_ramps.clear();
  ++n_patterns;
  Response &r = pattern_ramps[active_set];
  compute_ramp(active_set, r, damped);
  return r;
}

const RampSuperposition::Response &
RampSuperposition::response_for_pass(bool &same_active_set)
{
  same_active_set = true;
  if (!contacts_in_reach())
    return open_ramp;
  same_active_set = true;
  // the pushing set of every micro step: the contacts with an impulse
  // above round-off (A5) and the bilateral ones
  const unsigned int nrc = reach_contacts.size();
  double impulse_scale = 0.;
  for (const double l : pass_impulse)
    impulse_scale = std::max(impulse_scale, std::abs(l));
  for (unsigned int j = 1; j <= m; ++j)
    for (unsigned int c = 0; c < nrc; ++c)
      pass_active[(j - 1) * nrc + c] =
          system.contacts[reach_contacts[c]].bilateral ||
          pass_impulse[j * nrc + c] > pushing_impulse_fraction * impulse_scale;
  for (unsigned int c = 0; c < nrc; ++c)
    pattern[c] = pass_active[c];
  for (unsigned int j = 1; j < m && same_active_set; ++j)
    for (unsigned int c = 0; c < nrc; ++c)
      if (pass_active[j * nrc + c] != pattern[c])
      {
        same_active_set = false;
        break;
      }
  if (!same_active_set)
    return open_ramp;
  // (A9) the response of the set is that of its frictional contacts
  // sticking: a contact that slid in a micro step of the pass is not linear
  // in the multiplier. The micro steps are redone, corrected with the
  // response of the set with the sliding contacts' tangent rows left out
  // (their friction impulse held), which is closer to their true response
  // than sticking (sliding flags after the active ones in the pattern)
  if (reach_friction)
    for (unsigned int c = 0; c < nrc; ++c)
    {
      bool slides = false;
      for (unsigned int j = 0; j < m && reach_frictional[c] && pattern[c]; ++j)
        slides = slides || !pass_stick[j * nrc + c];
      pattern[nrc + c] = slides;
      same_active_set = same_active_set && !slides;
    }
  return ramp_for(pattern);
}

void RampSuperposition::start_pass(const CDLagrange &integrator, const bool contacts)
{
  pass_load_weight.resize(system.time_dependent_loads.size() * m);
  record_law_forces(0, integrator);
  // the normal velocities L V_{j-1/2} before each micro step: the first
  // here, the others from the sample after the step before
  const unsigned int nrc = reach_contacts.size();
  if (contacts)
    for (unsigned int c = 0; c < nrc; ++c)
    {
      const unsigned int k = reach_contacts[c];
      pass_impulse[c] = integrator.impulses()[k];
      pass_gap[c] = integrator.gaps()[k];
      pass_normal[nrc + c] = system.contacts[k].apply(integrator.velocity());
      if (reach_frictional[c])
        for (unsigned int t = 0; t < system.contacts[k].tangents.size(); ++t)
        {
          pass_tangential[2 * c + t] = integrator.friction().tangential_impulse(k, t);
          pass_tangential_velocity[2 * (nrc + c) + t] =
              system.contacts[k].tangents[t].apply(integrator.velocity());
        }
    }
}

bool RampSuperposition::superpose(const Response &r,
                                  const Vector<double> &lambda,
                                  CDLagrange &integrator,
                                  InterfaceIncrements &increments,
                                  std::vector<ContactSample> &samples,
                                  const unsigned int n_samples)
{
  if (r.moves_nonlinear_law && !nonlinear_laws_hold(r, lambda, integrator))
    return false;
  if (contacts_in_reach() &&
      !superpose_contacts(r, lambda, integrator, samples, n_samples))
    return false;
  if (r.moves_nonlinear_law)
    add_nonlinear_work(r, lambda, integrator);

  // superposition of the ramp response: the state, the interface
  // increments and the work of the time-dependent loads
  CDLagrange::CouplingView view = integrator.coupling_view();
  const auto state = integrator.linear_state();
  for (unsigned int s = 0; s < state.size(); ++s)
    r.state[s].add_multiply(*state[s], lambda);
  // A8: the memory variables are linear in the state too (S recomputed)
  if (with_memory)
    view.memory().modify_memory([&](const unsigned int b, Vector<double> &q)
                                { r.memory[b].add_multiply(q, lambda); });
  r.increment_sum.add_multiply(increments.increment_sum, lambda);
  r.increment_weighted.add_multiply(increments.increment_weighted, lambda);
  r.H_E.add_multiply(increments.v_end, lambda);
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
  view.add_external_work(work);
  if (records_damping())
    view.add_dissipated(ramp_dissipation(r, lambda));
  return true;
}

bool RampSuperposition::nonlinear_laws_hold(const Response &r,
                                            const Vector<double> &lambda,
                                            const CDLagrange &integrator)
{
  // the largest displacement the correction adds to a DoF of a nonlinear
  // law at a micro step, and the change of each law's force it can cause
  if (ramp_nonlinear.size() != m * nonlinear_dofs.size())
    ramp_nonlinear.reinit(m * nonlinear_dofs.size());
  r.nonlinear_displacement.vmult(ramp_nonlinear, lambda);
  const double du = ramp_nonlinear.linfty_norm();
  // the integrator holds the same laws in the same order (make_force_laws())
  for (const unsigned int i : nonlinear_laws)
    if (!(integrator.force_laws()[i]->relative_force_change(du) <=
          nonlinear_force_tolerance))
      return false;
  return true;
}

void RampSuperposition::add_nonlinear_work(const Response &r,
                                           const Vector<double> &lambda,
                                           CDLagrange &integrator)
{
  // the work of the pass's forces of each law on the velocity the correction
  // adds, sum_j 1/2 dt dV_{j-1/2} . (F_{j-1} + F_j) (the trapezoid of the
  // law's step() on the corrected velocities; the change of the forces
  // themselves is below nonlinear_force_tolerance and left out)
  const unsigned int n = nonlinear_dofs.size();
  if (ramp_nonlinear.size() != m * n)
    ramp_nonlinear.reinit(m * n);
  r.nonlinear_velocity.vmult(ramp_nonlinear, lambda);
  for (unsigned int a = 0; a < nonlinear_laws.size(); ++a)
  {
    double work = 0.;
    for (unsigned int j = 1; j <= m; ++j)
      for (unsigned int i = nonlinear_first[a]; i < nonlinear_first[a + 1]; ++i)
        work += 0.5 * dt * ramp_nonlinear[(j - 1) * n + i] *
                (pass_law_force[(j - 1) * n + i] + pass_law_force[j * n + i]);
    integrator.force_laws()[nonlinear_laws[a]]->add_superposed_work(work);
  }
}

void RampSuperposition::record_law_forces(const unsigned int j,
                                          const CDLagrange &integrator)
{
  const unsigned int n = nonlinear_dofs.size();
  for (unsigned int a = 0; a < nonlinear_laws.size(); ++a)
    integrator.force_laws()[nonlinear_laws[a]]->applied_force(pass_law_force.data() +
                                                              j * n + nonlinear_first[a]);
}

bool RampSuperposition::superpose_contacts(const Response &r,
                                           const Vector<double> &lambda,
                                           CDLagrange &integrator,
                                           std::vector<ContactSample> &samples,
                                           const unsigned int n_samples)
{
  // the contact quantities of pass + ramp, and the check that the active
  // set of the pass still holds
  const unsigned int nrc = reach_contacts.size();
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
  const double impulse_tolerance = lcp_check_tolerance * scale,
               velocity_tolerance =
                   lcp_check_tolerance * velocity_scale + velocity_tolerance_floor;
  for (unsigned int j = 1; j <= m; ++j)
    for (unsigned int c = 0; c < nrc; ++c)
    {
      const unsigned int i = j * nrc + c;
      if (pass_active[(j - 1) * nrc + c])
      {
        if (!system.contacts[reach_contacts[c]].bilateral &&
            total_impulse[i] < -impulse_tolerance)
          return false;
      }
      else if (total_gap[i] <= closed_gap_tolerance)
      {
        const double e = system.contacts[reach_contacts[c]].restitution,
                     w = total_normal[i + nrc] + e * total_normal[i];
        if (w < -velocity_tolerance)
          return false;
      }
    }
  if (reach_friction &&
      !superpose_friction(r, lambda, integrator, samples, n_samples, impulse_tolerance))
    return false;

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
  CDLagrange::CouplingView view = integrator.coupling_view();
  view.add_contact_work(work);
  for (unsigned int c = 0; c < nrc; ++c)
    view.set_contact_state(
        reach_contacts[c], total_gap[m * nrc + c], total_impulse[m * nrc + c]);
  for (unsigned int j = 1; j <= m && j <= n_samples; ++j)
  {
    ContactSample &s = samples[j - 1];
    for (unsigned int c = 0; c < nrc; ++c)
    {
      const unsigned int k = reach_contacts[c];
      s.gaps[k] = total_gap[j * nrc + c];
      s.impulses[k] = total_impulse[j * nrc + c];
      s.normal_velocities[k] = total_normal[(j + 1) * nrc + c];
    }
  }
  return true;
}

bool RampSuperposition::superpose_friction(const Response &r,
                                           const Vector<double> &lambda,
                                           CDLagrange &integrator,
                                           std::vector<ContactSample> &samples,
                                           const unsigned int n_samples,
                                           const double impulse_tolerance)
{
  // the tangential impulses and velocities of pass + ramp
  const unsigned int nrc = reach_contacts.size();
  if (ramp_tangential.size() != 2 * (m + 1) * nrc)
    ramp_tangential.reinit(2 * (m + 1) * nrc);
  if (ramp_tangential_velocity.size() != 2 * (m + 2) * nrc)
    ramp_tangential_velocity.reinit(2 * (m + 2) * nrc);
  r.tangential_impulse.vmult(ramp_tangential, lambda);
  r.tangential_velocity.vmult(ramp_tangential_velocity, lambda);
  total_tangential = pass_tangential;
  total_tangential_velocity = pass_tangential_velocity;
  for (unsigned int i = 2 * nrc; i < total_tangential.size(); ++i)
    total_tangential[i] += ramp_tangential[i];
  for (unsigned int i = 2 * nrc; i < total_tangential_velocity.size(); ++i)
    total_tangential_velocity[i] += ramp_tangential_velocity[i];

  // (A9) a sticking contact stays within its Coulomb cone at every micro
  // step, |lambda_t| <= mu lambda_n; response_for_pass() has checked that the
  // frictional contacts of the pushing set stuck in the pass
  for (unsigned int j = 1; j <= m; ++j)
    for (unsigned int c = 0; c < nrc; ++c)
      if (reach_frictional[c] && pass_active[(j - 1) * nrc + c])
      {
        const unsigned int i = 2 * (j * nrc + c);
        const double norm = std::hypot(total_tangential[i], total_tangential[i + 1]);
        if (norm >
            system.contacts[reach_contacts[c]].friction * total_impulse[j * nrc + c] +
                impulse_tolerance)
          return false;
      }

  // the friction work of the total, sum_j 1/2 (lambda_t,j-1 + lambda_t,j) .
  // T V_{j-1/2} (FrictionalContacts: the halves before and after each
  // impulse), minus what the pass booked; the last micro step's second half
  // is booked by the next step with the corrected impulses
  double work = 0.;
  for (unsigned int j = 1; j <= m; ++j)
    for (unsigned int c = 0; c < nrc; ++c)
      if (reach_frictional[c])
        for (unsigned int t = 0; t < 2; ++t)
        {
          const unsigned int i = 2 * (j * nrc + c) + t, h = 2 * ((j - 1) * nrc + c) + t;
          work += 0.5 * ((total_tangential[h] + total_tangential[i]) *
                             total_tangential_velocity[i] -
                         (pass_tangential[h] + pass_tangential[i]) *
                             pass_tangential_velocity[i]);
        }
  FrictionalContacts &friction = integrator.coupling_view().friction();
  friction.add_work(work);
  for (unsigned int c = 0; c < nrc; ++c)
    if (reach_frictional[c])
      for (unsigned int t = 0; t < 2; ++t)
        friction.set_tangential_impulse(
            reach_contacts[c], t, total_tangential[2 * (m * nrc + c) + t]);
  // the samples: tangential impulses, and the slip velocities |T V_{j+1/2}|
  // of the contacts that touch
  for (unsigned int j = 1; j <= m && j <= n_samples; ++j)
  {
    ContactSample &s = samples[j - 1];
    for (unsigned int c = 0; c < nrc; ++c)
      if (reach_frictional[c])
      {
        const unsigned int k = reach_contacts[c], i = 2 * (j * nrc + c);
        s.tangential_impulses[2 * k] = total_tangential[i];
        s.tangential_impulses[2 * k + 1] = total_tangential[i + 1];
        if (s.friction_states[k] != FrictionState::open)
          s.slip_velocities[k] = std::hypot(total_tangential_velocity[i + 2 * nrc],
                                            total_tangential_velocity[i + 2 * nrc + 1]);
      }
  }
  return true;
}

} // namespace hati
