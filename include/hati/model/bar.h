#ifndef hati_model_bar_h
#define hati_model_bar_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/grid/tria.h>

#include <hati/model/model.h>

namespace hati
{
/**
 * An elastic bar along x from 0 to L (`Triangulation<1>`, linear `FE_Q<1>`,
 * lumped mass by row sums), moving towards a rigid wall at `x = L + g0`
 * (algorithms.md 6.2). Contact row `L = [-1]` on the end node x = L, gap
 * `g = g0 - u(L)`. Monitor points `impact_end` (x = L) and `free_end`
 * (x = 0). Gravity acts along x with the x component of the gravity vector.
 * The end x = 0 may be fixed and the end x = L loaded by a constant force
 * (the coupling's reference bar); the wall may be left out.
 */
class Bar : public Model
{
public:
  struct Parameters
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

  explicit Bar(const Parameters &parameters);
  void build(const CommonModelParameters &common, DiscreteSystem &system) override;
  void write_vtu(std::ostream &out,
                 const std::vector<NamedVector> &fields,
                 const double time,
                 const unsigned int cycle) const override;
  std::string description() const override;
  std::vector<Point<3>> cell_centres() const override;

private:
  const Parameters parameters;
  Triangulation<1> triangulation;
  FE_Q<1> fe;
  DoFHandler<1> dof_handler;
};
} // namespace hati

#endif
