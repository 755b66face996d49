#include <hati/time/flange_engagement.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace hati
{
Registry<ForceLawFactory>::Entry FlangeEngagement::registration()
{
  return {"flanges",
          "wheel flanges that pass over their rail head above the flange depth, and "
          "the derailment (D1-D2)",
          {},
          [](const DiscreteSystem &system) -> std::unique_ptr<ForceLaw>
          {
            const auto data = system.law_data.find(wheel_flanges_key);
            if (data == system.law_data.end())
              return nullptr;
            return std::make_unique<FlangeEngagement>(
                system, std::any_cast<const std::vector<WheelFlange> &>(data->second));
          }};
}

FlangeEngagement::FlangeEngagement(const DiscreteSystem &system,
                                   const std::vector<WheelFlange> &flanges)
    : contacts(system.contacts), flanges(flanges)
{
  for (const auto &f : flanges)
    for (const unsigned int k : {f.tread_row, f.flange_rows[0], f.flange_rows[1]})
      AssertThrow(k < contacts.size(), ExcInternalError());
  current.off.assign(flanges.size(), false);
  current.off_time.assign(flanges.size(), 0.);
  current.first_off.assign(flanges.size(), -1.);
  current.time = system.start_time;
}

double FlangeEngagement::gap(const unsigned int k, const Vector<double> &U) const
{
  return contacts[k].initial_gap + contacts[k].apply(U);
}

namespace
{
/** @p x (m) in mm, three significant digits. */
std::string mm(const double x)
{
  std::ostringstream s;
  s << std::setprecision(3) << 1e3 * x << " mm";
  return s.str();
}
} // namespace

void FlangeEngagement::gate_rows(const double t,
                                 const Vector<double> &U,
                                 std::vector<bool> &off)
{
  const double dt = t - current.time;
  current.time = t;
  for (unsigned int w = 0; w < flanges.size(); ++w)
  {
    const WheelFlange &f = flanges[w];
    // (D1) the uplift z = g_tread; the flanges pass over the rail head above
    // the flange depth
    const double z = gap(f.tread_row, U);
    const bool over = z > f.flange_depth;
    off[f.flange_rows[0]] = off[f.flange_rows[1]] = over;
    current.off[w] = over;
    if (!over)
      continue;
    current.off_time[w] += dt;
    if (current.first_off[w] < 0.)
      current.first_off[w] = t;
    // (D2) the lateral offset y = |g_+ - g_-| / 2 beyond c + w / 2
    const double y = 0.5 * std::abs(gap(f.flange_rows[0], U) - gap(f.flange_rows[1], U));
    if (y > f.derailment_offset && current.end.status.empty())
    {
      std::ostringstream s;
      s << f.wheel << " derailed at t = " << std::setprecision(4) << t << " s: uplift "
        << mm(z) << " above its " << mm(f.flange_depth) << " flange, lateral offset "
        << mm(y);
      current.end = {"derailed", s.str(), t};
      current.wheel = w;
      current.uplift = z;
      current.offset = y;
    }
  }
}

void FlangeEngagement::save(std::any &state) const
{
  if (State *s = std::any_cast<State>(&state))
    *s = current;
  else
    state = current;
}

void FlangeEngagement::restore(const std::any &state)
{
  current = std::any_cast<const State &>(state);
}

void FlangeEngagement::add_summary(SummaryEntries &summary, std::ostream &out) const
{
  SummaryValue json = SummaryValue::object();
  unsigned int lifted = 0;
  for (unsigned int w = 0; w < flanges.size(); ++w)
  {
    SummaryValue entry = SummaryValue::object();
    entry.set("disengaged_time", current.off_time[w]);
    entry.set("first_disengaged_time",
              current.first_off[w] < 0. ? SummaryValue()
                                        : SummaryValue(current.first_off[w]));
    json.set(flanges[w].wheel, entry);
    lifted += current.first_off[w] >= 0. ? 1 : 0;
  }
  summary.emplace_back("flanges", json);
  out << "  flanges: " << lifted << " of " << flanges.size()
      << " wheels lifted above their flange depth" << std::endl;
  if (current.end.status.empty())
    return;
  const WheelFlange &f = flanges[current.wheel];
  SummaryValue d = SummaryValue::object();
  d.set("wheel", f.wheel);
  d.set("time", current.end.time);
  d.set("uplift", current.uplift);
  d.set("lateral_offset", current.offset);
  d.set("flange_depth", f.flange_depth);
  d.set("derailment_offset", f.derailment_offset);
  summary.emplace_back("derailment", d);
}

std::any FlangeEngagement::part_data(const std::vector<int> &local,
                                     const std::vector<bool> &fixed) const
{
  (void)local;
  (void)fixed;
  return flanges;
}
} // namespace hati
