#ifndef hati_output_member_result_h
#define hati_output_member_result_h

#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>

#include <string>
#include <utility>
#include <vector>

namespace hati
{
/**
 * What a suite keeps of one member run (doc/user_guide.md, "Qualifying a
 * crane on a suite of records"): which member it is, how it ended and its
 * key results read from its `summary.json` (read_member_summary()), with
 * the text of its `spectra.csv`. Serializable (boost), so that the ranks of
 * an MPI suite send their members' results to rank 0.
 */
struct MemberResult
{
  unsigned int index = 0;
  std::string name, record;
  double scale = 1.;
  unsigned int variation = 0;
  std::vector<std::string> variation_values;
  /** `completed`, `reused` (a complete earlier run), `failed`, `interrupted` or `not
   * run`. */
  std::string status = "not run";
  /** The one-line error of a failed member (empty otherwise). */
  std::string error;
  /** Wall time of the member (s): of this run, or of the earlier run when reused. */
  double wall_time = 0.;
  /** Key results, `quantity -> value`, in the order of summary.json (units there). */
  std::vector<std::pair<std::string, double>> values;
  /** The member's spectra.csv (empty without Output/Spectra). */
  std::string spectra;

  /** Whether its results count in the statistics (completed or reused). */
  bool usable() const { return status == "completed" || status == "reused"; }

  template <class Archive> void serialize(Archive &ar, const unsigned int)
  {
    ar &index &name &record &scale &variation &variation_values &status &error &wall_time
        &values &spectra;
  }
};

/**
 * The status (`status` of @p folder/summary.json, empty if the file is
 * missing or unreadable) and, for a completed run, the key results into
 * @p result.values: per wheel (`wheels`) `<wheel>.peak_mean_force` (N),
 * `<wheel>.slip_distance` (m, when present), `<wheel>.uplift_time` (s),
 * `<wheel>.max_lateral_offset` (m) and, for a runway wheel,
 * `<wheel>.runway_load.vertical_max`, `.vertical_min`, `.lateral_max`,
 * `.longitudinal_max` (N) and, on runway springs,
 * `<wheel>.runway_reaction.<vertical|lateral|longitudinal>_<max|min>` (N);
 * per one-sided contact `<contact>.max_uplift`
 * (m); per beam member `<member>.max_normal_stress` and `.max_von_mises`
 * (Pa);
 * the section-force envelope `section_force.N`, `.My`, `.Mz` (N, N m);
 * `<monitor>.max_absolute_acceleration` (m/s^2); per solid
 * `<solid>.max_von_mises` (Pa, when present); per rope
 * `<rope>.max_tension` (N, when present); and the run's `wall_time`.
 */
std::string read_member_summary(const std::string &folder, MemberResult &result);

/**
 * Whether @p folder holds the whole outputs of a completed transient run,
 * so that a suite may reuse them: `summary.json` says `completed` and has
 * the entries every completed run writes (`model`, `n_dofs`, `end_time`,
 * `n_steps`, `wall_time`), and every file listed in its manifest
 * `.hati-manifest` (`history.csv` among them) but the temporaries is a
 * regular file, every CSV ending on a whole line.
 */
bool member_outputs_whole(const std::string &folder);
} // namespace hati

#endif
