#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <hati/loading/accelerogram.h>
#include <hati/loading/artificial_records.h>
#include <hati/loading/design_spectrum.h>
#include <hati/loading/spectral_matching.h>
#include <hati/output/response_spectrum.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <sstream>

namespace hati
{
namespace
{
/** @p x as a short text (6 digits). */
std::string number_text(const double x)
{
  std::ostringstream s;
  s << x;
  return s.str();
}
} // namespace

void ArtificialRecordParameters::declare_parameters(ParameterHandler &prm)
{
  prm.enter_subsection("Artificial records");
  prm.declare_entry("Number",
                    "0",
                    Patterns::Integer(0, max_artificial_records),
                    "How many spectrum-compatible records to generate against subsection "
                    "Design spectrum (-), each with every component of Components, as "
                    "PEER AT2 files in <output>/records/ (art01_X.AT2, ...) with "
                    "records.png; Suite/Records = artificial runs them as a suite. 0: "
                    "none.");
  prm.declare_entry(
      "Duration", "20", Patterns::Double(0.), "Length of each record (s), > 0.");
  prm.declare_entry(
      "Strong motion",
      "10",
      Patterns::Double(0.),
      "Stationary part of the trapezoidal intensity envelope (s), at most "
      "the Duration: the envelope rises linearly over a quarter of the rest "
      "and decays linearly over three quarters.");
  prm.declare_entry("Seed",
                    "1",
                    Patterns::Integer(0),
                    "Seed of the random phases (integer >= 0): the same seed and "
                    "parameters give the same records bitwise.");
  prm.declare_entry("Components",
                    "X, Z",
                    Patterns::MultipleSelection("X|Y|Z"),
                    "The global axes of each record, each an independent record: X and "
                    "Y match the horizontal spectrum, Z the vertical one (Design "
                    "spectrum/Vertical).");
  prm.declare_entry(
      "Matching tolerance",
      "0.05",
      Patterns::Double(0.),
      "Largest relative deviation |S_a / S_a,target - 1| of a record's "
      "spectrum (at the Design spectrum's Damping ratio) over 200 periods "
      "of the Period range, and of its peak from the target's zero-period "
      "value (-), > 0: the correction iterates until both hold (with new "
      "phases if needed, 12 draws at most), else the generation is refused.");
  prm.declare_entry("Time step",
                    "0.005",
                    Patterns::Double(0.),
                    "Sample interval of the records (s), > 0: the records hold "
                    "frequencies up to 1 / (2 Time step).");
  prm.leave_subsection();
}

void ArtificialRecordParameters::parse_parameters(ParameterHandler &prm)
{
  prm.enter_subsection("Artificial records");
  number = prm.get_integer("Number");
  duration = prm.get_double("Duration");
  strong_motion = prm.get_double("Strong motion");
  seed = prm.get_integer("Seed");
  components.clear();
  for (const auto &c : Utilities::split_string_list(prm.get("Components")))
    components.push_back(c[0] - 'X');
  std::sort(components.begin(), components.end());
  components.erase(std::unique(components.begin(), components.end()), components.end());
  matching_tolerance = prm.get_double("Matching tolerance");
  time_step = prm.get_double("Time step");
  prm.leave_subsection();
  if (number == 0)
    return;
  const std::string head = "Artificial records/";
  AssertThrow(duration > 0. && duration <= 3600.,
              ExcMessage(head + "Duration: " + number_text(duration) +
                         ": a length 0 < D <= 3600 s is expected"));
  AssertThrow(strong_motion > 0. && strong_motion <= duration,
              ExcMessage(head + "Strong motion: " + number_text(strong_motion) +
                         ": 0 < strong motion <= Duration (" + number_text(duration) +
                         " s) is expected"));
  AssertThrow(time_step > 0. && time_step <= 0.1,
              ExcMessage(head + "Time step: " + number_text(time_step) +
                         ": 0 < dt <= 0.1 s is expected"));
  AssertThrow(duration / time_step <= max_record_samples,
              ExcMessage(head + "Time step: " + number_text(time_step) + " s over the " +
                         number_text(duration) + " s Duration gives " +
                         number_text(duration / time_step) +
                         " samples a record, more than the " +
                         number_text(max_record_samples) +
                         " the matching affords (about 0.3 ms a sample: half a minute a "
                         "record at the bound); a larger Time step or a shorter Duration "
                         "is expected"));
  AssertThrow(matching_tolerance > 0.,
              ExcMessage(head + "Matching tolerance: " + number_text(matching_tolerance) +
                         ": a tolerance > 0 is "
                         "expected"));
  AssertThrow(!components.empty(),
              ExcMessage(head + "Components: at least one of X, Y, Z is expected"));
}

std::vector<double> matching_periods(const DesignSpectrum &target)
{
  const auto &range = target.parameters().period_range;
  return log_spaced_periods(range[0], range[1], 200);
}

ArtificialRecord generate_record(const DesignSpectrum &target,
                                 const ArtificialRecordParameters &p,
                                 const unsigned int index,
                                 const unsigned int axis)
{
  // random phases: seed, record and axis through seed_seq (a fixed algorithm)
  std::seed_seq sequence{std::uint32_t(p.seed & 0xffffffffu),
                         std::uint32_t(p.seed >> 32),
                         std::uint32_t(index),
                         std::uint32_t(axis)};
  std::mt19937_64 random(sequence);
  ArtificialRecord record;
  record.time_step = p.time_step;
  double deviation = std::numeric_limits<double>::max();
  unsigned int attempt = 0;
  // a draw of phases that the corrections cannot bring within the
  // tolerance is replaced by the next draw of the same generator
  for (; attempt < max_matching_attempts && deviation > p.matching_tolerance; ++attempt)
  {
    double d = 0.;
    unsigned int iterations = 0;
    std::vector<double> a =
        match_record(target, p, axis, random, max_matching_iterations, d, iterations);
    record.iterations += iterations;
    if (d < deviation)
    {
      deviation = d;
      record.acceleration = std::move(a);
    }
  }
  record.attempts = attempt;
  record.max_deviation = deviation;
  AssertThrow(
      deviation <= p.matching_tolerance,
      ExcMessage("Artificial records/Matching tolerance: record " +
                 std::to_string(index) + " " + std::string(1, char('X' + axis)) +
                 " deviates from the target by " + number_text(deviation) + " after " +
                 std::to_string(max_matching_attempts) +
                 " draws of phases, more than the tolerance " +
                 number_text(p.matching_tolerance) +
                 " (a larger tolerance, a longer Strong motion or another Seed)"));
  record.peak_acceleration = 0.;
  for (const double x : record.acceleration)
    record.peak_acceleration = std::max(record.peak_acceleration, std::abs(x));
  std::vector<double> v, d;
  integrate_record(record.acceleration, p.time_step, v, d);
  double peak_v = 0., peak_d = 0.;
  for (std::size_t i = 0; i < v.size(); ++i)
  {
    peak_v = std::max(peak_v, std::abs(v[i]));
    peak_d = std::max(peak_d, std::abs(d[i]));
  }
  record.end_velocity_ratio = std::abs(v.back()) / std::max(peak_v, 1e-300);
  record.end_displacement_ratio = std::abs(d.back()) / std::max(peak_d, 1e-300);
  return record;
}

std::string at2_text(const ArtificialRecord &record,
                     const std::string &title,
                     const std::string &description)
{
  std::ostringstream s;
  char buffer[64];
  std::snprintf(buffer,
                sizeof(buffer),
                "NPTS= %zu, DT= %.9g SEC",
                record.acceleration.size(),
                record.time_step);
  s << "hati artificial record " << title << "\n"
    << description << "\n"
    << "ACCELERATION TIME SERIES IN UNITS OF G\n"
    << buffer << "\n";
  for (std::size_t i = 0; i < record.acceleration.size(); ++i)
  {
    std::snprintf(
        buffer, sizeof(buffer), "%17.9E", record.acceleration[i] / standard_gravity);
    s << buffer << ((i % 5 == 4 || i + 1 == record.acceleration.size()) ? "\n" : "");
  }
  return s.str();
}
} // namespace hati
