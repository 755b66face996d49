// The combination rules of the response-spectrum analysis
// (analysis/spectral_combination.h, doc/theory.md 14, issue #57), against
// the formulas written out here and hand values:
// - Der Kiureghian's coefficient (RS1): rho(r = 0.9, 5 %) = 0.4730 by hand
//   (8 0.0025 1.9 0.9^1.5 / (0.19^2 + 4 0.0025 0.9 1.9^2) = 0.032445 /
//   0.068590), 1 at equal frequencies, symmetric, and not the 0.18 of the
//   eigenvalue ratio that a published helper uses by mistake;
// - two closely spaced modes (frequency ratios 0.8, 0.9, 0.95): CQC against
//   sqrt(R1^2 + R2^2 + 2 rho R1 R2) written out, SRSS against
//   sqrt(R1^2 + R2^2), 1e-10, with responses of the same and of opposite
//   signs;
// - Gupta's rigid fraction (RS3) at f1, f2 and the geometric mean (0.5), and
//   the rigid part with the missing mass: no rigid fraction gives
//   sqrt(R_modes^2 + R_missing^2), every mode rigid the algebraic sum;
// - the directional rules (RS4) by hand from the peaks (3, 2, 1) (1e-12);
// - the one-line refusals of unknown rule names.
#include <hati/analysis/spectral_combination.h>

#include "test_tools.h"

#include <cmath>
#include <string>
#include <vector>

