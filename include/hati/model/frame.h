#ifndef hati_model_frame_h
#define hati_model_frame_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>

#include <hati/model/frame_element.h>
#include <hati/model/model.h>

#include <map>
#include <string>
#include <vector>

namespace hati
{
/**
 * A 3D frame of straight linear elastic members (algorithms.md section 5):
 * `Triangulation<1,3>` of line cells, `FESystem(FE_Q<1,3>(1), 6)` for the
 * six DoFs of a node (ux, uy, uz, rx, ry, rz in global axes), element
 * matrices of the Timoshenko frame element (frame_element.h) computed in
 * closed form, not by deal.II's FEValues.
 *
 * Every member gets its own vertices (deal.II 9.4 mishandles vertices
 * shared by three or more line cells, see shared/notes); members meeting at
 * a node are tied with AffineConstraints: all six DoFs for a rigid joint,
 * the translations only for the members after the first at a hinged joint.
 * Supports fix DoFs (constraints) or add a spring stiffness. The matrices
 * are condensed (constraints.distribute_local_to_global) and constrained DoFs
 * are flagged fixed in the DiscreteSystem; their values are restored with
 * constraints.distribute() for output.
 */
class Frame : public Model
{
public:
  /** The `Model/Frame` subsection, lists given as `name: values; ...`. */
  struct Parameters
  {
    static void declare_parameters(ParameterHandler &prm);
    void parse_parameters(ParameterHandler &prm);

    /**
     * A cross-section from the Sections syntax after the name, @p text =
     * 'rectangle, b, h' | 'box, b, h, t_web, t_flange' | 'general, A, Iy,
     * Iz, J, Asy, Asz' (m, m^2, m^4; frame_element.h); @p where (the entry
     * and item) starts every error message.
     */
    static FrameSection parse_section(const std::string &text, const std::string &where);

    struct Member
    {
      std::string name, start, end, section, material;
      unsigned int n_elements = 1;
      Tensor<1, 3> y_reference;
      /**
       * Nodes along the member, start to end, for members read from a mesh
       * file (one element between consecutive nodes); empty for members of
       * the Members entry, which are divided into n_elements equal elements.
       */
      std::vector<std::string> path;
    };
    struct PointMassData
    {
      std::string node;
      double mass = 0.;
      Tensor<1, 3> rotary_inertia;
    };
    struct Support
    {
      std::string node;
      /** Per DoF: -1 free, 0 fixed, > 0 spring stiffness (N/m, N m/rad). */
      std::array<double, 6> stiffness{{-1., -1., -1., -1., -1., -1.}};
    };

    std::map<std::string, Point<3>> nodes;
    std::vector<std::string> node_order;
    std::map<std::string, FrameMaterial> materials;
    std::map<std::string, FrameSection> sections;
    std::vector<Member> members;
    std::vector<PointMassData> point_masses;
    std::vector<Support> supports;
    std::vector<std::string> hinged_joints;
    std::map<std::string, std::array<double, 6>> nodal_loads;
    /**
     * One entry of Model/Frame/Contacts (doc/theory.md 1.2, doc/user_guide.md
     * "Contacts of frame nodes"): the gap is `g = gap + n . (u_node -
     * u_other)` (`u_other = 0` for a rigid plane that moves with the base).
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
    };
    std::vector<NodeContact> contacts;
    std::vector<std::string> monitor_nodes;
    std::vector<std::string> section_force_members;
  };

  explicit Frame(const Parameters &parameters);
  void build(const CommonModelParameters &common, DiscreteSystem &system) override;
  void write_vtu(std::ostream &out,
                 const std::vector<NamedVector> &fields,
                 const double time,
                 const unsigned int cycle) const override;
  std::string description() const override;
  std::vector<Point<3>> cell_centres() const override;
  std::vector<std::string> cell_members() const override;
  bool has_members() const override { return true; }
  std::string section_forces_header() const override;
  /**
   * `section_force_envelope`: the largest |N| (N), |My|, |Mz| (N m) among
   * the section forces written so far, with the member, the position along
   * it (m) and the time (s).
   */
  SummaryEntries summary_entries(
      const std::map<std::string, double> &static_contact_forces) const override;
  /** The envelope of the section forces as table lines. */
  std::string results_table() const override;
  void write_section_forces(std::ostream &out,
                            const double time,
                            const Vector<double> &U) const override;

private:
  /** Envelope of the written section forces: N, My, Mz (write_section_forces()). */
  struct EnvelopeEntry
  {
    double value = 0., x = 0., time = 0.;
    std::string member;
  };
  mutable std::array<EnvelopeEntry, 3> envelope;
  /** Per active cell: its member, its index along the member, its rotation. */
  struct CellInfo
  {
    unsigned int member = 0;
    unsigned int element = 0;
    double length = 0.;
    /** Distance of the element's first node from the member's start (m). */
    double position = 0.;
    Tensor<2, 3> rotation;
    std::array<types::global_dof_index, 12> dofs;
    /** Local stiffness and consistent mass (section forces at every history row). */
    FullMatrix<double> stiffness, mass;
  };

  /**
   * Section forces (N, Vy, Vz, T, My, Mz at both ends) of one cell from its
   * end forces k u minus its own weight (a span load). Inertia forces are
   * taken as nodal: between nodes the distributed inertia of a dynamic run
   * is not in the section forces.
   */
  std::array<double, 12> cell_section_forces(const CellInfo &cell,
                                             const Vector<double> &U) const;

  /**
   * The mesh (every member its own vertices), the DoFs, the cells' data and
   * the joint and support constraints: once, at the first build().
   */
  void create_mesh();

  const Parameters parameters;
  Triangulation<1, 3> triangulation;
  FESystem<1, 3> fe;
  DoFHandler<1, 3> dof_handler;
  AffineConstraints<double> constraints;
  std::vector<CellInfo> cells;
  std::map<std::string, std::array<types::global_dof_index, 6>> node_dofs;
  /** Active cells touching each named node (owner of the node's data). */
  std::map<std::string, std::vector<unsigned int>> node_cells;
  /** The six DoFs of every vertex. */
  std::vector<std::array<types::global_dof_index, 6>> vertex_dofs;
  double total_mass = 0.;
  /** Gravity (m/s^2): the members' weight is a span load for section forces. */
  Tensor<1, 3> gravity;
};
} // namespace hati

#endif
