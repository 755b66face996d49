#include <deal.II/base/utilities.h>

#include <hati/base/input_file.h>
#include <hati/base/names.h>
#include <hati/model/model.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace hati
{
void CommonModelParameters::declare_parameters(ParameterHandler &prm)
{
  prm.enter_subsection("Loading");
  prm.declare_entry("Gravity",
                    "0, 0, -9.81",
                    Patterns::List(Patterns::Double(), 3, 3, ","),
                    "Gravity acceleration vector gx, gy, gz (m/s^2), global axes. The 1D "
                    "bar uses its x component.");
  prm.declare_entry(
      "Base acceleration",
      "0, 0, 0",
      Patterns::List(Patterns::Double(), 3, 3, ","),
      "Uniform base (support) acceleration a_g, x, y, z (m/s^2), applied as a "
      "step from 'Base acceleration start' in the relative formulation "
      "F = -M r a_g (algorithms.md section 4): displacements are relative "
      "to the moving base.");
  prm.declare_entry("Base acceleration start",
                    "0",
                    Patterns::Double(0.),
                    "Time at which the base acceleration step is applied (s).");
  for (const char *d : {"X", "Y", "Z"})
    prm.declare_entry(
        std::string("Accelerogram ") + d,
        "",
        Patterns::Anything(),
        std::string("Recorded base acceleration along global ") + d +
            ": a PEER NGA .AT2 file (units of g; 1e-6 s <= DT <= 1 s, NPTS <= "
            "1e8) or a two-column 'time value' text file (units below; at most 1e8 "
            "samples), path relative to the current directory, a regular file "
            "(not a FIFO or a device); empty: none. Applied in the relative formulation "
            "F = -M r a_g(t), "
            "linearly interpolated, zero outside the record, added to the Base "
            "acceleration step.");
  prm.declare_entry(
      "Accelerogram units",
      "g",
      Patterns::Selection("g|m/s^2|cm/s^2"),
      "Units of the values of two-column accelerogram files (.AT2 files are "
      "always in g; g = 9.80665 m/s^2).");
  prm.declare_entry(
      "Accelerogram scale factor",
      "1",
      Patterns::Double(-100., 100.),
      "Factor applied to every accelerogram value (-), from -100 to 100, e.g. to "
      "scale a record to a design peak ground acceleration.");
  prm.declare_entry(
      "Excited members",
      "",
      Patterns::Anything(),
      "Frames: names of the members whose inertia the base acceleration loads, "
      "'member, member, ...' (e.g. girder_1, girder_2 of a bridge crane): F = -M_S r "
      "a_g is assembled from these members' elements and the point masses on their "
      "nodes only (a point mass at a joint counts if one of its members is "
      "excited), as when a record of the motion of those members is applied to "
      "them. Empty: the whole model (the usual relative formulation). Gravity is "
      "not affected. Other models: must be empty.");
  prm.leave_subsection();

  prm.enter_subsection("Contact");
  prm.declare_entry("Name",
                    "contact",
                    Patterns::Anything(),
                    "Name of the contact, used in contacts.csv: letters, digits, "
                    "'_', '-' and '.' only.");
  prm.declare_entry("Restitution coefficient",
                    "0",
                    Patterns::Double(0., 1.),
                    "Newton's restitution coefficient e (-), 0 <= e <= 1: the normal "
                    "velocity after an impact is -e times the one before. 0 (plastic "
                    "impact) is the usual choice for finite-element contact.");
  prm.declare_entry("Initial gap",
                    "0",
                    Patterns::Double(0.),
                    "Distance between the body and the rigid obstacle at t = 0 (m). Used "
                    "by the bar and the solid; the point mass uses its Initial height.");
  prm.leave_subsection();
}

void CommonModelParameters::parse_parameters(ParameterHandler &prm)
{
  prm.enter_subsection("Loading");
  const auto g =
      Utilities::string_to_double(Utilities::split_string_list(prm.get("Gravity"), ','));
  for (unsigned int d = 0; d < 3; ++d)
    gravity[d] = g[d];
  const auto a = Utilities::string_to_double(
      Utilities::split_string_list(prm.get("Base acceleration"), ','));
  for (unsigned int d = 0; d < 3; ++d)
    base_acceleration[d] = a[d];
  base_acceleration_start = prm.get_double("Base acceleration start");
  accelerogram_files = {{Utilities::trim(prm.get("Accelerogram X")),
                         Utilities::trim(prm.get("Accelerogram Y")),
                         Utilities::trim(prm.get("Accelerogram Z"))}};
  // refuse a FIFO or a device before any work (stat, never open)
  for (unsigned int d = 0; d < 3; ++d)
    if (!accelerogram_files[d].empty())
      require_regular_file(accelerogram_files[d],
                           std::string("Loading/Accelerogram ") + "XYZ"[d],
                           "accelerogram");
  accelerogram_units = prm.get("Accelerogram units");
  accelerogram_scale = prm.get_double("Accelerogram scale factor");
  excited_members.clear();
  for (const std::string &m :
       Utilities::split_string_list(prm.get("Excited members"), ','))
    if (!Utilities::trim(m).empty())
      excited_members.push_back(Utilities::trim(m));
  prm.leave_subsection();

  prm.enter_subsection("Contact");
  contact_name = prm.get("Name");
  check_name(contact_name, "Contact/Name", "contact");
  restitution = prm.get_double("Restitution coefficient");
  initial_gap = prm.get_double("Initial gap");
  prm.leave_subsection();
}

void DecompositionParameters::declare_parameters(ParameterHandler &prm)
{
  prm.declare_entry(
      "Explicit region",
      "",
      Patterns::Anything(),
      "Boxes of the explicit subdomain of Method = HATI, 'x_min, x_max[, y_min, "
      "y_max, z_min, z_max]; ...' (m, global axes; with two values a box bounds x "
      "only, as for the bar). A cell whose centre lies in a box is explicit "
      "(CD-Lagrange, step dt); the other cells are implicit (Newmark, step m dt). "
      "Ignored by single-domain methods.");
  prm.declare_entry(
      "Explicit members",
      "",
      Patterns::Anything(),
      "Frames: names of the members of the explicit subdomain, 'member, member, "
      "...' (members of a mesh file by their physical name), and of solids to put "
      "there (Model/Frame/Solids; by default solids are implicit); added to the "
      "cells of the Explicit region. Ignored by single-domain methods.");
  prm.declare_entry(
      "Implicit reduction",
      "none",
      Patterns::Selection("none|Craig-Bampton"),
      "Method = HATI: 'none' integrates the implicit subdomain on all its DoFs; "
      "'Craig-Bampton' on reduced coordinates (doc/theory.md 12.1, C1): the "
      "interface DoFs (6 per tie to a solid face) and DoFs with a time-dependent "
      "point load as boundary DoFs, plus the fixed-interface normal modes up to the "
      "Reduction cutoff frequency. For a large, linear implicit part (solid "
      "girders): one dense solve of the reduced size per macro step.");
  prm.declare_entry("Reduction cutoff frequency",
                    "150",
                    Patterns::Double(0., 1e9),
                    "Implicit reduction = Craig-Bampton: every fixed-interface "
                    "normal mode up to this frequency is kept (Hz, > 0).");
  prm.declare_entry("Reduction modal damping ratio",
                    "",
                    Patterns::Anything(),
                    "Implicit reduction = Craig-Bampton: empty (default) damps the "
                    "reduced part with the run's damping (Time integration/Damping, "
                    "Rayleigh or frequency range, on the reduced matrices); a ratio "
                    "(-, 0 <= ratio < 1, e.g. 0.02) gives each mode of the reduced part "
                    "that damping ratio instead (modal damping, doc/theory.md 12.3; "
                    "rigid-body modes undamped).");
  prm.declare_entry("Reduction maximum modes",
                    "500",
                    Patterns::Integer(1, 100000),
                    "Implicit reduction = Craig-Bampton: at most this many "
                    "fixed-interface modes (-); a cut-off that needs more is "
                    "refused with the count it would need.");
}

void DecompositionParameters::parse_parameters(ParameterHandler &prm)
{
  boxes.clear();
  members.clear();
  for (const std::string &raw :
       Utilities::split_string_list(prm.get("Explicit region"), ';'))
  {
    const std::string item = Utilities::trim(raw);
    if (item.empty())
      continue;
    std::vector<double> v;
    for (const std::string &x : Utilities::split_string_list(item, ','))
    {
      char *end = nullptr;
      const std::string t = Utilities::trim(x);
      const double d = std::strtod(t.c_str(), &end);
      AssertThrow(!t.empty() && *end == '\0' && std::isfinite(d),
                  ExcMessage("Model/Decomposition/Explicit region: '" + t +
                             "' in the box '" + item + "' is not a number"));
      v.push_back(d);
    }
    AssertThrow(v.size() == 2 || v.size() == 6,
                ExcMessage("Model/Decomposition/Explicit region: the box '" + item +
                           "' has " + std::to_string(v.size()) +
                           " values, expected 2 (x_min, x_max) or 6 (x_min, x_max, "
                           "y_min, y_max, z_min, z_max)"));
    std::array<double, 6> box{{v[0],
                               v[1],
                               -std::numeric_limits<double>::infinity(),
                               std::numeric_limits<double>::infinity(),
                               -std::numeric_limits<double>::infinity(),
                               std::numeric_limits<double>::infinity()}};
    if (v.size() == 6)
      std::copy(v.begin(), v.end(), box.begin());
    for (unsigned int d = 0; d < 3; ++d)
      AssertThrow(box[2 * d] <= box[2 * d + 1],
                  ExcMessage("Model/Decomposition/Explicit region: the box '" + item +
                             "' has a minimum above its maximum"));
    boxes.push_back(box);
  }
  for (const std::string &m :
       Utilities::split_string_list(prm.get("Explicit members"), ','))
    if (!Utilities::trim(m).empty())
      members.push_back(Utilities::trim(m));
  implicit_reduction = prm.get("Implicit reduction");
  reduction_cutoff_frequency = prm.get_double("Reduction cutoff frequency");
  AssertThrow(reduction_cutoff_frequency > 0.,
              ExcMessage("Model/Decomposition/Reduction cutoff frequency must be > 0 "
                         "Hz (the fixed-interface modes kept), not 0"));
  reduction_maximum_modes = prm.get_integer("Reduction maximum modes");
  const std::string ratio = Utilities::trim(prm.get("Reduction modal damping ratio"));
  reduction_modal_damping_ratio.reset();
  if (!ratio.empty())
  {
    char *end = nullptr;
    const double value = std::strtod(ratio.c_str(), &end);
    AssertThrow(*end == '\0' && value >= 0. && value < 1.,
                ExcMessage("Model/Decomposition/Reduction modal damping ratio: '" +
                           ratio +
                           "' is not a damping ratio (a number >= 0 and < 1, e.g. "
                           "0.02), or leave it empty for the run's damping"));
    reduction_modal_damping_ratio = value;
  }
}

double Model::size() const
{
  const std::vector<Point<3>> centres = cell_centres();
  if (centres.empty())
    return 0.;
  Point<3> low = centres[0], high = centres[0];
  for (const auto &x : centres)
    for (unsigned int d = 0; d < 3; ++d)
    {
      low[d] = std::min(low[d], x[d]);
      high[d] = std::max(high[d], x[d]);
    }
  return low.distance(high);
}

std::vector<unsigned char>
Model::cell_parts(const DecompositionParameters &parameters) const
{
  const std::vector<Point<3>> centres = cell_centres();
  std::vector<unsigned char> result(centres.size(), 1);
  for (unsigned int c = 0; c < centres.size(); ++c)
    for (const auto &box : parameters.boxes)
    {
      bool inside = true;
      for (unsigned int d = 0; d < 3; ++d)
        inside = inside && centres[c][d] >= box[2 * d] && centres[c][d] <= box[2 * d + 1];
      if (inside)
        result[c] = 0;
    }
  if (!parameters.members.empty())
  {
    const std::vector<std::string> names = cell_members();
    AssertThrow(!names.empty(),
                ExcMessage("Model/Decomposition/Explicit members: this model has no "
                           "members (only frames do); use the Explicit region."));
    for (const auto &m : parameters.members)
    {
      bool found = false;
      for (unsigned int c = 0; c < names.size(); ++c)
        if (names[c] == m)
        {
          result[c] = 0;
          found = true;
        }
      AssertThrow(found,
                  ExcMessage("Model/Decomposition/Explicit members: no member named '" +
                             m + "'"));
    }
  }
  return result;
}

void Model::select_part(const std::vector<unsigned char> &cell_parts, const int part)
{
  parts = cell_parts;
  selected_part = parts.empty() ? -1 : part;
  Assert(part >= -1 && part <= 1, ExcInternalError());
}

bool Model::owns_node(const std::vector<unsigned int> &cells) const
{
  if (selected_part < 0)
    return true;
  bool touches_explicit = false;
  for (const unsigned int c : cells)
    touches_explicit = touches_explicit || parts[c] == 0;
  return touches_explicit == (selected_part == 0);
}

Vector<float> Model::subdomain_field() const
{
  Vector<float> f(parts.size());
  for (unsigned int c = 0; c < parts.size(); ++c)
    f[c] = parts[c];
  return f;
}
} // namespace hati
