#include <hati/time/ramp_superposition.h>

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
} // namespace

// The dissipated energy of the superposed ramp (doc/theory.md 9.6, "Cost of
// the superposition"; A7, A8): its quadratic form per ramp response and
// the cross terms with the pass.

void RampSuperposition::store_dissipation(
    const std::vector<FullMatrix<double>> &velocity_reach,
    const std::vector<FullMatrix<double>> &damping_reach,
    Response &r) const
{
  const unsigned int n_gamma = interface.size(), nR = reach_dofs.size();
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
  // A8: the ramp's branch forces are not a function of its velocities
  if (with_memory)
  {
    r.damping_on_reach.resize(m + 1);
    for (unsigned int j = 1; j <= m; ++j)
      r.damping_on_reach[j] = SparseColumns(damping_reach[j]);
  }
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
          r.dissipation_quadratic.add(
              l,
              k,
              reach_mass[i] * v * (damping_reach[j - 1](i, k) + damping_reach[j](i, k)));
      }
  r.dissipation_quadratic.skip_zero_rows();
}

double RampSuperposition::ramp_dissipation(const Response &ramp,
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
  const unsigned int nR = reach_dofs.size(), n_gamma = interface.size();
  const double alpha = 0.5 * ramp_integrator->mass_damping_coefficient() * dt,
               a1 = ramp_integrator->stiffness_damping_coefficient();
  const double *__restrict const mass = reach_mass.data();
  double *__restrict const cj = dissipation_c.data();
  dissipation_p_prev = 0.;
  dissipation_g = 0.;
  double impulse_term = 0.;
  const unsigned int nrc = reach_contacts.size();
  // the contacts' impulses of the ramp part, computed by superpose_contacts()
  const bool with_impulses = contacts_in_reach() && ramp_impulse.size() == (m + 1) * nrc;
  const auto &contacts = system.contacts;
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
    // A8: the pass's velocities on the ramp's branch forces,
    // v_a,j . M (d_r,j-1 + d_r,j) summed over j is sum_j M p_j . d_r,j
    if (with_memory)
    {
      for (unsigned int r = 0; r < nR; ++r)
        cj[r] = mass[r] * p[r];
      ramp.damping_on_reach[j].Tvmult_add(dissipation_g, cj);
    }
    // the interface ramp's and the contacts' velocity jumps in the ramp's
    // free velocity
    const double s = dt * double(j) / m;
    for (unsigned int l = 0; l < n_gamma; ++l)
    {
      double cp = 0.; // C_E,l p on the reach
      for (const auto &[r, c] : interface_reach_rows[l])
        cp += c * p[r];
      impulse_term += cp * s * lambda[l];
    }
    if (with_impulses)
      for (unsigned int c = 0; c < nrc; ++c)
      {
        const double impulse = ramp_impulse[j * nrc + c];
        if (impulse != 0.)
          impulse_term += contacts[reach_contacts[c]].apply(dissipation_p) * impulse;
        // (A9) the tangential impulses of the sticking contacts
        if (reach_friction && reach_frictional[c])
          for (unsigned int t = 0; t < contacts[reach_contacts[c]].tangents.size(); ++t)
          {
            const double tangential = ramp_tangential[2 * (j * nrc + c) + t];
            if (tangential != 0.)
              impulse_term +=
                  contacts[reach_contacts[c]].tangents[t].apply(dissipation_p) *
                  tangential;
          }
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

} // namespace hati
