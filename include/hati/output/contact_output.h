#ifndef hati_output_contact_output_h
#define hati_output_contact_output_h

#include <hati/model/discrete_system.h>
#include <hati/output/contact_statistics.h>
#include <hati/output/law_output.h>
#include <hati/time/frictional_contacts.h>

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
 * `wheels` (Model::wheel_contacts()), the file `contact_episodes.csv` and
 * the results table on the terminal.
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
  const LawOutputContext context;
  /** With friction (A9): its record, for the counts; nullptr without. */
  const FrictionalContacts *const friction;
  ContactStatistics statistics;
};
} // namespace hati

#endif
