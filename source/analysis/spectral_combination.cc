#include <deal.II/base/exceptions.h>

#include <hati/analysis/spectral_combination.h>

#include <algorithm>
#include <cmath>

namespace hati
{
using namespace dealii;

ModalCombination parse_modal_combination(const std::string &name)
{
  if (name == "CQC")
    return ModalCombination::CQC;
  if (name == "SRSS")
    return ModalCombination::SRSS;
  AssertThrow(false,
              ExcMessage("Response spectrum/Modal combination: '" + name +
                         "': CQC or SRSS is expected"));
  return ModalCombination::CQC;
}

DirectionalCombination parse_directional_combination(const std::string &name)
{
  if (name == "SRSS")
    return DirectionalCombination::SRSS;
  if (name == "100-40-40")
    return DirectionalCombination::percent_40;
  if (name == "100-30-30")
    return DirectionalCombination::percent_30;
  AssertThrow(false,
              ExcMessage("Response spectrum/Directional combination: '" + name +
                         "': SRSS, 100-40-40 or 100-30-30 is expected"));
  return DirectionalCombination::SRSS;
}

std::string name_of(const ModalCombination rule)
{
  return rule == ModalCombination::CQC ? "CQC" : "SRSS";
}

std::string name_of(const DirectionalCombination rule)
{
  switch (rule)
  {
  case DirectionalCombination::SRSS:
    return "SRSS";
  case DirectionalCombination::percent_40:
    return "100-40-40";
  case DirectionalCombination::percent_30:
    return "100-30-30";
  }
  return "SRSS";
}

double cqc_correlation(const double omega_i, const double omega_j, const double xi)
{
  AssertThrow(omega_i > 0. && omega_j > 0. && xi > 0.,
              ExcMessage("cqc_correlation: frequencies and damping ratio > 0 expected"));
  const double r = omega_j / omega_i;
  const double xi2 = xi * xi;
  return 8. * xi2 * (1. + r) * std::pow(r, 1.5) /
         ((1. - r * r) * (1. - r * r) + 4. * xi2 * r * (1. + r) * (1. + r));
}

double combine_modes(const std::vector<double> &modal,
                     const std::vector<double> &omega,
                     const double xi,
                     const ModalCombination rule)
{
  AssertThrow(modal.size() == omega.size(),
              ExcMessage("combine_modes: one frequency per modal response expected"));
  return ModalCorrelation(omega, xi, rule).combine(modal.data(), 0.);
}

double gupta_rigid_fraction(const double f, const double f1, const double f2)
{
  AssertThrow(
      f1 > 0. && f2 > f1,
      ExcMessage("Response spectrum/Gupta frequencies: two frequencies 0 < f1 < f2 "
                 "(Hz) are expected"));
  if (f <= f1)
    return 0.;
  if (f >= f2)
    return 1.;
  return std::log(f / f1) / std::log(f2 / f1);
}

double combine_with_rigid_part(const std::vector<double> &modal,
                               const std::vector<double> &omega,
                               const double xi,
                               const ModalCombination rule,
                               const std::vector<double> &rigid_fraction,
                               const double missing_mass)
{
  AssertThrow(
      rigid_fraction.empty() || rigid_fraction.size() == modal.size(),
      ExcMessage("combine_with_rigid_part: one rigid fraction per mode expected"));
  AssertThrow(modal.size() == omega.size(),
              ExcMessage("combine_modes: one frequency per modal response expected"));
  return ModalCorrelation(omega, xi, rule, rigid_fraction)
      .combine(modal.data(), missing_mass);
}

ModalCorrelation::ModalCorrelation(const std::vector<double> &omega,
                                   const double xi,
                                   const ModalCombination rule,
                                   const std::vector<double> &rigid_fraction)
    : n(omega.size()), srss(rule == ModalCombination::SRSS), alpha(rigid_fraction)
{
  AssertThrow(alpha.empty() || alpha.size() == n,
              ExcMessage("ModalCorrelation: one rigid fraction per mode expected"));
  if (alpha.empty())
    alpha.assign(n, 0.);
  periodic_factor.resize(n);
  for (std::size_t k = 0; k < n; ++k)
    periodic_factor[k] = std::sqrt(std::max(1. - alpha[k] * alpha[k], 0.));
  if (!srss)
  {
    twice_rho.reserve(n * (n - (n > 0)) / 2);
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j)
        twice_rho.push_back(2. * cqc_correlation(omega[i], omega[j], xi));
  }
}

double ModalCorrelation::combine(const double *modal,
                                 const double missing_mass,
                                 const std::size_t stride) const
{
  double sum = 0., rigid = missing_mass;
  const double *rho = twice_rho.data();
  for (std::size_t i = 0; i < n; ++i)
  {
    const double r_i = periodic_factor[i] * modal[i * stride];
    rigid += alpha[i] * modal[i * stride];
    sum += r_i * r_i;
    if (!srss)
    {
      double row = 0.;
      for (std::size_t j = i + 1; j < n; ++j)
        row += *rho++ * periodic_factor[j] * modal[j * stride];
      sum += r_i * row;
    }
  }
  // a quadratic form with a positive semi-definite matrix: a negative sum
  // is round-off
  return std::sqrt(std::max(sum, 0.) + rigid * rigid);
}

double combine_directions(const std::array<double, 3> &peaks,
                          const DirectionalCombination rule)
{
  if (rule == DirectionalCombination::SRSS)
    return std::sqrt(peaks[0] * peaks[0] + peaks[1] * peaks[1] + peaks[2] * peaks[2]);
  const double c = rule == DirectionalCombination::percent_40 ? 0.4 : 0.3;
  const double sum = peaks[0] + peaks[1] + peaks[2];
  double largest = 0.;
  for (const double r : peaks)
    largest = std::max(largest, r + c * (sum - r));
  return largest;
}
} // namespace hati
