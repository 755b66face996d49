#ifndef hati_model_solid_h
#define hati_model_solid_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/tria.h>

#include <hati/model/model.h>

namespace hati
{
/**
 * A 3D linear elastic prismatic bar `[0, L] x [-b/2, b/2] x [-h/2, h/2]`
 * (`Triangulation<3>`, `FE_Q<3>^3`, lumped mass by row sums), moving along
 * +x towards a rigid wall at `x = L + g0` (code_aster SDNV100,
 * algorithms.md 6.2). Every node of the face x = L carries a contact row
 * `L = [-1]` on its x displacement. With `Lateral constraint = true` the
 * normal displacement of the four lateral faces is fixed (sliding
 * supports), so that the bar deforms in uniaxial strain and waves travel
 * at the P-wave speed. Monitor points `impact_end` and `free_end` (the
 * centres of the end faces).
 */
class Solid : public Model
{
public:
  struct Parameters
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

  explicit Solid(const Parameters &parameters);
  void build(const CommonModelParameters &common, DiscreteSystem &system) override;
  void write_vtu(std::ostream &out,
                 const std::vector<NamedVector> &fields,
                 const double time,
                 const unsigned int cycle) const override;
  std::string description() const override;
  std::vector<Point<3>> cell_centres() const override;

private:
  const Parameters parameters;
  Triangulation<3> triangulation;
  FESystem<3> fe;
  DoFHandler<3> dof_handler;
};
} // namespace hati

#endif
