#ifndef hati_time_frictional_contacts_h
#define hati_time_frictional_contacts_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <hati/contact/condensed_cluster.h>
#include <hati/contact/friction_solver.h>
#include <hati/model/discrete_system.h>

#include <vector>

namespace hati
{
using namespace dealii;

/**
 * Coulomb friction in CD-Lagrange (A9, doc/theory.md A9): the clusters of
 * active contacts that hold a frictional contact are solved here by
 * nonsmooth Gauss-Seidel (solve_frictional_cluster()) instead of the LCP of
 * A5, which the frictionless clusters keep unchanged. Holds the tangential
 * impulses of the last step, the friction work and the solver's counts.
 *
 * The friction work is booked like the contact work (doc/theory.md E1):
 * the impulse of a step times the mean of the tangential velocities before
 * and after it, `lambda_t . (u_t,n+1/2 + u_t,n+3/2) / 2`, in two halves
 * (the second at the next step, when the velocity after it is final).
 */
class FrictionalContacts
{
public:
  /** Friction for the contact rows @p contacts (kept by reference). */
  explicit FrictionalContacts(const std::vector<ContactRow> &contacts);

  /** Whether a contact has friction (otherwise nothing here is used). */
  bool any() const { return with_friction; }

  /** Whether the cluster @p cluster (contact indices) holds a frictional contact. */
  bool frictional(const std::vector<unsigned int> &cluster) const;

  /**
   * Start the contact update of a step: book the first half of the work of
   * the last step's tangential impulses with @p v_after (its velocity after
   * them, V_{n+1/2}) and clear the impulses and states.
   */
  void begin_step(const Vector<double> &v_after);

  /**
   * Solve the cluster @p cluster (A9): its Delassus matrix over the normal
   * and tangent rows with @p inverse_mass, `q = L V_free + e L V_{n+1/2}`
   * for the normal rows (@p v_before = V_{n+1/2}) and `T V_free` for the
   * tangent rows; with @p prescribed every row is an equality (the linear
   * response of a prescribed active set, sticking, G3') except the tangent
   * rows of the contacts flagged in @p sliding (one flag per contact, or
   * nullptr), which are left out: the response of a sliding contact
   * without the change of its friction impulse (G3', the matrix of the
   * corrections of a redone macro step). @p v (V_free)
   * becomes V_{n+3/2}; the normal impulses go to @p lambda.
   */
  void solve(const std::vector<unsigned int> &cluster,
             const Vector<double> &inverse_mass,
             const Vector<double> &v_before,
             const bool prescribed,
             const std::vector<bool> *sliding,
             Vector<double> &v,
             std::vector<double> &lambda);

  /** The second half of the work of this step's tangential impulses (@p v_before =
   * V_{n+1/2}). */
  void end_step(const Vector<double> &v_before);

  /** Tangential impulse of contact @p k in the last step, per tangent row (N s). */
  double tangential_impulse(const unsigned int k, const unsigned int t) const
  {
    return tangential[2 * k + t];
  }
  /**
   * Set the tangential impulse of contact @p k in the last step, tangent row
   * @p t, to @p value (N s): the coupling's superposition (G3', A9).
   */
  void
  set_tangential_impulse(const unsigned int k, const unsigned int t, const double value)
  {
    tangential[2 * k + t] = value;
  }
  /** `||lambda_t||` of contact @p k in the last step (N s). */
  double tangential_impulse_norm(const unsigned int k) const;
  /**
   * The state of contact @p k in the last step (open, stick or slip); a
   * frictionless contact outside a frictional cluster is `slip` while it
   * has an impulse (@p impulse), `open` otherwise.
   */
  FrictionState state(const unsigned int k, const double impulse) const;

  /**
   * The friction record of the last step for the outputs: @p tangential
   * (two per contact, N s), @p slip the slip velocity `||T_k V||` (m/s) of
   * each contact that is not open (0 if open or frictionless) with @p V =
   * V_{n+3/2}, @p states (state(), with the normal impulses @p impulses).
   * No allocation once the vectors have their sizes.
   */
  void sample(const Vector<double> &V,
              const std::vector<double> &impulses,
              std::vector<double> &tangential,
              std::vector<double> &slip,
              std::vector<FrictionState> &states) const;

  /** Work of the friction impulses since t = 0 (J), <= 0. */
  double work() const { return friction_work; }
  /** Add @p w (J) to the friction work (the coupling's superposition). */
  void add_work(const double w) { friction_work += w; }
  /** Largest number of Gauss-Seidel sweeps of a cluster so far. */
  unsigned int max_sweeps() const { return sweeps_max; }
  /** Number of cluster solutions that did not converge (counted, never silent). */
  unsigned long unconverged() const { return n_unconverged; }

  /** What a step changes (CDLagrange::Snapshot). */
  struct Record
  {
    std::vector<double> tangential;
    std::vector<FrictionState> states;
    std::vector<char> in_cluster;
    double work = 0.;
  };
  void save(Record &record) const;
  void restore(const Record &record);

private:
  /** Half the work of the step's tangential impulses at velocity @p v (E1, A9). */
  void add_half_work(const Vector<double> &v);

  const std::vector<ContactRow> &contacts;
  bool with_friction = false;
  FrictionSolverControl control;
  /** Two entries per contact (unused ones zero). */
  std::vector<double> tangential;
  std::vector<FrictionState> states;
  std::vector<char> in_friction_cluster;
  double friction_work = 0.;
  unsigned int sweeps_max = 0;
  unsigned long n_unconverged = 0;
  // work space of solve()
  std::vector<const SparseRow *> rows;
  std::vector<unsigned int> first;
  std::vector<double> mu;
  std::vector<bool> bilateral;
  std::vector<FrictionState> cluster_states;
  /** q and the impulses of a cluster, per number of rows (W: cached_clusters). */
  struct WorkSpace
  {
    Vector<double> q, r;
  };
  std::vector<WorkSpace> work_space;
  /**
   * The Delassus matrix of each cluster with the condensation of its links
   * (CondensedLinks), keyed by the cluster's first contact: constant while
   * the cluster's rows (its contacts, and which have their tangent rows:
   * `mu`) and the inverse mass are, so formed once (formed every step they
   * cost a third of the braked crane's step with true heights).
   */
  struct CachedCluster
  {
    std::vector<unsigned int> cluster;
    std::vector<double> mu;
    const Vector<double> *inverse_mass = nullptr;
    FullMatrix<double> W;
    CondensedLinks links;
    /** W^-1 for a prescribed active set (the ramp responses, G3'), once valid. */
    FullMatrix<double> W_inverse;
    bool inverted = false;
  };
  std::vector<CachedCluster> cached_clusters;
};
} // namespace hati

#endif
