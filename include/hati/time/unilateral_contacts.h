#ifndef hati_time_unilateral_contacts_h
#define hati_time_unilateral_contacts_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <hati/contact/lcp_solver.h>
#include <hati/model/discrete_system.h>
#include <hati/time/force_law.h>
#include <hati/time/frictional_contacts.h>

#include <array>
#include <vector>

namespace hati
{
/**
 * A contact that was in the active set of the previous step (or closed at
 * the start) stays in it while its gap is up to this (m), against
 * closed_gap_tolerance for a contact that closes (A4, doc/theory.md 1.1).
 * The coupling moves a resting contact more than round-off: the 3D crane
 * with its Craig-Bampton reduced girders (doc/theory.md 12.2) moved a
 * trolley wheel's tied rail node by 1.3e-12 m in its first micro step from
 * rest (the interface forces balance the reduced part to some 1e-9
 * relative), which opened that contact under its 59 kN static load: the rail
 * node jumped at 0.19 m/s and the wheel ended 7.7 um inside it. Being in
 * the active set does not hold a contact closed (the LCP lets it separate
 * with a zero impulse); it only stops it approaching, here 1 nm short of
 * touching. Contacts that close keep the 1e-12 m of closed_gap_tolerance, so
 * impacts are caught at the same step as before.
 */
constexpr double held_gap_tolerance = 1e-9;

using namespace dealii;

/**
 * The contact rows of a system as CD-Lagrange resolves them, a ForceLaw
 * registered as `contacts`: the unilateral contacts (A4-A6: the active set
 * from the position-level gaps, the clusters of active rows that share a
 * free DoF, one LCP `w = W lambda + q` per cluster with the Delassus matrix
 * `W = L M^-1 L^T`, Newton's restitution in `q`), their Coulomb friction
 * (A9: a cluster holding a frictional contact goes to FrictionalContacts'
 * nonsmooth Gauss-Seidel), the bilateral rows (A5 as an equality) and the
 * constraint rows of ties and rigid links (B1, ContactRow::constraint),
 * which the models append after the contacts and which share their
 * clusters (separate clusters would change the order of the sums). Holds
 * the gaps, impulses, active flags, the contact work (E1) and the friction
 * record.
 *
 * One instance per CD-Lagrange, also for a system without contact rows
 * (then it does nothing), so that the integrator's contact accessors always
 * have one to read.
 */
class UnilateralContacts : public ForceLaw
{
public:
  /** The registration: an instance for every system. */
  static Registry<ForceLawFactory>::Entry registration();

  /** The rows of @p system (kept by reference, with its fixed flags). */
  explicit UnilateralContacts(const DiscreteSystem &system);

  std::string name() const override { return "contacts"; }

  bool has_rows() const override { return !contacts.empty(); }

  /**
   * The gaps at @p U (`U_0`), the check that every row acts on a DoF with
   * mass (@p dt_minv = `dt M^-1`) and which rows share a free DoF (their
   * tangent rows included with friction): the A5 clusters.
   */
  void start_rows(const Vector<double> &U, const Vector<double> &dt_minv) override;

  /**
   * (A4)-(A6), A9: the active set from the gaps at @p U (`U_{n+1}`) or the
   * prescribed one, the clusters' LCPs or Gauss-Seidel with @p inverse_mass,
   * `q = L V_free + e L V_{n+1/2}` (@p v_before = `V_{n+1/2}`); @p v
   * (`V_free`) becomes `V_{n+3/2} = V_free + M^-1 L^T lambda`; the contact
   * and friction work (E1).
   */
  void apply_impulses(const Vector<double> &U,
                      const Vector<double> &v_before,
                      const Vector<double> &inverse_mass,
                      Vector<double> &v) override;

  /** The contact work and the friction dissipation (E1, A9). */
  void add_energies(Energies &e) const override;

  /**
   * The rows' columns of the outputs (one per row of system.contacts): the
   * gaps, impulses and active flags of the last step, the normal velocities
   * `L_k V` at @p V (not in a sample of every step, LawSample::every_step),
   * and with friction (A9) the tangential impulses, slip
   * velocities and states (FrictionalContacts::sample()).
   */
  void sample(const Vector<double> &V, LawSample &s) const override;

  /**
   * The contacts' outputs (ContactOutput: statistics per contact name,
   * their summary.json entries, `contact_episodes.csv`), or nullptr for a
   * system without contacts (its rows only those of ties and rigid links).
   */
  std::unique_ptr<LawOutput> make_output(const LawOutputContext &context) const override;

  /**
   * `Newmark` refused when the system has rows (contacts, or those of ties
   * and rigid links); `event-driven` when a contact has friction or is
   * bilateral (refusal_of()).
   */
  std::string refusal(const std::string &method) const override;
  /** The refusal of @p method for the rows @p contacts (empty: none). */
  static std::string refusal_of(const std::vector<ContactRow> &contacts,
                                const std::string &method);

  /** Gaps, impulses, active flags, contact work and the friction record. */
  void save(std::any &state) const override;
  void restore(const std::any &state) override;

