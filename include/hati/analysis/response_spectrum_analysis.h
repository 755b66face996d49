#ifndef hati_analysis_response_spectrum_analysis_h
#define hati_analysis_response_spectrum_analysis_h

#include <deal.II/lac/vector.h>

#include <hati/analysis/response_spectrum_parameters.h>
#include <hati/analysis/spectral_combination.h>
#include <hati/loading/design_spectrum.h>
#include <hati/model/discrete_system.h>
#include <hati/model/response_quantities.h>

#include <functional>

#include <array>
#include <string>
#include <vector>

namespace hati
{
using namespace dealii;

/**
 * What a response-spectrum analysis asks of the model, without the model
 * itself (analysis/ sees no Model: the runner fills it from
 * Model::response_groups(), Model::response_values() and
 * Model::describe_dof()).
 */
struct ResponseModel
{
  /** The groups of linear response quantities (a frame's section forces, stresses). */
  std::vector<ResponseGroup> groups;
  /**
   * Their values for a displacement (one group after another), with the
   * members' own weight as span load when the flag is set (the static state).
   */
  std::function<void(const Vector<double> &, std::vector<double> &, bool)> values;
  /** A DoF for messages, e.g. `ux at node 'A1'` (empty if unknown). */
  std::function<std::string(types::global_dof_index)> describe_dof;
};

/** One mode of a response-spectrum analysis (response_spectrum_modes.csv). */
struct SpectralMode
{
  /** f (Hz) and T = 1/f (s). */
  double frequency = 0., period = 0.;
  /** S_a(T) (m/s^2) per axis (0 for an axis not excited). */
  std::array<double, 3> spectral_acceleration{{0., 0., 0.}};
  /** Gamma_kd = phi_k.M r_d (kg^(1/2)). */
  std::array<double, 3> participation{{0., 0., 0.}};
  /** Gamma_kd^2 / m_d and its sum over the modes up to this one (-). */
  std::array<double, 3> effective_mass_ratio{{0., 0., 0.}},
      cumulative_mass_ratio{{0., 0., 0.}};
  /** Gupta's rigid fraction alpha_k (-; 0 without a rigid response). */
  double rigid_fraction = 0.;
};

/**
 * One combined quantity (a row of response_spectrum.csv): the peak per
 * excitation direction (0 for an axis not excited) and their directional
 * combination, >= 0.
 */
struct SpectralQuantity
{
  std::string name, unit;
  std::array<double, 3> peak{{0., 0., 0.}};
  double combined = 0.;
  /**
   * With the static state (ResponseSpectrumAnalysis::set_static_state()):
   * the largest over the stations of |static| + combined (a stress: the von
   * Mises stress of the static components moved away from zero by the
   * combined ones), the value a time history's envelope (static and
   * dynamic) compares with; -1 before.
   */
  double with_static = -1.;
};

/** What the linear method says about a contact (summary.json). */
struct SpectralContact
{
  std::string name;
  /** The force of the static state (N, >= 0 pressing). */
  double static_force = 0.;
  /** The combined change of the force (N, >= 0). */
  double change = 0.;
  /** A two-sided contact (a flange's play held): its force acts either way. */
  bool two_sided = false;
  double max_force() const { return static_force + change; }
  double min_force() const { return static_force - change; }
  /** A one-sided contact whose minimum force is negative: lift-off predicted. */
  bool uplift_predicted() const { return !two_sided && min_force() < 0.; }
};

/**
 * The response-spectrum analysis of a linearised model (doc/theory.md 14):
 * the modal analysis of compute_modes() (zero-gap contacts closed, closed
 * frictional contacts held in their tangent directions, ropes linearised
 * about @p static_state) with the clearance contacts held or not; every
 * mode up to the cut-off frequency (counted first by the inertia of `K -
 * omega_c^2 M`, RS5); each mode's response of every quantity computed once
 * from its shape (RS6: the monitors, the contacts' multipliers, the
 * model's ResponseGroups, the base reaction); the missing mass as one
 * static solve per direction (RS3); the modal (RS1, RS2) and directional
 * (RS4) combinations.
 */
class ResponseSpectrumAnalysis
{
public:
  /**
   * Run it. @p rope_state: the displacement the ropes are linearised about
   * (m, the static state; zero without ropes); @p linear_solver: `Time
   * integration/Newmark/Linear solver`. Throws one-line messages: no mass
   * along a direction, a direction without spectrum, more modes than
   * Maximum modes, a mechanism.
   */
  ResponseSpectrumAnalysis(const DiscreteSystem &system,
                           const ResponseModel &model,
                           const ResponseSpectrumParameters &parameters,
                           const DesignSpectrum &spectrum,
                           const Vector<double> &rope_state,
                           const std::string &linear_solver);