namespace hati_unit_spectral_combination
{

using namespace hati;
using hati_test::check;
using hati_test::expect;

namespace
{
/** Der Kiureghian's coefficient written out (r = omega_j / omega_i). */
double rho_by_hand(const double r, const double xi)
{
  return 8. * xi * xi * (1. + r) * std::pow(r, 1.5) /
         (std::pow(1. - r * r, 2) + 4. * xi * xi * r * std::pow(1. + r, 2));
}

void check_correlation()
{
  const double w = 2. * M_PI * 3.;
  check("rho(0.9, 5 %) (hand: 0.4730)", cqc_correlation(w, 0.9 * w, 0.05), 0.4730, 5e-5);
  check("rho(0.9, 5 %) against the formula",
        cqc_correlation(w, 0.9 * w, 0.05),
        rho_by_hand(0.9, 0.05),
        1e-14);
  check("rho of equal frequencies", cqc_correlation(w, w, 0.05), 1., 1e-15);
  check("rho symmetric (0.8)",
        cqc_correlation(0.8 * w, w, 0.02),
        cqc_correlation(w, 0.8 * w, 0.02),
        1e-14);
  // with the eigenvalue ratio r = 0.81 the coefficient would be 0.18
  check("the eigenvalue ratio's coefficient (the mistake) is 0.18",
        rho_by_hand(0.81, 0.05),
        0.18,
        5e-3);
  expect(std::abs(cqc_correlation(w, 0.9 * w, 0.05) - rho_by_hand(0.81, 0.05)) > 0.25,
         "the frequency ratio is used, not the eigenvalue ratio");
  check("well separated modes (ratio 0.2) hardly correlate",
        cqc_correlation(w, 0.2 * w, 0.05),
        rho_by_hand(0.2, 0.05),
        1e-15);
}

void check_two_modes()
{
  const double w1 = 2. * M_PI * 5.;
  for (const double ratio : {0.8, 0.9, 0.95})
    for (const double sign : {1., -1.})
    {
      const double r1 = 0.012, r2 = sign * 0.007;
      const std::vector<double> modal = {r1, r2}, omega = {w1, ratio * w1};
      const double rho = rho_by_hand(ratio, 0.05);
      const std::string tag = "ratio " + std::to_string(ratio).substr(0, 4) +
                              (sign > 0 ? ", same signs" : ", opposite signs");
      check("CQC, " + tag,
            combine_modes(modal, omega, 0.05, ModalCombination::CQC),
            std::sqrt(r1 * r1 + r2 * r2 + 2. * rho * r1 * r2),
            1e-10);
      check("SRSS, " + tag,
            combine_modes(modal, omega, 0.05, ModalCombination::SRSS),
            std::sqrt(r1 * r1 + r2 * r2),
            1e-10);
    }
  // three modes: the double sum over every pair
  const std::vector<double> modal = {1., -0.5, 0.25}, omega = {10., 11., 30.};
  double sum = 0.;
  for (unsigned int i = 0; i < 3; ++i)
    for (unsigned int j = 0; j < 3; ++j)
      sum += rho_by_hand(omega[j] / omega[i], 0.03) * modal[i] * modal[j];
  check("CQC of three modes, the double sum written out",
        combine_modes(modal, omega, 0.03, ModalCombination::CQC),
        std::sqrt(sum),
        1e-12);
}

void check_rigid_part()
{
  check("Gupta alpha at f1", gupta_rigid_fraction(2., 2., 32.), 0., 0.);
  check("Gupta alpha below f1", gupta_rigid_fraction(1., 2., 32.), 0., 0.);
  check("Gupta alpha at f2", gupta_rigid_fraction(32., 2., 32.), 1., 0.);
  check("Gupta alpha at sqrt(f1 f2) = 8 Hz (hand: 0.5)",
        gupta_rigid_fraction(8., 2., 32.),
        0.5,
        1e-15);
  const std::vector<double> modal = {0.3, -0.2, 0.1}, omega = {10., 40., 200.};
  const double modes = combine_modes(modal, omega, 0.05, ModalCombination::CQC);
  check("missing mass without rigid fractions: SRSS with the modes",
        combine_with_rigid_part(modal, omega, 0.05, ModalCombination::CQC, {}, 0.05),
        std::sqrt(modes * modes + 0.05 * 0.05),
        1e-15);
  check("every mode rigid: the algebraic sum with the missing mass (hand 0.25)",
        combine_with_rigid_part(
            modal, omega, 0.05, ModalCombination::CQC, {1., 1., 1.}, 0.05),
        0.25,
        1e-15);
  // alpha = (0, 0.5, 1): periodic (0.3, -0.2 sqrt(0.75), 0), rigid -0.1 + 0.1 + 0.05
  const std::vector<double> periodic = {0.3, -0.2 * std::sqrt(0.75), 0.};
  const double p = combine_modes(periodic, omega, 0.05, ModalCombination::SRSS);
  check("alpha = 0, 0.5, 1: periodic by SRSS, rigid 0.05 (hand)",
        combine_with_rigid_part(
            modal, omega, 0.05, ModalCombination::SRSS, {0., 0.5, 1.}, 0.05),
        std::sqrt(p * p + 0.05 * 0.05),
        1e-15);
}

void check_directions()
{
  const std::array<double, 3> peaks = {{3., 2., 1.}};
  check("directions SRSS (hand: sqrt(14))",
        combine_directions(peaks, DirectionalCombination::SRSS),
        std::sqrt(14.),
        1e-12);
  check("100-40-40 (hand: 3 + 0.4 (2 + 1) = 4.2)",
        combine_directions(peaks, DirectionalCombination::percent_40),
        4.2,
        1e-12);
  check("100-30-30 (hand: 3 + 0.3 (2 + 1) = 3.9)",
        combine_directions(peaks, DirectionalCombination::percent_30),
        3.9,
        1e-12);
  check("100-40-40, Y governs (1, 5, 0; hand 5.4)",
        combine_directions({{1., 5., 0.}}, DirectionalCombination::percent_40),
        5.4,
        1e-12);
  expect(parse_directional_combination("100-30-30") ==
                 DirectionalCombination::percent_30 &&
             name_of(DirectionalCombination::percent_40) == "100-40-40" &&
             parse_modal_combination("SRSS") == ModalCombination::SRSS,
         "rule names parse and print back");
  for (const std::string bad : {"ABS", "cqc", ""})
    try
    {
      parse_modal_combination(bad);
      expect(false, "modal combination '" + bad + "' refused");
    }
    catch (const std::exception &e)
    {
      const std::string m = hati_test::message_of(e);
      expect(m == "Response spectrum/Modal combination: '" + bad +
                      "': CQC or SRSS is expected",
             "modal combination '" + bad + "' refused: " + m);
    }
  try
  {
    parse_directional_combination("100-40");
    expect(false, "directional combination '100-40' refused");
  }
  catch (const std::exception &e)
  {
    const std::string m = hati_test::message_of(e);
    expect(m.rfind("Response spectrum/Directional combination: '100-40'", 0) == 0,
           "directional combination '100-40' refused: " + m);
  }
}
} // namespace

HATI_UNIT_TEST(spectral_combination)
{
  try
  {
    check_correlation();
    check_two_modes();
    check_rigid_part();
    check_directions();
  }
  catch (const std::exception &e)
  {
    expect(false, std::string("unexpected exception: ") + hati_test::message_of(e));
  }
  return hati_test::finish();
}
} // namespace hati_unit_spectral_combination
