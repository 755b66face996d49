#include <deal.II/base/utilities.h>

#include <hati/model/bridge_crane.h>
#include <hati/model/frame_parser.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

namespace hati
{
namespace
{

/** Largest Young's modulus (Pa) and density (kg/m^3) of the Material. */
constexpr double max_young_modulus = 1e13, max_density = 1e5;
/** Largest mass of the girders, end carriages and rails (kg, mass_bridge()). */
constexpr double max_structure_mass = 1e8;

double section_area(const std::string &text, const std::string &entry)
{
  return parse_frame_section(text, bridge_crane_where + entry).A;
}

/**
 * Ranges of a crane's section: its dimensions (m: b, h and the plate
 * thicknesses), its areas (m^2), its second moments and torsion constant
 * (m^4), and its radii of gyration sqrt(I / A) and sqrt(J / 2 A) (m):
 * beyond them a member is so soft (a girder of 20 m under its load deflects
 * by kilometres), so stiff or so unlike a beam beside the rest of the
 * crane that its stiffness matrix is singular to round-off (measured on the
 * default crane: a 1 cm square girder, A = 40 m^2 with I = 1e3 m^4, A =
 * 1 m^2 with I = 1e-8 m^4 were reported "singular"; the corners of these
 * ranges solve).
 */
constexpr std::array<double, 2> section_dimension_range = {{1e-3, 5.}},
                                section_area_range = {{1e-4, 1.}},
                                section_inertia_range = {{1e-8, 10.}},
                                radius_of_gyration_range = {{1e-3, 5.}};

/**
 * Check the section @p text of the entry @p entry (the Model/Frame/Sections
 * syntax, parse_frame_section()) and that its dimensions and properties lie
 * in the ranges above; a one-line error naming the entry, the value and the
 * range.
 */
void check_section(const std::string &text, const std::string &entry)
{
  const FrameSection s =
      parse_frame_section(text, bridge_crane_where + entry); // the syntax first
  const std::vector<std::string> values = Utilities::split_string_list(text, ',');
  const bool general = Utilities::trim(values[0]) == "general";
  const auto refuse = [&](const std::string &name,
                          const double x,
                          const std::string &unit,
                          const std::string &what,
                          const std::array<double, 2> &range)
  {
    std::ostringstream m;
    m << bridge_crane_where << entry << ": " << name << " = " << x << " " << unit
      << (general ? "" : " (of " + text + ")")
      << " is outside the range of a crane section's " << what << ", " << range[0]
      << " to " << range[1] << " " << unit;
    AssertThrow(false, ExcMessage(m.str()));
  };
  const auto in = [](const double x, const std::array<double, 2> &range)
  { return x >= range[0] && x <= range[1]; };
  if (!general)
  {
    const std::vector<std::string> names = {"b", "h", "t_web", "t_flange"};
    for (unsigned int i = 1; i < values.size() && i <= names.size(); ++i)
    {
      const double x = Utilities::string_to_double(Utilities::trim(values[i]));
      if (!in(x, section_dimension_range))
      {
        std::ostringstream m;
        m << bridge_crane_where << entry << ": " << names[i - 1] << " = "
          << Utilities::trim(values[i])
          << " m is outside the range of a crane section's dimensions, "
          << section_dimension_range[0] << " to " << section_dimension_range[1] << " m";
        AssertThrow(false, ExcMessage(m.str()));
      }
    }
  }
  if (!in(s.A, section_area_range))
    refuse("A", s.A, "m^2", "areas", section_area_range);
  using Property = std::pair<const char *, double>;
  const Property shear[] = {{"Asy", s.shear_area_y}, {"Asz", s.shear_area_z}};
  for (const auto &[name, x] : shear)
    if (general && x != 0. && !in(x, section_area_range))
      refuse(name, x, "m^2", "areas (or 0: no shear deformation)", section_area_range);
  const Property inertia[] = {{"Iy", s.Iy}, {"Iz", s.Iz}, {"J", s.J}};
  for (const auto &[name, x] : inertia)
  {
    if (!in(x, section_inertia_range))
      refuse(
          name, x, "m^4", "second moments and torsion constant", section_inertia_range);
    // radius of gyration sqrt(I / A), polar sqrt(J / 2 A)
    const bool polar = name[0] == 'J';
    const double r = std::sqrt((polar ? 0.5 : 1.) * x / s.A);
    if (!in(r, radius_of_gyration_range))
    {
      std::ostringstream m;
      m << bridge_crane_where << entry << ": " << name << " = " << x
        << " m^4 with A = " << s.A << " m^2" << (general ? "" : " (of " + text + ")")
        << " gives a "
        << (polar ? "polar radius of gyration sqrt(J / 2 A)" : "radius of gyration")
        << " of " << r << " m, outside the range of a crane section's, "
        << radius_of_gyration_range[0] << " to " << radius_of_gyration_range[1] << " m";
      AssertThrow(false, ExcMessage(m.str()));
    }
  }
}

/** The entries after the geometry, sections and material: the masses and the rope. */
void declare_masses(ParameterHandler &prm)
{
  prm.declare_entry(
      "Rail mass per metre",
      "25",
      Patterns::Double(0., 1e4),
      "Mass of the trolley rail on each girder (kg/m), from 0 to 1e4 kg/m, lumped on the "
      "girder nodes. Default 25 kg/m (light rail or 50 x 50 bar, 20-40 "
      "kg/m, doc/crane_data.md section 2). Diaphragms, walkway, drives (about "
      "+50 % of the plates) are not in the default model: add them here "
      "or to rho.");
  prm.declare_entry(
      "Trolley mass",
      "3000",
      Patterns::Double(0., 1e7),
      "Trolley (crab) machinery (kg), from 0 to 1e7 kg, a quarter on each trolley wheel "
      "node. Default 3 t: European compact double-rail crab for 20 t, 2-4 t "
      "(doc/crane_data.md section 4; a classic open-winch crab is 6-8 t).");
  prm.declare_entry(
      "Hoist mass",
      "20350",
      Patterns::Double(0., 1e7),
      "Lifted load and hook block (kg), from 0 to 1e7 kg: on its rope below the "
      "trolley's centre (Hoist = rope) or rigidly at the trolley's centre (Hoist = "
      "rigid). Default: the rated 20 t plus a 0.35 t hook block (doc/crane_data.md "
      "section 0).");
  prm.declare_entry(
      "Hoist",
      "rope",
      Patterns::Selection("rope|rigid"),
      "rope: the hoist mass hangs on a rope (Model/Frame/Ropes, R1: tension only, "
      "geometrically exact; a pendulum that also goes slack) from the trolley's centre "
      "(node hoist) at the node load, Rope length below it; rigid: the hoist mass sits "
      "at the trolley's centre (no pendulum: the paper's case). A rope needs "
      "CD-Lagrange or HATI (the trolley is explicit).");
  prm.declare_entry("Rope length",
                    "6",
                    Patterns::Double(0., 1e3),
                    "Hoist = rope: length from the hook point (trolley's centre) to the "
                    "load (m), > 0; the rope's rest length (gravity stretches it by "
                    "m g / k). Default 6 m: pendulum frequency sqrt(g / L) / (2 pi) = "
                    "0.2035 Hz.");
  prm.declare_entry(
      "Rope stiffness",
      "0",
      Patterns::Double(0., 1e12),
      "Hoist = rope: axial stiffness of the rope, all falls together "
      "(N/m); 0 (default): the four-fall wire rope of doc/crane_data.md "
      "section 11, k = 4 E_r A_r / L = 9.328e7 N m / L (d = 20 mm, metallic "
      "area 0.583 d^2, rope modulus E_r = 100 GPa): 1.555e7 N/m for L = 6 "
      "m.");
}

/** The wheel contacts, the damping and how the crane is held along its travel. */
void declare_contacts_and_damping(ParameterHandler &prm)
{
  prm.declare_entry(
      "Flange clearance",
      "0.02",
      Patterns::Double(0., 0.5),
      "Total lateral play of a wheel between its flanges (m), from 0 to 0.5 m, for "
      "the crane and the trolley wheels (two-sided contacts, +-c/2). "
      "Default 20 mm: CMAA practice 19-25 mm for bridge wheels, 15-30 mm "
      "in Europe (doc/crane_data.md section 5).");
  prm.declare_entry("Wheel restitution",
                    "0",
                    Patterns::Double(0., 1.),
                    "Newton's restitution coefficient of every wheel contact (-), in "
                    "[0, 1]. Default 0: plastic impact, the usual choice for "
                    "finite-element contact.");
  prm.declare_entry(
      "Damping ratio",
      "0.02",
      Patterns::Double(0., 1.),
      "Damping ratio zeta (-) of a transient run when Time integration/Damping "
      "is not set, with the Damping type: in [0, 0.3] for frequency range, "
      "[0, 1) for Rayleigh. 0: undamped. Default 0.02 (2 %, welded steel "
      "structure).");
  prm.declare_entry(
      "Damping type",
      "frequency range",
      Patterns::Selection("frequency range|Rayleigh"),
      "How the Damping ratio is applied when Time integration/Damping is not "
      "set. frequency range (default): nearly constant over the Damping band, "
      "three Maxwell branches proportional to K (A8, N4): the explicit critical "
      "step shrinks only by 1/sqrt(1 + sum alpha), about 0.92. Rayleigh: "
      "C = a0 M + a1 K reaching the ratio at the first mode dominated by "
      "vertical (Z) and the first dominated by horizontal (X or Y) effective "
      "mass, computed with the zero-gap contacts closed (the paper's case); its "
      "stiffness term divides the explicit critical step by 13 (HATI) to 27 "
      "(fully explicit) on the default crane.");
  prm.declare_entry("Damping band",
                    "0.5, 30",
                    Patterns::List(Patterns::Double(0.), 2, 2),
                    "Damping type = frequency range: lower and upper frequency (Hz) "
                    "of the band over which the damping ratio is nearly the Damping "
                    "ratio, 0 < lower < upper. Default 0.5-30 Hz: the band of crane "
                    "seismic response (rigid-body sway of the hoisted load to the "
                    "local girder modes; floor spectra rarely hold energy above 30 Hz).");
  prm.declare_entry(
      "Travel",
      "braked",
      Patterns::Selection("braked|free|tied"),
      "How the crane and the trolley are held along their travel (doc/user_guide.md "
      "3.4). braked (default): Coulomb friction (A9) with the Wheel friction "
      "coefficient at the wheel contacts; the Braked crane wheels hold in every "
      "direction of the rail's plane, the other crane wheels roll freely along the "
      "runway (X; friction only across it), the four trolley wheels are braked. "
      "free: every wheel rolls along its rail (crane wheels along X, trolley wheels "
      "along Y), friction only across it (then a static state along X and Y does "
      "not exist: use Initial state = given). tied: the crane wheels are held along "
      "the runway (X) by supports, even when lifted off, and the trolley wheels tied "
      "to their girder nodes along Y (two-sided contacts without clearance, "
      "trolley_wheel_<i>_travel); no friction (the paper's case, the results before "
      "friction).");
  prm.declare_entry("Braked crane wheels",
                    "one per end carriage",
                    Patterns::Selection("one per end carriage|all|none"),
                    "Travel = braked: which crane wheels are braked (the others roll "
                    "along the runway). one per end carriage (default: one driven and "
                    "braked wheel per end carriage, the usual central or twin drive): "
                    "crane_wheel_1 and crane_wheel_3; all; none (all roll).");
  prm.declare_entry("Wheel friction coefficient",
                    "0.15",
                    Patterns::Double(0., 2.),
                    "Coulomb friction coefficient mu (-) of the wheel contacts with "
                    "Travel = braked or free, from 0 to 2. Default 0.15, steel wheel "
                    "on steel rail (doc/crane_data.md section 12).");
  prm.declare_entry("Crane wheels",
                    "contacts",
                    Patterns::Selection("contacts|pinned"),
                    "contacts: the four crane wheels stand on the rigid runway rails "
                    "(one-sided vertical contacts crane_wheel_<i>, two-sided lateral "
                    "ones with the Flange clearance); pinned: they are held in X, Y and "
                    "Z (no crane wheel contact: the paper's case, where only the trolley "
                    "wheels can lift off).");
}

/** The element lengths and the explicit zones around the wheels. */
void declare_mesh(ParameterHandler &prm)
{
  prm.declare_entry("Explicit element length",
                    "0.5",
                    Patterns::Double(0., 200.),
                    "Largest element length inside the explicit zones around the wheels "
                    "(m), > 0 and at most 200 m. Default 0.5 m: half the Element length, "
                    "so that the zone "
                    "has a node between the wheel and the interface on each side. With "
                    "the stiffness part of the Rayleigh damping the explicit critical "
                    "step falls about with the square of this length (A7).");
  prm.declare_entry(
      "Element length",
      "1",
      Patterns::Double(0., 200.),
      "Largest element length outside the explicit zones and in the "
      "trolley frame (m), > 0 and at most 200 m. Default 1 m: 20 elements over a 20 m "
      "girder, enough for the envelope of its section forces.");
  prm.declare_entry("Explicit zone length",
                    "1",
                    Patterns::Double(0., 200.),
                    "Length of girder and of end carriage centred on each wheel that is "
                    "meshed with the Explicit element length (m), from 0 to 200 m and "
                    "not longer than a girder (the span). Method = HATI without "
                    "Model/Decomposition needs a length > 0: the zones are its explicit "
                    "subdomain, where the wheel contacts are.");
}
} // namespace

void BridgeCrane::Parameters::declare_parameters(ParameterHandler &prm)
{
  // defaults: a 20 t, 20 m span double-girder crane, doc/crane_data.md
  prm.declare_entry("Span",
                    "20",
                    Patterns::Double(1., 200.),
                    "Distance between the runway rails (m, along Y), from 1 to 200 m. "
                    "Default: the "
                    "20 t / 20 m reference crane (doc/crane_data.md section 0; spans "
                    "10.5-31.5 m in 3 m steps).");
  prm.declare_entry(
      "Girder spacing",
      "2",
      Patterns::Double(0., 50.),
      "Distance between the two girders = trolley rail gauge (m, along X), "
      "> 0, at most 50 m and < End carriage wheelbase. Default 2 m: trolley gauges are "
      "1.4-2.5 m, classic 20/5 t crabs about 2 m (doc/crane_data.md section 4, "
      "estimate).");
  prm.declare_entry(
      "End carriage wheelbase",
      "3.5",
      Patterns::Double(0., 50.),
      "Distance between the two wheels of an end carriage (m, along X), > "
      "Girder spacing and at most 50 m. Default 3.5 m: anti-skew rule wheelbase >= "
      "span/7 "
      "(2.9 m) and the IS 800 25 t / 16 m example (doc/crane_data.md section "
      "3).");
  prm.declare_entry("Trolley wheelbase",
                    "1.8",
                    Patterns::Double(0., 50.),
                    "Distance between the trolley's two wheels on one girder (m, along "
                    "Y), > 0, at most 50 m and shorter than the Span. Default 1.8 m "
                    "(range 1.2-2.5 m, doc/crane_data.md section 4, "
                    "estimate).");
  prm.declare_entry("Trolley position",
                    "0.5",
                    Patterns::Double(0., 1.),
                    "Position of the trolley's centre, where the hoist stands, as a "
                    "fraction of the span from the rail at Y = 0 (-); all trolley wheels "
                    "must lie strictly inside the span. Default 0.5 (mid-span: largest "
                    "girder deflection).");
  prm.declare_entry("Girder section",
                    "box, 0.46, 1.10, 0.006, 0.013",
                    Patterns::Anything(),
                    "Section of each girder, Model/Frame/Sections syntax after the name "
                    "(m). Default: welded box 1.10 m deep (L/h = 18), flanges 460 x 13 "
                    "mm, webs 6 mm: A = 248 cm^2, I_vertical = 4.8e-3 m^4 "
                    "(doc/crane_data.md section 1, estimate meeting the L/800 deflection "
                    "limit).");
  prm.declare_entry(
      "End carriage section",
      "box, 0.3, 0.5, 0.008, 0.012",
      Patterns::Anything(),
      "Section of each end carriage, Model/Frame/Sections syntax (m). "
      "Default: box 0.5 m high, 0.3 m wide, 8/12 mm plates (doc/crane_data.md "
      "section 3, estimate).");
  prm.declare_entry("Trolley section",
                    "box, 0.2, 0.3, 0.008, 0.010",
                    Patterns::Anything(),
                    "Section of the trolley frame members, Model/Frame/Sections syntax "
                    "(m). Default: box 0.3 x 0.2 m, 8/10 mm plates (estimate for a "
                    "welded crab frame; its mass, 0.64 t, is part of the trolley).");
  prm.declare_entry("Material",
                    "2.1e11, 0.3, 7850",
                    Patterns::List(Patterns::Double(), 3, 3, ","),
                    "E (Pa), nu (-), rho (kg/m^3) of every member: 0 < E <= 1e13 Pa, "
                    "-1 < nu < 0.5, 0 < rho <= 1e5 kg/m^3. Default: structural steel. "
                    "The girders and end carriages with their rails (mass_bridge) may "
                    "weigh at most 1e8 kg.");
  declare_masses(prm);
  declare_contacts_and_damping(prm);
  RunwayParameters::declare_parameters(prm);
  declare_mesh(prm);
  declare_girder_model(prm);
  declare_heights(prm);
}

void BridgeCrane::Parameters::parse_parameters(ParameterHandler &prm)
{
  auto positive = [&](const std::string &name, const bool allow_zero = false)
  {
    const double x = prm.get_double(name);
    AssertThrow(std::isfinite(x) && (allow_zero ? x >= 0. : x > 0.),
                ExcMessage(bridge_crane_where + name + ": expected a value " +
                           (allow_zero ? ">= 0" : "> 0") + ", got " + prm.get(name)));
    return x;
  };
  span = positive("Span");
  girder_spacing = positive("Girder spacing");
  end_carriage_wheelbase = positive("End carriage wheelbase");
  trolley_wheelbase = positive("Trolley wheelbase");
  trolley_position = prm.get_double("Trolley position");
  girder_section = prm.get("Girder section");
  end_carriage_section = prm.get("End carriage section");
  trolley_section = prm.get("Trolley section");
  const auto m =
      Utilities::string_to_double(Utilities::split_string_list(prm.get("Material"), ','));
  E = m[0];
  nu = m[1];
  rho = m[2];
  AssertThrow(E > 0. && E <= max_young_modulus && nu > -1. && nu < 0.5 && rho > 0. &&
                  rho <= max_density,
              ExcMessage(bridge_crane_where +
                         "Material: expected 0 < E <= 1e13 Pa, -1 < nu < 0.5, "
                         "0 < rho <= 1e5 kg/m^3, got " +
                         prm.get("Material")));
  rail_mass_per_metre = positive("Rail mass per metre", true);
  trolley_mass = positive("Trolley mass", true);
  hoist_mass = positive("Hoist mass", true);
  hoist = prm.get("Hoist");
  rope_length = positive("Rope length");
  rope_stiffness = positive("Rope stiffness", true);
  if (rope_stiffness == 0.)
  {
    rope_stiffness = default_rope_stiffness(rope_length);
    // the default stiffness is c / L: a too short rope is the length's fault,
    // the shortest length is c / k_max
    const double shortest = default_rope_stiffness(FrameDescription::max_rope_stiffness);
    if (hoist == "rope" && !(rope_stiffness <= FrameDescription::max_rope_stiffness))
    {
      std::ostringstream r;
      r << bridge_crane_where << "Rope length: " << prm.get("Rope length")
        << " m is too short for the default Rope stiffness 9.328e7 N m / L ("
        << rope_stiffness << " N/m, more than " << FrameDescription::max_rope_stiffness
        << " N/m): expected a length of at least " << shortest
        << " m, or give the Rope stiffness";
      AssertThrow(false, ExcMessage(r.str()));
    }
  }
  AssertThrow(hoist == "rigid" || hoist_mass > 0.,
              ExcMessage(bridge_crane_where +
                         "Hoist mass: expected > 0 with Hoist = rope (the load "
                         "on the rope), got " +
                         prm.get("Hoist mass")));
  flange_clearance = positive("Flange clearance", true);
  runway.parse_parameters(prm);
  wheel_restitution = prm.get_double("Wheel restitution");
  AssertThrow(wheel_restitution >= 0. && wheel_restitution <= 1.,
              ExcMessage(bridge_crane_where +
                         "Wheel restitution: expected a value in [0, 1], got " +
                         prm.get("Wheel restitution")));
  damping_ratio = prm.get_double("Damping ratio");
  damping_type = prm.get("Damping type");
  AssertThrow(std::isfinite(damping_ratio) && damping_ratio >= 0. &&
                  damping_ratio < (damping_type == "Rayleigh" ? 1. : 0.3 + 1e-15),
              ExcMessage(bridge_crane_where + "Damping ratio: expected a value in " +
                         (damping_type == "Rayleigh" ? "[0, 1)" : "[0, 0.3]") +
                         " with Damping type = " + damping_type + ", got " +
                         prm.get("Damping ratio")));
  const std::vector<std::string> band =
      Utilities::split_string_list(prm.get("Damping band"), ',');
  damping_band = {
      {Utilities::string_to_double(band[0]), Utilities::string_to_double(band[1])}};
  AssertThrow(damping_band[0] > 0. && damping_band[0] < damping_band[1] &&
                  std::isfinite(damping_band[1]),
              ExcMessage(bridge_crane_where +
                         "Damping band: expected 0 < lower < upper frequency (Hz), "
                         "got " +
                         prm.get("Damping band")));
  travel = prm.get("Travel");
  braked_crane_wheels = prm.get("Braked crane wheels");
  wheel_friction = prm.get_double("Wheel friction coefficient");
  crane_wheels = prm.get("Crane wheels");
  AssertThrow(crane_wheels == "contacts" || !runway.springs(),
              ExcMessage(bridge_crane_where +
                         "Runway = springs: the crane wheels are "
                         "held (Crane wheels = " +
                         crane_wheels +
                         "), not on the runway; set Crane wheels = contacts or Runway = "
                         "rigid"));
  AssertThrow(crane_wheels == "contacts" || !runway.restrained(false),
              ExcMessage(bridge_crane_where +
                         "Uplift restraints = " + runway.uplift_restraints +
                         ": the crane wheels are held (Crane wheels = " + crane_wheels +
                         "), so nothing lifts them; restrain the trolley wheels only or "
                         "set Crane wheels = contacts"));
  element_length = positive("Element length");
  explicit_element_length = positive("Explicit element length");
  explicit_zone_length = positive("Explicit zone length", true);

  AssertThrow(girder_spacing < end_carriage_wheelbase,
              ExcMessage(bridge_crane_where +
                         "Girder spacing: expected less than the End carriage "
                         "wheelbase (the girders sit between the wheels)"));
  if (!(trolley_wheelbase < span))
  {
    std::ostringstream t;
    t << bridge_crane_where << "Trolley wheelbase: " << trolley_wheelbase
      << " m is not shorter than the Span (" << span
      << " m): the trolley's wheels cannot stand between the rails";
    AssertThrow(false, ExcMessage(t.str()));
  }
  const double y1 = (trolley_position - 0.5 * trolley_wheelbase / span) * span,
               y2 = y1 + trolley_wheelbase;
  std::ostringstream s;
  s << bridge_crane_where
    << "Trolley position: the trolley is off the span: its wheels at y = " << y1
    << " and " << y2 << " m must lie strictly between the rails at 0 and " << span
    << " m";
  AssertThrow(y1 > 0. && y2 < span, ExcMessage(s.str()));
  std::ostringstream z;
  z << bridge_crane_where << "Explicit zone length: " << explicit_zone_length
    << " m is longer than a girder (Span = " << span << " m)";
  AssertThrow(explicit_zone_length <= span, ExcMessage(z.str()));
  // the longest member (a girder or an end carriage) divided by the shortest
  // element: at most max_elements_per_member elements (an element length in
  // the wrong unit would otherwise exhaust the memory or overflow the count)
  const double longest = std::max(span, end_carriage_wheelbase),
               shortest = std::min(element_length, explicit_element_length);
  if (!(longest / shortest <= max_elements_per_member))
  {
    std::ostringstream e;
    e << bridge_crane_where << "Element length, Explicit element length: " << shortest
      << " m gives more than " << max_elements_per_member
      << " elements along a member of " << longest << " m; use longer elements";
    AssertThrow(false, ExcMessage(e.str()));
  }
  // check the sections now (one-line errors naming the entry)
  check_section(girder_section, "Girder section");
  check_section(end_carriage_section, "End carriage section");
  check_section(trolley_section, "Trolley section");
  parse_girder_model(prm);
  parse_heights(prm);
  check_flange_depth();
  if (girder_model == "solid")
    check_section(rail_section, "Rail section");
  if (!(mass_bridge() <= max_structure_mass))
  {
    std::ostringstream b;
    b << bridge_crane_where
      << "Girder section, End carriage section, Material, Rail mass per metre: "
      << "the girders and end carriages would weigh " << mass_bridge()
      << " kg, more than " << max_structure_mass << " kg";
    AssertThrow(false, ExcMessage(b.str()));
  }
}

double BridgeCrane::Parameters::mass_bridge() const
{
  // solid girders: their diaphragms too
  const double girders = girder_model == "solid"
                             ? 2. * solid_girder_volume()
                             : 2. * section_area(girder_section, "Girder section") * span;
  const double m =
      rho * (girders + 2. * section_area(end_carriage_section, "End carriage section") *
                           end_carriage_wheelbase) +
      2. * rail_mass_per_metre * span;
  // the crane wheel and rail posts of the true heights
  return eccentricities ? m + offset_mass(true) : m;
}

double BridgeCrane::Parameters::mass_trolley() const
{
  // frame: two sides (wheelbase), two ends and the hoist beam (gauge)
  const double m = rho * section_area(trolley_section, "Trolley section") *
                       (2. * trolley_wheelbase + 3. * girder_spacing) +
                   trolley_mass + hoist_mass;
  // the trolley wheel posts of the true heights
  return eccentricities ? m + offset_mass(false) : m;
}

BridgeCrane::BridgeCrane(const Parameters &parameters)
    : crane(parameters), frame(parameters.frame())
{
}

void BridgeCrane::build(const CommonModelParameters &common, DiscreteSystem &system)
{
  frame.build(common, system);
  // Runway = springs: the spring forces, the loads on the building
  if (crane.crane_wheels == "contacts")
    crane.runway.add_reaction_springs(system);
}

void BridgeCrane::select_part(const std::vector<unsigned char> &cell_parts,
                              const int part)
{
  Model::select_part(cell_parts, part);
  frame.select_part(cell_parts, part);
}

void BridgeCrane::write_vtu(std::ostream &out, const VtuSnapshot &snapshot) const
{
  frame.write_vtu(out, snapshot);
}

std::vector<Point<3>> BridgeCrane::cell_centres() const { return frame.cell_centres(); }

std::vector<std::string> BridgeCrane::cell_members() const
{
  return frame.cell_members();
}

std::string BridgeCrane::results_table() const { return frame.results_table(); }

std::string BridgeCrane::section_forces_header() const
{
  return frame.section_forces_header();
}

void BridgeCrane::write_section_forces(std::ostream *out,
                                       const double time,
                                       const Vector<double> &U,
                                       const Vector<double> *functional_values) const
{
  frame.write_section_forces(out, time, U, functional_values);
}

DecompositionParameters BridgeCrane::default_decomposition() const
{
  DecompositionParameters d;
  const double S = crane.span, a = 0.5 * crane.girder_spacing,
               w = 0.5 * crane.end_carriage_wheelbase,
               hz = 0.5 * crane.explicit_zone_length, yc = crane.trolley_position * S,
               y1 = yc - 0.5 * crane.trolley_wheelbase,
               y2 = yc + 0.5 * crane.trolley_wheelbase, eps = 1e-6 * S,
               z = 0.25 * trolley_height; // girders and end carriages lie at z = 0
  // the wheel contacts are explicit only inside the zones (no zone: the
  // subdomain would hold the trolley frame but not its wheels' rail nodes)
  AssertThrow(hz > 0.,
              ExcMessage(bridge_crane_where +
                         "Explicit zone length = 0: Method = HATI takes its "
                         "explicit subdomain from the zones around the wheels, "
                         "where the wheel contacts are; set a length > 0 (e.g. "
                         "1 m) or give the subdomain in Model/Decomposition"));
  // girder cells around the trolley wheels' rail nodes, and between
  // them: one zone per girder (two interface nodes instead of four)
  // (solid girders: the trolley rails' cells on the top flanges, not the
  // flanges' cells below them: every solid is implicit)
  const double zr = crane.rail_height(), zz = crane.girder_model == "solid" ? eps : z;
  for (const double x : {-a, a})
    d.boxes.push_back(
        {{x - eps, x + eps, y1 - hz - eps, y2 + hz + eps, zr - zz, zr + zz}});
  // end carriage cells around the crane wheels (at the carriage ends),
  // when they are contacts
  for (const double y : crane.crane_wheels == "contacts" ? std::vector<double>{0., S}
                                                         : std::vector<double>{})
    for (const double x : {-w, w})
      d.boxes.push_back({{x - hz - eps, x + hz + eps, y - eps, y + eps, -z, z}});
  d.members = {"trolley_side_1a",
               "trolley_side_1b",
               "trolley_side_2a",
               "trolley_side_2b",
               "trolley_end_1",
               "trolley_end_2",
               "trolley_beam_1",
               "trolley_beam_2"};
  // the true heights' posts where the wheels are explicit (add_offsets())
  for (unsigned int k = 1; k <= 4 && crane.eccentricities; ++k)
  {
    const std::string n = std::to_string(k);
    d.members.push_back("trolley_wheel_post_" + n);
    if (crane.girder_model != "solid")
      d.members.push_back("rail_post_" + n);
    if (crane.crane_wheels == "contacts")
      d.members.push_back("crane_wheel_post_" + n);
  }
  // the runway nodes with their wheels
  for (unsigned int k = 1;
       k <= 4 && crane.runway.springs() && crane.crane_wheels == "contacts";
       ++k)
    d.members.push_back("runway_post_" + std::to_string(k));
  return d;
}

std::vector<std::string> BridgeCrane::wheel_contacts() const
{
  std::vector<std::string> names;
  for (const char *kind : {"crane_wheel_", "trolley_wheel_"})
    for (unsigned int k = 1; k <= 4; ++k)
      names.push_back(kind + std::to_string(k));
  return names;
}

DefaultDamping BridgeCrane::default_damping() const
{
  DefaultDamping d;
  d.ratio = crane.damping_ratio;
  d.type = crane.damping_type;
  d.lower_frequency = crane.damping_band[0];
  d.upper_frequency = crane.damping_band[1];
  d.entries = "Model/Bridge crane/Damping ratio, Damping type and Damping band";
  return d;
}

std::string BridgeCrane::description() const
{
  std::ostringstream s;
  s << "bridge crane: span " << crane.span << " m, trolley at " << crane.trolley_position
    << " of the span, bridge " << crane.mass_bridge() << " kg, trolley "
    << crane.mass_trolley() << " kg; " << frame.description();
  return s.str();
}

SummaryEntries BridgeCrane::summary_entries(
    const std::map<std::string, double> &static_contact_forces) const
{
  SummaryEntries entries = {{"mass_bridge", crane.mass_bridge()},
                            {"mass_trolley", crane.mass_trolley()}};
  for (const auto &e : frame.summary_entries(static_contact_forces))
    entries.push_back(e);
  if (!static_contact_forces.empty())
  {
    SummaryValue loads = SummaryValue::object();
    for (const char *kind : {"crane_wheel_", "trolley_wheel_"})
      for (unsigned int k = 1; k <= 4; ++k)
      {
        const std::string name = kind + std::to_string(k);
        const auto it = static_contact_forces.find(name);
        if (it != static_contact_forces.end())
          loads.set(name, it->second);
      }
    entries.emplace_back("static_wheel_loads", loads);
  }
  return entries;
}
} // namespace hati
