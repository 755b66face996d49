#ifndef hati_analysis_modal_damping_h
#define hati_analysis_modal_damping_h

#include <hati/analysis/modal_analysis.h>
#include <hati/base/summary_value.h>
#include <hati/model/discrete_system.h>
#include <hati/time/rayleigh_damping.h>

#include <string>
#include <utility>
#include <vector>

namespace hati
{
/**
 * Rayleigh damping fitted to two modes of a model (doc/theory.md 7.4): the
 * first elastic mode dominated by vertical (global Z) effective mass and the
 * first dominated by horizontal (X or Y) effective mass.
 */
struct ModalRayleighDamping
{
  /** Damping ratio zeta reached at both frequencies (-). */
  double damping_ratio = 0.;
  /** Frequency of the first vertical mode (Hz). */
  double f_vertical = 0.;
  /** Frequency of the first horizontal mode (Hz). */
  double f_horizontal = 0.;
  /** Their numbers in the ascending list of modes (1-based, -). */
  unsigned int mode_vertical = 0, mode_horizontal = 0;
  /** Mass-proportional coefficient a0 = 2 zeta w1 w2 / (w1 + w2) (1/s). */
  double a0 = 0.;
  /** Stiffness-proportional coefficient a1 = 2 zeta / (w1 + w2) (s). */
  double a1 = 0.;
};

/**
 * The modes of @p system with its zero-gap contacts closed
 * (compute_modes(), doc/theory.md 7.3) and the Rayleigh coefficients of
 * doc/theory.md 4.4 for the damping ratio @p damping_ratio at the first
 * vertical and the first horizontal mode (doc/theory.md 7.4). A mode is
 * rigid (skipped) if `omega^2 <= 1e-8 omega_ref^2`, `omega_ref` the highest
 * computed frequency; an elastic mode is dominated by direction d if its
 * effective mass along d is the largest of the three and at least 1e-3 of
 * the free mass along d (modes without net participation are skipped).
 * Up to 160 modes are searched, more only if the model has fewer free DoFs.
 * Equal frequencies are accepted: the formulas then give zeta at that
 * frequency and more damping at every other one.
 *
 * @param system the discrete system (stiffness, mass, contacts).
 * @param damping_ratio zeta (-), > 0.
 * @param linear_solver `Time integration/Newmark/Linear solver` (auto, KLU,
 *        MUMPS, direct or iterative): the factorisation of the modal
 *        analysis (compute_modes()).
 *
 * Throws ExcMessage naming Time integration/Damping if no vertical or no
 * horizontal mode is found.
 */
ModalRayleighDamping modal_rayleigh_damping(const DiscreteSystem &system,
                                            const double damping_ratio,
                                            const std::string &linear_solver = "auto");

/**
 * The default damping of a transient run: if the model's default damping
 * ratio @p zeta is > 0, @p damping was not given by the user
 * (`RayleighDamping::given`) and @p method applies Rayleigh damping (every
 * method but event-driven, which is left undamped with a note), set
 * `damping.a0`, `damping.a1` from modal_rayleigh_damping(), print the two
 * frequencies and the coefficients, and return the summary.json entries
 * `damping_frequencies` ([f_vertical, f_horizontal], Hz), `rayleigh_a0`
 * (1/s) and `rayleigh_a1` (s). Returns no entry otherwise.
 *
 * @param zeta the model's default damping ratio (-, Model::default_damping_ratio()).
 * @param system its discrete system, built.
 * @param method Time integration/Method.
 * @param linear_solver `Time integration/Newmark/Linear solver` (auto, KLU,
 *        MUMPS, direct or iterative), passed to modal_rayleigh_damping().
 * @param damping the Time integration/Damping of the run, updated.
 */
SummaryEntries apply_default_damping(const double zeta,
                                     const DiscreteSystem &system,
                                     const std::string &method,
                                     const std::string &linear_solver,
                                     RayleighDamping &damping);
} // namespace hati

#endif
