#ifndef hati_model_bridge_crane_runway_h
#define hati_model_bridge_crane_runway_h

#include <deal.II/base/parameter_handler.h>

#include <hati/model/discrete_system.h>
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
 *
 * With `Runway = springs` each crane wheel k runs on a node `runway_k`
 * instead of the rigid ground: the runway girder, its column and bracket at
 * the wheel, with the mass `Runway mass per wheel` and the three
 * stiffnesses. The springs are a short vertical post `runway_post_k` (length
 * runway_post_length) from that node down to a clamped anchor, the node's
 * rotations held (a guided cantilever): axial stiffness E A / L = the
 * vertical one, 12 E I / L^3 = the lateral (Y) and the longitudinal (X)
 * ones, without shear deformation; a tenth of the runway's mass in the
 * post, the rest at the node (its lumped mass is the Runway mass per
 * wheel).
 * The wheel's contacts act between the wheel and that node; the spring
 * forces are the reactions `runway_reaction` (ReactionSpring).
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
  /** `rigid` (the ground) or `springs` (a runway node on springs per crane wheel). */
  std::string runway = "rigid";
  /** Per crane wheel (N/m): vertical, lateral (Y), longitudinal (X). */
  double vertical_stiffness = 2e8, lateral_stiffness = 5e7, longitudinal_stiffness = 5e8;
  /** The runway's mass that moves with each crane wheel (kg). */
  double mass_per_wheel = 500.;
  /**
   * The uplift above which a wheel's flanges pass over the rail head (m,
   * >= 0; 0: the flanges always engage, D1).
   */
  double flange_depth = 0.;
  /** The rail head width (m, > 0): a wheel over its flange derails beyond c + w / 2 (D2).
   */
  double rail_head_width = 0.055;
  /** The length of the springs' posts (m): any, the stiffnesses fix their sections. */
  static constexpr double runway_post_length = 0.5;

  /** Whether the crane wheels run on runway springs. */
  bool springs() const { return runway == "springs"; }

  /**
   * With springs: the runway node, post, anchor, mass and supports of the
   * crane wheel `cw<k>` of @p frame (the wheel's node exists), E and nu the
   * crane's material. Returns the node the wheel's contacts act against
   * (`runway_<k>`), empty for a rigid runway (the ground).
   */
  /**
   * With springs: the reaction springs of the four runway nodes (the
   * runway_reaction of summary.json: longitudinal X, lateral Y, vertical
   * positive pushing the runway down) into @p system.
   */
  void add_reaction_springs(DiscreteSystem &system) const;

  std::string add_runway_node(FrameDescription &frame,
                              const unsigned int k,
                              const double E,
                              const double nu) const;

  /** Whether the crane wheels (or the trolley wheels: @p trolley) are restrained. */
  bool restrained(const bool trolley) const
  {
    return uplift_restraints == "both" ||
           uplift_restraints == (trolley ? "trolley wheels" : "crane wheels");
  }

  /**
   * With a Flange depth: the flanges of the wheel @p wheel (its tread
   * contact @p wheel, its flange contact `<wheel>_lateral`) into @p frame
   * (FrameDescription::Flange, D1-D2); nothing without.
   */
  void add_flange(FrameDescription &frame, const std::string &wheel) const;

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
