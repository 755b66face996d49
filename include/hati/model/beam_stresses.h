#ifndef hati_model_beam_stresses_h
#define hati_model_beam_stresses_h

#include <deal.II/base/tensor.h>
#include <deal.II/lac/vector.h>

#include <hati/base/summary_value.h>
#include <hati/model/frame_description.h>
#include <hati/model/frame_element.h>
#include <hati/model/frame_section_forces.h>

#include <array>
#include <string>
#include <vector>

namespace hati
{
/**
 * The stresses of a beam section under its section forces (doc/theory.md
 * 15.1, S1-S3), at the extreme fibres:
 *  - the normal stress (S1) at the corners `(+-c_y, +-c_z)`,
 *    `|N| / A + |My| c_z / Iy + |Mz| c_y / Iz` (Pa);
 *  - the shear stress (S2): a box's walls carry the shear flow of the
 *    torque, `T / (2 A_m t)` (Bredt, A_m = b_m h_m on the wall centre
 *    lines), and the shear forces as the mean over their walls, `Vz / (2 h_m
 *    t_web)` in the webs, `Vy / (2 b_m t_flange)` in the flanges; a
 *    rectangle, at the middle of its sides, the largest torsional stress
 *    (Roark, `T (3 a + 1.8 c) / (8 a^2 c^2)` with the half sides a >= c) and
 *    the largest shear of the parabola, `1.5 V / A`; a `general` section
 *    `|T| max(c_y, c_z) / J` (exact for a circle, above the wall stress of an
 *    open thin-walled section) plus the larger of `|Vy| / Asy`, `|Vz| / Asz`
 *    (`/ A` without shear areas);
 *  - the von Mises stress (S3) `sqrt(sigma^2 + 3 tau^2)`: of a box at its
 *    corners with the shear of the more loaded wall there, of a rectangle the
 *    largest of its corners (no shear) and the middles of its sides (the
 *    normal stress of one bending plane with the shear there), of a
 *    `general` section the largest normal and shear stresses together (a
 *    bound).
 */
struct BeamSectionStress
{
  /** Largest |normal stress| (Pa), largest shear stress (Pa), von Mises (Pa). */
  double normal = 0., shear = 0., von_mises = 0.;
};

/**
 * The section of every member of @p frame whose stresses are computed, in
 * order (pointers into @p frame, which must outlive them); nullptr for a
 * member made rigid by a rigid link between its end nodes (a post of a
 * true height).
 */
std::vector<const FrameSection *> stressed_member_sections(const FrameDescription &frame);

/** Whether @p section has stresses: a rectangle, a box, or `general` with c_y, c_z. */
bool has_fibre_distances(const FrameSection &section);

/**
 * The stresses of @p section under the section forces @p s (N, Vy, Vz in N;
 * T, My, Mz in N m; local axes), S1-S3. Requires has_fibre_distances().
 */
BeamSectionStress beam_section_stress(const FrameSection &section,
                                      const std::array<double, 6> &s);

/**
 * The envelope of the stresses of every beam member whose section has
 * them (has_fibre_distances()), from its section forces at both ends of
 * every element at each row it is given (the rows of `Output/Section force
 * interval`): per member the largest normal and von Mises stresses (Pa)
 * with the station along the member (m) and the time (s); summary.json
 * `beam_stresses` and the results table.
 */
class BeamStressEnvelope
{
public:
  /**
   * @p member_names the frame's members, @p member_sections the section of
   * each (nullptr or without fibre distances: no stresses).
   */
  BeamStressEnvelope(const std::vector<std::string> &member_names,
                     const std::vector<const FrameSection *> &member_sections);

  /** Whether any member has stresses. */
  bool enabled() const { return !members.empty(); }

  /**
   * Account for the state @p U (constraints distributed) at time @p time
   * (s) of the frame of @p cells under @p gravity (m/s^2).
   */
  void update(const double time,
              const Vector<double> &U,
              const std::vector<FrameCell> &cells,
              const Tensor<1, 3> &gravity);

  /**
   * `beam_stresses`: `{member: {"max_normal_stress": {"value", "x",
   * "time"}, "max_von_mises": {...}}}` (Pa, m, s); none if not enabled().
   */
  SummaryEntries summary_entries() const;

  /** The members' largest stresses as table lines (empty if not enabled()). */
  std::string results_table() const;

private:
  struct Peak
  {
    double value = 0., x = 0., time = 0.;
  };
  struct Member
  {
    unsigned int index;
    std::string name;
    const FrameSection *section;
    Peak normal, von_mises;
  };
  std::vector<Member> members;
  /** Per frame member: its entry in members, or -1. */
  std::vector<int> entry_of_member;
};
} // namespace hati

#endif
