#ifndef hati_time_rope_forces_h
#define hati_time_rope_forces_h

#include <deal.II/lac/vector.h>

#include <hati/model/rope.h>

#include <array>
#include <vector>

namespace hati
{
using namespace dealii;

/**
 * The ropes of a system as CD-Lagrange applies them (R1, doc/theory.md 10):
 * the rope forces at `U_{n+1}` join the external force of the update
 * (A2-A3), their work on the step is the trapezoid
 * `1/2 (U_{n+1} - U_n) . (F_r,n + F_r,n+1)` (so that the energy balance E1
 * closes to round-off; the rope energy is booked in the internal energy as
 * `Phi(U_0) - work`), and the tension statistics of every rope are kept
 * (minimum, maximum, time slack).
 */
class RopeForces
{
public:
  /** What a step changes (CDLagrange::Snapshot). */
  struct State
  {
    /** The force F_r,n on the six DoFs of each rope (N; hook, then load). */
    std::vector<std::array<double, 6>> force;
    /** The tension of each rope at U_n (N). */
    std::vector<double> tension;
    /** Per rope: the smallest and largest tension (N) and the time slack (s). */
    std::vector<double> min_tension, max_tension, slack_time;
    /** Work of the rope forces on the structure since t = 0 (J). */
    double work = 0.;
  };

  /** The ropes of the system (they must outlive this object). */
  explicit RopeForces(const std::vector<Rope> &ropes) : ropes(ropes) {}

  /** Whether there is a rope. */
  bool active() const { return !ropes.empty(); }

  /**
   * At t = 0: the tensions at @p U (`U_0`), the statistics from them, the
   * strain energy `Phi(U_0)`, and the rope forces added to @p f (N).
   */
  void start(const Vector<double> &U, Vector<double> &f);

  /**
   * One step: the tensions at @p U (`U_{n+1}`), `dt M^-1 F_r,n+1` added to
   * @p a (with @p dt_minv = `dt M^-1`), the work with the step's velocity
   * @p V (`V_{n+1/2}`) and time step @p dt, the statistics.
   */
  void step(const Vector<double> &U,
            const Vector<double> &V,
            const Vector<double> &dt_minv,
            const double dt,
            double *a);

  /** The rope strain energy as the balance books it, `Phi(U_0) - work` (J). */
  double stored_energy() const { return initial_energy - current.work; }

  const State &state() const { return current; }
  void set_state(const State &state) { current = state; }

  const std::vector<Rope> &elements() const { return ropes; }

private:
  /** F_r on the six DoFs of rope @p r at @p U into @p force; returns T (N). */
  double force_of(const unsigned int r,
                  const Vector<double> &U,
                  std::array<double, 6> &force) const;

  const std::vector<Rope> &ropes;
  State current;
  double initial_energy = 0.;
};
} // namespace hati

#endif