  /**
   * The static state @p U (m, solve_static() under the constant loads) and
   * @p static_forces, the static force of every contact row (N): each
   * contact's static force (summed over its rows), each quantity's
   * SpectralQuantity::with_static.
   */
  void set_static_state(const Vector<double> &U,
                        const std::vector<double> &static_forces);

  /** The modes combined, ascending. */
  const std::vector<SpectralMode> &modes() const { return kept_modes; }
  /** The rows of response_spectrum.csv, in order. */
  const std::vector<SpectralQuantity> &quantities() const { return rows; }
  /**
   * Per stress group of the model's response_groups(), in their order, the
   * combined von Mises stress (Pa) at each of its points
   * (Model::write_response_envelope()).
   */
  const std::vector<std::vector<double>> &stress_envelopes() const { return envelopes; }
  /** The contacts (summary.json), in the order of their first row. */
  const std::vector<SpectralContact> &contacts() const { return contact_results; }
  /** The total mass m_d per axis (kg). */
  const std::array<double, 3> &total_mass() const { return masses; }
  /** The kept modes' effective mass per axis over m_d (-). */
  const std::array<double, 3> &effective_mass_ratio() const { return effective_ratio; }
  /**
   * The mass the kept modes leave out per axis over m_d (-): `r_d.(M r_d -
   * sum_k Gamma_kd M phi_k) / m_d`, from the missing-mass load itself.
   */
  const std::array<double, 3> &missing_mass_ratio() const { return missing_ratio; }
  /** The zero-period acceleration per axis (m/s^2). */
  const std::array<double, 3> &zero_period_acceleration() const { return zpa; }
  /** Closed contact rows and held clearance rows (-). */
  unsigned int n_closed_rows() const { return n_closed; }
  unsigned int n_held_clearance_rows() const { return n_held; }
  /** The number of modes below the cut-off frequency (-, the inertia count). */
  unsigned int n_modes_below_cutoff() const { return n_below; }
  /** Wall times (s): modes, per-mode quantities, missing mass, combination. */
  std::array<double, 4> wall_times{{0., 0., 0., 0.}};

private:
  std::vector<SpectralMode> kept_modes;
  std::vector<SpectralQuantity> rows;
  std::vector<SpectralContact> contact_results;
  std::vector<std::vector<double>> envelopes;
  /** The model's quantities (set_static_state()). */
  const ResponseModel model;
  /** The quantities of the displacement block and how they lie in their values. */
  struct Row
  {
    std::size_t first = 0, size = 1;
    bool stress = false;
  };
  std::vector<Row> layout;
  /** The combined value of every value of the displacement block (stresses: 0). */
  std::vector<double> combined_values;
  /** The combined components of every stress point (6 per point, group after group). */
  std::vector<double> combined_stress;
  std::size_t first_group_value = 0, n_group_values = 0;
  /** The contact rows of each entry of contact_results. */
  std::vector<std::vector<unsigned int>> contact_rows;
  std::array<double, 3> masses{{0., 0., 0.}}, effective_ratio{{0., 0., 0.}},
      missing_ratio{{0., 0., 0.}}, zpa{{0., 0., 0.}};
  unsigned int n_closed = 0, n_held = 0, n_below = 0;
};
} // namespace hati

#endif
