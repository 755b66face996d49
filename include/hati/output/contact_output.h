#ifndef hati_output_contact_output_h
#define hati_output_contact_output_h

#include <hati/model/discrete_system.h>
#include <hati/output/contact_statistics.h>
#include <hati/output/law_output.h>
#include <hati/time/frictional_contacts.h>

#include <array>
#include <string>
#include <vector>

namespace hati
{
/** The gap of every row of @p system's contacts in its initial state (m). */
std::vector<double> initial_gaps(const DiscreteSystem &system);

/**
 * The outputs of the contacts' law (UnilateralContacts::make_output(), a
 * LawOutput): per contact name the statistics of every step
 * (ContactStatistics: impacts, peak force over `Output/Contact force
 * window`, time out of contact, episodes; with friction, A9, slip distance
 * and peak friction force), and at the end the summary.json entries
 * `wall_time_contacts`, `wall_time_contact_statistics`, with friction
 * `friction_iterations_max` and `friction_unconverged` (a warning when
 * a cluster did not converge), `contacts`, `contact_force_window`,
 * `wheels` (Model::wheel_contacts(), with their lateral offsets and
 * runway loads), the files `contact_episodes.csv` and `runway_loads.csv`
 * (Model::runway_wheels()) and the results table on the terminal.
 */
class ContactOutput : public LawOutput
{
public:
  /**
   * The statistics of the contact rows of @p context.system; @p friction
   * is the law's friction record (its counts at the end).
   */
  ContactOutput(const LawOutputContext &context, const FrictionalContacts &friction);

  void add_step(const LawSample &sample, const double dt) override;

  void finish(SummaryEntries &summary,
              std::ostream &out,
              const LawOutputTimes &times) override;

private:
  /**
   * The loads a runway wheel (Model::runway_wheels()) hands to the runway
   * (N) and their times (s): the largest and smallest mean vertical
   * contact force, the largest mean flange force (its lateral contact)
   * and the largest mean friction force along the rail (its longitudinal
   * tangent; 0 for a wheel that rolls), all over the force window.
   */
  struct RunwayLoad
  {
    std::string wheel;
    std::array<double, 4> value, time;
  };
  /** The runway loads (none without a force window or runway wheels). */
  std::vector<RunwayLoad> runway_loads() const;
  /**
   * `wheels`: the statistics of every wheel with its `max_lateral_offset`
   * (m, the flange contact's max_offset) and, for a runway wheel,
   * `runway_load` (`vertical_max`, `vertical_min`, `lateral_max`,
   * `longitudinal_max`, N, each with its `_time`, s).
   */
  SummaryValue wheels_json() const;

  const LawOutputContext context;
  /** With friction (A9): its record, for the counts; nullptr without. */
  const FrictionalContacts *const friction;
  ContactStatistics statistics;
};
} // namespace hati

#endif
