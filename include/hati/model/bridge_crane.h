#ifndef hati_model_bridge_crane_h
#define hati_model_bridge_crane_h

#include <hati/model/bridge_crane_runway.h>
#include <hati/model/frame.h>
#include <hati/model/frame_description.h>
#include <hati/model/model.h>

#include <array>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace hati
{
/** The bridge crane's parameter subsection, as its messages name it. */
inline const std::string bridge_crane_where = "Model/Bridge crane/";

/**
 * A parametric double-girder overhead travelling (bridge) crane, generated
 * as a Frame description (doc/user_guide.md "Bridge crane"): two box girders
 * along Y (span) on two end carriages along X (runway), four crane wheels on
 * rigid runway rails (node-to-plane contacts, doc/theory.md 1.2), a trolley
 * frame with four wheels on the flexible girders (node-to-node contacts
 * against the girder node under each wheel) and the hoist mass at the
 * trolley's centre. Vertical contacts are one-sided with zero gap (closed in
 * the static state); lateral contacts are two-sided with the flange
 * clearance. X is the runway (long travel), Y the span (cross travel), Z up.
 *
 * The crane generates a FrameDescription (Parameters::frame()) and holds the
 * Frame built from it: the Model functions are the frame's, with the
 * crane's own summary entries, damping ratio, decomposition and wheel
 * contacts.
 */
class BridgeCrane : public Model
{
public:
  /** The `Model/Bridge crane` subsection. */
  struct Parameters
  {
    static void declare_parameters(ParameterHandler &prm);
    void parse_parameters(ParameterHandler &prm);

    /** Distance between the runway rails (m, along Y). */
    double span = 20.;
    /** Distance between the girders = trolley rail gauge (m, along X). */
    double girder_spacing = 2.;
    /** Distance between the two wheels of an end carriage (m, along X). */
    double end_carriage_wheelbase = 3.5;
    /** Distance between the trolley's wheels along a girder (m, along Y). */
    double trolley_wheelbase = 1.8;
    /** Position of the trolley's centre (and hoist) as a fraction of the span (-). */
    double trolley_position = 0.5;
    /** Sections, Model/Frame/Sections syntax after the name. */
    std::string girder_section, end_carriage_section, trolley_section;
    /** Young's modulus (Pa), Poisson's ratio (-), density (kg/m^3). */
    double E = 2.1e11, nu = 0.3, rho = 7850.;
    /** Trolley rail on each girder (kg/m), lumped on the girder nodes. */
    double rail_mass_per_metre = 25.;
    /** Trolley (crab) machinery (kg), a quarter on each trolley wheel node. */
    double trolley_mass = 3000.;
    /**
     * Lifted load and hook block (kg), on its rope (hoist = "rope") or
     * rigidly at the trolley's centre ("rigid").
     */
    double hoist_mass = 20350.;
    /** "rope" (a pendulum on Model/Frame/Ropes, R1) or "rigid". */
    std::string hoist = "rope";
    /** Hook point (trolley's centre) to load (m): the rope's rest length. */
    double rope_length = 6.;
    /** Axial stiffness of all falls (N/m); default_rope_stiffness(rope_length). */
    double rope_stiffness = default_rope_stiffness(6.);
    /** Total lateral play of a wheel between its flanges (m). */
    double flange_clearance = 0.02;
    /** Newton's restitution coefficient of every wheel contact (-). */
    double wheel_restitution = 0.;
    /** What holds the crane on its runway: the uplift restraints. */
    RunwayParameters runway;
    /**
     * "braked" (friction at the wheels: braked wheels hold, the others roll
     * along their rail), "free" (every wheel rolls along its rail, friction
     * across it) or "tied" (crane wheels fixed along X, trolley tied along
     * Y, no friction).
     */
    std::string travel = "braked";
    /** Travel = braked: "one per end carriage", "all" or "none". */
    std::string braked_crane_wheels = "one per end carriage";
    /** Coulomb friction coefficient of the wheel contacts (-, A9). */
    double wheel_friction = 0.15;
    /** "contacts" (on the runway rails) or "pinned" (held in X, Y, Z: paper case). */
    std::string crane_wheels = "contacts";
    /**
     * Damping ratio (-) of a transient run when Time integration/Damping is
     * not set; 0: undamped.
     */
    double damping_ratio = 0.02;
    /**
     * `frequency range`: the ratio nearly constant over damping_band (A8,
     * N4); `Rayleigh`: reached at the first vertical and the first
     * horizontal mode.
     */
    std::string damping_type = "frequency range";
    /** The band (Hz) of frequency-range damping. */
    std::array<double, 2> damping_band = {{0.5, 30.}};
    /** Element lengths outside and inside the explicit zones (m). */
    double element_length = 1., explicit_element_length = 0.5;
    /** Length of girder / end carriage around each wheel meshed finely (m). */
    double explicit_zone_length = 1.;

    /**
     * `beam` (default) or `solid`: the girders as `box girder` solids with
     * trolley rails tied on their top flanges (bridge_crane_girders.cc).
     */
    std::string girder_model = "beam";
    /** Girder model = solid: in-plane element size of the plates (m). */
    double girder_element_size = 0.1;
    /** Girder model = solid: degree of the solid elements (-). */
    unsigned int girder_element_degree = 2;
    /** Girder model = solid: spacing of the transverse diaphragms (m; 0: none). */
    double girder_diaphragm_spacing = 2.;
    /** Girder model = solid: the trolley rail's section (Model/Frame/Sections syntax). */
    std::string rail_section;

    /**
     * Model/Bridge crane/Eccentricities: the crane wheels' contact points at
     * the runway rail head, the trolley rails' heads on the girders' top
     * flanges, the trolley frame and the hook point at their own heights,
     * each offset a short member joined to the axis by a rigid link
     * (bridge_crane_heights.cc); false: every mass and wheel on the member
     * axes, the results of the crane before the option.
     */
    bool eccentricities = true;
    /** Height of the end carriages' axis above the runway rail head (m). */
    double end_carriage_height = 0.5;

    /** The entries Eccentricities and End carriage height. */
    static void declare_heights(ParameterHandler &prm);
    /** Parse and check the entries of declare_heights(). */
    void parse_heights(ParameterHandler &prm);
    /**
     * The Flange depth below the girder height (the section's h; a general
     * section's 2 sqrt(Iy / A)): a one-line error naming the entry otherwise.
     */
    void check_flange_depth() const;
    /**
     * The height of the trolley wheels' contact points above the girder
     * axes (m): rail_height() without eccentricities; with them the rail
     * head, half the girder height plus trolley_rail_height for beam
     * girders, the rail beam's nodes (half the girder height) for solid
     * ones.
     */
    double rail_head_height() const;
    /** The height of the trolley frame above the girder axes (m). */
    double trolley_frame_height() const;
    /**
     * The mass of the offsets' members (kg, 0 without eccentricities): the
     * four crane wheel posts and, for beam girders, the four rail posts
     * (part of mass_bridge()) if @p bridge, else the four trolley wheel
     * posts (part of mass_trolley()).
     */
    double offset_mass(const bool bridge) const;

    /** The frame: nodes, members, sections, masses, supports, contacts. */
    FrameDescription frame() const;
    /** Whether the crane wheel @p k (1-4) is braked (Travel, Braked crane wheels). */
    bool crane_wheel_braked(const unsigned int k) const
    {
      return travel == "braked" &&
             (braked_crane_wheels == "all" ||
              (braked_crane_wheels == "one per end carriage" && (k == 1 || k == 3)));
    }
    /** The entries of Girder model = solid (bridge_crane_girders.cc). */
    static void declare_girder_model(ParameterHandler &prm);
    /** Parse and check the entries of declare_girder_model(). */
    void parse_girder_model(ParameterHandler &prm);
    /**
     * Girder model = solid: the girders as box-girder solids with their
     * diaphragms and a cut at each, the trolley rails as beams on their top
     * flanges tied at their nodes (B1), and the end carriages' joints tied
     * to the girders' end faces, added to @p f (its trolley-rail nodes
     * `rail_1` ... `rail_4` under the trolley wheels, as the beam girders').
     */
    void add_solid_girders(FrameDescription &f) const;
    /** Girder model = solid: the steel volume of one girder with its diaphragms (m^3). */
    double solid_girder_volume() const;
    /**
     * The height of the trolley rails' nodes above the girder axes (m): 0
     * for beam girders, the top flange's (half the girder height) for solid
     * ones.
     */
    double rail_height() const;
    /**
     * Girder model = solid: the radius (m) of the top flange tied to each
     * rail node: half the rail's foot, at least 3/4 of the element size.
     */
    double rail_tie_radius() const;
    /** Girders, end carriages and rails (kg). */
    double mass_bridge() const;
    /** Trolley frame, trolley mass and hoist mass (kg). */
    double mass_trolley() const;
  };

  /** The crane of @p parameters (its frame validated, FrameDescription::validate()). */
  explicit BridgeCrane(const Parameters &parameters);
  void build(const CommonModelParameters &common, DiscreteSystem &system) override;
  /** Model::select_part() for the crane and its frame. */
  void select_part(const std::vector<unsigned char> &cell_parts, const int part) override;
  void write_vtu(std::ostream &out, const VtuSnapshot &snapshot) const override;
  std::vector<Point<3>> cell_centres() const override;
  double size() const override { return frame.size(); }
  std::vector<std::string> cell_members() const override;
  bool has_members() const override { return true; }
  std::string results_table() const override;
  std::string section_forces_header() const override;
  void write_section_forces(std::ostream *out,
                            const double time,
                            const Vector<double> &U,
                            const Vector<double> *functional_values) const override;
  /** Frame::output_functionals(). */
  std::vector<SparseRow> output_functionals() const override
  {
    return frame.output_functionals();
  }
  /** Frame::section_force_dofs(). */
  std::vector<types::global_dof_index> section_force_dofs() const override
  {
    return frame.section_force_dofs();
  }
  /** Frame::response_groups(). */
  std::vector<ResponseGroup> response_groups() const override
  {
    return frame.response_groups();
  }
  /** Frame::response_values(). */
  void response_values(const Vector<double> &U,
                       std::vector<double> &values,
                       const bool own_weight = false) const override
  {
    frame.response_values(U, values, own_weight);
  }
  /** Frame::section_force_members() (the girders). */
  std::vector<std::string> section_force_members() const override
  {
    return frame.section_force_members();
  }
  /** Frame::response_envelope_files(). */
  std::vector<std::string> response_envelope_files() const override
  {
    return frame.response_envelope_files();
  }
  /** Frame::write_response_envelope(). */
  void write_response_envelope(const std::string &name,
                               const std::vector<std::vector<double>> &von_mises,
                               std::ostream &out) const override
  {
    frame.write_response_envelope(name, von_mises, out);
  }
  std::string description() const override;
  /** Frame::describe_dof(). */
  DofDescription describe_dof(const types::global_dof_index dof) const override
  {
    return frame.describe_dof(dof);
  }
  /** @name The frame's solid outputs (Girder model = solid), Frame's */
  /** @{ */
  std::vector<std::string> vtu_series() const override { return frame.vtu_series(); }
  void write_series_vtu(const std::string &series,
                        std::ostream &out,
                        const VtuSnapshot &snapshot) const override
  {
    frame.write_series_vtu(series, out, snapshot);
  }
  void update_envelopes(const double time, const Vector<double> &U) const override
  {
    frame.update_envelopes(time, U);
  }
  std::vector<std::string> envelope_files() const override
  {
    return frame.envelope_files();
  }
  void write_envelope_file(const std::string &name, std::ostream &out) const override
  {
    frame.write_envelope_file(name, out);
  }
  /** Frame::interface_rows(): the ties across HATI's interface. */
  std::vector<SparseRow> interface_rows() const override
  {
    return frame.interface_rows();
  }
  void complete_solution(Vector<double> &U) const override { frame.complete_solution(U); }
  void condense_force(Vector<double> &f) const override { frame.condense_force(f); }
  /** @} */

  /** Model/Bridge crane/Damping ratio, Damping type and Damping band. */
  DefaultDamping default_damping() const override;
  /**
   * `mass_bridge`, `mass_trolley` (kg), the frame's entries
   * (`section_force_envelope`) and `static_wheel_loads` (wheel contact name
   * -> vertical static force, N) from @p static_contact_forces.
   */
  SummaryEntries summary_entries(
      const std::map<std::string, double> &static_contact_forces) const override;

  /**
   * The trolley members and the cells of girder and end carriage whose
   * centres lie within half the `Explicit zone length` of a wheel (boxes
   * around the wheels' rail nodes), and the girder cells between the two
   * trolley wheels on it (one zone per girder: two interface nodes instead
   * of four, the interface problem G3' is 2/3 the size): the subdomain of
   * Method = HATI when `Model/Decomposition` is empty.
   */
  DecompositionParameters default_decomposition() const override;

  /** crane_wheel_1..4 and trolley_wheel_1..4 (the vertical contacts). */
  std::vector<std::string> wheel_contacts() const override;
  std::vector<std::string> members_without_stresses() const override
  {
    return frame.members_without_stresses();
  }
  std::string geometry_csv() const override { return frame.geometry_csv(); }
  bool member_stress(const std::string &member,
                     const std::array<double, 6> &forces,
                     double &normal,
                     double &von_mises) const override
  {
    return frame.member_stress(member, forces, normal, von_mises);
  }
  /** `<wheel>_lateral` of every wheel. */
  std::vector<std::string> wheel_lateral_contacts() const override;
  /**
   * The four crane wheels `crane_wheel_<i>` (with Crane wheels = contacts):
   * a braked wheel's friction tangents are X (the runway) and Y, a rolling
   * wheel's only Y (contact_tangent_directions()).
   */
  std::vector<RunwayWheel> runway_wheels() const override;

  /**
   * The four-fall wire rope of doc/crane_data.md section 11 (N/m): `4 E_r A_r
   * / L`, `E_r = 100 GPa`, `A_r = 0.583 d^2`, `d = 20 mm`, for a rope
   * length @p length (m).
   */
  static double default_rope_stiffness(const double length)
  {
    return 4. * 1.0e11 * 0.583 * 0.02 * 0.02 / length;
  }

  /**
   * Height of the trolley frame above the trolley wheels' contact points
   * (m): above the girder axes without eccentricities, above the rail heads
   * with them.
   */
  static constexpr double trolley_height = 0.5;
  /**
   * Height of the trolley rail (m) from the top flange to its head, with
   * Eccentricities and beam girders: the A55 crane rail's 65 mm (DIN 536,
   * the default Rail section of the solid girders).
   */
  static constexpr double trolley_rail_height = 0.065;

private:
  const Parameters crane;
  Frame frame;
};
} // namespace hati

#endif
