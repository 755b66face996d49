#ifndef hati_time_rope_forces_h
#define hati_time_rope_forces_h

#include <deal.II/lac/vector.h>

#include <hati/model/rope.h>
#include <hati/time/force_law.h>

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
 * (minimum, maximum, time slack). A ForceLaw, registered as `ropes`
 * (summary.json `rope_tension`).
 */
class RopeForces : public ForceLaw
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

  /** The registration: an instance for a system with ropes. */
  static Registry<ForceLawFactory>::Entry registration();

  std::string name() const override { return "ropes"; }

  bool adds_forces() const override { return true; }

  /**
   * At t = 0: the tensions at @p U (`U_0`), the statistics from them, the
   * strain energy `Phi(U_0)`, and the rope forces added to @p f (N).
   */
  void start(const Vector<double> &U, Vector<double> &f) override;

  /**
   * One step: the tensions at @p U (`U_{n+1}`), `dt M^-1 F_r,n+1` added to
   * @p a (with @p dt_minv = `dt M^-1`), the work with the step's velocity
   * @p V (`V_{n+1/2}`) and time step @p dt, the statistics.
   */
  void step(const Vector<double> &U,
            const Vector<double> &V,
            const Vector<double> &dt_minv,
            const double dt,
            double *a) override;

  /** The rope strain energy as the balance books it, `Phi(U_0) - work` (J). */
  double stored_energy() const override { return initial_energy - current.work; }

  /** The translations of both ends of every rope (R1 is nonlinear in them). */
  std::vector<types::global_dof_index> nonlinear_dofs() const override;
  /**
   * `max_r 2 sqrt(3) k_r du / T_max,r`: the force `T e` of a rope is
   * Lipschitz in its chord with the constant `k` (the tangent is at most
   * `k I`, doc/theory.md 10.2, and a slack rope has none), ends moving by
   * at most @p du each change the chord by at most `2 sqrt(3) du`, and the
   * scale is the largest tension so far (infinite if a rope has not been
   * taut and @p du > 0).
   */
  double relative_force_change(const double du) const override;
  /** `F_r,n+1` of every rope, hook x, y, z, load x, y, z (held DoFs: 0). */
  void applied_force(double *f) const override;
  void add_superposed_work(const double work) override { current.work += work; }

  /**
   * 0: the ropes' bound `k (1/m_a + 1/m_b)` is part of the model's
   * `omega_max` bound already (rope_omega_squared_bound()).
   */
  double omega_squared_bound() const override { return 0.; }

  /** `Newmark` and `event-driven` refused, naming the first rope. */
  std::string refusal(const std::string &method) const override;

  void save(std::any &state) const override;
  void restore(const std::any &state) override;

  /**
   * `rope_tension`: per rope its least and largest tension (N) and the time
   * it was slack (s), and the same as a table on @p out.
   */
  void add_summary(SummaryEntries &summary, std::ostream &out) const override;

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
