#include <hati/output/contact_statistics.h>
#include <hati/output/output_writer.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace hati
{
namespace
{
/**
 * Put @p value in slot @p slot of the ring @p ring of @p n entries and
 * update the ring's running @p sum, summed afresh once per turn of the
 * ring so that round-off does not accumulate (the windowed mean forces).
 */
void push_ring(double *ring,
               const unsigned long n,
               const unsigned long slot,
               const double value,
               double &sum)
{
  double &old = ring[slot];
  sum += value - old;
  old = value;
  if (slot == n - 1)
  {
    double s = 0.;
    for (unsigned long i = 0; i < n; ++i)
      s += ring[i];
    sum = s;
  }
}

/** Whether the rows @p a and @p b are the two sides of one clearance (L_b = -L_a). */
bool opposite(const ContactRow &a, const ContactRow &b)
{
  if (a.dofs != b.dofs)
    return false;
  for (unsigned int i = 0; i < a.coefficients.size(); ++i)
    if (a.coefficients[i] != -b.coefficients[i])
      return false;
  return true;
}
} // namespace

ContactStatistics::ContactStatistics(const std::vector<ContactRow> &contacts,
                                     const std::vector<double> &initial_gaps,
                                     const double force_window)
    : contacts(contacts), force_window(force_window)
{
  for (const auto &c : contacts)
  {
    if (c.constraint) // the rows of ties and rigid links follow the contacts
      break;
    auto it = std::find_if(
        groups.begin(), groups.end(), [&](const Entry &e) { return e.name == c.name; });
    group_of_row.push_back(it - groups.begin());
    if (it == groups.end())
    {
      groups.emplace_back();
      groups.back().name = c.name;
    }
  }
  group_impulse.assign(groups.size(), 0.);
  // a group of bilateral rows (two-sided without clearance) never separates
  always_closed.assign(groups.size(), 1);
  for (unsigned int k = 0; k < group_of_row.size(); ++k)
    if (!contacts[k].bilateral)
      always_closed[group_of_row[k]] = 0;
  pushing.assign(groups.size(), 0);
  pushed_once.assign(groups.size(), 0);
  // touching in the initial state: pushing before the first step
  for (unsigned int k = 0; k < group_of_row.size() && k < initial_gaps.size(); ++k)
    if (initially_touching(initial_gaps[k]))
      pushing[group_of_row[k]] = pushed_once[group_of_row[k]] = 1;
  initially_closed = pushed_once;
  // two-sided groups with clearance: two rows of the name, neither bilateral
  std::vector<std::vector<unsigned int>> rows(groups.size());
  for (unsigned int k = 0; k < group_of_row.size(); ++k)
    rows[group_of_row[k]].push_back(k);
  offset_rows.assign(groups.size(), {{-1, -1}});
  for (unsigned int g = 0; g < groups.size(); ++g)
    if (rows[g].size() == 2 && !always_closed[g] &&
        opposite(contacts[rows[g][0]], contacts[rows[g][1]]))
    {
      offset_rows[g] = {{int(rows[g][0]), int(rows[g][1])}};
      groups[g].two_sided = true;
    }
  group_gap.assign(groups.size(), 0.);
  min_counted.assign(groups.size(), 0);
}

const ContactStatistics::Entry *ContactStatistics::entry(const std::string &name) const
{
  for (const auto &e : groups)
    if (e.name == name)
      return &e;
  return nullptr;
}

void ContactStatistics::add_step(const double time,
                                 const double dt,
                                 const std::vector<double> &impulses,
                                 const std::vector<double> &gaps)
{
  ++n_steps;
  std::fill(group_impulse.begin(), group_impulse.end(), 0.);
  for (unsigned int k = 0; k < group_of_row.size(); ++k)
  {
    const double l = contacts[k].bilateral ? std::abs(impulses[k]) : impulses[k];
    if (l > 0.)
      group_impulse[group_of_row[k]] += l;
  }
  if (force_window > 0.)
  {
    if (n_window == 0)
    {
      n_window = std::max(1L, std::lround(force_window / dt));
      window_impulses.assign(groups.size() * n_window, 0.);
      window_sum.assign(groups.size(), 0.);
    }
    // ring position of this step; the sums are summed afresh once per turn
    // of the ring so that round-off does not accumulate
    const unsigned long slot = (n_steps - 1) % n_window;
    for (unsigned int g = 0; g < groups.size(); ++g)
    {
      push_ring(&window_impulses[g * n_window],
                n_window,
                slot,
                group_impulse[g],
                window_sum[g]);
      const double mean_force = window_sum[g] / (n_window * dt);
      if ((n_steps > n_window || !initially_closed[g]) &&
          mean_force > groups[g].peak_mean_force)
      {
        groups[g].peak_mean_force = mean_force;
        groups[g].peak_mean_force_time = time;
      }
      // the smallest mean over whole windows (after the first step of a
      // contact closed in the initial state)
      if (n_steps >= n_window + initially_closed[g] &&
          (!min_counted[g] || mean_force < groups[g].min_mean_force))
      {
        groups[g].min_mean_force = mean_force;
        groups[g].min_mean_force_time = time;
        min_counted[g] = 1;
      }
    }
  }
  for (unsigned int g = 0; g < groups.size(); ++g)
  {
    Entry &e = groups[g];
    // the first step from a state at rest on closed contacts also carries
    // the reaction of the initial half step (A1): not a peak
    const bool count_peak = n_steps > 1 || !pushed_once[g];
    if (always_closed[g])
    {
      if (!count_peak)
        continue;
      e.peak_impulse = std::max(e.peak_impulse, group_impulse[g]);
      if (group_impulse[g] / dt > e.peak_force)
      {
        e.peak_force = group_impulse[g] / dt;
        e.peak_force_time = time;
      }
      continue;
    }
    const bool push = group_impulse[g] > 0.;
    if (push)
    {
      const double force = count_peak ? group_impulse[g] / dt : 0.;
      e.peak_impulse = std::max(e.peak_impulse, count_peak ? group_impulse[g] : 0.);
      if (force > e.peak_force)
      {
        e.peak_force = force;
        e.peak_force_time = time;
      }
      if (!pushing[g])
      {
        ++e.n_impacts;
        if (!e.episodes.empty() && e.episodes.back().second < 0.)
          e.episodes.back().second = time;
      }
      pushed_once[g] = 1;
    }
    else if (pushed_once[g])
    {
      e.uplift_time += dt;
      if (pushing[g])
        e.episodes.emplace_back(time, -1.);
    }
    pushing[g] = push;
  }
  if (gaps.size() < group_of_row.size())
    return;
  // the uplift (the smallest gap of a name's rows) after the first push,
  // the offset of a two-sided contact within its clearance
  std::fill(group_gap.begin(), group_gap.end(), std::numeric_limits<double>::max());
  for (unsigned int k = 0; k < group_of_row.size(); ++k)
    group_gap[group_of_row[k]] = std::min(group_gap[group_of_row[k]], gaps[k]);
  for (unsigned int g = 0; g < groups.size(); ++g)
  {
    Entry &e = groups[g];
    if (always_closed[g])
      continue;
    if (e.two_sided)
    {
      const double offset =
          0.5 * std::abs(gaps[offset_rows[g][0]] - gaps[offset_rows[g][1]]);
      if (offset > e.max_offset)
      {
        e.max_offset = offset;
        e.max_offset_time = time;
      }
    }
    // in the steps without push only: a contact held in the active set
    // keeps a gap of round-off size (up to held_gap_tolerance), no uplift
    else if (pushed_once[g] && !pushing[g] && group_gap[g] > e.max_uplift)
    {
      e.max_uplift = group_gap[g];
      e.max_uplift_time = time;
    }
  }
}

void ContactStatistics::add_friction_step(const double time,
                                          const double dt,
                                          const std::vector<double> &tangential,
                                          const std::vector<double> &slip)
{
  const unsigned int ng = groups.size();
  if (!friction)
  {
    friction = true;
    group_tangential.assign(2 * ng, 0.);
    group_slip.assign(ng, 0.);
    friction_window.assign(ng * std::max(1UL, n_window), 0.);
    friction_sum.assign(ng, 0.);
    tangent_window.assign(2 * ng * std::max(1UL, n_window), 0.);
    tangent_sum.assign(2 * ng, 0.);
  }
  std::fill(group_tangential.begin(), group_tangential.end(), 0.);
  std::fill(group_slip.begin(), group_slip.end(), 0.);
  for (unsigned int k = 0; k < group_of_row.size(); ++k)
  {
    const unsigned int g = group_of_row[k];
    group_tangential[2 * g] += tangential[2 * k];
    group_tangential[2 * g + 1] += tangential[2 * k + 1];
    group_slip[g] = std::max(group_slip[g], slip[k]);
  }
  const unsigned long n = std::max(1UL, n_window);
  const unsigned long slot = (n_steps - 1) % n;
  for (unsigned int g = 0; g < ng; ++g)
  {
    Entry &e = groups[g];
    e.slip_distance += group_slip[g] * dt;
    const double impulse =
        std::hypot(group_tangential[2 * g], group_tangential[2 * g + 1]);
    // the same window as the mean contact force (summed afresh once per turn)
    push_ring(&friction_window[g * n], n, slot, impulse, friction_sum[g]);
    const double force = friction_sum[g] / (n * dt);
    if ((n_steps > n || !initially_closed[g]) && force > e.peak_friction_force)
    {
      e.peak_friction_force = force;
      e.peak_friction_force_time = time;
    }
    for (unsigned int t = 0; t < 2; ++t)
    {
      push_ring(&tangent_window[(2 * g + t) * n],
                n,
                slot,
                std::abs(group_tangential[2 * g + t]),
                tangent_sum[2 * g + t]);
      const double component = tangent_sum[2 * g + t] / (n * dt);
      if ((n_steps > n || !initially_closed[g]) && component > e.peak_tangent_force[t])
      {
        e.peak_tangent_force[t] = component;
        e.peak_tangent_force_time[t] = time;
      }
    }
  }
}

SummaryValue ContactStatistics::json(const std::vector<std::string> &names) const
{
  SummaryValue result = SummaryValue::object();
  for (const auto &e : groups)
  {
    if (!names.empty() && std::find(names.begin(), names.end(), e.name) == names.end())
      continue;
    SummaryValue entry = SummaryValue::object()
                             .set("n_impacts", e.n_impacts)
                             .set("peak_impact_force", e.peak_force)
                             .set("peak_force_time", e.peak_force_time)
                             .set("peak_impulse", e.peak_impulse)
                             .set("peak_mean_force", e.peak_mean_force)
                             .set("peak_mean_force_time", e.peak_mean_force_time)
                             .set("uplift_time", e.uplift_time)
                             .set("n_contact_loss_episodes", e.episodes.size());
    if (force_window > 0.)
      entry.set("min_mean_force", e.min_mean_force)
          .set("min_mean_force_time", e.min_mean_force_time);
    if (e.two_sided)
      entry.set("max_offset", e.max_offset).set("max_offset_time", e.max_offset_time);
    else
      entry.set("max_uplift", e.max_uplift).set("max_uplift_time", e.max_uplift_time);
    if (friction)
      entry.set("slip_distance", e.slip_distance)
          .set("peak_friction_force", e.peak_friction_force)
          .set("peak_friction_force_time", e.peak_friction_force_time);
    result.set(e.name, std::move(entry));
  }
  return result;
}

void ContactStatistics::write_episodes(std::ostream &out) const
{
  out << "contact,start,end,duration\n" << std::setprecision(15);
  for (const auto &e : groups)
    for (const auto &[start, end] : e.episodes)
    {
      out << e.name << ',' << start << ',';
      if (end >= 0.)
        out << end << ',' << end - start;
      else
        out << ',';
      out << '\n';
    }
}

void ContactStatistics::print_table(std::ostream &out) const
{
  const auto flags = out.flags();
  const auto precision = out.precision();
  out << "  contacts:        name   impacts  peak force (N)    at t (s)  mean force (N)  "
         "  at t "
         "(s)  time out of contact (s)  loss episodes";
  // with friction (A9): the slip distance and the peak friction force
  if (friction)
    out << "  slip distance (m)  friction force (N)    at t (s)";
  out << '\n';
  if (force_window > 0.)
    out << "    (peak force: impulse of one step / dt; mean force: largest impulse "
           "within "
        << force_window << " s / " << force_window << " s"
        << (friction ? "; friction force: the same with the tangential impulse" : "")
        << ")\n";
  for (const auto &e : groups)
  {
    out << "    " << std::setw(24) << e.name << std::setw(10) << e.n_impacts
        << std::setw(16) << std::setprecision(6) << e.peak_force << std::setw(12)
        << e.peak_force_time << std::setw(16) << e.peak_mean_force << std::setw(12)
        << e.peak_mean_force_time << std::setw(25) << e.uplift_time << std::setw(15)
        << e.episodes.size();
    if (friction)
      out << std::setw(19) << e.slip_distance << std::setw(20) << e.peak_friction_force
          << std::setw(12) << e.peak_friction_force_time;
    out << '\n';
  }
  out.flags(flags);
  out.precision(precision);
}
} // namespace hati
