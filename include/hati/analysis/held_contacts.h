#ifndef hati_analysis_held_contacts_h
#define hati_analysis_held_contacts_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <hati/model/discrete_system.h>

#include <string>
#include <vector>

namespace hati
{
using namespace dealii;

/**
 * The contacts of a system as a response-spectrum analysis holds them
 * (doc/theory.md 14.5, 14.6): every contact name with its rows; the rows
 * held, those with a zero gap (with the tangents of a closed frictional
 * contact: it sticks, A9) and, when the clearances are closed, the rows of
 * the two-sided contacts with a play (two opposite rows of one name with
 * positive gaps: the wheel flanges); and their multipliers (RS6): the
 * forces `mu` with `L^T mu = K U - F` for a displacement U in equilibrium
 * with the load F on the constrained space, the minimum-norm solution
 * `mu = (L L^T)^+ L (K U - F)` (a pair of opposite rows shares its force,
 * and the contact's force is their difference along its first row).
 */
class HeldContacts
{
public:
  /** The contacts of @p system, the clearances held if @p clearance_closed. */
  HeldContacts(const DiscreteSystem &system, const bool clearance_closed);

  /**
   * The clearance rows to hold besides the zero-gap rows (the held rows of
   * ModalProblem); empty when the clearances are open.
   */
  const std::vector<SparseRow> &clearance_rows() const { return held_clearance; }

  /**
   * The force of every contact name (N, along its first row's normal) for
   * the residual @p residual = K U - F (zero on fixed DoFs), appended to
   * @p forces.
   */
  void forces(const Vector<double> &residual, std::vector<double> &forces) const;

  /** The contact names (not the constraint rows), in the order of their first row. */
  std::vector<std::string> names;
  /** The rows of each name. */
  std::vector<std::vector<unsigned int>> members;
  /** Per name: a two-sided contact (two opposite rows). */
  std::vector<bool> two_sided;
  /** Zero-gap rows held and clearance rows held (-). */
  unsigned int n_closed = 0, n_clearance = 0;

private:
  /** Add @p row (its fixed DoFs left out) for the contact @p c with the sign @p s. */
  void add_row(const SparseRow &row, const std::size_t c, const double s);

  const std::vector<bool> &fixed;
  std::vector<SparseRow> rows, held_clearance;
  /** Per held row: its contact name (names.size() for a tangent) and sign. */
  std::vector<std::size_t> contact;
  std::vector<double> sign;
  /** (L L^T)^+. */
  FullMatrix<double> pseudo_inverse;
};

/** The dot product of two sparse rows. */
double row_product(const SparseRow &a, const SparseRow &b);
} // namespace hati

#endif
