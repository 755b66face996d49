#ifndef hati_model_frame_description_h
#define hati_model_frame_description_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <hati/model/frame_element.h>
#include <hati/model/solid_description.h>

#include <array>
#include <map>
#include <string>
#include <vector>

namespace hati
{
/** The labels of a frame node's six DoFs, in their order. */
inline constexpr const char *dof_component_labels[6] = {"x", "y", "z", "rx", "ry", "rz"};

using namespace dealii;

/**
 * What a 3D frame is made of, as plain data (doc/user_guide.md "Frames"):
 * named nodes, materials and sections, members between nodes, and the
 * nodal data (point masses, supports, hinged joints, loads, contacts,
 * monitors, section-force output) that refer to them by name.
 *
 * Three producers fill it: the `Model/Frame` mini-language parser
 * (frame_parser.h), with the members and nodes of a Gmsh mesh file merged in
 * (gmsh_frame_reader.h), and the bridge crane generator (bridge_crane.h).
 * Each further kind of nodal or member data (ropes, wheel friction) is one
 * more list here. Frame (frame.h) builds the mesh and the discrete system
 * from a description after validate() has accepted it.
 *
 * Errors name the `Model/Frame` entry that holds the wrong item, also for a
 * generated description: the entries are the frame's vocabulary.
 */
/**
 * The tangent directions in which the friction of a contact with the unit
 * normal @p normal acts (A9, doc/theory.md A9): two orthonormal vectors
 * `t1, t2` of the contact plane, `t1` along the global axis least aligned
 * with the normal projected on the plane and `t2 = n x t1`; with a rolling
 * axis @p rolls (0, 1, 2; -1: none) the one direction `n x e_rolls`
 * (normalised), which excludes the axis. Empty if the rolling axis is along
 * the normal (validate() refuses that).
 */
std::vector<Tensor<1, 3>> contact_tangent_directions(const Tensor<1, 3> &normal,
                                                     const int rolls);

struct FrameDescription
{
  /** A straight member, or a chain of straight elements (mesh members). */
  struct Member
  {
    std::string name, start, end, section, material;
    unsigned int n_elements = 1;
    /** Reference vector of the section's local y axis (global axes; 0: default). */
    Tensor<1, 3> y_reference;
    /**
     * Nodes along the member, start to end, for members read from a mesh
     * file (one element between consecutive nodes); empty for members of
     * the Members entry, which are divided into n_elements equal elements.
     */
    std::vector<std::string> path;
  };

  /** A point mass (kg) and rotary inertias about global axes (kg m^2) at a node. */
  struct PointMassData
  {
    std::string node;
    double mass = 0.;
    Tensor<1, 3> rotary_inertia;
  };

  /** A support of a node. */
  struct Support
  {
    std::string node;
    /** Per DoF: -1 free, 0 fixed, > 0 spring stiffness (N/m, N m/rad). */
    std::array<double, 6> stiffness{{-1., -1., -1., -1., -1., -1.}};
  };

  /**
   * A contact of a node (doc/theory.md 1.2, doc/user_guide.md "Contacts of
   * frame nodes"): the gap is `g = gap + n . (u_node - u_other)` (`u_other
   * = 0` for a rigid plane that moves with the base).
   */
  struct NodeContact
  {
    std::string name, node;
    /** Node-to-node: the node of the obstacle; empty for a rigid plane. */
    std::string other_node;
    /** Normal (unit, global axes) pointing from the obstacle to the node. */
    Tensor<1, 3> normal;
    /**
     * One-sided: the initial gap (m, >= 0). Two-sided: the total clearance
     * c (m, >= 0), two rows with normals n and -n and initial gaps c / 2.
     */
    double gap = 0.;
    /** Negative: Contact/Restitution coefficient. */
    double restitution = -1.;
    /** Two rows, one per side of the clearance, both named `name`. */
    bool two_sided = false;
    /** Coulomb friction coefficient mu (-, >= 0; 0: frictionless, A9). */
    double friction = 0.;
    /**
     * The global axis (0, 1, 2 for x, y, z) along which the node rolls
     * freely (no friction along it, `rolls=`); -1: none.
     */
    int rolls = -1;
  };

