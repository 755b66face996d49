// Unit test of FrameDescription::validate() and its producers (issue #15):
// - a hand-built two-member frame is accepted, and each of its broken
//   variants (a node, member or support given twice, an unknown node,
//   section or material, a zero-length member, a negative point mass, a
//   contact naming its node twice, a node off every member, an unknown
//   section-force member) is refused with a one-line message naming the
//   Model/Frame entry and the item;
// - the Model/Frame parser (FrameParameters) fills a description that
//   validates, and a bad entry is refused by validate() with the parser's
//   message;
// - the bridge crane's generated frame validates for the default crane and
//   its variants (pinned wheels, free travel, no zones, no masses).
// Returns non-zero on failure.
#include <deal.II/base/parameter_handler.h>

#include "test_tools.h"

#include <hati/model/bridge_crane.h>
#include <hati/model/frame_description.h>
#include <hati/model/frame_parser.h>

#include <functional>
#include <string>

namespace hati_unit_frame_description
{

using namespace hati_test;
using hati::FrameDescription;

namespace
{
/** Two members a-b-c, a clamped, a point mass and a monitor at c. */
FrameDescription portal()
{
  FrameDescription d;
  d.add_node("a", dealii::Point<3>(0., 0., 0.));
  d.add_node("b", dealii::Point<3>(0., 0., 3.));
  d.add_node("c", dealii::Point<3>(4., 0., 3.));
  d.materials["steel"] = {2.1e11, 2.1e11 / 2.6, 7850.};
  d.sections["s"] = hati::FrameSection::rectangle(0.1, 0.2);
  FrameDescription::Member m;
  m.name = "column";
  m.start = "a";
  m.end = "b";
  m.section = "s";
  m.material = "steel";
  m.n_elements = 2;
  d.members.push_back(m);
  m.name = "beam";
  m.start = "b";
  m.end = "c";
  d.members.push_back(m);
  FrameDescription::Support s;
  s.node = "a";
  s.stiffness = {{0., 0., 0., 0., 0., 0.}};
  d.supports.push_back(s);
  FrameDescription::PointMassData p;
  p.node = "c";
  p.mass = 100.;
  d.point_masses.push_back(p);
  d.monitor_nodes = {"c"};
  d.section_force_members = {"beam"};
  return d;
}

/** The message validate() throws for @p d (empty: none). */
std::string error_of(const FrameDescription &d)
{
  try
  {
    d.validate();
  }
  catch (const std::exception &e)
  {
    return message_of(e);
  }
  return "";
}

/** @p change made to the portal is refused with a message holding @p fragment. */
void expect_refused(const std::string &what,
                    const std::function<void(FrameDescription &)> &change,
                    const std::string &fragment)
{
  FrameDescription d = portal();
  change(d);
  const std::string message = error_of(d);
  expect(message.find(fragment) != std::string::npos,
         what + ": '" + message + "' holds '" + fragment + "'");
}

void check_hand_built()
{
  expect(error_of(portal()).empty(), "the portal is accepted");
  expect_refused(
      "node twice",
      [](FrameDescription &d) { d.add_node("b", dealii::Point<3>(1., 1., 1.)); },
      "Model/Frame/Nodes: node 'b' is defined twice");
  expect_refused(
      "member twice",
      [](FrameDescription &d) { d.members.push_back(d.members[0]); },
      "Model/Frame/Members: member 'column' is defined twice");
  expect_refused(
      "unknown node",
      [](FrameDescription &d) { d.members[1].end = "nowhere"; },
      "member 'beam' names node 'nowhere', which is not in Model/Frame/Nodes");
  expect_refused(
      "unknown section",
      [](FrameDescription &d) { d.members[1].section = "box"; },
      "member 'beam' names section 'box'");
  expect_refused(
      "unknown material",
      [](FrameDescription &d) { d.members[0].material = "wood"; },
      "member 'column' names material 'wood'");
  expect_refused(
      "zero length",
      [](FrameDescription &d) { d.nodes["c"] = d.nodes["b"]; },
      "Model/Frame/Members: member 'beam' has zero length");
  expect_refused(
      "support twice",
      [](FrameDescription &d) { d.supports.push_back(d.supports[0]); },
      "Model/Frame/Supports: node 'a' is listed twice");
  expect_refused(
      "negative point mass",
      [](FrameDescription &d) { d.point_masses[0].mass = -1.; },
      "Model/Frame/Point masses: node 'c'");
  expect_refused(
      "monitor off the members",
      [](FrameDescription &d)
      {
        d.add_node("d", dealii::Point<3>(9., 9., 9.));
        d.monitor_nodes.push_back("d");
      },
      "Model/Frame/Monitor nodes: node 'd' is not an end of any member");
  expect_refused(
      "contact on one node",
      [](FrameDescription &d)
      {
        FrameDescription::NodeContact c;
        c.name = "hit";
        c.node = c.other_node = "c";
        c.normal[2] = 1.;
        d.contacts.push_back(c);
      },
      "Model/Frame/Contacts: contact 'hit' names the node 'c' twice");
  expect_refused(
      "unknown section-force member",
      [](FrameDescription &d) { d.section_force_members.push_back("girder"); },
      "Model/Frame/Section force members: no member named 'girder'");
  expect_refused(
      "no member",
      [](FrameDescription &d) { d.members.clear(); },
      "Model/Frame/Members: no member is defined");
}

/** The Model/Frame entries of @p input parsed into a description. */
FrameDescription parse(const std::string &input)
{
  dealii::ParameterHandler prm;
  hati::FrameParameters::declare_parameters(prm);
  prm.parse_input_from_string(input);
  hati::FrameParameters p;
  p.parse_parameters(prm);
  return p.description;
}

void check_parser()
{
  const std::string frame =
      "set Nodes = a: 0, 0, 0; b: 0, 0, 3; c: 4, 0, 3\n"
      "set Sections = s: rectangle, 0.1, 0.2\n"
      "set Members = col: a, b, s, steel, 2; beam: b, c, s, steel, 4\n"
      "set Supports = a: clamped\n";
  const FrameDescription d = parse(frame);
  expect(d.node_order.size() == 3 && d.node_order[2] == "c" && d.members.size() == 2 &&
             d.members[1].n_elements == 4 && d.materials.count("steel") == 1,
         "the parser fills nodes (in order), members and the default material");
  expect(error_of(d).empty(), "the parsed frame is accepted");
  const std::string message = error_of(parse(frame + "set Monitor nodes = q\n"));
  expect(message == "Model/Frame/Monitor nodes: node 'q' is not an end of any member in "
                    "Model/Frame/Members",
         "a monitor off the members is refused: '" + message + "'");
}

void check_crane()
{
  const std::vector<std::pair<std::string, std::string>> variants = {
      {"Span", "20"},
      {"Crane wheels", "pinned"},
      {"Travel", "free"},
      {"Explicit zone length", "0"},
      {"Rail mass per metre", "0"},
      {"Hoist mass", "0"}, // with Hoist = rigid: a rope needs the load's mass
      {"Hoist", "rigid"},
      {"Rope length", "12"},
      {"Trolley position", "0.1"},
      {"Eccentricities", "false"}};
  for (const auto &[entry, value] : variants)
  {
    dealii::ParameterHandler prm;
    hati::BridgeCrane::Parameters::declare_parameters(prm);
    prm.set(entry, value);
    if (entry == "Hoist mass")
      prm.set("Hoist", "rigid");
    hati::BridgeCrane::Parameters p;
    p.parse_parameters(prm);
    const FrameDescription d = p.frame();
    const std::string message = error_of(d);
    // Hoist = rope (the default): the load on its rope, a node only it holds
    const bool rope = p.hoist == "rope";
    // true heights (the default): a post and a rigid link per crane wheel,
    // trolley rail head and trolley wheel (bridge_crane_frame.cc add_offsets())
    const unsigned int offsets = p.eccentricities ? 12 : 0;
    expect(message.empty() && d.members.size() == 12 + offsets &&
               d.solids.rigid_links.size() == offsets &&
               d.nodes.size() == d.node_order.size() &&
               d.ropes.size() == (rope ? 1u : 0u) &&
               d.rope_only_nodes() ==
                   (rope ? std::vector<std::string>{"load"} : std::vector<std::string>{}),
           "the crane's frame with " + entry + " = " + value + " is valid: '" + message +
               "'");
  }
}
} // namespace

HATI_UNIT_TEST(frame_description)
{
  check_hand_built();
  check_parser();
  check_crane();
  return finish();
}
} // namespace hati_unit_frame_description
