#ifndef hati_model_point_mass_h
#define hati_model_point_mass_h

#include <hati/model/model.h>

namespace hati
{
/** The `Model/Point mass` subsection: the ball's mass and initial state. */
struct PointMassParameters
{
  double mass = 1.;             ///< kg
  double initial_height = 1.;   ///< m, above the ground
  double initial_velocity = 0.; ///< m/s, vertical, positive upwards

  /** Declare the entries (the caller enters the subsection). */
  static void declare_parameters(ParameterHandler &prm);
  void parse_parameters(ParameterHandler &prm);
};

/**
 * A rigid point mass with three translational DoFs above a rigid ground
 * plane z = 0 (the bouncing ball, doc/theory.md). The contact row is
 * `L = [0 0 1]`, the gap `g = z0 + u_z`. Monitor point `ball`.
 */
class PointMass : public Model
{
public:
  using Parameters = PointMassParameters;

  explicit PointMass(const Parameters &parameters);
  void build(const CommonModelParameters &common, DiscreteSystem &system) override;
  void write_vtu(std::ostream &out, const VtuSnapshot &snapshot) const override;
  std::string description() const override;
  /** `ux`, `uy` or `uz` of the ball. */
  DofDescription describe_dof(const types::global_dof_index dof) const override
  {
    return {dof < 3 ? std::string("u") + "xyz"[dof] : std::string(), "the ball", false};
  }
  std::vector<Point<3>> cell_centres() const override;

private:
  const Parameters parameters;
};
} // namespace hati

#endif
