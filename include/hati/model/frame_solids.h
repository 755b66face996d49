#ifndef hati_model_frame_solids_h
#define hati_model_frame_solids_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <hati/model/discrete_system.h>
#include <hati/model/frame_description.h>
#include <hati/model/solid_tie.h>

#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace hati
{
using namespace dealii;

class SolidCuts;
class SolidStressOutput;

/**
 * The 3D solids of a frame model (doc/user_guide.md "Solids and ties"):
 * one `Triangulation<3>` of every solid (create_solid_mesh(), the solid's
 * index as material id), `FE_Q(p)^3` on its own DoFHandler, the DoFs
 * numbered after the beams' in the model's one global numbering; linear
 * elasticity with the consistent mass and the row-sum lumped mass
 * (positive for FE_Q(p)); the supports of solid faces and the ties of beam
 * nodes to solid faces (B1) as lines of the frame's AffineConstraints.
 * Its SolidStressOutput writes the stresses (`solids.pvd`,
 * `stress_envelope.vtu`, summary.json `solids`), its SolidCuts the section
 * forces of the cuts; it finds the nodes of the solid monitors.
 */
class FrameSolids
{
public:
  /**
   * The mesh and the DoFs of the solids of @p frame (whose materials they
   * name); the DoFs numbered from @p offset.
   */
  FrameSolids(const FrameDescription &frame, const types::global_dof_index offset);
  ~FrameSolids();

  /** Number of DoFs of the solids. */
  types::global_dof_index n_dofs() const { return dof_handler.n_dofs(); }
  /** The global index of the first solid DoF. */
  types::global_dof_index offset() const { return first_dof; }

  /**
   * The supports of solid faces (every translation fixed) into
   * @p constraints, before it is closed. Throws a one-line error naming the
   * entry for a face with no solid node.
   */
  void add_supports(AffineConstraints<double> &constraints) const;

  /**
   * The ties of beam nodes (B1): each node's six DoFs (@p node_dofs) as
   * functions of its face's DoFs. Throws one-line errors naming the tie for
   * a face with no solid node or a face that is a line.
   */
  std::vector<LinkRows>
  ties(const std::map<std::string, std::array<types::global_dof_index, 6>> &node_dofs)
      const;

  /** The couplings of the solid cells, condensed with @p constraints. */
  void add_pattern(const AffineConstraints<double> &constraints,
                   DynamicSparsityPattern &pattern) const;

  /**
   * Stiffness, consistent and lumped masses, and the mass influence
   * vectors `M r_d` of the solid cells into @p system, condensed with
   * @p constraints; raises @p omega2 (1/s^2) to the largest element bound
   * of omega^2 (element eigenproblems with the lumped mass) and adds the
   * solids' mass (kg) to @p mass. Only the cells flagged in @p owned (by
   * active cell index; empty: every cell), the cells of one subdomain.
   */
  void assemble(const AffineConstraints<double> &constraints,
                DiscreteSystem &system,
                double &omega2,
                double &mass,
                const std::vector<bool> &owned = {}) const;

  /** The centre of every active cell (m), by active cell index. */
  std::vector<Point<3>> cell_centres() const;
  /** The index of the solid of every active cell. */
  std::vector<unsigned int> cell_solids() const;

  /** 1 on the free solid DoFs of component d in @p influence[d]. */
  void add_influence(const std::vector<bool> &fixed,
                     std::array<Vector<double>, 3> &influence) const;

  /**
   * The stress tensor (Pa) at every quadrature point of every cell for the
   * displacement @p U (global numbering, constraints distributed), with the
   * points: for the patch tests and the stress output.
   */
  void stresses(const Vector<double> &U,
                std::vector<SymmetricTensor<2, 3>> &stress,
                std::vector<Point<3>> &points) const;

  /** The stress (Pa) of @p strain in the solid of index @p solid (Hooke). */
  SymmetricTensor<2, 3> stress(const unsigned int solid,
                               const SymmetricTensor<2, 3> &strain) const
  {
    const Material &m = materials[solid];
    return m.lambda * trace(strain) * unit_symmetric_tensor<3>() + 2. * m.mu * strain;
  }

  /** The density (kg/m^3) of the solid of index @p solid. */
  double density(const unsigned int solid) const { return materials[solid].rho; }

  /** Number of solids; the name of the solid of index @p solid. */
  unsigned int n_solids() const { return materials.size(); }
  const std::string &solid_name(const unsigned int solid) const
  {
    return frame.solids.solids[solid].name;
  }

  /**
   * The stress output of the solids; not const: its envelope is updated
   * from the model's const output functions (Model::update_envelopes()).
   */
  SolidStressOutput &stress_output() const { return *output; }

  /** The section forces of the cuts of the solids (`Solid cuts`). */
  const SolidCuts &cuts() const { return *cut_output; }

  /**
   * A monitor point at a solid's node (`Monitor nodes` item `name: solid,
   * x, y, z`): the node of the solid nearest to the requested point.
   */
  struct MonitorNode
  {
    std::string name;
    /** The global DoFs of its translations x, y, z. */
    std::array<types::global_dof_index, 3> dofs;
    /** The node (m) and its distance from the requested point (m). */
    Point<3> node;
    double distance = 0.;
    /** The largest cell diameter of its solid (m): a point inside the
     * solid is nearer than that to a node. */
    double cell_size = 0.;
  };
  /** The monitor points at solid nodes, in the order of `Monitor nodes`. */
  const std::vector<MonitorNode> &monitor_nodes() const { return monitors; }

  /** The diagonal of the box around the solids' vertices (m). */
  double size() const;
  /**
   * Number of cells and of DoFs, e.g. "2 solids: 640 hexahedra of degree
   * 2"; the node of every solid monitor and its distance from the point
   * given.
   */
  std::string description() const;
  const DoFHandler<3> &dofs() const { return dof_handler; }

private:
  /** The Lame constants lambda, mu (Pa) and the density (kg/m^3) of each solid. */
  struct Material
  {
    double lambda = 0., mu = 0., rho = 0.;
  };

  const FrameDescription &frame;
  std::vector<Material> materials;
  Triangulation<3> triangulation;
  FESystem<3> fe;
  DoFHandler<3> dof_handler;
  types::global_dof_index first_dof = 0;
  std::vector<MonitorNode> monitors;
  /** stresses(): per quadrature point of every cell, and the reference cell's gradients.
   */
  struct StressPoints
  {
    std::vector<Point<3>> points;
    /** `J^-1 = d xi / d x` at each point (cell-major). */
    std::vector<Tensor<2, 3>> inverse_jacobians;
    /** Every cell's global DoFs (cell-major) and material id. */
    std::vector<types::global_dof_index> dofs;
    std::vector<types::material_id> materials;
    /**
     * The scalar shape functions' gradients on the reference cell, entry
     * `(q n_b + b) 3 + d` for point q, function b (of n_b), direction d.
     */
    std::vector<double> reference_gradients;
    /** Component and scalar shape function of each DoF of a cell. */
    std::vector<unsigned int> components, scalar_index;
  };
  mutable StressPoints stress_points;
  /** Fill stress_points at the points of @p quadrature. */
  void fill_stress_points(const Quadrature<3> &quadrature) const;
  /** Created last: they read the DoFHandler. */
  std::unique_ptr<SolidStressOutput> output;
  std::unique_ptr<SolidCuts> cut_output;
};
} // namespace hati

#endif
