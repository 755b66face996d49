#include <deal.II/base/exceptions.h>
#include <deal.II/lac/full_matrix.h>

#include <hati/base/cpu_clones.h>
#include <hati/time/cd_lagrange.h>
#include <hati/time/cd_lagrange_kernels.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <sstream>
#include <type_traits>
#include <utility>

namespace hati
{
using namespace cd_lagrange_kernels;

CDLagrange::CDLagrange(const DiscreteSystem &system,
                       const double dt,
                       const double safety_factor,
                       const RayleighDamping &damping,
                       const MaxwellBranches &maxwell)
    : system(system), dt(dt), a0(damping.a0), a1(damping.a1),
      c1((1. - 0.5 * damping.a0 * dt) / (1. + 0.5 * damping.a0 * dt)),
      c2(1. / (1. + 0.5 * damping.a0 * dt)), branches(maxwell, dt, system.n_dofs()),
      laws(make_force_laws(system))
{
  for (const auto &law : laws)
  {
    if (law->adds_forces())
      forcing_laws.push_back(law.get());
    if (auto *c = dynamic_cast<UnilateralContacts *>(law.get()))
      contacts = c;
    if (law->gates_rows())
      gating_laws.push_back(law.get());
  }
  AssertThrow(contacts, ExcInternalError());
  if (!gating_laws.empty())
  {
    rows_off.assign(system.contacts.size(), false);
    contacts->switch_off(&rows_off);
  }
  const unsigned int n = system.n_dofs();
  AssertThrow(system.lumped_mass_refusal.empty(), ExcMessage(system.lumped_mass_refusal));
  AssertThrow(dt > 0. && std::isfinite(dt),
              ExcMessage("Time integration/Time step must be positive and finite."));
  AssertThrow(a0 >= 0. && a1 >= 0. && std::isfinite(a0) && std::isfinite(a1),
              ExcMessage("Rayleigh damping: a0 and a1 must be >= 0 and finite."));
  AssertThrow(!branches.active() || !damped(),
              ExcMessage("CD-Lagrange: Rayleigh and frequency-range damping cannot be "
                         "combined (Time integration/Damping/Type selects one)."));

  check_time_step(safety_factor);
  for (unsigned int i = 0; i < n; ++i)
    AssertThrow(
        system.fixed[i] || system.lumped_mass[i] > 0.,
        ExcMessage("CD-Lagrange needs a positive lumped mass on every free DoF."));

  dt_minv.reinit(n);
  minv.reinit(n);
  mass.reinit(n);
  zero_force.reinit(n);
  for (unsigned int i = 0; i < n; ++i)
  {
    minv[i] = system.fixed[i] ? 0. : 1. / system.lumped_mass[i];
    mass[i] = system.fixed[i] ? 0. : system.lumped_mass[i];
    dt_minv[i] = dt * minv[i];
  }

  build_stiffness_operator();
  build_loads();
  t = system.start_time;
  initial_state();
  // the laws' rows at U_0 (e.g. the contacts' A5 clusters)
  for (const auto &law : laws)
    if (law->has_rows())
    {
      law->start_rows(U, dt_minv);
      row_laws.push_back(law.get());
    }
}

void CDLagrange::check_time_step(const double safety_factor)
{
  dt_crit = stability_limit(
      system, laws, dt, safety_factor, a1, branches.active(), branches.alpha_sum());
}

double CDLagrange::stability_limit(const DiscreteSystem &system,
                                   const double dt,
                                   const double safety_factor,
                                   const RayleighDamping &damping,
                                   const MaxwellBranches &branches)
{
  return stability_limit(system,
                         make_force_laws(system),
                         dt,
                         safety_factor,
                         damping.a1,
                         !branches.alpha.empty(),
                         branches.alpha_sum());
}

double CDLagrange::stability_limit(const DiscreteSystem &system,
                                   const std::vector<std::unique_ptr<ForceLaw>> &laws,
                                   const double dt,
                                   const double safety_factor,
                                   const double a1,
                                   const bool with_branches,
                                   const double alpha_sum)
{
  // Stability (algorithms.md section 1, A7): dt <= safety * dt_crit with
  // dt_crit = (2/omega_max) (sqrt(1 + xi^2) - xi), xi = a1 omega_max / 2,
  // written 2 / (omega_max (sqrt(1 + xi^2) + xi)) to avoid the cancellation.
  // It is the exact limit of the scheme for every mode (doc/theory.md 1.6)
  // and decreases with omega, so the bound omega_max gives a safe step.
  // With frequency-range damping (A8) the branches act as springs
  // (sum alpha) K at high frequency: dt_crit = (2/omega_max)/sqrt(1 + sum alpha).
  // The force laws whose stiffness the model's bound leaves out add their
  // omega^2 bounds (ForceLaw::omega_squared_bound()).
  double omega_max = system.highest_frequency_bound();
  double law_omega_squared = 0.;
  for (const auto &law : laws)
    law_omega_squared += law->omega_squared_bound();
  if (law_omega_squared > 0.)
    omega_max = std::sqrt(omega_max * omega_max + law_omega_squared);
  const double xi = 0.5 * a1 * omega_max;
  double dt_crit = omega_max > 0. ? 2. / (omega_max * (std::sqrt(1. + xi * xi) + xi))
                                  : std::numeric_limits<double>::infinity();
  if (with_branches)
    dt_crit = omega_max > 0. ? 2. / omega_max / std::sqrt(1. + alpha_sum)
                             : std::numeric_limits<double>::infinity();
  if (dt > safety_factor * dt_crit)
  {
    std::ostringstream s;
    s.precision(6);
    s << "the time step dt = " << dt << " s is above the stability limit of the "
      << "explicit scheme";
    if (with_branches)
      s << " with frequency-range damping, sum alpha = " << alpha_sum
        << ": dt_crit = (2/omega_max)/sqrt(1 + sum alpha) = " << dt_crit
        << " s, omega_max = " << omega_max << " rad/s";
    else if (a1 > 0.)
      s << " with Rayleigh stiffness damping a1 = " << a1
        << " s: dt_crit = (2/omega_max) (sqrt(1 + xi^2) - xi) = " << dt_crit
        << " s, xi = a1 omega_max / 2 = " << xi << ", omega_max = " << omega_max
        << " rad/s";
    else
      s << ": dt_crit = 2/omega_max = " << dt_crit << " s";
    if (law_omega_squared > 0.)
    {
      s << " (omega_max = " << omega_max << " rad/s includes " << law_omega_squared
        << " rad^2/s^2 of the force laws";
      for (const auto &law : laws)
        if (law->omega_squared_bound() > 0.)
          s << " '" << law->name() << "'";
      s << ")";
    }
    s << " (safety factor " << safety_factor
      << ", so dt must be <= " << safety_factor * dt_crit
      << " s). Reduce 'Time integration/Time step'";
    if (a1 > 0.)
      s << " or the stiffness damping (Time integration/Damping)";
    s << ".";
    AssertThrow(false, ExcMessage(s.str()));
  }
  return dt_crit;
}

void CDLagrange::build_stiffness_operator()
{
  const unsigned int n = system.n_dofs();
  // dt M^-1 K, the nonzero entries of each free row in the stiffness's
  // order; fixed DoFs have empty rows. Each row goes to the group of its
  // padded width (padding entries are zeros pointing at the row itself),
  // rows wider than every compiled kernel and empty rows to the CSR group
  // (width 0). The groups are disjoint, so each row's result is the same
  // whatever the group order.
  row_groups.clear();
  row_work.assign(n, 0.);
  std::vector<unsigned int> row_nonzeros(n, 0);
  for (unsigned int i = 0; i < n; ++i)
    if (system.has_stiffness() && !system.fixed[i])
      for (auto it = system.stiffness.begin(i); it != system.stiffness.end(i); ++it)
        row_nonzeros[i] += it->value() != 0.;
  std::map<unsigned int, RowGroup> groups;
  for (unsigned int i = 0; i < n; ++i)
  {
    unsigned int w = padded_width(row_nonzeros[i], KernelWidths());
    if (!has_compiled_width(w, KernelWidths()))
      w = 0;
    RowGroup &g = groups[w];
    g.width = w;
    if (w == 0 && g.start.empty())
      g.start.push_back(0);
    g.rows.push_back(i);
    if (row_nonzeros[i] > 0)
      for (auto it = system.stiffness.begin(i); it != system.stiffness.end(i); ++it)
        if (it->value() != 0.)
        {
          g.column.push_back(it->column());
          g.value.push_back(dt_minv[i] * it->value());
        }
    if (w == 0)
      g.start.push_back(g.column.size());
    else
      for (unsigned int k = row_nonzeros[i]; k < w; ++k)
      {
        g.column.push_back(i);
        g.value.push_back(0.);
      }
  }
  for (auto &[w, g] : groups)
    row_groups.push_back(std::move(g));
}

void CDLagrange::build_loads()
{
  const unsigned int n = system.n_dofs();
  // External forces with the lumped mass for the acceleration loads (gravity,
  // base excitation): -M_lumped r a instead of the consistent M r a of the
  // system, so that a rigid motion (free flight) is exact with CD.
  force = system.constant_force;
  force += system.lumped_gravity_correction();
  dt_minv_force.reinit(n);
  for (unsigned int i = 0; i < n; ++i)
    dt_minv_force[i] = dt_minv[i] * force[i];
  for (const auto &load : system.time_dependent_loads)
  {
    Vector<double> shape(load.shape);
    const int d = load.acceleration_direction;
    // the lumped mass of the excited part (Loading/Excited members) if the
    // model restricted the excitation to some members
    const Vector<double> &mass = system.excited_lumped_mass.size() == n
                                     ? system.excited_lumped_mass
                                     : system.lumped_mass;
    if (d >= 0 && system.influence[d].size() == n)
      for (unsigned int i = 0; i < n; ++i)
        shape[i] = -mass[i] * system.influence[d][i];
    load_shapes.push_back(shape);
    shape.scale(dt_minv);
    dt_minv_load_shapes.push_back(shape);
  }
}

void CDLagrange::initial_state()
{
  const unsigned int n = system.n_dofs();
  // initial state
  U = system.initial_displacement;
  U0 = U;
  velocity_a.reinit(n);
  velocity_b.reinit(n);
  V = &velocity_a;
  V_prev = &velocity_b;

  // V_{1/2} = V_0 + dt/2 M^-1 G_0, G_0 = F_ext(0) - K U_0 - C V_0, and
  // V_{-1/2} = V_{1/2} - dt M^-1 G_0; d_0 = dt M^-1 C V_0 (A7, theory 1.1)
  Vector<double> f(force), ku(n), v0(n), kv(n);
  for (unsigned int l = 0; l < load_shapes.size(); ++l)
    f.add(system.time_dependent_loads[l].amplitude(system.start_time), load_shapes[l]);
  for (ForceLaw *law : forcing_laws) // e.g. (R1) the rope forces at U_0
    law->start(U, f);
  // a static start: the closed contacts carry their static forces from t = 0
  // (doc/theory.md 1.1)
  if (system.initial_contact_reaction.size() == n)
    f += system.initial_contact_reaction;
  for (unsigned int i = 0; i < n; ++i)
    v0[i] = system.fixed[i] ? 0. : system.initial_velocity[i];
  if (system.has_stiffness())
  {
    system.stiffness.vmult(ku, U);
    if (a1 != 0.)
      system.stiffness.vmult(kv, v0);
  }
  d_prev.reinit(n);
  for (unsigned int i = 0; i < n; ++i)
  {
    d_prev[i] = system.fixed[i] ? 0. : dt * a0 * v0[i] + a1 * dt_minv[i] * kv[i];
    const double g = dt_minv[i] * (f[i] - ku[i]) - d_prev[i]; // dt M^-1 G_0
    (*V)[i] = v0[i] + 0.5 * g;
    (*V_prev)[i] = (*V)[i] - g; // stands for V_{-1/2}
  }
}

void CDLagrange::integer_velocity(Vector<double> &v) const
{
  const unsigned int n = U.size();
  v.reinit(n, true);
  for (unsigned int i = 0; i < n; ++i)
    v[i] = system.fixed[i] ? 0. : 0.5 * ((*V)[i] + (*V_prev)[i]);
}

void CDLagrange::contact_force(Vector<double> &r) const
{
  const unsigned int n = U.size();
  // G_n as the last update had it: loads and laws at t_n, K U_n, d_n
  Vector<double> f(force), ku(n);
  for (unsigned int l = 0; l < load_shapes.size(); ++l)
    f.add(system.time_dependent_loads[l].amplitude(t), load_shapes[l]);
  for (const ForceLaw *law : forcing_laws)
  {
    const auto dofs = law->nonlinear_dofs();
    std::vector<double> applied(dofs.size());
    law->applied_force(applied.data());
    for (unsigned int i = 0; i < dofs.size(); ++i)
      f[dofs[i]] += applied[i];
  }
  if (system.has_stiffness())
    system.stiffness.vmult(ku, U);
  // d_n as the restart's initial_state() forms it from V_n (Rayleigh); the
  // frequency-range branches' force as the last step had it (their memory
  // restarts at zero)
  Vector<double> d(d_prev);
  if (a0 != 0. || a1 != 0.)
  {
    Vector<double> v_n(n), kv(n);
    integer_velocity(v_n);
    if (a1 != 0. && system.has_stiffness())
      system.stiffness.vmult(kv, v_n);
    for (unsigned int i = 0; i < n; ++i)
      d[i] = system.fixed[i] ? 0. : dt * a0 * v_n[i] + a1 * dt_minv[i] * kv[i];
  }
  r.reinit(n);
  for (unsigned int i = 0; i < n; ++i)
    if (!system.fixed[i])
      r[i] = mass[i] * ((*V)[i] - (*V_prev)[i] + d[i]) / dt - (f[i] - ku[i]);
}

void CDLagrange::step()
{
  predict();
  free_velocity();
  finish_step();
}

void CDLagrange::predict()
{
  const unsigned int n = U.size();
  double *const u = U.data();
  const double *const v = V->data();
  // (A1) U_{n+1} = U_n + dt V_{n+1/2}
  for (unsigned int i = 0; i < n; ++i)
    u[i] += dt * v[i];
  // (A8) q_l <- e_l q_l + tau_l (1 - e_l) V_{n+1/2}, S = sum_l alpha_l q_l
  if (branches.active())
    branches.update(*V);
  ++n_steps;
  t = system.start_time + n_steps * dt;
}

HATI_AVX2_CLONES void CDLagrange::free_velocity(const bool with_loads)
{
  // (A2)-(A3) V_free = V_{n+1/2} + dt M^-1 (F_ext(t_{n+1}) - K U_{n+1}),
  // with dt M^-1 folded into the stored operator and force; V_prev receives
  // V_free (it becomes V_{n+3/2} in finish_step())
  const double *a = with_loads ? dt_minv_force.data() : zero_force.data();
  const unsigned int n_loads = with_loads ? dt_minv_load_shapes.size() : 0;
  if (n_loads > 0)
    a = load_step_force();
  const bool damped = this->damped();
  const unsigned int n = U.size();
  if (with_loads && !forcing_laws.empty())
  {
    // the force laws' forces at U_{n+1} (e.g. R1) with the external force
    if (a != step_force.data())
    {
      if (step_force.size() != n)
        step_force.reinit(n);
      std::copy(a, a + n, step_force.begin());
    }
    for (ForceLaw *law : forcing_laws)
      law->step(U, *V, dt_minv, dt, step_force.data());
    a = step_force.data();
  }
  const double *const u = U.data(), *const v = V->data();
  double *const v_new = V_prev->data();
  double *const work = row_work.data();
  // each row's work summed in row order, as one pass over the rows would
  const auto row_order_work = [&]()
  {
    double sum = 0.;
    for (unsigned int i = 0; i < n; ++i)
      sum += work[i];
    return 0.5 * sum;
  };
  if (branches.active())
  {
    // (A8) V_free = V_{n+1/2} + dt M^-1 (F_ext(t_{n+1}) - K (U_{n+1} + S_{n+1}));
    // the branch force K S_{n+1} takes 1/2 dU . K (S_n + S_{n+1}) from the
    // structure in the step (E1 with the branches, doc/theory.md A8)
    for (const RowGroup &g : row_groups)
      with_kernel_width(
          g.width,
          [&](auto w)
          {
            branch_free_velocity_rows<decltype(w)::value>(g,
                                                          u,
                                                          branches.sum().data(),
                                                          v,
                                                          a,
                                                          mass.data(),
                                                          d_prev.data(),
                                                          v_new,
                                                          work);
            return 0.;
          },
          KernelWidths());
    branches.add_work(row_order_work());
  }
  else if (!damped)
    for (const RowGroup &g : row_groups)
      with_kernel_width(
          g.width,
          [&](auto w)
          {
            free_velocity_rows<decltype(w)::value>(g, u, v, a, v_new);
            return 0.;
          },
          KernelWidths());
  else
  {
    // (A7) (1 + a0 dt/2) V_free = (1 - a0 dt/2) V_{n+1/2}
    //        + dt M^-1 (F_ext(t_{n+1}) - K U_{n+1} - a1 K V_{n+1/2}),
    // damping force D_{n+1} = a0 M (V_{n+1/2} + V_free)/2 + a1 K V_{n+1/2};
    // its work on dU = dt V_{n+1/2} is 1/2 dU . (D_n + D_{n+1}) (the
    // time-dependent loads enter V_free scaled by c2 and the rest, (1 - c2)
    // of them, the damping force and its work)
    for (const RowGroup &g : row_groups)
      with_kernel_width(
          g.width,
          [&](auto w)
          {
            damped_free_velocity_rows<decltype(w)::value>(g,
                                                          u,
                                                          v,
                                                          a,
                                                          mass.data(),
                                                          c1,
                                                          c2,
                                                          a1,
                                                          d_prev.data(),
                                                          v_new,
                                                          stiffness_velocity_out,
                                                          work);
            return 0.;
          },
          KernelWidths());
    dissipated += row_order_work();
  }
}

template <unsigned int L, bool Accumulate>
void CDLagrange::load_pass(const unsigned int n,
                           double *__restrict a,
                           const unsigned int first)
{
  // L loads known at compile time: the amplitudes, velocities and shapes in
  // registers
  double s[L], w[L];
  const double *__restrict g[L], *__restrict shape[L];
  for (unsigned int l = 0; l < L; ++l)
  {
    s[l] = load_amplitude[first + l];
    w[l] = 0.;
    g[l] = load_force_data[first + l];
    shape[l] = load_shape_data[first + l];
  }
  const double *__restrict f = dt_minv_force.data(), *__restrict v = V->data();
  for (unsigned int i = 0; i < n; ++i)
  {
    double ai = Accumulate ? a[i] : f[i];
    for (unsigned int l = 0; l < L; ++l)
    {
      ai += s[l] * g[l][i];
      w[l] += shape[l][i] * v[i];
    }
    a[i] = ai;
  }
  for (unsigned int l = 0; l < L; ++l)
    load_velocity[first + l] = w[l];
}

const double *CDLagrange::load_step_force()
{
  // dt M^-1 F_ext(t_{n+1}) and the load velocities shape_l . V_{n+1/2} in
  // one pass; the work of the time-dependent loads is trapezoidal on the
  // increment (the constant part is F . (U - U_0), computed at output
  // times). The previous amplitude is the one at t_n computed as in
  // predict(), n dt (t_{n+1} - dt can differ from it by round-off and miss
  // a step load that starts at t_n), kept from the step before.
  const unsigned int n = U.size(), n_loads = dt_minv_load_shapes.size();
  load_amplitude.resize(n_loads);
  load_previous_amplitude.resize(n_loads);
  load_velocity.resize(n_loads);
  load_shape_data.resize(n_loads);
  load_force_data.resize(n_loads);
  const bool previous_known = amplitude_step + 1 == n_steps;
  for (unsigned int l = 0; l < n_loads; ++l)
  {
    const auto &load = system.time_dependent_loads[l];
    load_previous_amplitude[l] =
        previous_known ? load_amplitude[l]
                       : load.amplitude(system.start_time + (n_steps - 1) * dt);
    load_amplitude[l] = load.amplitude(t);
    load_velocity[l] = 0.;
    load_shape_data[l] = load_shapes[l].data();
    load_force_data[l] = dt_minv_load_shapes[l].data();
  }
  amplitude_step = n_steps;
  if (step_force.size() != n)
    step_force.reinit(n);
  double *const a = step_force.data();
  unsigned int first = 0;
  for (; n_loads - first > 3; first += 3)
    first == 0 ? load_pass<3, false>(n, a, first) : load_pass<3, true>(n, a, first);
  switch (n_loads - first)
  {
  case 1:
    first == 0 ? load_pass<1, false>(n, a, first) : load_pass<1, true>(n, a, first);
    break;
  case 2:
    first == 0 ? load_pass<2, false>(n, a, first) : load_pass<2, true>(n, a, first);
    break;
  case 3:
    first == 0 ? load_pass<3, false>(n, a, first) : load_pass<3, true>(n, a, first);
  }
  for (unsigned int l = 0; l < n_loads; ++l)
    time_dependent_work +=
        0.5 * (load_previous_amplitude[l] + load_amplitude[l]) * dt * load_velocity[l];
  return a;
}

void CDLagrange::finish_step(const bool with_contacts)
{
  std::swap(V, V_prev); // V = V_free, V_prev = V_{n+1/2}
  // (A4)-(A6) the impulses of the laws with rows (e.g. the contacts)
  if (with_contacts && !row_laws.empty())
  {
    const SampledWallClock::Scope scope(contact_clock);
    for (ForceLaw *law : gating_laws) // e.g. (D1) the flanges over their rails
      law->gate_rows(t, U, rows_off);
    for (ForceLaw *law : row_laws)
      law->apply_impulses(U, *V_prev, minv, *V);
  }
}

void CDLagrange::save(Snapshot &s) const
{
  s.U = U;
  s.V = *V;
  s.V_prev = *V_prev;
  s.d_prev = d_prev;
  s.q = branches.memory();
  s.branch_work = branches.work();
  s.t = t;
  s.n_steps = n_steps;
  s.time_dependent_work = time_dependent_work;
  s.dissipated = dissipated;
  s.laws.resize(laws.size());
  for (unsigned int l = 0; l < laws.size(); ++l)
    laws[l]->save(s.laws[l]);
}

void CDLagrange::restore(const Snapshot &s)
{
  U = s.U;
  *V = s.V;
  *V_prev = s.V_prev;
  d_prev = s.d_prev;
  if (branches.active())
    branches.set_memory(s.q, s.branch_work);
  t = s.t;
  n_steps = s.n_steps;
  time_dependent_work = s.time_dependent_work;
  dissipated = s.dissipated;
  for (unsigned int l = 0; l < laws.size(); ++l)
    laws[l]->restore(s.laws[l]);
}

std::vector<double> CDLagrange::normal_velocities() const
{
  std::vector<double> w(system.contacts.size());
  for (unsigned int k = 0; k < w.size(); ++k)
    w[k] = system.contacts[k].apply(*V);
  return w;
}

double CDLagrange::dissipated_energy() const
{
  return branches.active()
             ? dissipated + branches.work() - branches.stored_energy(system.stiffness)
             : dissipated;
}

Energies CDLagrange::energies() const
{
  Energies e;
  const unsigned int n = U.size();
  for (unsigned int i = 0; i < n; ++i)
    e.kinetic += 0.5 * (*V_prev)[i] * system.lumped_mass[i] * (*V)[i];
  if (system.has_stiffness())
    e.internal = 0.5 * system.stiffness.matrix_norm_square(U);
  for (const auto &law : laws) // e.g. the ropes' energy, the contact work
    law->add_energies(e);
  Vector<double> du(U);
  du -= U0;
  e.external_work = force * du + time_dependent_work;
  e.dissipated = dissipated;
  branches.add_energies(e, system.stiffness);
  e.kinetic_explicit = e.kinetic;
  e.internal_explicit = e.internal;
  return e;
}
} // namespace hati
