#include <deal.II/base/exceptions.h>

#include <hati/time/damping.h>

#include <sstream>

namespace hati
{
namespace
{
/** Rayleigh damping: RayleighDamping read from its entries. */
DampingModel read_rayleigh_damping(dealii::ParameterHandler &prm)
{
  AssertThrow(prm.get_double("Lower frequency") == 0. &&
                  prm.get_double("Upper frequency") == 0.,
              dealii::ExcMessage(
                  "Time integration/Damping: Lower frequency and Upper frequency "
                  "belong to Type = frequency range; Type = Rayleigh takes the "
                  "Damping ratio at the First frequency and the Second frequency (or "
                  "the Mass and Stiffness coefficients)."));
  DampingModel damping;
  damping.type = "Rayleigh";
  damping.rayleigh.parse_parameters(prm);
  return damping;
}

/** Declare the entries of frequency-range damping besides the shared Damping ratio. */
void declare_frequency_range_damping(dealii::ParameterHandler &prm)
{
  prm.declare_entry("Lower frequency",
                    "0",
                    dealii::Patterns::Double(0.),
                    "Type = frequency range: lower end f1 (Hz) of the band over which "
                    "the damping ratio is nearly the Damping ratio (A8).");
  prm.declare_entry("Upper frequency",
                    "0",
                    dealii::Patterns::Double(0.),
                    "Type = frequency range: upper end f2 (Hz) of the band, > Lower "
                    "frequency.");
  prm.declare_entry("Number of branches",
                    "3",
                    dealii::Patterns::Integer(1, 8),
                    "Type = frequency range: number of Maxwell branches (memory "
                    "vectors), relaxation times log-spaced over the band (3 fits "
                    "bands up to about two decades within a few percent).");
}

/** Frequency-range damping: the branches fitted to the entries, checked. */
DampingModel read_frequency_range_damping(dealii::ParameterHandler &prm)
{
  DampingModel damping;
  damping.type = "frequency range";
  damping.ratio = prm.get_double("Damping ratio");
  damping.lower_frequency = prm.get_double("Lower frequency");
  damping.upper_frequency = prm.get_double("Upper frequency");
  const unsigned int n = prm.get_integer("Number of branches");
  AssertThrow(prm.get_double("Mass coefficient") == 0. &&
                  prm.get_double("Stiffness coefficient") == 0. &&
                  prm.get_double("First frequency") == 0. &&
                  prm.get_double("Second frequency") == 0.,
              dealii::ExcMessage(
                  "Time integration/Damping: Type = frequency range is given by "
                  "Damping ratio, Lower frequency, Upper frequency and Number of "
                  "branches; remove the Rayleigh entries Mass coefficient, Stiffness "
                  "coefficient, First frequency and Second frequency."));
  std::ostringstream s;
  s.precision(6);
  if (!(damping.ratio > 0. && damping.ratio <= 0.3))
  {
    s << "Time integration/Damping: Type = frequency range needs 0 < Damping ratio "
         "<= 0.3, got Damping ratio = "
      << damping.ratio << ".";
    AssertThrow(false, dealii::ExcMessage(s.str()));
  }
  if (!(damping.lower_frequency > 0. &&
        damping.lower_frequency < damping.upper_frequency))
  {
    s << "Time integration/Damping: Type = frequency range needs 0 < Lower frequency "
         "< Upper frequency (Hz), got Lower frequency = "
      << damping.lower_frequency << ", Upper frequency = " << damping.upper_frequency
      << ".";
    AssertThrow(false, dealii::ExcMessage(s.str()));
  }
  damping = frequency_range_damping(
      damping.ratio, damping.lower_frequency, damping.upper_frequency, n);
  if (!damping.fit_acceptable())
  {
    s << "Time integration/Damping: " << n << " Maxwell branches (Number of branches) "
      << "fit the Damping ratio = " << damping.ratio
      << " over Lower frequency = " << damping.lower_frequency
      << " to Upper frequency = " << damping.upper_frequency << " Hz only within "
      << 100. * damping.fit_error
      << " % (at most 10 % accepted): narrow the band or raise Number of branches.";
    AssertThrow(false, dealii::ExcMessage(s.str()));
  }
  return damping;
}
} // namespace

DampingModel frequency_range_damping(const double ratio,
                                     const double lower_frequency,
                                     const double upper_frequency,
                                     const unsigned int n_branches)
{
  DampingModel damping;
  damping.type = "frequency range";
  damping.ratio = ratio;
  damping.lower_frequency = lower_frequency;
  damping.upper_frequency = upper_frequency;
  const MaxwellFit fit =
      fit_maxwell_branches(ratio, lower_frequency, upper_frequency, n_branches);
  damping.branches = fit.branches;
  damping.fit_error = fit.error;
  return damping;
}

const Registry<DampingFactory> &damping_registry()
{
  // one entry per damping model: name, documentation, parameters, reader
  static const Registry<DampingFactory> registry(
      "Time integration/Damping/Type",
      {{"Rayleigh",
        "Rayleigh: C = a0 M + a1 K in CD-Lagrange (A7) and Newmark, from the "
        "coefficients or from a damping ratio at two frequencies",
        RayleighDamping::declare_parameters,
        read_rayleigh_damping},
       {"frequency range",
        "frequency range: a nearly constant Damping ratio between the Lower and "
        "the Upper frequency from Maxwell branches proportional to K with memory "
        "variables (A8 in CD-Lagrange, N4 in Newmark; the explicit stable step "
        "shrinks by 1/sqrt(1 + sum alpha) only, not with the band)",
        declare_frequency_range_damping,
        read_frequency_range_damping}});
  return registry;
}

void declare_damping_parameters(dealii::ParameterHandler &prm)
{
  const auto &models = damping_registry();
  prm.declare_entry("Type",
                    "Rayleigh",
                    dealii::Patterns::Selection(models.selection()),
                    "Damping model of a transient run: " + models.join("; ", "; ", true) +
                        ". Static and modal analyses ignore damping.");
  models.declare_parameters(prm);
}

DampingModel parse_damping_parameters(dealii::ParameterHandler &prm)
{
  return damping_registry().get(prm.get("Type")).create(prm);
}
} // namespace hati
