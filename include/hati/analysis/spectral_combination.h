#ifndef hati_analysis_spectral_combination_h
#define hati_analysis_spectral_combination_h

#include <array>
#include <string>
#include <vector>

namespace hati
{
/**
 * The rules of a response-spectrum analysis that turn peak modal responses
 * into one peak (doc/theory.md 14): the modal combination (RS1, RS2), the
 * rigid part of the modes and the missing mass (RS3), and the combination
 * of the excitation directions (RS4). Plain functions of numbers: the
 * analysis computes each mode's response of a quantity once (its sign
 * included) and combines it here.
 */
enum class ModalCombination
{
  /** Complete quadratic combination with Der Kiureghian's coefficient. */
  CQC,
  /** Square root of the sum of the squares. */
  SRSS
};

/** How the peaks of the three excitation directions are combined (RS4). */
enum class DirectionalCombination
{
  /** Square root of the sum of the squares of the directions' peaks. */
  SRSS,
  /** The largest of R_i + 0.4 (R_j + R_k) (ASCE 4, ASME NOG-1 practice). */
  percent_40,
  /** The largest of R_i + 0.3 (R_j + R_k) (EN 1998-1 4.3.3.5.2). */
  percent_30
};

/** `CQC` or `SRSS`; anything else throws naming the value and the choices. */
ModalCombination parse_modal_combination(const std::string &name);

/** `SRSS`, `100-40-40` or `100-30-30`; anything else throws likewise. */
DirectionalCombination parse_directional_combination(const std::string &name);

/** The name a rule is parsed from (for summary.json and the terminal). */
std::string name_of(ModalCombination rule);
/** The name a rule is parsed from. */
std::string name_of(DirectionalCombination rule);

/**
 * Der Kiureghian's correlation coefficient of two modes of circular
 * frequencies @p omega_i and @p omega_j (rad/s, > 0) at one damping ratio
 * @p xi (-, > 0) for both (RS1): with r = omega_j / omega_i, the ratio of
 * the frequencies (not of the eigenvalues omega^2),
 * rho = 8 xi^2 (1 + r) r^1.5 / ((1 - r^2)^2 + 4 xi^2 r (1 + r)^2);
 * 1 for equal frequencies, symmetric in i and j.
 */
double cqc_correlation(double omega_i, double omega_j, double xi);

/**
 * The combined peak of a quantity whose peak responses in the modes are
 * @p modal (signed, one per mode, in the order of @p omega, rad/s) (RS2):
 * CQC sqrt(sum_i sum_j rho_ij R_i R_j), SRSS sqrt(sum_i R_i^2); >= 0.
 * Throws if the two lists differ in length.
 */
double combine_modes(const std::vector<double> &modal,
                     const std::vector<double> &omega,
                     double xi,
                     ModalCombination rule);

/**
 * Gupta's rigid fraction of a mode of frequency @p f (Hz) between the
 * frequencies @p f1 < @p f2 (Hz) (RS3): alpha = ln(f / f1) / ln(f2 / f1)
 * clipped to [0, 1]; 0 below f1 (periodic), 1 above f2 (rigid).
 */
double gupta_rigid_fraction(double f, double f1, double f2);

/**
 * The combined peak of a quantity with the rigid part of its modes and the
 * missing mass (RS3): the periodic parts sqrt(1 - alpha_k^2) R_k combined
 * by @p rule, the rigid parts alpha_k R_k summed algebraically with
 * @p missing_mass (the static response to the inertia the kept modes leave
 * out, at the zero-period acceleration), the two by SRSS:
 * R = sqrt(R_periodic^2 + (sum_k alpha_k R_k + R_missing)^2).
 * @p rigid_fraction empty: every alpha_k = 0 (no rigid response), so that
 * R = sqrt(R_modes^2 + R_missing^2) (EN 1998-1 4.3.3.3, RG 1.92 method A).
 */
double combine_with_rigid_part(const std::vector<double> &modal,
                               const std::vector<double> &omega,
                               double xi,
                               ModalCombination rule,
                               const std::vector<double> &rigid_fraction,
                               double missing_mass);

/**
 * The coefficients of a modal combination kept for many quantities: the
 * correlation matrix rho_ij of the modes (RS1; the identity for SRSS) and
 * their rigid fractions alpha_k (RS3), so that combining a quantity costs
 * its double sum only. combine() is combine_with_rigid_part() with them.
 */
class ModalCorrelation
{
public:
  /**
   * @p omega (rad/s, > 0), @p xi (-, > 0), @p rule; @p rigid_fraction empty
   * or one per mode.
   */
  ModalCorrelation(const std::vector<double> &omega,
                   double xi,
                   ModalCombination rule,
                   const std::vector<double> &rigid_fraction = {});

  /** The number of modes. */
  std::size_t size() const { return n; }

  /**
   * The combined peak of the modal responses @p modal (signed, size() of
   * them, at a stride @p stride) with the missing mass @p missing_mass
   * (RS2, RS3).
   */
  double combine(const double *modal, double missing_mass, std::size_t stride = 1) const;

private:
  std::size_t n;
  bool srss;
  /** rho_ij, i < j, row by row (the strict upper triangle), times 2. */
  std::vector<double> twice_rho;
  std::vector<double> alpha, periodic_factor;
};

/**
 * The combined peak of the three directions' peaks @p peaks (X, Y, Z,
 * >= 0; 0 for a direction not excited) (RS4): SRSS sqrt(R_X^2 + R_Y^2 +
 * R_Z^2), or the largest over i of R_i + c (R_j + R_k) with c = 0.4 or 0.3.
 */
double combine_directions(const std::array<double, 3> &peaks,
                          DirectionalCombination rule);
} // namespace hati

#endif