  /** Contact gaps g_k(U_n) (m), the order of system.contacts. */
  const std::vector<double> &gaps() const { return gap; }
  /** Impulses lambda_k of the last step (N s); zero for inactive contacts. */
  const std::vector<double> &impulses() const { return lambda; }
  /** Whether contact k was active in the last step (A4). */
  const std::vector<bool> &active() const { return is_active; }
  /** Coulomb friction (A9): the tangential impulses, states and counts. */
  const FrictionalContacts &friction() const { return frictional_contacts; }
  FrictionalContacts &friction() { return frictional_contacts; }

  /**
   * With a non-null @p pattern (one flag per contact), the flagged
   * contacts are active whatever their gap and (A5) is solved as
   * equalities, the tangent rows of frictional contacts too unless flagged
   * in @p sliding (CDLagrange::CouplingView::prescribe_active_set()).
   */
  void prescribe_active_set(const std::vector<bool> *pattern,
                            const std::vector<bool> *sliding = nullptr)
  {
    prescribed = pattern;
    prescribed_sliding = sliding;
  }
  /**
   * With a non-null @p pattern (one flag per contact), the flagged contacts
   * are active and the others not, whatever their gaps; (A5) is solved as
   * usual on that set (CDLagrange::CouplingView::freeze_activation()).
   * prescribe_active_set() takes precedence.
   */
  void freeze_activation(const std::vector<bool> *pattern) { frozen = pattern; }
  /**
   * With a non-null @p off (one flag per contact, owned by the caller), a
   * flagged contact is out of the active set whatever its gap (ForceLaw::
   * gate_rows() of another law, e.g. a flange over its rail, D1); a
   * prescribed or frozen active set is taken as it is.
   */
  void switch_off(const std::vector<bool> *off) { switched_off = off; }
  /** Set the gap (m) and impulse (N s) of contact @p k (the superposition, G3'). */
  void set_state(const unsigned int k, const double gap_k, const double impulse)
  {
    gap[k] = gap_k;
    lambda[k] = impulse;
  }
  /** Add @p work (J) to the contact work. */
  void add_work(const double work) { contact_work += work; }

private:
  /** What save() keeps. */
  struct State
  {
    std::vector<double> gap, lambda;
    std::vector<bool> is_active, was_closed;
    double contact_work = 0.;
    FrictionalContacts::Record friction;
  };

  const DiscreteSystem &system;
  const std::vector<ContactRow> &contacts;
  std::vector<double> gap, lambda;
  std::vector<bool> is_active;
  /**
   * Contacts in the active set of the previous step, or closed at the start
   * (gap within closed_gap_tolerance): they stay in it up to
   * held_gap_tolerance.
   */
  std::vector<bool> was_closed;
  std::vector<std::vector<unsigned int>> coupled_with;
  /** Active set imposed by prescribe_active_set() (nullptr: from the gaps). */
  const std::vector<bool> *prescribed = nullptr;
  /** Active set imposed by freeze_activation() (nullptr: from the gaps). */
  const std::vector<bool> *frozen = nullptr;
  /** Rows switched off by another law (switch_off(); nullptr: none). */
  const std::vector<bool> *switched_off = nullptr;
  /**
   * With a prescribed active set: the frictional contacts taken as sliding
   * (their tangent rows left out, FrictionalContacts::solve()), or nullptr.
   */
  const std::vector<bool> *prescribed_sliding = nullptr;
  /** Work space of apply_impulses(), reused from step to step. */
  std::vector<unsigned int> active_list, cluster;
  std::vector<bool> clustered;
  std::vector<const ContactRow *> cluster_rows;
  // the LCP of a cluster of each size: q, lambda, bilateral flags
  std::vector<Vector<double>> lcp_q, lcp_lambda;
  /**
   * The Delassus block `L M^-1 L^T` of a cluster (contacts, ties, rigid
   * links), constant while the cluster's rows and the inverse mass are: the
   * rows are (linear gaps), so it is formed when the cluster first appears
   * (formed every step, the blocks of the rails' ties with a trolley wheel
   * on them took 77 % of the fully explicit solid crane's step).
   */
  struct DelassusBlock
  {
    std::vector<unsigned int> cluster;
    const Vector<double> *inverse_mass = nullptr;
    FullMatrix<double> W;
    /** W^-1 for a prescribed active set (the ramp responses, G3'), once valid. */
    FullMatrix<double> W_inverse;
    bool inverted = false;
    /** Its equalities eliminated for the LCP (ties with a contact on them, A5). */
    BilateralElimination elimination;
  };
  /** The last two clusters that began with a row, keyed by that row. */
  struct DelassusBlocks
  {
    std::array<DelassusBlock, 2> entries;
    unsigned int next = 0;
  };
  std::vector<DelassusBlocks> delassus_blocks;
  std::vector<std::vector<bool>> lcp_bilateral;
  double contact_work = 0.;
  /** The clusters with friction (A9) and their record. */
  FrictionalContacts frictional_contacts;
};
} // namespace hati

#endif
