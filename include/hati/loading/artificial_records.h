#ifndef hati_loading_artificial_records_h
#define hati_loading_artificial_records_h

#include <deal.II/base/parameter_handler.h>

#include <cstdint>
#include <string>
#include <vector>

namespace hati
{
using namespace dealii;

class DesignSpectrum;

/** The most artificial records one parameter file may ask for. */
constexpr unsigned int max_artificial_records = 1000;
/** Draws of phases per record, and corrections per draw, before a record is refused. */
constexpr unsigned int max_matching_attempts = 12, max_matching_iterations = 60;
/**
 * The most samples a record may have (Duration / Time step): the matching
 * costs about 0.3 ms and a few kB a sample (measured: 6 s at 0.000625 s,
 * 9,600 samples, 3 s; 6e5 samples ran past 90 s, 6e6 reached
 * std::bad_alloc), so a record at the bound takes about half a minute.
 */
constexpr double max_record_samples = 1e5;
/** The matching's measured cost per sample of a record, all its corrections (s). */
constexpr double seconds_per_record_sample = 3e-4;

/**
 * `subsection Artificial records` (doc/user_guide.md, "Qualifying against
 * a design spectrum"): how many spectrum-compatible records to generate
 * against `subsection Design spectrum`, and how (DS3, doc/theory.md 13.3).
 */
struct ArtificialRecordParameters
{
  static void declare_parameters(ParameterHandler &prm);
  /** Read and check them; one-line errors naming the entry. */
  void parse_parameters(ParameterHandler &prm);

  /** How many records (each with every component); 0: none. */
  unsigned int number = 0;
  /** Length of each record (s). */
  double duration = 20.;
  /** The stationary part of the trapezoidal intensity envelope (s). */
  double strong_motion = 10.;
  /** The seed of the random phases: the same seed gives the same records bitwise. */
  std::uint64_t seed = 1;
  /** The global axes (0, 1, 2) of the components, each an independent record. */
  std::vector<unsigned int> components = {0, 2};
  /** Largest relative deviation of the record's spectrum from the target (-). */
  double matching_tolerance = 0.05;
  /** Sample interval of the records (s). */
  double time_step = 0.005;
};

/** One generated component (generate_record()). */
struct ArtificialRecord
{
  /** Ground acceleration (m/s^2) at t_i = i time_step. */
  std::vector<double> acceleration;
  double time_step = 0.;
  /** Corrections used, over every draw (-). */
  unsigned int iterations = 0;
  /** Draws of phases used (-). */
  unsigned int attempts = 0;
  /**
   * Largest of |S_a / S_a,target - 1| over matching_periods() (at the
   * target's damping ratio) and of |PGA / S_a,target(0) - 1| (-).
   */
  double max_deviation = 0.;
  /** max |a| (m/s^2). */
  double peak_acceleration = 0.;
  /** End velocity and displacement over their peaks (-), after the baseline correction.
   */
  double end_velocity_ratio = 0., end_displacement_ratio = 0.;
};

/**
 * The periods (s) at which a record is checked against its target: 200
 * periods equally spaced in log T over the Design spectrum's Period range.
 */
std::vector<double> matching_periods(const DesignSpectrum &target);

/**
 * Generate component @p axis (0, 1, 2) of record @p index (1-based) against
 * @p target (DS3, doc/theory.md 13.3): match_record() with the phases of
 * std::mt19937_64 seeded by `seed, index, axis` through std::seed_seq
 * (reproducible bitwise), and, if the deviation stays above the Matching
 * tolerance, again with the next draw of phases, at most
 * max_matching_attempts draws. Throws a one-line message naming
 * `Artificial records/Matching tolerance` if no draw meets it.
 */
ArtificialRecord generate_record(const DesignSpectrum &target,
                                 const ArtificialRecordParameters &parameters,
                                 const unsigned int index,
                                 const unsigned int axis);

/**
 * The record as a PEER AT2 file's text (units of g): four header lines
 * naming @p title and @p description, `NPTS=, DT=`, then five values per line.
 */
std::string at2_text(const ArtificialRecord &record,
                     const std::string &title,
                     const std::string &description);
} // namespace hati

#endif
