#ifndef hati_model_continuum_h
#define hati_model_continuum_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/tria.h>

#include <hati/model/model.h>

#include <map>

namespace hati
{
/**
 * The parameters of Continuum<dim>, one specialisation per dimension:
 * `Model/Bar` for dim = 1, `Model/Solid` for dim = 3.
 */
template <int dim> struct ContinuumParameters;

/** `Model/Bar`: the 1D elastic bar (Continuum<1>). */
template <> struct ContinuumParameters<1>
{
  static void declare_parameters(ParameterHandler &prm);
  void parse_parameters(ParameterHandler &prm);
  double length = 1.;          ///< m
  double area = 1e-4;          ///< m^2
  double young_modulus = 2e11; ///< Pa
  double density = 7800.;      ///< kg/m^3
  unsigned int n_elements = 100;
  double initial_velocity = 1.; ///< m/s, towards the wall (+x)
  /** "free" or "fixed": the end x = 0. */
  std::string left_end = "free";
  /** Constant force at x = L along +x from t = 0 (N). */
  double end_force = 0.;
  /** Whether the rigid wall at x = L + g0 (the contact) exists. */
  bool wall = true;
};

/** `Model/Solid`: the 3D elastic prism (Continuum<3>). */
template <> struct ContinuumParameters<3>
{
  static void declare_parameters(ParameterHandler &prm);
  void parse_parameters(ParameterHandler &prm);
  double length = 0.2;          ///< m
  double width = 0.02;          ///< m (y)
  double height = 0.02;         ///< m (z)
  double young_modulus = 2e11;  ///< Pa
  double poisson_ratio = 0.3;   ///< -
  double density = 8000.;       ///< kg/m^3
  unsigned int n_elements = 40; ///< along the length
  unsigned int n_elements_across = 2;
  bool lateral_constraint = true;
  double initial_velocity = 100.; ///< m/s, towards the wall (+x)
};

/**
 * A linear elastic body along x from 0 to L, meshed with `dim`-linear
 * Lagrange elements (`FE_Q<dim>(1)^dim`, lumped mass by row sums), moving
 * with a uniform initial velocity along +x towards a rigid wall at
 * `x = L + g0` (algorithms.md 6.2). Every node of the end x = L carries a
 * contact row `L = [-1]` on its x displacement, gap `g = g0 - u_x`.
 * Monitor points `impact_end` and `free_end`: the nodes nearest to the
 * centres of the ends x = L and x = 0. Gravity loads each displacement
 * component with its component of the gravity vector.
 *
 * - dim = 1, `Bar` (`Model/Bar`): a bar of cross-section A
 *   (`Triangulation<1>`). The end x = 0 may be fixed and the end x = L
 *   loaded by a constant force (the coupling's reference bar); the wall may
 *   be left out.
 * - dim = 3, `Solid` (`Model/Solid`): the prism
 *   `[0, L] x [-b/2, b/2] x [-h/2, h/2]` (code_aster SDNV100). With
 *   `Lateral constraint = true` the normal displacement of the four lateral
 *   faces is fixed (sliding supports), so that the prism deforms in
 *   uniaxial strain and waves travel at the P-wave speed.
 */
template <int dim> class Continuum : public Model
{
public:
  using Parameters = ContinuumParameters<dim>;

  explicit Continuum(const Parameters &parameters);
  void build(const CommonModelParameters &common, DiscreteSystem &system) override;
  void write_vtu(std::ostream &out, const VtuSnapshot &snapshot) const override;
  std::string description() const override;
  std::vector<Point<3>> cell_centres() const override;
  /** The diagonal of the box around the vertices (m). */
  double size() const override;
  /** The component and the position of the node (m). */
  DofDescription describe_dof(const types::global_dof_index dof) const override;

private:
  /** The DoFs of the monitor points and the nodes of the end x = L. */
  struct EndNodes
  {
    /** Components of the node nearest to the centre of x = 0 resp. x = L. */
    std::array<types::global_dof_index, dim> left, right;
    /** x DoF of every node of the face x = L -> the cells that touch it. */
    std::map<types::global_dof_index, std::vector<unsigned int>> face_cells;
  };

  /** The mesh, after checking its memory estimate (once). */
  void make_grid();

  /**
   * Stiffness, consistent and lumped mass, gravity forces and the bound
   * omega_max of the selected cells, with the material constants of the
   * dimension.
   */
  void assemble(const CommonModelParameters &common, DiscreteSystem &system) const;

  /**
   * The cell loop of assemble(): @p mass_density per unit measure of the
   * mesh (kg/m in 1D, kg/m^3 in 3D) and the stiffness integrand
   * `stiffness(grad phi_i, grad phi_j, component i, component j)` without
   * JxW.
   */
  template <typename StiffnessIntegrand>
  void assemble_cells(const CommonModelParameters &common,
                      const double mass_density,
                      const StiffnessIntegrand &stiffness,
                      DiscreteSystem &system) const;

  /**
   * Set the initial velocity along x on every node and find the monitor
   * nodes and the face x = L.
   */
  EndNodes find_end_nodes(DiscreteSystem &system) const;

  /**
   * The supports: the end x = 0 of a fixed bar (the node `ends.left`),
   * the lateral faces of a constrained solid (and the solid's `M r`, which
   * keeps the inertia coupled to them).
   */
  void fix_supports(const EndNodes &ends, DiscreteSystem &system) const;

  const Parameters parameters;
  Triangulation<dim> triangulation;
  FESystem<dim> fe;
  DoFHandler<dim> dof_handler;
};

/** The 1D elastic bar. */
using Bar = Continuum<1>;
/** The 3D elastic prism. */
using Solid = Continuum<3>;
} // namespace hati

#endif