  /**
   * A rope (doc/theory.md 10, R1) from a hook point (a node of a member) to
   * a load: another member node, or a node that only the rope holds (with
   * its point mass): such a node has the three translations only, its
   * rotations are held (no rotational stiffness or inertia).
   */
  struct RopeData
  {
    std::string name, node, other_node;
    /** Axial stiffness k = E A / L of all falls (N/m). */
    double stiffness = 0.;
    /** Rest length (m); negative: the distance between the two nodes. */
    double rest_length = -1.;
  };

  /**
   * A wheel's flanges over its rail (doc/theory.md D1-D2, user guide "The
   * crane on its runway"): the flange contact's rows act only while the
   * tread contact's gap (the uplift) is at most the flange depth; a wheel
   * above it whose lateral offset exceeds the flange contact's clearance
   * plus half the rail head width has derailed (the run stops).
   */
  struct Flange
  {
    std::string name;
    /** The wheel's tread contact: one-sided (its gap is the uplift). */
    std::string tread_contact;
    /** The wheel's flange contact: two-sided with a clearance, the same node. */
    std::string flange_contact;
    /** The uplift above which the flanges pass over the rail head (m, > 0). */
    double depth = 0.;
    /** The rail head width (m, >= 0). */
    double rail_head_width = 0.;
  };

  /** Add the node @p name at @p x (m) at the end of node_order. */
  void add_node(const std::string &name, const Point<3> &x);

  /**
   * Check the description as a whole, before anything is built from it:
   * every name it defines or names follows check_name() (letters, digits,
   * `_`, `-`, `.`; node names `@<tag>` or not a number); at least one member; no node,
   * member or support given twice; every node, section and material a member names
   * exists; no member or mesh element of zero length and no node coordinates that
   * overflow; every node that a point mass, support, hinged joint, monitor, nodal load or
   * contact names is a node of a member (or, except for supports and hinged
   * joints, the load node of a rope); every section-force member exists;
   * sections, materials, masses, springs, contacts and ropes within their
   * ranges (a rope: its hook point a member node, two different nodes,
   * 0 < k <= max_rope_stiffness, rest length > 0).
   * Throws a one-line error naming the `Model/Frame` entry otherwise.
   */
  void validate() const;

  /**
   * The nodes that only a rope holds (the load nodes of ropes that are not
   * a node of any member), in rope order, each once.
   */
  std::vector<std::string> rope_only_nodes() const;

  /** Largest rope stiffness accepted (N/m). */
  static constexpr double max_rope_stiffness = 1e12;

  /** Node positions (m, global axes) by name. */
  std::map<std::string, Point<3>> nodes;
  /** Node names in the order they were given (every node once). */
  std::vector<std::string> node_order;
  std::map<std::string, FrameMaterial> materials;
  std::map<std::string, FrameSection> sections;
  std::vector<Member> members;
  std::vector<PointMassData> point_masses;
  std::vector<Support> supports;
  /** Nodes where the members after the first share only the translations. */
  std::vector<std::string> hinged_joints;
  /** Constant nodal loads Fx, Fy, Fz, Mx, My, Mz (N, N m, global axes) by node. */
  std::map<std::string, std::array<double, 6>> nodal_loads;
  std::vector<NodeContact> contacts;
  std::vector<RopeData> ropes;
  std::vector<Flange> flanges;
  /** Nodes written to history.csv. */
  std::vector<std::string> monitor_nodes;
  /** Members whose section forces are written to section_forces.csv. */
  std::vector<std::string> section_force_members;
  /** 3D solids, ties, solid supports and rigid links (solid_description.h). */
  SolidDescription solids;
};
} // namespace hati

#endif
