#ifndef hati_model_response_quantities_h
#define hati_model_response_quantities_h

#include <string>

namespace hati
{
/**
 * A group of linear response quantities of a model that a
 * response-spectrum analysis combines (doc/theory.md 14.6): the values of
 * the group for a displacement U are linear in U (no gravity, no initial
 * state: the change a vibration brings), so that each mode's response is
 * the group's values for the mode shape, scaled.
 */
struct ResponseGroup
{
  /** The quantity of response_spectrum.csv, e.g. `girder_1.My`. */
  std::string name;
  /** Its unit (N, N m, Pa). */
  std::string unit;
  /**
   * The number of values: the stations of a section force (both ends of
   * each element of the member: combined one by one, the largest reported),
   * or 6 per point for a stress (stress).
   */
  unsigned int size = 0;
  /**
   * The values are stress tensors, 6 components per point (xx, yy, zz, xy,
   * yz, xz, Pa): each component is combined, then the von Mises stress of
   * the combined components (a conservative bound: the peaks of the
   * components do not occur at once) and its largest value over the points
   * is reported.
   */
  bool stress = false;
};
} // namespace hati

#endif
