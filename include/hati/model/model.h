#ifndef hati_model_model_h
#define hati_model_model_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>

#include <hati/model/discrete_system.h>

#include <array>
#include <memory>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace hati
{
using namespace dealii;

/** Parameters shared by every model: loads and the contact law. */
struct CommonModelParameters
{
  /** Declare `Loading` and `Contact` subsections. */
  static void declare_parameters(ParameterHandler &prm);
  void parse_parameters(ParameterHandler &prm);

  /** Gravity acceleration vector (m/s^2). */
  Tensor<1, 3> gravity;
  /** Base (support) acceleration step, applied from base_acceleration_start (m/s^2). */
  Tensor<1, 3> base_acceleration;
  /** Time at which the base acceleration step starts (s). */
  double base_acceleration_start = 0.;
  /** Accelerogram files per global direction x, y, z (empty: none). */
  std::array<std::string, 3> accelerogram_files;
  /** Units of two-column accelerogram files: g, m/s^2 or cm/s^2. */
  std::string accelerogram_units = "g";
  /** Factor on every accelerogram value (-). */
  double accelerogram_scale = 1.;
  /** Name of the contact in contacts.csv. */
  std::string contact_name;
  /** Newton's restitution coefficient e in [0, 1]. */
  double restitution = 0.;
  /** Initial gap between the body and the obstacle (m). */
  double initial_gap = 0.;
};

/** A DoF vector to write, with its name. */
using NamedVector = std::pair<std::string, const Vector<double> *>;

/**
 * A model turns its `.prm` description into a DiscreteSystem (mesh, DoFs,
 * lumped mass, stiffness, loads, contacts, monitors, initial state) and
 * writes DoF vectors of that system to VTU. Integrators never see a model.
 */
class Model
{
public:
  virtual ~Model() = default;

  /** Build the discrete system. */
  virtual void build(const CommonModelParameters &common, DiscreteSystem &system) = 0;

  /**
   * Write DoF vectors (displacement, velocity, contact fields) as one VTU
   * file; @p time (s) and @p cycle are stored in the file.
   */
  virtual void write_vtu(std::ostream &out,
                         const std::vector<NamedVector> &fields,
                         const double time,
                         const unsigned int cycle) const = 0;

  /** One line describing the model for the terminal and summary.json. */
  virtual std::string description() const = 0;

  /**
   * Header of `section_forces.csv`, or an empty string if the model writes
   * no section forces (the default).
   */
  virtual std::string section_forces_header() const { return ""; }

  /** Rows of `section_forces.csv` at time @p time for displacement @p U. */
  virtual void write_section_forces(std::ostream & /*out*/,
                                    const double /*time*/,
                                    const Vector<double> & /*U*/) const
  {
  }
};

/** Declare the `Model` subsection with the parameters of every model type. */
void declare_model_parameters(ParameterHandler &prm);

/** Create the model chosen by `Model/Type` and parse its parameters. */
std::unique_ptr<Model> create_model(ParameterHandler &prm);
} // namespace hati

#endif
