#ifndef hati_time_maxwell_memory_h
#define hati_time_maxwell_memory_h

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <hati/time/energies.h>
#include <hati/time/frequency_range_damping.h>

#include <vector>

namespace hati
{
using namespace dealii;

/**
 * The memory variables of frequency-range damping (doc/theory.md, A8 for
 * CD-Lagrange, N4 for Newmark), shared by both integrators: one vector
 * `q_l` per Maxwell branch, their weighted sum `S = sum_l alpha_l q_l` (the
 * internal force is `K (U + S)`) and the energy bookkeeping of the branches.
 *
 * A step updates the memory with the velocity that is constant over it
 * (`V_{n+1/2}` in CD-Lagrange, `(U_{n+1} - U_n) / dt` in Newmark):
 * `q_l <- e_l q_l + tau_l (1 - e_l) V`, `e_l = exp(-dt / tau_l)`, exact
 * for that velocity. Branch `l` stores `1/2 alpha_l q_l.K q_l`; the energy
 * the branches take from the structure in a step is the work of their
 * force on the increment, `1/2 (U_{n+1} - U_n).K (S_n + S_{n+1})`, booked
 * by the integrator with add_work(); what they have dissipated is that work
 * minus what they store, so the balance closes to round-off.
 *
 * Without branches (the default) the object is inactive and holds nothing.
 */
class MaxwellMemory
{
public:
  /** The most branches one memory holds (the loops keep them on the stack). */
  static constexpr unsigned int max_branches = 8;

  /** No branches: inactive. */
  MaxwellMemory() = default;

  /**
   * The branches @p branches (at most max_branches, alpha_l >= 0, tau_l > 0 s) for the
   * time step
   * @p dt (s) on @p n_dofs DoFs, all memory variables zero (a relaxed
   * state). Without branches the object is inactive.
   */
  MaxwellMemory(const MaxwellBranches &branches, double dt, unsigned int n_dofs);

  /** Whether there is at least one branch. */
  bool active() const { return !alpha.empty(); }

  /** Number of branches. */
  unsigned int n_branches() const { return alpha.size(); }

  /** `sum_l alpha_l` (-): the explicit stable step is `(2/w_max)/sqrt(1 + sum alpha)`. */
  double alpha_sum() const;

  /**
   * `beta_s = sum_l alpha_l tau_l (1 - e_l) / dt` (-): `S_{n+1}` is
   * `history() + beta_s (U_{n+1} - U_n)` (N4), so Newmark adds
   * `beta_s beta DT^2 K` to its effective matrix.
   */
  double stiffness_factor() const;

  /** All memory variables (and S) to zero, the branch work too. */
  void reset();

  /**
   * The memory update of one step with the velocity @p v (m/s) that is
   * constant over it: `q_l <- e_l q_l + tau_l (1 - e_l) v`, then
   * `S = sum_l alpha_l q_l`. One pass over the vectors.
   */
  void update(const Vector<double> &v);

  /** `S = sum_l alpha_l q_l` (m) after the last update(). */
  const Vector<double> &sum() const { return S; }

  /**
   * `h = sum_l alpha_l e_l q_l` (m): the part of `S_{n+1}` known before the
   * step (N4).
   */
  void history(Vector<double> &h) const;

  /** Stored energy of the branches, `1/2 sum_l alpha_l q_l.K q_l` (J), with @p K. */
  double stored_energy(const SparseMatrix<double> &K) const;

  /**
   * With branches, book them in @p e (A8): `damping_stored` the stored
   * energy with @p K, and the branch work less it added to `dissipated`.
   */
  void add_energies(Energies &e, const SparseMatrix<double> &K) const;

  /** Add @p work (J), the work of the branch force on a step's increment. */
  void add_work(const double work) { branch_work += work; }

  /** Work taken by the branches since t = 0 (J). */
  double work() const { return branch_work; }

  /** The memory vectors q_l (m), one per branch: snapshots of the state. */
  const std::vector<Vector<double>> &memory() const { return q; }

  /** Set the memory vectors (a snapshot) and recompute S; @p work: the branch work (J).
   */
  void set_memory(const std::vector<Vector<double>> &memory, double work);

  /**
   * Change each q_l in place with `change(l, q_l)` (one call per branch),
   * then recompute S, keeping the branch work: the coupling's
   * superposition of the unit-ramp response and its macro-step map (G3').
   */
  template <typename Change> void modify_memory(const Change &change)
  {
    if (!active())
      return;
    for (unsigned int l = 0; l < q.size(); ++l)
      change(l, q[l]);
    sum_branches();
  }

private:
  /** S = sum_l alpha_l q_l (weighted_sum()). */
  void sum_branches();
  /** @p out = sum_l weight_l q_l, summed in the branches' order, in one pass. */
  void weighted_sum(const double *weight, Vector<double> &out) const;

  std::vector<double> alpha, decay, gain;
  std::vector<Vector<double>> q;
  Vector<double> S;
  double dt = 0.;
  std::vector<double> tau;
  double branch_work = 0.;
};
} // namespace hati

#endif
