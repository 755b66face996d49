#include <deal.II/base/exceptions.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <hati/analysis/reduced_part.h>
#include <hati/time/hati_coupling.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>

namespace hati
{
namespace
{
/**
 * The run's damping for the implicit part, or none when that part has a
 * damping matrix of its own (the reduced part's modal damping, doc/theory.md
 * 12.3).
 */
DampingModel implicit_damping(const DiscreteSystem &implicit, const DampingModel &damping)
{
  return implicit.has_damping_matrix() ? DampingModel() : damping;
}

using Clock = std::chrono::steady_clock;

double seconds_since(const Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/** The seconds since @p mark, which moves to now: one clock read per phase. */
double lap(Clock::time_point &mark)
{
  const Clock::time_point now = Clock::now();
  const double seconds = std::chrono::duration<double>(now - mark).count();
  mark = now;
  return seconds;
}
} // namespace

void HATIParameters::declare_parameters(ParameterHandler &prm)
{
  prm.declare_entry("Time step ratio",
                    "10",
                    Patterns::Integer(1, max_time_step_ratio),
                    "m = DT / dt (-), an integer from 1 to 10000: the implicit subdomain "
                    "steps with DT = m dt, the explicit one with Time integration/Time "
                    "step dt. The unit-ramp responses of the coupling are stored for "
                    "the m micro steps of a macro step (memory about m x interface "
                    "DoFs x explicit DoFs near the interface x 8 bytes; about 2 GB for "
                    "the bridge crane at m = 10000).");
  prm.declare_entry(
      "Coupling method",
      "macro-linear",
      Patterns::Selection("macro-linear"),
      "Interface problem of the coupling. macro-linear (G3'): velocity continuity at "
      "the macro-step ends, the interface force linear in time over the macro step; "
      "stable (spectral radius of a macro step <= 1) and energy-consistent.");
  prm.declare_entry(
      "Superposition",
      "true",
      Patterns::Bool(),
      "true: a macro step with contacts or ropes within reach of the interface whose "
      "pushing contacts stay the same and stick over the macro step (and whose ropes' "
      "forces the correction changes by at most 1e-8 of their largest tension) adds the "
      "interface correction by "
      "superposition of the unit-ramp responses (doc/theory.md 9.6); the others are "
      "redone with the full multiplier. false (a check, slower): every such macro step "
      "is redone; the results agree with true to round-off and the friction solver's "
      "tolerance.");
}

void HATIParameters::parse_parameters(ParameterHandler &prm)
{
  const long ratio = prm.get_integer("Time step ratio");
  AssertThrow(ratio >= 1 && ratio <= max_time_step_ratio,
              ExcMessage("Time integration/HATI/Time step ratio must be an integer from "
                         "1 to " +
                         std::to_string(max_time_step_ratio) + " (DT = m dt), got " +
                         std::to_string(ratio)));
  time_step_ratio = ratio;
  coupling_method = prm.get("Coupling method");
  superposition = prm.get_bool("Superposition");
}

HATICoupling::HATICoupling(const Decomposition &decomposition,
                           const unsigned int n_global_dofs,
                           const double dt,
                           const double safety_factor,
                           const HATIParameters &parameters,
                           const NewmarkParameters &newmark_parameters,
                           const DampingModel &damping)
    : decomposition(decomposition), m(parameters.time_step_ratio),
      superpose_steps(parameters.superposition),
      explicit_integrator(decomposition.parts[0].system,
                          dt,
                          safety_factor,
                          damping.rayleigh,
                          damping.branches),
      explicit_view(explicit_integrator.coupling_view()),
      implicit(implicit_system(decomposition),
               m * dt,
               newmark_parameters,
               implicit_damping(implicit_system(decomposition), damping).rayleigh,
               implicit_damping(implicit_system(decomposition), damping).branches)
{
  const auto start = Clock::now();
  AssertThrow(
      m >= 1,
      ExcMessage("Time integration/HATI/Time step ratio must be an integer >= 1"));
  // (G3') H_I and the link columns, then the explicit response to the unit
  // ramps and its interface matrices
  interface = std::make_unique<InterfaceProblem>(
      decomposition, implicit, newmark_parameters.gamma);
  superposition = std::make_unique<RampSuperposition>(decomposition.parts[0].system,
                                                      dt,
                                                      m,
                                                      damping.rayleigh,
                                                      damping.branches,
                                                      *interface);
  const unsigned int n_gamma = interface->size();
  for (auto *v : {&lambda_n,
                  &lambda_m,
                  &delta_lambda,
                  &increments.v_end,
                  &increments.increment_sum,
                  &increments.increment_weighted})
    v->reinit(n_gamma);
  global_U.reinit(n_global_dofs);
  global_V.reinit(n_global_dofs);
  const bool restarted = decomposition.initial_multiplier.size() == n_gamma;
  interface->initial_multiplier(explicit_integrator,
                                implicit,
                                lambda_n,
                                restarted ? &decomposition.initial_multiplier : nullptr);
  setup = seconds_since(start);
}

void HATICoupling::micro_steps(const Vector<double> &lambda_end, const bool pass)
{
  const std::vector<SparseRow> &rows_E = interface->explicit_rows();
  const unsigned int n_gamma = rows_E.size();
  const double dt = explicit_integrator.time_step();
  Vector<double> &increment_sum = increments.increment_sum,
                 &increment_weighted = increments.increment_weighted,
                 &v_end = increments.v_end;
  increment_sum = 0.;
  increment_weighted = 0.;
  RampSuperposition &record = *superposition;
  const bool record_damping = record.records_damping() && pass;
  record.start_pass(explicit_integrator, record_contacts);
  if (record_damping)
    record.record_damping_force(0, explicit_view.damping_force());
  for (unsigned int j = 1; j <= m; ++j)
  {
    if (record_damping)
      record.record_velocity(j, explicit_integrator.velocity());
    // interface displacement increment of this step, dt C_E V_{j-1/2}
    // (C_E: +1 on the explicit DoF of each interface pair; a sparse row for
    // a tie to an explicit solid, G3'')
    const Vector<double> &V = explicit_integrator.velocity();
    const double weight = (2. * j - 1.) / (2. * m);
    for (unsigned int k = 0; k < n_gamma; ++k)
    {
      const double du = dt * rows_E[k].apply(V);
      increment_sum[k] += du;
      increment_weighted[k] += weight * du;
    }
    // the closures of the best pass (redo_micro_steps(), doc/theory.md 9.6)
    if (!frozen_activation.empty())
      explicit_view.freeze_activation(&frozen_activation[j - 1]);
    // (G2) Lambda_j = (1 - j/m) Lambda_n [+ (j/m) Lambda_{n+m}] over the step
    explicit_view.predict();
    if (record_damping)
      explicit_view.record_stiffness_velocity(record.stiffness_velocity_buffer(j));
    explicit_view.free_velocity();
    if (record_damping)
    {
      explicit_view.record_stiffness_velocity(nullptr);
      record.record_stiffness_velocity(j);
    }
    const double w0 = 1. - double(j) / m, w1 = double(j) / m;
    for (unsigned int k = 0; k < n_gamma; ++k)
    {
      const double lambda = w0 * lambda_n[k] + w1 * lambda_end[k];
      if (lambda != 0.)
        for (unsigned int i = 0; i < rows_E[k].dofs.size(); ++i)
          explicit_view.add_dof_force(rows_E[k].dofs[i],
                                      rows_E[k].coefficients[i] * lambda);
    }
    explicit_view.finish_step();
    // (G3') C_E V^E_m, the impulses of the last micro step included
    if (j == m)
      for (unsigned int k = 0; k < n_gamma; ++k)
      {
        double v = 0.;
        for (unsigned int i = 0; i < rows_E[k].dofs.size(); ++i)
          v += rows_E[k].coefficients[i] *
               explicit_view.integer_velocity(rows_E[k].dofs[i]);
        v_end[k] = v;
      }
    if (pass)
    {
      record.record_load_weights(j, explicit_view);
      record.record_law_forces(j, explicit_integrator);
    }
    if (record_damping)
      record.record_damping_force(j, explicit_view.damping_force());
    if (record_contacts)
    {
      if (n_recorded == contact_record.size())
        contact_record.emplace_back();
      ContactSample &s = contact_record[n_recorded++];
      take_sample(s);
      record.record_contacts(j, s, explicit_integrator.velocity());
    }
    else if (after_micro_step)
    {
      {
        const SampledWallClock::Scope scope(sample_clock);
        take_sample(sample);
      }
      after_micro_step(sample);
    }
  }
  explicit_view.freeze_activation(nullptr);
}

void HATICoupling::step()
{
  // (G1) the free implicit step (the phases are timed on one macro step in
  // SampledWallClock::sample_every, consecutive ones sharing their clock
  // reads; a redo always)
  const bool timed = n_macro_steps_seen++ % SampledWallClock::sample_every == 0;
  n_macro_steps_timed += timed;
  Clock::time_point start;
  if (timed)
    start = Clock::now();
  // ends phase k on a timed macro step (seconds[k]; the next one starts)
  const auto close_phase = [&](const unsigned int k)
  {
    if (timed)
      seconds[k] += lap(start);
  };
  implicit.free_step();
  close_phase(1);

  // (G2) the micro steps with the known part of the multiplier; with
  // contacts within reach of the ramp response, keep the state to redo them
  record_contacts = superposition->nonlinear_in_reach();
  n_recorded = 0;
  if (record_contacts)
    explicit_integrator.save(snapshot);
  micro_steps(lambda_n, true);
  close_phase(0);

  // (G3') Lambda_{n+m} from the velocity continuity at t_{n+m}: the pass
  // ran with the guess Lambda_{n+m} = Lambda_n, the correction solves
  // H dLambda = -(C_E V_pass + C_I V_free + H_I Lambda_n), with the ramp
  // response of the active set of the contacts within reach when it stayed
  // the same over the pass
  bool same_active_set = true;
  const RampSuperposition::Response &ramp =
      superposition->response_for_pass(same_active_set);
  interface->set_free_implicit_velocity(implicit);
  interface->correction(ramp.H_inverse, increments.v_end, lambda_n, delta_lambda);
  for (unsigned int k = 0; k < lambda_m.size(); ++k)
    lambda_m[k] = lambda_n[k] + delta_lambda[k];
  close_phase(2);

  // the correction added by superposition, or the micro steps redone
  // friction within reach of the ramp (A9) is linear in the multiplier while
  // its contacts stick: response_for_pass() and superpose() check it
  const bool superposed = same_active_set && superpose_steps &&
                          superposition->superpose(ramp,
                                                   delta_lambda,
                                                   explicit_integrator,
                                                   increments,
                                                   contact_record,
                                                   n_recorded);
  if (superposed)
  {
    if (after_micro_step)
      for (unsigned int j = 0; j < n_recorded; ++j)
        after_micro_step(contact_record[j]);
    close_phase(3);
  }
  else
  {
    close_phase(3);
    const auto redo_start = Clock::now();
    redo_micro_steps(ramp.H_inverse);
    seconds[4] += seconds_since(redo_start);
    if (timed)
      start = Clock::now();
  }
  record_contacts = false;

  // (G5) interface work of the explicit side: the trapezoid of each micro
  // step, sum_j 1/2 dU_j . C_E^T (Lambda_{j-1} + Lambda_j)
  for (unsigned int k = 0; k < interface->size(); ++k)
    interface_work += increments.increment_sum[k] * lambda_n[k] +
                      increments.increment_weighted[k] * (lambda_m[k] - lambda_n[k]);
  close_phase(2);

  // (G4) the implicit link with Lambda_{n+m}, its interface work
  // 1/2 dU_I . C_I^T (Lambda_n + Lambda_{n+m}) and the continuity check
  interface->link(
      implicit, lambda_n, lambda_m, increments.v_end, interface_work, max_jump);
  implicit.finish_step();
  lambda_n = lambda_m;
  close_phase(1);
}

void HATICoupling::broyden_step(const DenseColumns &H_inverse,
                                FullMatrix<double> &B,
                                Vector<double> &step,
                                const Vector<double> &last_residual,
                                const Vector<double> &residual) const
{
  // doc/theory.md 9.6: B ~ H_true^-1 from H^-1 and the secant condition
  // B (r_{k-1} - r_k) = dLambda_{k-1} (Broyden's inverse update); @p step
  // holds dLambda_{k-1} on entry
  const unsigned int n = residual.size();
  if (B.m() != n)
  {
    B.reinit(n, n);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        B(i, j) = H_inverse(i, j);
  }
  Vector<double> y(last_residual), By(n);
  y -= residual;
  const double yy = y * y;
  if (yy > 0.)
  {
    B.vmult(By, y);
    for (unsigned int i = 0; i < n; ++i)
    {
      const double c = (step[i] - By[i]) / yy;
      for (unsigned int j = 0; j < n; ++j)
        B(i, j) += c * y[j];
    }
  }
  B.vmult(step, residual);
}

void HATICoupling::redo_micro_steps(const DenseColumns &H_inverse)
{
  ++n_redone;
  unsigned int iterations = 0;
  const unsigned int n_gamma = interface->size();
  Vector<double> residual(n_gamma), last_residual(n_gamma), step(n_gamma),
      update(n_gamma);
  // the correction matrix of the accelerated corrections (Broyden)
  FullMatrix<double> B;
  // the safeguard (RampSuperposition::safeguarded_corrections): the residual
  // before the last correction, halvings of it, plain corrections left
  double last_norm = std::numeric_limits<double>::max();
  unsigned int halvings = 0, plain_left = RampSuperposition::plain_corrections;
  // the iterate with the smallest residual (RampSuperposition::accepted_discontinuity),
  // whether its pass had the closures frozen, and its active sets
  double best_norm = std::numeric_limits<double>::max(), best_scale = 0.;
  Vector<double> best_lambda;
  bool best_frozen = false;
  std::vector<std::vector<bool>> best_activation;
  // the frozen pass's Jacobian, pseudo-inverted (chord Newton, theory 9.6)
  LAPACKFullMatrix<double> J_inverse;
  for (;; ++iterations)
  {
    explicit_integrator.restore(snapshot);
    record_contacts = true;
    n_recorded = 0;
    micro_steps(lambda_m, false);
    double scale = 0.;
    const double norm = interface->residual(increments.v_end, lambda_m, residual, scale);
    AssertThrow(
        std::isfinite(norm),
        ExcMessage("HATI: the interface velocity continuity is not finite at t = " +
                   std::to_string(explicit_integrator.time()) +
                   " s (a correction of the interface forces gave NaN or "
                   "infinity): report this run"));
    if (norm <= RampSuperposition::continuity_tolerance * std::max(scale, 1e-300) ||
        norm == 0.)
      break;
    if (norm < best_norm)
    {
      best_norm = norm;
      best_scale = scale;
      best_lambda = lambda_m;
      best_frozen = !frozen_activation.empty();
      if (!best_frozen)
      {
        best_activation.resize(n_recorded);
        for (unsigned int j = 0; j < n_recorded; ++j)
          best_activation[j] = contact_record[j].active;
      }
    }
    if (iterations == RampSuperposition::safeguarded_corrections &&
        frozen_activation.empty())
    {
      // stalled (a closure moves by a micro step between passes, items 5-6 of
      // doc/theory.md 9.6): go on from the best iterate with its contacts'
      // closures frozen, where the macro-end velocity is continuous in
      // Lambda_{n+m}
      frozen_activation = best_activation;
      lambda_m = best_lambda;
      B.reinit(0, 0);
      plain_left = RampSuperposition::plain_corrections;
      last_norm = std::numeric_limits<double>::max();
      halvings = 0;
      continue;
    }
    if (iterations >= RampSuperposition::max_corrections &&
        best_norm <= RampSuperposition::accepted_discontinuity * best_scale)
    {
      // no root: keep the iterate with the smallest residual (the macro-end
      // velocity jumps where a contact's closure moves by a micro step)
      lambda_m = best_lambda;
      if (!best_frozen)
        frozen_activation.clear();
      explicit_integrator.restore(snapshot);
      n_recorded = 0;
      micro_steps(lambda_m, false);
      ++n_discontinuous;
      largest_discontinuity = std::max(largest_discontinuity, best_norm / best_scale);
      break;
    }
    if (iterations >= RampSuperposition::max_corrections)
    {
      frozen_activation.clear();
      AssertThrow(false, ExcMessage(not_converged_message(norm, scale)));
    }
    if (!frozen_activation.empty() &&
        iterations == RampSuperposition::safeguarded_corrections +
                          RampSuperposition::frozen_corrections_before_jacobian)
    {
      // the frozen closures' corrections with H^-1 stalled: with its active
      // sets frozen the pass is (piecewise) affine in Lambda, so its own
      // Jacobian (one pass per interface row) gives Newton's step
      frozen_jacobian(lambda_m, residual, J_inverse);
      last_norm = std::numeric_limits<double>::max();
      halvings = 0;
    }
    if (J_inverse.m() > 0)
    {
      if (norm > last_norm && halvings < RampSuperposition::max_halvings)
      {
        // back half of the last Newton step
        step *= 0.5;
        lambda_m += step;
        ++halvings;
        continue;
      }
      halvings = 0;
      J_inverse.vmult(step, residual);
      lambda_m -= step;
      last_norm = norm;
      continue;
    }
    if (iterations >= RampSuperposition::safeguarded_corrections && norm > last_norm &&
        halvings < RampSuperposition::max_halvings)
    {
      // the last correction grew the residual (a contact switched across
      // it): go back half of it, and restart the secant update from H^-1
      step *= 0.5;
      lambda_m -= step;
      ++halvings;
      B.reinit(0, 0);
      plain_left = RampSuperposition::plain_corrections;
      ++n_halvings;
      continue;
    }
    halvings = 0;
    if (plain_left > 0)
    {
      // Lambda += H^-1 r with the interface matrix of the ramp response
      step = residual;
      interface->solve(H_inverse, step);
      --plain_left;
    }
    else
      broyden_step(H_inverse, B, step, last_residual, residual);
    last_residual = residual;
    last_norm = norm;
    lambda_m += step;
  }
  if (!frozen_activation.empty())
    frozen_closures();
  max_iterations = std::max(max_iterations, iterations + 1);
  n_redo_passes += iterations + 1;
  if (after_micro_step)
    for (unsigned int j = 0; j < n_recorded; ++j)
      after_micro_step(contact_record[j]);
}

std::string HATICoupling::not_converged_message(const double norm,
                                                const double scale) const
{
  std::ostringstream message;
  message << "HATI: the interface velocity continuity with contacts within "
             "reach of the interface did not converge in "
          << RampSuperposition::max_corrections
          << " corrections at t = " << explicit_integrator.time() << " s (residual "
          << norm << " m/s, velocity scale " << scale
          << " m/s): move the interface further from the contacts or reduce the "
             "Time step ratio";
  return message.str();
}

void HATICoupling::frozen_jacobian(const Vector<double> &lambda,
                                   const Vector<double> &r0,
                                   LAPACKFullMatrix<double> &J_inverse)
{
  const unsigned int n = lambda.size();
  // the frozen pass is affine only piecewise (impulse signs, friction
  // states): a small perturbation gives the local Jacobian, its
  // differences still far above round-off
  const double h = 1e-6 * std::max(lambda.linfty_norm(), 1.);
  J_inverse.reinit(n, n);
  Vector<double> perturbed(lambda), r(n);
  double scale = 0.;
  for (unsigned int k = 0; k < n; ++k)
  {
    perturbed[k] += h;
    explicit_integrator.restore(snapshot);
    n_recorded = 0;
    micro_steps(perturbed, false);
    interface->residual(increments.v_end, perturbed, r, scale);
    for (unsigned int i = 0; i < n; ++i)
      J_inverse(i, k) = (r[i] - r0[i]) / h;
    perturbed[k] = lambda[k];
  }
  n_redo_passes += n;
  ++n_jacobians;
  // pseudo-inverse: a direction the pass cannot change is left alone
  J_inverse.compute_inverse_svd(1e-12);
}

void HATICoupling::frozen_closures()
{
  // the kept pass ran with the closures frozen: how far its active sets are
  // from the gaps' (a contact taken as closed at a positive gap, or left open
  // at a negative one)
  ++n_frozen;
  const auto &contacts = decomposition.parts[0].system.contacts;
  for (unsigned int j = 0; j < n_recorded; ++j)
  {
    const ContactSample &s = contact_record[j];
    for (unsigned int k = 0; k < s.active.size() && k < s.gaps.size(); ++k)
      if (!contacts[k].bilateral && s.active[k] != (s.gaps[k] <= 0.))
        largest_frozen_gap = std::max(largest_frozen_gap, std::abs(s.gaps[k]));
  }
  frozen_activation.clear();
}

void HATICoupling::take_sample(ContactSample &s) const
{
  // the explicit subdomain's laws: the contacts' gaps, normal velocities,
  // impulses, active flags and friction columns
  s.time = explicit_integrator.time();
  sample_force_laws(explicit_integrator.force_laws(), explicit_integrator.velocity(), s);
}

const Vector<double> &HATICoupling::to_global(const Vector<double> &implicit_part,
                                              const Vector<double> &explicit_part,
                                              Vector<double> &global) const
{
  const auto &E = decomposition.parts[0], &I = decomposition.parts[1];
  global = 0.;
  for (unsigned int i = 0; i < I.global_dofs.size(); ++i)
    global[I.global_dofs[i]] = implicit_part[i];
  for (unsigned int i = 0; i < E.global_dofs.size(); ++i)
    global[E.global_dofs[i]] = explicit_part[i];
  return global;
}

Energies HATICoupling::energies() const
{
  const Energies e = explicit_integrator.energies(), i = implicit.energies();
  Energies r;
  r.kinetic = e.kinetic + i.kinetic;
  r.internal = e.internal + i.internal;
  r.external_work = e.external_work + i.external_work;
  r.contact_work = e.contact_work;
  r.friction_dissipated = e.friction_dissipated;
  r.dissipated = e.dissipated + i.dissipated;
  r.damping_stored = e.damping_stored + i.damping_stored;
  r.interface_work = interface_work;
  r.kinetic_explicit = e.kinetic;
  r.kinetic_implicit = i.kinetic;
  r.internal_explicit = e.internal;
  r.internal_implicit = i.internal;
  return r;
}

unsigned int HATICoupling::state_size() const
{
  const unsigned int n_branches = explicit_integrator.memory().n_branches();
  return (2 + n_branches) * decomposition.parts[0].system.n_dofs() +
         (3 + n_branches) * implicit_system(decomposition).n_dofs() + interface->size();
}

void HATICoupling::get_state(Vector<double> &x) const
{
  const unsigned int nE = decomposition.parts[0].system.n_dofs(),
                     nI = implicit_system(decomposition).n_dofs();
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
  for (unsigned int k = 0; k < interface->size(); ++k)
    x[o++] = lambda_n[k];
  for (const auto *memory : {&explicit_integrator.memory(), &implicit.memory()})
    for (const Vector<double> &q : memory->memory())
      for (unsigned int i = 0; i < q.size(); ++i)
        x[o++] = q[i];
}

void HATICoupling::set_state(const Vector<double> &x)
{
  AssertThrow(x.size() == state_size(), ExcDimensionMismatch(x.size(), state_size()));
  const unsigned int nE = decomposition.parts[0].system.n_dofs(),
                     nI = implicit_system(decomposition).n_dofs();
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
  for (unsigned int k = 0; k < interface->size(); ++k)
    lambda_n[k] = x[o++];
  // the memory variables (A8, N4); S and the branch forces follow from them
  explicit_view.memory().modify_memory(
      [&](unsigned int, Vector<double> &q)
      {
        for (unsigned int i = 0; i < nE; ++i)
          q[i] = x[o++];
      });
  std::vector<Vector<double>> q(implicit.memory().memory());
  for (Vector<double> &ql : q)
    for (unsigned int i = 0; i < nI; ++i)
      ql[i] = x[o++];
  implicit.set_memory(q);
}
} // namespace hati
