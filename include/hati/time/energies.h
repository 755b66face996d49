#ifndef hati_time_energies_h
#define hati_time_energies_h

namespace hati
{
/**
 * Discrete energies of a run at one output time (J), whatever the
 * integrator (doc/theory.md, E1 for CD-Lagrange, the Newmark balance, and
 * the interface work of the coupling, G5). The kinetic energy of
 * CD-Lagrange is the staggered one, `1/2 V_{n-1/2} . M V_{n+1/2}`, so that
 * total() is constant to round-off for every scheme.
 */
struct Energies
{
  /** Kinetic energy of the whole model (J). */
  double kinetic = 0.;
  /** Internal (strain) energy of the whole model, 1/2 U.K U (J). */
  double internal = 0.;
  /** Work of the external loads since t = 0 (J). */
  double external_work = 0.;
  /** Work of the contact impulses since t = 0 (J), <= 0. */
  double contact_work = 0.;
  /** Energy dissipated by damping since t = 0 (J), >= 0. */
  double dissipated = 0.;
  /**
   * Energy stored by the Maxwell branches of frequency-range damping,
   * `1/2 sum_l alpha_l q_l.K q_l` (J, A8); zero otherwise.
   */
  double damping_stored = 0.;
  /**
   * Work of the interface forces of the coupling since t = 0 (J), each
   * side's own discrete work (G5); zero for a single domain.
   */
  double interface_work = 0.;
  /**
   * Energy dissipated by Coulomb friction since t = 0 (J, >= 0): minus the
   * work of the tangential impulses (A9); zero without friction.
   */
  double friction_dissipated = 0.;
  /** Kinetic and internal energies of the explicit and implicit subdomains (J). */
  double kinetic_explicit = 0., kinetic_implicit = 0.;
  double internal_explicit = 0., internal_implicit = 0.;

  /**
   * The balance kinetic + internal + damping_stored + dissipated - works,
   * constant in time.
   */
  double total() const
  {
    const double t = kinetic + internal + damping_stored + dissipated - external_work -
                     contact_work - interface_work;
    // added only with friction, so that a frictionless total keeps its bits
    return friction_dissipated != 0. ? t + friction_dissipated : t;
  }
};
} // namespace hati

#endif
