#include <deal.II/base/exceptions.h>
#include <deal.II/lac/full_matrix.h>

#include <hati/contact/lcp_solver.h>
#include <hati/time/cd_lagrange.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>

namespace hati
{
namespace
{
/** Padded row widths with a compiled kernel; wider rows use the generic one. */
constexpr unsigned int kernel_widths[] = {2, 3, 4, 6, 8, 12, 16, 24, 32, 48, 64, 81, 96};

unsigned int padded_width(const unsigned int w)
{
  if (w == 0)
    return 0;
  for (const unsigned int k : kernel_widths)
    if (w <= k)
      return k;
  return w;
}

/**
 * v_new = v + a - S u for a row-padded operator S of width W (A2-A3 with
 * S = dt M^-1 K, a = dt M^-1 F_ext). W is a compile-time constant so that
 * the row loop is unrolled.
 */
template <unsigned int W>
void free_velocity_rows(const unsigned int n,
                        const unsigned int *__restrict col,
                        const double *__restrict val,
                        const double *__restrict u,
                        const double *__restrict v,
                        const double *__restrict a,
                        double *__restrict v_new)
{
  for (unsigned int i = 0; i < n; ++i)
  {
    double ku = 0.;
    for (unsigned int k = 0; k < W; ++k)
      ku += val[std::size_t(i) * W + k] * u[col[std::size_t(i) * W + k]];
    v_new[i] = v[i] + a[i] - ku;
  }
}

void free_velocity_kernel(const unsigned int width,
                          const unsigned int n,
                          const unsigned int *col,
                          const double *val,
                          const double *u,
                          const double *v,
                          const double *a,
                          double *v_new)
{
  switch (width)
  {
#define HATI_KERNEL(W)                                                                   \
  case W:                                                                                \
    return free_velocity_rows<W>(n, col, val, u, v, a, v_new);
    HATI_KERNEL(0)
    HATI_KERNEL(2)
    HATI_KERNEL(3)
    HATI_KERNEL(4)
    HATI_KERNEL(6)
    HATI_KERNEL(8)
    HATI_KERNEL(12)
    HATI_KERNEL(16)
    HATI_KERNEL(24)
    HATI_KERNEL(32)
    HATI_KERNEL(48)
    HATI_KERNEL(64)
    HATI_KERNEL(81)
    HATI_KERNEL(96)
#undef HATI_KERNEL
  default:
    for (unsigned int i = 0; i < n; ++i)
    {
      double ku = 0.;
      for (unsigned int k = 0; k < width; ++k)
        ku += val[std::size_t(i) * width + k] * u[col[std::size_t(i) * width + k]];
      v_new[i] = v[i] + a[i] - ku;
    }
  }
}
} // namespace

CDLagrange::CDLagrange(const DiscreteSystem &system,
                       const double dt,
                       const double safety_factor)
    : system(system), dt(dt)
{
  const unsigned int n = system.n_dofs();
  AssertThrow(dt > 0. && std::isfinite(dt),
              ExcMessage("Time integration/Time step must be positive and finite."));

  // Stability: dt <= safety * 2 / omega_max (algorithms.md section 1)
  const double omega_max = system.highest_frequency_bound();
  dt_crit = omega_max > 0. ? 2. / omega_max : std::numeric_limits<double>::infinity();
  if (dt > safety_factor * dt_crit)
  {
    std::ostringstream s;
    s.precision(6);
    s << "the time step dt = " << dt << " s is above the stability limit of the "
      << "explicit scheme: dt_crit = 2/omega_max = " << dt_crit << " s (safety factor "
      << safety_factor << ", so dt must be <= " << safety_factor * dt_crit
      << " s). Reduce 'Time integration/Time step'.";
    AssertThrow(false, ExcMessage(s.str()));
  }

  for (unsigned int i = 0; i < n; ++i)
    AssertThrow(
        system.fixed[i] || system.lumped_mass[i] > 0.,
        ExcMessage("CD-Lagrange needs a positive lumped mass on every free DoF."));

  dt_minv.reinit(n);
  minv.reinit(n);
  zero_force.reinit(n);
  for (unsigned int i = 0; i < n; ++i)
  {
    minv[i] = system.fixed[i] ? 0. : 1. / system.lumped_mass[i];
    dt_minv[i] = dt * minv[i];
  }

  // dt M^-1 K in padded rows of a fixed width (ELLPACK): rows of fixed DoFs
  // are empty, padding entries are zeros pointing at the row itself
  row_width = 0;
  if (system.has_stiffness())
  {
    for (unsigned int i = 0; i < n; ++i)
      if (!system.fixed[i])
        row_width = std::max<unsigned int>(row_width, system.stiffness.get_row_length(i));
    row_width = padded_width(row_width);
    column.assign(std::size_t(n) * row_width, 0);
    value.assign(std::size_t(n) * row_width, 0.);
    for (unsigned int i = 0; i < n; ++i)
    {
      unsigned int k = 0;
      if (!system.fixed[i])
        for (auto it = system.stiffness.begin(i); it != system.stiffness.end(i); ++it)
          if (it->value() != 0.)
          {
            column[std::size_t(i) * row_width + k] = it->column();
            value[std::size_t(i) * row_width + k] = dt_minv[i] * it->value();
            ++k;
          }
      for (; k < row_width; ++k)
        column[std::size_t(i) * row_width + k] = i;
    }
  }

  // External forces with the lumped mass for the acceleration loads (gravity,
  // base excitation): -M_lumped r a instead of the consistent M r a of the
  // system, so that a rigid motion (free flight) is exact with CD.
  force = system.constant_force;
  for (unsigned int d = 0; d < 3; ++d)
    if (system.gravity[d] != 0. && system.mass_influence[d].size() == n &&
        system.influence[d].size() == n)
      for (unsigned int i = 0; i < n; ++i)
        force[i] += system.gravity[d] * (system.lumped_mass[i] * system.influence[d][i] -
                                         system.mass_influence[d][i]);
  dt_minv_force.reinit(n);
  for (unsigned int i = 0; i < n; ++i)
    dt_minv_force[i] = dt_minv[i] * force[i];
  for (const auto &load : system.time_dependent_loads)
  {
    Vector<double> shape(load.shape);
    const int d = load.acceleration_direction;
    if (d >= 0 && system.influence[d].size() == n)
      for (unsigned int i = 0; i < n; ++i)
        shape[i] = -system.lumped_mass[i] * system.influence[d][i];
    load_shapes.push_back(shape);
    shape.scale(dt_minv);
    dt_minv_load_shapes.push_back(shape);
  }

  // initial state
  U = system.initial_displacement;
  U0 = U;
  velocity_a.reinit(n);
  velocity_b.reinit(n);
  V = &velocity_a;
  V_prev = &velocity_b;

  // V_{1/2} = V_0 + dt/2 M^-1 (F_ext(0) - K U_0)
  Vector<double> f(force), ku(n);
  for (unsigned int l = 0; l < load_shapes.size(); ++l)
    f.add(system.time_dependent_loads[l].amplitude(0.), load_shapes[l]);
  if (system.has_stiffness())
    system.stiffness.vmult(ku, U);
  for (unsigned int i = 0; i < n; ++i)
  {
    const double v0 = system.fixed[i] ? 0. : system.initial_velocity[i];
    (*V)[i] = v0 + 0.5 * dt_minv[i] * (f[i] - ku[i]);
    (*V_prev)[i] = (*V)[i] - dt_minv[i] * (f[i] - ku[i]); // stands for V_{-1/2}
  }

  // contacts: which contacts are coupled through a common free DoF
  const unsigned int nc = system.contacts.size();
  gap.resize(nc);
  lambda.assign(nc, 0.);
  is_active.assign(nc, false);
  coupled_with.resize(nc);
  for (unsigned int k = 0; k < nc; ++k)
  {
    const auto &c = system.contacts[k];
    double w = 0.;
    for (unsigned int a = 0; a < c.dofs.size(); ++a)
      w += c.coefficients[a] * c.coefficients[a] * dt_minv[c.dofs[a]];
    AssertThrow(w > 0.,
                ExcMessage("contact '" + c.name +
                           "' acts only on fixed or massless degrees of freedom"));
    gap[k] = c.initial_gap + c.apply(U);
  }
  for (unsigned int k = 0; k < nc; ++k)
    for (unsigned int l = k + 1; l < nc; ++l)
    {
      bool shared = false;
      for (const auto d : system.contacts[k].dofs)
        if (!system.fixed[d])
          for (const auto e : system.contacts[l].dofs)
            shared = shared || (d == e);
      if (shared)
      {
        coupled_with[k].push_back(l);
        coupled_with[l].push_back(k);
      }
    }
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
  ++n_steps;
  t = n_steps * dt;
}

void CDLagrange::free_velocity(const bool with_loads)
{
  // (A2)-(A3) V_free = V_{n+1/2} + dt M^-1 (F_ext(t_{n+1}) - K U_{n+1}),
  // with dt M^-1 folded into the stored operator and force; V_prev receives
  // V_free (it becomes V_{n+3/2} in finish_step())
  const double *const a = with_loads ? dt_minv_force.data() : zero_force.data();
  free_velocity_kernel(row_width,
                       U.size(),
                       column.data(),
                       value.data(),
                       U.data(),
                       V->data(),
                       a,
                       V_prev->data());
  if (with_loads)
    // work of the time-dependent loads, trapezoidal on the increment
    // (the constant part is F . (U - U_0), computed at output times); the
    // previous amplitude is taken at t_n computed as in predict(), n dt:
    // t_{n+1} - dt can differ from it by round-off and miss a step load
    // that starts at t_n
    for (unsigned int l = 0; l < dt_minv_load_shapes.size(); ++l)
    {
      const auto &load = system.time_dependent_loads[l];
      const double s1 = load.amplitude(t), s0 = load.amplitude((n_steps - 1) * dt);
      time_dependent_work += 0.5 * (s0 + s1) * dt * (load_shapes[l] * (*V));
      V_prev->add(s1, dt_minv_load_shapes[l]);
    }
}

void CDLagrange::add_force(const SparseRow &row, const double force)
{
  row.add_transpose(force, dt_minv, *V_prev);
}

void CDLagrange::finish_step(const bool with_contacts)
{
  std::swap(V, V_prev); // V = V_free, V_prev = V_{n+1/2}
  if (with_contacts && !system.contacts.empty())
    apply_contacts();
}

void CDLagrange::save(Snapshot &s) const
{
  s.U = U;
  s.V = *V;
  s.V_prev = *V_prev;
  s.t = t;
  s.n_steps = n_steps;
  s.gap = gap;
  s.lambda = lambda;
  s.is_active = is_active;
  s.contact_work = contact_work;
  s.time_dependent_work = time_dependent_work;
}

void CDLagrange::restore(const Snapshot &s)
{
  U = s.U;
  *V = s.V;
  *V_prev = s.V_prev;
  t = s.t;
  n_steps = s.n_steps;
  gap = s.gap;
  lambda = s.lambda;
  is_active = s.is_active;
  contact_work = s.contact_work;
  time_dependent_work = s.time_dependent_work;
}

void CDLagrange::apply_contacts()
{
  const unsigned int nc = system.contacts.size();
  Vector<double> &v = *V;

  // contact work, first half: 1/2 (L V_{n+1/2}) lambda_n (doc/theory.md E1)
  for (unsigned int k = 0; k < nc; ++k)
    if (lambda[k] != 0.)
      contact_work += 0.5 * system.contacts[k].apply(*V_prev) * lambda[k];

  // (A4) active set from the position-level gap
  std::vector<unsigned int> active_list;
  for (unsigned int k = 0; k < nc; ++k)
  {
    const auto &c = system.contacts[k];
    gap[k] = c.initial_gap + c.apply(U);
    is_active[k] = (gap[k] <= 0.);
    lambda[k] = 0.;
    if (is_active[k])
      active_list.push_back(k);
  }
  if (active_list.empty())
    return;

  // (A5) clusters of coupled active contacts, each an LCP w = W lambda + q
  std::vector<bool> done(nc, false);
  for (const unsigned int k0 : active_list)
  {
    if (done[k0])
      continue;
    std::vector<unsigned int> cluster{k0};
    done[k0] = true;
    for (unsigned int c = 0; c < cluster.size(); ++c)
      for (const unsigned int l : coupled_with[cluster[c]])
        if (is_active[l] && !done[l])
        {
          done[l] = true;
          cluster.push_back(l);
        }

    const unsigned int m = cluster.size();
    std::vector<const ContactRow *> rows(m);
    Vector<double> q(m);
    for (unsigned int a = 0; a < m; ++a)
    {
      rows[a] = &system.contacts[cluster[a]];
      // q = L V_free + e L V_{n+1/2}
      q[a] = rows[a]->apply(v) + rows[a]->restitution * rows[a]->apply(*V_prev);
    }
    const FullMatrix<double> W = delassus(rows, minv);
    const Vector<double> l = solve_lcp(W, q);

    // V_{n+3/2} = V_free + M^-1 L^T lambda  (A5); lambda is an impulse (A6)
    for (unsigned int a = 0; a < m; ++a)
    {
      const auto &c = system.contacts[cluster[a]];
      lambda[cluster[a]] = l[a];
      c.add_transpose(l[a], minv, v);
    }
  }

  // contact work, second half: 1/2 (L V_{n+1/2}) lambda_{n+1}
  for (const unsigned int k : active_list)
    if (lambda[k] != 0.)
      contact_work += 0.5 * system.contacts[k].apply(*V_prev) * lambda[k];
}

std::vector<double> CDLagrange::normal_velocities() const
{
  std::vector<double> w(system.contacts.size());
  for (unsigned int k = 0; k < w.size(); ++k)
    w[k] = system.contacts[k].apply(*V);
  return w;
}

Energies CDLagrange::energies() const
{
  Energies e;
  const unsigned int n = U.size();
  for (unsigned int i = 0; i < n; ++i)
    e.kinetic += 0.5 * (*V_prev)[i] * system.lumped_mass[i] * (*V)[i];
  if (system.has_stiffness())
    e.internal = 0.5 * system.stiffness.matrix_norm_square(U);
  Vector<double> du(U);
  du -= U0;
  e.external_work = force * du + time_dependent_work;
  e.contact_work = contact_work;
  e.kinetic_explicit = e.kinetic;
  e.internal_explicit = e.internal;
  return e;
}
} // namespace hati
