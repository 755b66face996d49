#ifndef hati_model_wheel_flange_h
#define hati_model_wheel_flange_h

#include <array>
#include <string>
#include <vector>

namespace hati
{
/**
 * A wheel's flanges over its rail as the explicit integrator takes them
 * (doc/theory.md D1-D2, the force law `flanges`, FlangeEngagement): the
 * wheel's tread contact (one-sided, its gap the uplift `z`) and its two-sided
 * lateral (flange) contact, two rows of total clearance `c` whose gaps give
 * the lateral offset `y = (g_- - g_+) / 2` (D1). While `z` exceeds the
 * flange depth the flange rows do not act (they pass over the rail head);
 * a wheel whose flanges do not act and whose offset exceeds the derailment
 * offset `c + w / 2` (w the rail head width) has left its rail (D2).
 *
 * The model stores a std::vector of these in DiscreteSystem::law_data under
 * wheel_flanges_key; the row indices are those of DiscreteSystem::contacts
 * (a HATI subsystem keeps every contact row in its order, so they hold
 * there too).
 */
struct WheelFlange
{
  /** The wheel's name (its tread contact's), e.g. `crane_wheel_3`. */
  std::string wheel;
  /** The row of the tread contact in DiscreteSystem::contacts. */
  unsigned int tread_row = 0;
  /** The two rows of the flange contact (normals +n and -n, gaps c / 2). */
  std::array<unsigned int, 2> flange_rows{{0, 0}};
  /** The uplift above which the flange rows do not act (m, > 0). */
  double flange_depth = 0.;
  /** The lateral offset beyond which a wheel over its flange has left its rail (m). */
  double derailment_offset = 0.;
};

/** The key of DiscreteSystem::law_data that holds the std::vector<WheelFlange>. */
inline const std::string wheel_flanges_key = "flanges";
} // namespace hati

#endif
