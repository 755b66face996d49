#ifndef hati_analysis_response_spectrum_parameters_h
#define hati_analysis_response_spectrum_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <hati/analysis/spectral_combination.h>

#include <array>
#include <vector>

namespace hati
{
using namespace dealii;

/**
 * `subsection Response spectrum` (doc/user_guide.md, "Response-spectrum
 * analysis and what the time history saves"): the excitation directions,
 * the combinations, the cut-off, the missing mass and the rigid response
 * of `Analysis/Type = response spectrum` (doc/theory.md 14).
 */
struct ResponseSpectrumParameters
{
  /** Declare the subsection (entered here). */
  static void declare_parameters(ParameterHandler &prm);
  /** Read and check it (one-line errors naming the entry). */
  void parse_parameters(ParameterHandler &prm);

  /** The excited global axes (0, 1, 2), ascending, without repetition. */
  std::vector<unsigned int> directions{0, 1, 2};
  ModalCombination modal_combination = ModalCombination::CQC;
  DirectionalCombination directional_combination = DirectionalCombination::SRSS;
  /** Modes up to this frequency are combined (Hz, > 0). */
  double cutoff_frequency = 33.;
  /** The most modes computed; more needed is refused (-). */
  unsigned int maximum_modes = 500;
  /** The static response to the inertia the kept modes leave out (RS3). */
  bool missing_mass = true;
  /** Gupta's rigid response of the modes between f1 and f2 (RS3). */
  bool gupta = false;
  /** f1 < f2 (Hz) of Gupta's rigid fraction. */
  std::array<double, 2> gupta_frequencies{{0., 0.}};
  /**
   * Contacts with a clearance (two-sided contacts with a play, the wheel
   * flanges) held at their centred position (closed) or left open.
   */
  bool clearance_closed = true;
};

} // namespace hati

#endif
