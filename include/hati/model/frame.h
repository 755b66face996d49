#ifndef hati_model_frame_h
#define hati_model_frame_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>

#include <hati/model/beam_stresses.h>
#include <hati/model/frame_description.h>
#include <hati/model/frame_element.h>
#include <hati/model/frame_section_forces.h>
#include <hati/model/model.h>
#include <hati/model/solid_tie.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace hati
{
class FrameSolids;

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
 *
 * What the frame is made of comes from a FrameDescription (the `Model/Frame`
 * parser, frame_parser.h, or a generator such as the bridge crane); the
 * section forces are written by FrameSectionForces, the solids' stresses by
 * their SolidStressOutput (frame_results.cc).
 */
class Frame : public Model
{
public:
  /**
   * The frame of @p description, which is validated here
   * (FrameDescription::validate(); throws a one-line error).
   */
  explicit Frame(const FrameDescription &description);
  ~Frame() override;
  void build(const CommonModelParameters &common, DiscreteSystem &system) override;
  void write_vtu(std::ostream &out, const VtuSnapshot &snapshot) const override;
  std::string description() const override;
  /** A named node, or the member and the distance from its start (m). */
  DofDescription describe_dof(const types::global_dof_index dof) const override;
  std::vector<Point<3>> cell_centres() const override;
  /** The diagonal of the box around the vertices (m). */
  double size() const override;
  std::vector<std::string> cell_members() const override;
  bool has_members() const override { return true; }
  std::string section_forces_header() const override;
  /**
   * FrameSectionForces::summary_entries() and, with solids, `solids`
   * (SolidStressOutput::summary()).
   */
  SummaryEntries summary_entries(
      const std::map<std::string, double> &static_contact_forces) const override;
  /** The envelopes of the section forces and of the solids' stress as table lines. */
  std::string results_table() const override;
  /** The members with a `general` section without c_y, c_z (none rigidly linked). */
  std::vector<std::string> members_without_stresses() const override;
  /** Every beam element from its member's start to its end. */
  std::string geometry_csv() const override;
  bool member_stress(const std::string &member,
                     const std::array<double, 6> &forces,
                     double &normal,
                     double &von_mises) const override;
  void write_section_forces(std::ostream *out,
                            const double time,
                            const Vector<double> &U,
                            const Vector<double> *functional_values) const override;
  /** The solids' cuts' rows (SolidCuts::rows()) with the constraints folded in. */
  std::vector<SparseRow> output_functionals() const override;
  /** The DoFs of the section force members' elements (the cuts: output_functionals()). */
  std::vector<types::global_dof_index> section_force_dofs() const override;
  /** `solids` for a frame with solids (SolidStressOutput), none otherwise. */
  /**
   * Every member's section forces N, Vy, Vz, T, My, Mz (N, N m) at both
   * ends of each of its elements (`<member>.N`, ...), in the order of the
   * members, then every solid's stress tensor at the quadrature points of
   * its cells (`<solid>.max_von_mises`, Pa; frame_response.cc).
   */
  std::vector<ResponseGroup> response_groups() const override;
  /** The section forces and stresses of response_groups() for @p U. */
  void response_values(const Vector<double> &U,
                       std::vector<double> &values,
                       const bool own_weight = false) const override;
  /** `Section force members`. */
  std::vector<std::string> section_force_members() const override
  {
    return frame.section_force_members;
  }
  /** `stress_envelope.vtu` for a frame with solids, none otherwise. */
  std::vector<std::string> response_envelope_files() const override;
  /** `stress_envelope.vtu`: per solid cell the largest combined von Mises stress. */
  void write_response_envelope(const std::string &name,
                               const std::vector<std::vector<double>> &von_mises,
                               std::ostream &out) const override;
  std::vector<std::string> vtu_series() const override;
  /** The snapshot of `solids` (SolidStressOutput::write_vtu()). */
  void write_series_vtu(const std::string &series,
                        std::ostream &out,
                        const VtuSnapshot &snapshot) const override;
  /** The envelope of the solids' von Mises stress. */
  void update_envelopes(const double time, const Vector<double> &U) const override;
  /** `stress_envelope.vtu` for a frame with solids, none otherwise. */
  std::vector<std::string> envelope_files() const override;
  void write_envelope_file(const std::string &name, std::ostream &out) const override;
  /**
   * Model::select_part(), and the links eliminated in it (place_links()):
   * the ties of implicit nodes and the rigid links between implicit nodes
   * (a tie of an explicit node and a rigid link with one explicit node cross
   * the interface, interface_rows(); a rigid link between explicit nodes is
   * six bilateral rows of the explicit part); a tie across when its node
   * and its solid are on different sides. The solid cells' parts follow the
   * beam cells' in @p parts (cell_centres()).
   */
  void select_part(const std::vector<unsigned char> &parts, const int part) override;
  /**
   * The links across the interface as interface rows `U_P,c - sum_j R_cj u_j
   * = 0` (G3'', doc/theory.md 11.3), whole numbering: the ties of explicit
   * nodes to the (implicit) solids, and the rigid links with one explicit
   * node, written with that node as the slave (the explicit side one DoF per
   * row). A master DoF eliminated in the implicit part (a chain of links) is
   * replaced by its constraint line.
   */
  std::vector<SparseRow> interface_rows() const override;
  /** The constraints of the ties and rigid links eliminated here, distributed. */
  void complete_solution(Vector<double> &U) const override { constraints.distribute(U); }
  /** A force on constrained DoFs moved onto their masters (homogeneous lines). */
  void condense_force(Vector<double> &f) const override { constraints.condense(f); }
  /** The solids of the frame (null if it has none). */
  const FrameSolids *solid_part() const { return solids.get(); }

private:
  /** The vertices and cells of the members before the triangulation exists. */
  struct MeshLayout;

  /**
   * The mesh (every member its own vertices), the DoFs, the cells' data and
   * the joint and support constraints: once, at the first build().
   */
  void create_mesh();
  /** The cells' members, places, axes, DoFs and matrices; the vertices' DoFs. */
  void set_up_cells(const MeshLayout &layout,
                    std::vector<std::vector<unsigned int>> &vertex_cells);
  /** Joints (members meeting at a node) and fixed supports as constraints. */
  void set_up_constraints(const MeshLayout &layout,
                          const std::vector<std::vector<unsigned int>> &vertex_cells);

  /** Per member, whether the base acceleration loads it (Loading/Excited members). */
  std::vector<bool> excited_members(const CommonModelParameters &common) const;
  /** Whether a cell at @p node belongs to an excited member. */
  bool node_excited(const std::string &node, const std::vector<bool> &excited) const;
  /**
   * The selected cells' stiffness, masses and mass influence vectors into
   * @p system; @p omega2 the largest element bound of omega^2 (1/s^2),
   * @p mass (kg) the members' mass, both accumulated.
   */
  void assemble_cells(const std::vector<bool> &excited,
                      const bool restricted,
                      DiscreteSystem &system,
                      double &omega2,
                      double &mass) const;
  /** Spring supports into the stiffness; the spring on every DoF (N/m, N m/rad). */
  std::vector<double> add_springs(DiscreteSystem &system) const;
  /** Point masses into the masses and the mass influence vectors. */
  void add_point_masses(const std::vector<bool> &excited,
                        const bool restricted,
                        DiscreteSystem &system) const;
  /** Rigid translations, gravity and nodal loads (the system's DoFs fixed first). */
  void add_loads(const CommonModelParameters &common, DiscreteSystem &system) const;
  /** The contact rows of the contacts owned by the part built (frame_rows.cc). */
  void add_contacts(const CommonModelParameters &common, DiscreteSystem &system) const;
  /**
   * The wheels' flanges whose contacts the part built holds
   * (DiscreteSystem::law_data under wheel_flanges_key, D1-D2), after
   * add_contacts() (frame_rows.cc).
   */
  void add_flanges(DiscreteSystem &system) const;
  /**
   * With links_as_rows, the ties and rigid links as bilateral constraint
   * rows after the contacts (frame_rows.cc).
   */
  void add_link_rows(DiscreteSystem &system) const;
  /** The monitor points of history.csv. */
  void add_monitors(DiscreteSystem &system) const;
  /**
   * The ropes owned by the part built (R1; a rope goes with its hook point),
   * and the bound of omega^2 they add (1/s^2).
   */
  double add_ropes(DiscreteSystem &system) const;
  /**
   * The sparsity pattern of the DoFHandler's DoFs, extended by the DoFs of
   * the nodes only a rope holds and the couplings of every rope's nodes.
   */
  void make_pattern(DiscreteSystem &system) const;
  /** Whether DoF @p i is held: constrained, or a rotation of a rope-only node. */
  bool held(const types::global_dof_index i) const
  {
    return constraints.is_constrained(i) ||
           (i >= n_mesh_dofs && i < n_beam_dofs && (i - n_mesh_dofs) % 6 >= 3);
  }
  /**
   * Add @p value to the diagonal entry of DoF @p i of @p matrix through the
   * constraints: on the DoFs a tied node or a rigid link's slave follows,
   * `C^T value C` (a spring or a point mass at such a node).
   */
  void add_to_diagonal(const types::global_dof_index i,
                       const double value,
                       SparseMatrix<double> &matrix) const;
  /** The solids, their supports, and the rows of the ties and rigid links (links). */
  void add_link_constraints();
  /**
   * constraints: the joints and supports (open_constraints) and the links
   * eliminated in the current part, closed.
   */
  void close_constraints();
  /** Whether @p node touches an explicit cell of the current parts. */
  bool node_explicit(const std::string &node) const;
  /**
   * The side of every link for part @p part (link_sides) and each rigid
   * link's orientation: the explicit node as the slave of a link across
   * the interface (`u_m = u_s + theta_s x (x_m - x_s)`, `theta_m =
   * theta_s` is the same link), the description's otherwise.
   */
  void place_links(const int part);
  /**
   * The part (0 explicit, 1 implicit) of every cell of the solid @p solid
   * in the current parts, -1 if they differ; 1 without a decomposition.
   */
  int solid_part(const std::string &solid) const;

  const FrameDescription frame;
  Triangulation<1, 3> triangulation;
  FESystem<1, 3> fe;
  DoFHandler<1, 3> dof_handler;
  AffineConstraints<double> constraints;
  std::vector<FrameCell> cells;
  std::map<std::string, std::array<types::global_dof_index, 6>> node_dofs;
  /** Active cells touching each named node (owner of the node's data). */
  std::map<std::string, std::vector<unsigned int>> node_cells;
  /** The six DoFs of every vertex. */
  std::vector<std::array<types::global_dof_index, 6>> vertex_dofs;
  /**
   * DoFs of the DoFHandler; the nodes only a rope holds
   * (FrameDescription::rope_only_nodes()) have six DoFs each after them
   * (their rotations held), outside the mesh.
   */
  types::global_dof_index n_mesh_dofs = 0;
  /** DoFs of the beams and the rope-only nodes; the solids' DoFs follow. */
  types::global_dof_index n_beam_dofs = 0;
  /** The 3D solids (frame_solids.h), null without. */
  std::unique_ptr<FrameSolids> solids;
  /** The ties and rigid links: the six DoFs of a node as functions of others. */
  std::vector<LinkRows> links;
  /** The node (tied, or slave) of each link. */
  std::vector<std::string> link_nodes;
  /** Where a link acts in a decomposed model (place_links()). */
  enum class LinkSide
  {
    /** an AffineConstraints line (both nodes implicit, or no decomposition) */
    eliminated,
    /** bilateral rows of the explicit part (both nodes explicit) */
    explicit_rows,
    /**
     * interface rows (G3''): a rigid link's slave explicit and its master
     * implicit; a tie's node and solid on different sides
     */
    interface
  };
  /** Per link (empty: every link eliminated, or rows with links_as_rows). */
  std::vector<LinkSide> link_sides;
  /** The joints and supports, before the links are added and it is closed. */
  AffineConstraints<double> open_constraints;
  /**
   * CommonModelParameters::links_as_rows of the first build(): the links as
   * bilateral rows (explicit scheme) instead of constraints.
   */
  bool links_as_rows = false;
  double total_mass = 0.;
  /** Gravity (m/s^2): the members' weight is a span load for section forces. */
  Tensor<1, 3> gravity;
  /** section_forces.csv and its envelope (written from const functions). */
  mutable FrameSectionForces section_force_output;
  /** The members' stresses at the section force rows (beam_stresses, S1-S3). */
  mutable BeamStressEnvelope beam_stresses;
};
} // namespace hati

#endif
