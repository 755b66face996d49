#ifndef hati_analysis_static_contacts_h
#define hati_analysis_static_contacts_h

#include <deal.II/lac/vector.h>

#include <hati/model/discrete_system.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace hati
{
using namespace dealii;

/**
 * The contact rows the static state holds closed (doc/theory.md 6): zero
 * initial gap and a free DoF in the row; the second of two opposite rows
 * (two-sided without clearance) is left to the first; the first row of a
 * two-sided pair with a clearance is held where it is (centred), unless it
 * was released (release()).
 */
struct ClosedContacts
{
  /** The closed rows, in the order of the contacts. */
  std::vector<unsigned int> closed;
  /** The first rows of two-sided pairs with a clearance, held where they are. */
  std::vector<unsigned int> centred;
  /** Per contact row: the closed row it is the opposite of, or -1. */
  std::vector<int> opposite;
  /** The centred rows released (free within their play), in release order. */
  std::vector<unsigned int> released;

  explicit ClosedContacts(const DiscreteSystem &system);

  /** Whether the closed row @p k is the first of a pair with a clearance. */
  bool is_centred(const unsigned int k) const;

  /** Stop holding the centred row @p k: its pair is free within its play. */
  void release(const unsigned int k);
};

/** Whether contact rows @p a and @p b are exact opposites (two-sided, no clearance). */
bool opposite_rows(const ContactRow &a, const ContactRow &b);

/**
 * A centred pair that the static load pushes to one side: its first row
 * and its multiplier (N).
 */
using PushedPair = std::pair<unsigned int, double>;

/**
 * The contact force per contact row (N) from the multipliers @p lambda of
 * the closed rows (solve_closed()): a bilateral pair in tension is carried
 * by its second row; throws if a unilateral contact is in tension. A
 * two-sided pair with a clearance that the load @p F pushes to a side is
 * recorded in @p pushed if given (push_message() otherwise thrown).
 */
std::vector<double> closed_contact_forces(const DiscreteSystem &system,
                                          const ClosedContacts &contacts,
                                          const std::vector<double> &lambda,
                                          const Vector<double> &F,
                                          std::vector<PushedPair> *pushed = nullptr);

/**
 * Whether a centred pair's multiplier @p lambda (N) pushes it to a side: above
 * 1e-9 of the largest multiplier @p largest and of the largest load
 * component @p load (round-off otherwise).
 */
inline bool pushes(const double lambda, const double largest, const double load)
{
  return std::abs(lambda) > 1e-9 * std::max(largest, load);
}

/**
 * The multiplier block of the inverse of the static saddle matrix `[K L^T;
 * L 0]` on the pushed centred rows (doc/theory.md 6): by Jacobi's identity
 * of complementary minors, `det` of the matrix without the rows of a set S
 * is `det [K L^T; L 0] det (A^-1)_SS`, so the rows of S may be released
 * together iff `(A^-1)_SS` is regular.
 */
struct PlayProbe
{
  /** The pushed centred rows (indices into ClosedContacts::closed). */
  std::vector<unsigned int> rows;
  /** `(A^-1)_SS` on them, row-major. */
  std::vector<double> block;

  /**
   * The largest subset of rows, taken in order, whose block is regular (a
   * pivot above 1e-8 of the largest diagonal entry): their contact rows
   * (ClosedContacts::closed of @p contacts).
   */
  std::vector<unsigned int> releasable(const ClosedContacts &contacts) const;
};

/** The one-line refusal of a pushed pair @p p. */
std::string push_message(const DiscreteSystem &system, const PushedPair &p);

/** Whether rows @p a and @p b are parallel on the free DoFs (the same constraint). */
bool parallel_rows(const SparseRow &a,
                   const SparseRow &b,
                   const std::vector<bool> &fixed);

/**
 * The tangent rows of the closed contacts with friction (not the pairs with
 * a clearance, which do not touch), appended to @p held with a zero
 * right-hand side: per closed row with friction, its index in `closed`,
 * the index of its first tangent row in @p held and their number (tangent
 * rows on fixed DoFs only, or parallel to a row held already, are left
 * out).
 */
std::vector<std::array<unsigned int, 3>>
sticking_tangents(const DiscreteSystem &system,
                  const ClosedContacts &contacts,
                  std::vector<const SparseRow *> &held,
                  std::vector<double> &held_rhs);

/**
 * Coulomb's cone at the sticking closed contacts (A9): `||lambda_t|| <= mu
 * |lambda_n|` with the multipliers @p lambda of solve_closed(); throws a
 * one-line error naming the first contact where the static state would
 * slide.
 */
void check_static_friction(const DiscreteSystem &system,
                           const ClosedContacts &contacts,
                           const std::vector<std::array<unsigned int, 3>> &sticking,
                           const std::vector<double> &lambda);
} // namespace hati

#endif
