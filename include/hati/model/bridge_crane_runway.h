#ifndef hati_model_bridge_crane_runway_h
#define hati_model_bridge_crane_runway_h

#include <deal.II/base/parameter_handler.h>

#include <hati/model/frame_description.h>

#include <string>

namespace hati
{
using namespace dealii;

/**
 * What holds a bridge crane on its runway (`Model/Bridge crane`, doc/user_guide.md
 * "The crane on its runway", issue #55): the seismic restraints against
 * uplift, the lugs or clips under the rail head that stop a wheel lifting
 * more than their clearance (ASME NOG-1 Type I, KTA 3902).
 *
 * A restrained wheel gets a one-sided contact `<wheel>_restraint` of the
 * existing kind (A4-A6): its normal points down (from the clip to the
 * wheel), its gap is the Restraint clearance and its restitution the
 * Restraint restitution; a crane wheel's clip is fixed to the ground (it
 * moves with the base), a trolley wheel's to its rail node. Open in the
 * static state, the modal and the response-spectrum analyses (a positive
 * gap), so that only a lifting wheel meets it.
 */
struct RunwayParameters
{
  /** Declare the entries in the current subsection (Model/Bridge crane). */
  static void declare_parameters(ParameterHandler &prm);
  /** Parse and check them (one-line errors naming the entry). */
  void parse_parameters(ParameterHandler &prm);

  /** `none`, `crane wheels`, `trolley wheels` or `both`. */
  std::string uplift_restraints = "none";
  /** The uplift at which a restraint stops its wheel (m, > 0). */
  double restraint_clearance = 0.01;
  /** Newton's restitution coefficient of the restraint contacts (-, [0, 1]). */
  double restraint_restitution = 0.;

  /** Whether the crane wheels (or the trolley wheels: @p trolley) are restrained. */
  bool restrained(const bool trolley) const
  {
    return uplift_restraints == "both" ||
           uplift_restraints == (trolley ? "trolley wheels" : "crane wheels");
  }

  /**
   * Add the restraint contacts of the wheel @p wheel (its node @p node; the
   * node it runs on, @p rail, empty: the ground) to @p frame.
   */
  void add_restraint(FrameDescription &frame,
                     const std::string &wheel,
                     const std::string &node,
                     const std::string &rail) const;
};
} // namespace hati

#endif
