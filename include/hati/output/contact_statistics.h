#ifndef hati_output_contact_statistics_h
#define hati_output_contact_statistics_h

#include <hati/base/summary_value.h>
#include <hati/model/discrete_system.h>

#include <array>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace hati
{
/**
 * What a crane engineer asks of every contact (a wheel on its rail), at the
 * resolution of the (micro) steps: the impacts, the peak contact force and
 * the time out of contact, per contact name (the rows of a name, e.g. the
 * two rows of a two-sided contact, form one group).
 *
 * A group is *pushing* in a step when one of its rows has a compressive
 * impulse (A6; a bilateral row when its impulse is non-zero). An impact is
 * a step where a group starts pushing after a step without; a group that
 * touches (gap <= 0) in the initial state counts as pushing before the
 * first step, so a crane starting from its static state on its wheels has
 * no impact at t = 0. The time out of contact (`uplift_time`) sums the
 * steps without push after the first push; a contact-loss episode runs from
 * the first step without push to the first step with push again. A group
 * of bilateral rows (two-sided without clearance) never separates. The
 * first step of a contact closed in the initial state is left out of the
 * peaks: the central-difference start (A1, V_{1/2} from the free
 * acceleration) makes it carry the reaction of half a step more.
 */
class ContactStatistics
{
public:
  /** Per contact name. */
  struct Entry
  {
    std::string name;
    unsigned int n_impacts = 0;
    /** Largest contact force sum(lambda) / dt (N) and its time (s). */
    double peak_force = 0., peak_force_time = 0.;
    /**
     * Largest impulse of one step (N s): the dt-independent measure of a
     * plastic impact, which the event-capturing scheme resolves in one step
     * (its force impulse / dt grows as dt falls).
     */
    double peak_impulse = 0.;
    /**
     * Largest mean contact force over the force window (N): the largest
     * impulse within any window of that length, divided by the length, and
     * the end of that window (s).
     */
    double peak_mean_force = 0., peak_mean_force_time = 0.;
    /**
     * Smallest mean contact force over the force window (N) among the
     * whole windows (of a contact closed in the initial state, those after
     * its first step) and the end of that window (s); with a force window
     * only, 0 before the first whole window. At rest on its support it
     * equals peak_mean_force.
     */
    double min_mean_force = 0., min_mean_force_time = 0.;
    /** Total time without push after the first push (s). */
    double uplift_time = 0.;
    /**
     * One-sided contacts: the largest gap (m; the smallest of the gaps of
     * its rows) in the steps without push after the first push (for a
     * contact closed in the initial state, from the start: a wheel's lift
     * off its rail) and its time (s).
     */
    double max_uplift = 0., max_uplift_time = 0.;
    /**
     * Two-sided contacts with a clearance (two rows of opposite normals):
     * the largest offset from the middle of the clearance, |g_1 - g_2| / 2
     * (m; a wheel's lateral offset between its flanges), and its time (s).
     */
    double max_offset = 0., max_offset_time = 0.;
    /** Whether the name is a two-sided contact with clearance (max_offset, no
     * max_uplift). */
    bool two_sided = false;
    /** With friction (A9): the accumulated slip `sum ||u_t|| dt` (m). */
    double slip_distance = 0.;
    /**
     * With friction: the largest mean friction force (N), `sum ||lambda_t||`
     * over the force window divided by its length (per step, / dt, without
     * a window), and the end of that window (s).
     */
    double peak_friction_force = 0., peak_friction_force_time = 0.;
    /**
     * With friction: the same largest mean of each tangential component
     * alone (N; the first and the second tangent of the contact's rows,
     * e.g. along and across a rail) and the ends of their windows (s).
     */
    std::array<double, 2> peak_tangent_force = {{0., 0.}},
                          peak_tangent_force_time = {{0., 0.}};
    /** Contact-loss episodes (start, end) in s; end < 0: still open. */
    std::vector<std::pair<double, double>> episodes;
  };

  /**
   * @param contacts the contact rows (grouped by name, in order of first appearance)
   * @param initial_gaps gap of each row in the initial state (m)
   * @param force_window window of the mean contact force (s; 0: none);
   *        the windows of a contact closed in the initial state count once
   *        they no longer hold its first step
   */
  ContactStatistics(const std::vector<ContactRow> &contacts,
                    const std::vector<double> &initial_gaps,
                    const double force_window = 0.);

  /**
   * Account for one step of duration @p dt (s) ending at @p time (s) with
   * the impulses @p impulses (N s) and the gaps @p gaps (m, at the step's
   * end; empty: no uplift and offset) of every row. No allocation.
   */
  void add_step(const double time,
                const double dt,
                const std::vector<double> &impulses,
                const std::vector<double> &gaps = {});

  /**
   * With friction (A9), after add_step() of the same step: the tangential
   * impulses @p tangential (N s, two per row) and the slip velocities
   * @p slip (m/s per row) give each name's slip distance and peak friction
   * force (the rows of a name share their tangents: their impulses are
   * summed, the largest slip velocity counts). No allocation.
   */
  void add_friction_step(const double time,
                         const double dt,
                         const std::vector<double> &tangential,
                         const std::vector<double> &slip);
  const std::vector<Entry> &entries() const { return groups; }

  /** The entry of the name @p name; nullptr if there is none. */
  const Entry *entry(const std::string &name) const;

  /** Whether a force window is set (the mean forces exist). */
  bool has_force_window() const { return force_window > 0.; }

  /**
   * `{"name": {"n_impacts": .., "peak_impact_force": .., "uplift_time": ..,
   * "max_uplift": .. (one-sided) or "max_offset": .. (two-sided), ..}, ...}`.
   */
  SummaryValue json(const std::vector<std::string> &names = {}) const;

  /** `contact_episodes.csv`: contact,start,end,duration (s; end empty if open). */
  void write_episodes(std::ostream &out) const;

  /**
   * The results table (one line per contact name) for the terminal; with
   * friction (add_friction_step() called) also the slip distance, the peak
   * friction force and its time of each name.
   */
  void print_table(std::ostream &out) const;

private:
  const std::vector<ContactRow> &contacts;
  std::vector<unsigned int> group_of_row;
  std::vector<Entry> groups;
  std::vector<double> group_impulse;
  unsigned long n_steps = 0;
  std::vector<char> always_closed;
  std::vector<char> pushing, pushed_once, initially_closed;
  // the rows of a two-sided group with clearance (its offset); -1: none
  std::vector<std::array<int, 2>> offset_rows;
  std::vector<double> group_gap;
  // whether a group's min_mean_force has seen a whole window
  std::vector<char> min_counted;
  // the mean force: the last n_window impulses of every group (a ring) and their sum
  double force_window = 0.;
  unsigned long n_window = 0;
  std::vector<double> window_impulses, window_sum;
  // friction (A9): whether add_friction_step() was called, per-name scratch
  // and the ring of the mean friction force
  bool friction = false;
  std::vector<double> group_tangential, group_slip, friction_window, friction_sum;
  // the rings of each tangential component's mean force (two per name)
  std::vector<double> tangent_window, tangent_sum;
};
} // namespace hati

#endif
