#ifndef hati_time_macro_aliasing_h
#define hati_time_macro_aliasing_h

#include <hati/model/discrete_system.h>

#include <string>
#include <vector>

namespace hati
{
/** A free-interface mode of the explicit subdomain (free_interface_modes()). */
struct FreeInterfaceMode
{
  /** Circular frequency Omega (rad/s). */
  double omega = 0.;
  /**
   * Its share of the interface's static flexibility: `sum_k (C_E,k phi)^2 /
   * Omega^2` over the same sum for every flexible mode (phi mass-normalised,
   * C_E the interface rows), 0 for a rigid-body mode. A mode that hardly
   * moves the interface cannot exchange energy through it.
   */
  double share = 0.;
};

/**
 * The free-interface modes of the explicit subdomain of HATI, ascending:
 * `K_E phi = Omega^2 M_E phi` with its lumped mass, its interface DoFs free
 * and its fixed DoFs held (contacts open), by a dense symmetric
 * eigensolution of `M_E^-1/2 K_E M_E^-1/2`, with each mode's share of the
 * flexibility of the interface rows @p rows (explicit numbering). Empty
 * when the part has more than @p max_dofs free DoFs (the check is meant
 * for small explicit zones: its cost grows as n^3).
 */
std::vector<FreeInterfaceMode> free_interface_modes(const DiscreteSystem &explicit_part,
                                                    const std::vector<SparseRow> &rows,
                                                    const unsigned int max_dofs = 2000);

/**
 * The folded phase per macro step (rad) below which the HATI set-up warns of
 * a mode (aliasing_modes()): on `beam_solid_prism.prm` the ratios with a
 * mode of at least aliasing_share folded within 0.3 rad (m = 16-19, 22-25)
 * have translation errors of 0.3-1.3 % against the fully explicit run, the
 * others (m <= 15, 20, 21) at most 0.09 % (doc/theory.md 11.3, the sweep).
 */
constexpr double aliasing_phase = 0.3;
/** The smallest share of the interface flexibility of a mode warned of. */
constexpr double aliasing_share = 0.01;

/** An explicit free-interface mode that macro-step sampling folds down. */
struct AliasingMode
{
  /** Its number among the free-interface modes, from 1 (ascending). */
  unsigned int number = 0;
  /** Its share of the interface flexibility (FreeInterfaceMode::share). */
  double share = 0.;
  /** Its frequency `Omega / 2 pi` (Hz). */
  double frequency = 0.;
  /**
   * The frequency it appears at when sampled once per macro step,
   * `|Omega - k 2 pi / DT| / 2 pi` with `k = round(Omega DT / 2 pi) >= 1` (Hz).
   */
  double folded_frequency = 0.;
};

/**
 * Macro-step aliasing (spec G3'', doc/theory.md 11.3): the modes of
 * @p modes with at least @p min_share of the interface flexibility, above
 * the macro step's Nyquist frequency `pi / DT`, `DT = m dt` (@p m, @p dt in
 * s), that fold to within @p folded_phase (rad per macro step) of zero
 * frequency, `|Omega DT - 2 pi k| < folded_phase`, where they meet the
 * coupled structure's low modes; the G3' coupling then lets them exchange
 * energy with those modes once per macro step (a mode splitting whose error
 * does not shrink with DT).
 */
std::vector<AliasingMode> aliasing_modes(const std::vector<FreeInterfaceMode> &modes,
                                         const double dt,
                                         const unsigned int m,
                                         const double folded_phase,
                                         const double min_share);

/**
 * The one-line set-up warning for @p aliased (empty if none): the worst
 * mode, its frequency, where it folds to, and the ratios within 4 of @p m
 * with no aliasing mode among @p modes (same criteria).
 */
std::string aliasing_warning(const std::vector<AliasingMode> &aliased,
                             const std::vector<FreeInterfaceMode> &modes,
                             const double dt,
                             const unsigned int m,
                             const double folded_phase,
                             const double min_share);
} // namespace hati

#endif
