#ifndef hati_time_interface_problem_h
#define hati_time_interface_problem_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <hati/contact/sparse_rows.h>
#include <hati/model/decomposition.h>
#include <hati/time/cd_lagrange.h>
#include <hati/time/column_matrices.h>
#include <hati/time/newmark.h>

#include <vector>

namespace hati
{
using namespace dealii;

/**
 * The interface problem of the HATI coupling (doc/theory.md 9.1-9.5,
 * G3'-G4): the Lagrange multipliers Lambda (interface forces, N) act as
 * `C_E^T Lambda` on the explicit subdomain and `C_I^T Lambda` on the
 * implicit one, the rows of Decomposition::rows: `C_E = +1`, `C_I = -1` on
 * the DoFs of each interface pair, `C_E = +1` on a tied beam node's DoF and
 * `C_I` minus its B1 row on the solid face (G3'', doc/theory.md 11.3).
 *
 * It owns what does not depend on the explicit response: the rows C_E,
 * C_I, the implicit part of the interface matrix
 * `H_I = gamma DT C_I M_eff^-1 C_I^T`, and the link columns
 * `M_eff^-1 C_I^T` (G4). For the explicit part H_E of a unit-ramp response
 * (RampSuperposition) it inverts `H = H_E + H_I` once (invert()); a macro
 * step then costs one product with H^-1 (correction()), and the link one
 * product with the columns (link()).
 */
class InterfaceProblem
{
public:
  /**
   * The link columns `M_eff^-1 C_I^T` (n_I x n_G) are kept when they have
   * at most this many entries (2e7 doubles, 160 MB): the link (G4) is then
   * a product instead of a solve with M_eff.
   */
  static constexpr double max_link_column_entries = 2e7;

  /**
   * The rows of the interface pairs of @p decomposition, H_I and the link
   * columns from the effective matrix of @p implicit, whose step is DT and
   * whose Newmark parameter is @p gamma (-). Both must outlive this object.
   */
  InterfaceProblem(const Decomposition &decomposition,
                   const Newmark &implicit,
                   const double gamma);

  /** Number of interface DoF pairs n_G. */
  unsigned int size() const { return rows_E.size(); }
  /**
   * The rows C_E (+1 on the explicit DoF of each pair; a sparse row for a
   * tie to an explicit solid, G3''): the micro steps add `C_E^T Lambda_j`.
   */
  const std::vector<SparseRow> &explicit_rows() const { return rows_E; }

  /**
   * (G3') @p H_inverse = `(H_E + H_I)^-1` for the explicit part @p H_E
   * (n_G x n_G, `C_E V_ramp`: the integer-time velocity of the unit ramps),
   * inverted once.
   */
  void invert(const FullMatrix<double> &H_E, DenseColumns &H_inverse) const;

  /**
   * Lambda_0 (N) from the acceleration continuity at t = 0,
   * `(C_E M_E^-1 C_E^T + C_I M_I^-1 C_I^T) Lambda_0 = -(C_E a_E + C_I a_I)`
   * (doc/theory.md 9.5), written to @p lambda and applied to the initial
   * states of @p explicit_integrator and @p implicit; @p lambda is left
   * unchanged if the accelerations are already continuous. With @p given
   * (a restart's multiplier, Decomposition::initial_multiplier) that one
   * is applied instead of solved for.
   */
  void initial_multiplier(CDLagrange &explicit_integrator,
                          Newmark &implicit,
                          Vector<double> &lambda,
                          const Vector<double> *given = nullptr) const;

  /** After the free implicit step (G1): keeps `C_I V^I_free` (m/s). */
  void set_free_implicit_velocity(const Newmark &implicit);

  /**
   * (G3') the correction @p delta (N) of the guess @p lambda_guess with
   * which the micro steps ran, from the velocity continuity at the
   * macro-step end: `H delta = -(C_E V^E + C_I V^I_free + H_I lambda_guess)`,
   * @p v_end = `C_E V^E` the integer-time explicit velocity (m/s).
   */
  void correction(const DenseColumns &H_inverse,
                  const Vector<double> &v_end,
                  const Vector<double> &lambda_guess,
                  Vector<double> &delta);

  /**
   * The continuity residual `r = -(C_E V^E + C_I V^I_free + H_I lambda)`
   * (m/s) of micro steps run with the full multiplier @p lambda (redone
   * macro steps); returns max_k |r_k| and sets @p scale to the largest
   * |C_E V^E|, |C_I V^I_free|.
   */
  double residual(const Vector<double> &v_end,
                  const Vector<double> &lambda,
                  Vector<double> &r,
                  double &scale) const;

  /** @p x = H^-1 @p x (one product, the work vector of the problem). */
  void solve(const DenseColumns &H_inverse, Vector<double> &x);

  /**
   * (G4) the link of @p implicit with `Lambda_{n+m}` = @p lambda_end:
   * `A_link = M_eff^-1 C_I^T Lambda_{n+m}`. Adds the implicit interface
   * work `1/2 dU_I . C_I^T (Lambda_n + Lambda_{n+m})` (G5, J) to @p work,
   * pair by pair, and raises @p max_jump to the velocity jump
   * `|C_E V^E + C_I V^I|` (m/s) at t_{n+m}.
   */
  void link(Newmark &implicit,
            const Vector<double> &lambda_start,
            const Vector<double> &lambda_end,
            const Vector<double> &v_end,
            double &work,
            double &max_jump);

private:
  const Decomposition &decomposition;
  std::vector<SparseRow> rows_E, rows_I;
  /** gamma DT C_I M_eff^-1 C_I^T (G3'). */
  DenseColumns H_I;
  /** M_eff^-1 C_I^T, if it fits in max_link_column_entries (empty: solves). */
  DenseColumns link_columns;
  /** C_I V^I_free of the current macro step (set_free_implicit_velocity()). */
  Vector<double> free_jump;
  /** Work vectors (no allocation per macro step). */
  Vector<double> implicit_guess, solve_work, u_old;
  mutable Vector<double> implicit_part;
  Vector<double> link_force, link_acceleration;
};
} // namespace hati

#endif
