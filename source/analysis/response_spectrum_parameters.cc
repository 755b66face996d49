// subsection Response spectrum (doc/user_guide.md 4.8).

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <hati/analysis/response_spectrum_parameters.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace hati
{
namespace
{
/** @p text as a finite number, or one line naming @p entry. */
double parse_number(const std::string &text, const std::string &entry)
{
  const std::string t = Utilities::trim(text);
  char *end = nullptr;
  const double value = std::strtod(t.c_str(), &end);
  AssertThrow(!t.empty() && end == t.c_str() + t.size() && std::isfinite(value),
              ExcMessage(entry + ": '" + t + "' is not a number"));
  return value;
}
} // namespace

void ResponseSpectrumParameters::declare_parameters(ParameterHandler &prm)
{
  prm.enter_subsection("Response spectrum");
  prm.declare_entry(
      "Directions",
      "X, Y, Z",
      Patterns::Anything(),
      "The excitation directions of Analysis/Type = response spectrum, a list of X, Y "
      "and Z (global axes), each with its spectrum of subsection Design spectrum "
      "(Z: the EC8 vertical spectrum, or a table).");
  prm.declare_entry(
      "Modal combination",
      "CQC",
      Patterns::Selection("CQC|SRSS"),
      "How the modes' peaks are combined (doc/theory.md 14, RS1-RS2): CQC, the "
      "complete quadratic combination with Der Kiureghian's correlation coefficient on "
      "the ratio of the frequencies at the spectrum's Damping ratio; SRSS, the square "
      "root of the sum of the squares.");
  prm.declare_entry("Cutoff frequency",
                    "33",
                    Patterns::Anything(),
                    "Modes up to this frequency (Hz, > 0) are combined: every one of "
                    "them is computed (counted first, RS5), however many Analysis/Number "
                    "of modes asks for.");
  prm.declare_entry("Maximum modes",
                    "500",
                    Patterns::Integer(1),
                    "The most modes computed (-): a cut-off that needs more is refused "
                    "with the count it needs.");
  prm.declare_entry(
      "Missing mass",
      "true",
      Patterns::Bool(),
      "Add the static response to the inertia the kept modes leave out, K^-1 (M r - "
      "sum Gamma_k M phi_k) times the spectrum's zero-period acceleration, to the modal "
      "part by SRSS (RS3; EN 1998-1 4.3.3.3, US NRC RG 1.92 method A).");
  prm.declare_entry(
      "Rigid response",
      "none",
      Patterns::Selection("none|Gupta"),
      "Gupta: the rigid part alpha_k R_k of the modes between the Gupta frequencies "
      "(alpha_k = ln(f/f1) / ln(f2/f1), 0 below f1, 1 above f2) is summed "
      "algebraically with the missing mass (RS3, US NRC RG 1.92); none: alpha = 0.");
  prm.declare_entry("Gupta frequencies",
                    "",
                    Patterns::Anything(),
                    "f1, f2 (Hz, 0 < f1 < f2) of Rigid response = Gupta.");
  prm.declare_entry(
      "Directional combination",
      "SRSS",
      Patterns::Selection("SRSS|100-40-40|100-30-30"),
      "How the directions' peaks are combined (RS4): SRSS; 100-40-40 (ASCE 4, ASME "
      "NOG-1 practice) or 100-30-30 (EN 1998-1 4.3.3.5.2), the largest of R_i + c (R_j "
      "+ R_k).");
  prm.declare_entry(
      "Clearance contacts",
      "closed",
      Patterns::Selection("closed|open"),
      "Two-sided contacts with a clearance (the wheel flanges' lateral play): closed, "
      "held as bilateral supports at their centred position (the flanges engaged); "
      "open, left free as in the modal analysis (the default crane then has modes of "
      "zero frequency along its play, which are refused as mechanisms).");
  prm.leave_subsection();
}

void ResponseSpectrumParameters::parse_parameters(ParameterHandler &prm)
{
  prm.enter_subsection("Response spectrum");
  directions.clear();
  for (const std::string &item : Utilities::split_string_list(prm.get("Directions"), ','))
  {
    const std::string axis = Utilities::trim(item);
    AssertThrow(axis == "X" || axis == "Y" || axis == "Z",
                ExcMessage("Response spectrum/Directions: '" + axis +
                           "': a list of X, Y and Z is expected"));
    const unsigned int d = axis[0] - 'X';
    AssertThrow(std::find(directions.begin(), directions.end(), d) == directions.end(),
                ExcMessage("Response spectrum/Directions: " + axis + " is given twice"));
    directions.push_back(d);
  }
  AssertThrow(!directions.empty(),
              ExcMessage("Response spectrum/Directions: empty; a list of X, Y and Z is "
                         "expected"));
  std::sort(directions.begin(), directions.end());
  modal_combination = parse_modal_combination(prm.get("Modal combination"));
  directional_combination =
      parse_directional_combination(prm.get("Directional combination"));
  cutoff_frequency =
      parse_number(prm.get("Cutoff frequency"), "Response spectrum/Cutoff frequency");
  AssertThrow(
      cutoff_frequency > 0.,
      ExcMessage("Response spectrum/Cutoff frequency: " + prm.get("Cutoff frequency") +
                 " Hz; a frequency > 0 is expected"));
  maximum_modes = prm.get_integer("Maximum modes");
  missing_mass = prm.get_bool("Missing mass");
  gupta = prm.get("Rigid response") == "Gupta";
  const std::string frequencies = prm.get("Gupta frequencies");
  if (gupta)
  {
    const std::vector<std::string> items = Utilities::split_string_list(frequencies, ',');
    AssertThrow(items.size() == 2,
                ExcMessage("Response spectrum/Gupta frequencies: '" + frequencies +
                           "': two frequencies f1, f2 (Hz) are expected with Rigid "
                           "response = Gupta"));
    for (unsigned int i = 0; i < 2; ++i)
      gupta_frequencies[i] =
          parse_number(items[i], "Response spectrum/Gupta frequencies");
    AssertThrow(gupta_frequencies[0] > 0. && gupta_frequencies[1] > gupta_frequencies[0],
                ExcMessage("Response spectrum/Gupta frequencies: '" + frequencies +
                           "': 0 < f1 < f2 (Hz) is expected"));
  }
  clearance_closed = prm.get("Clearance contacts") == "closed";
  prm.leave_subsection();
}
} // namespace hati
