#include <hati/run/run_tools.h>

#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <limits>

namespace hati
{
Watchdog::Watchdog(const Model &model, const DiscreteSystem &system)
    : model(model), size(std::max(1., model.size()))
{
  for (const auto &c : system.contacts)
    size = std::max(size, std::abs(c.initial_gap));
  for (const double u : system.initial_displacement)
    size = std::max(size, std::abs(u));
}

void Watchdog::check(const dealii::Vector<double> &u,
                     const dealii::Vector<double> *v,
                     const double t) const
{
  bool ok = within_bound(u);
  if (v)
    for (const double x : *v)
      ok &= std::abs(x) <= std::numeric_limits<double>::max();
  if (!ok)
    fail(u, v, &t);
}

void Watchdog::check_static(const dealii::Vector<double> &u) const
{
  if (!within_bound(u))
    fail(u, nullptr, nullptr);
}

bool Watchdog::within_bound(const dealii::Vector<double> &u) const
{
  // one comparison per entry, false for a NaN too
  const double bound = displacement_factor * size;
  bool ok = true;
  for (const double x : u)
    ok &= std::abs(x) <= bound;
  return ok;
}

void Watchdog::fail(const dealii::Vector<double> &u,
                    const dealii::Vector<double> *v,
                    const double *t) const
{
  // the first entry that is not finite (displacement, then velocity), or
  // else the largest displacement
  const dealii::Vector<double> *vector = &u;
  types::global_dof_index dof = u.size();
  for (types::global_dof_index i = 0; i < u.size() && dof == u.size(); ++i)
    if (!std::isfinite(u[i]))
      dof = i;
  if (dof == u.size() && v)
    for (types::global_dof_index i = 0; i < v->size() && dof == u.size(); ++i)
      if (!std::isfinite((*v)[i]))
      {
        vector = v;
        dof = i;
      }
  if (dof == u.size())
  {
    dof = 0;
    for (types::global_dof_index i = 0; i < u.size(); ++i)
      if (std::abs(u[i]) > std::abs(u[dof]))
        dof = i;
  }
  const DofDescription d = model.describe_dof(dof);
  const bool velocity = vector != &u;
  std::string component = d.component;
  if (velocity && !component.empty() && component[0] == 'u')
    component[0] = 'v';
  const double value = (*vector)[dof];
  static_assert(displacement_factor == 1e3, "the message says 1e3");
  const char *const unit = d.rotation ? " rad" : " m";
  std::ostringstream s;
  if (t != nullptr)
    s << "the run diverged at t = " << *t << " s: the ";
  else
    s << "the static solution is out of scale: the ";
  s << (velocity ? (d.rotation ? "angular velocity" : "velocity")
                 : (d.rotation ? "rotation" : "displacement"));
  if (!component.empty())
    s << ' ' << component;
  if (std::isfinite(value))
    s << " = " << value << unit;
  if (!d.location.empty())
    s << " at " << d.location;
  s << " (DoF " << dof << ")";
  if (!std::isfinite(value))
    s << " is not finite (" << value << ")";
  else
    s << " exceeds 1e3 times the model size, 1e3 x " << size
      << " m = " << displacement_factor * size << unit;
  if (t != nullptr)
    s << " (look for a load, an accelerogram or a time step out of scale, or an "
         "unstable scheme)";
  else
    s << " (look for a load out of scale, or a structure held too weakly: a "
         "mechanism or a material or section out of scale)";
  AssertThrow(false, dealii::ExcMessage(s.str()));
  std::abort(); // not reached
}

void check_state(const Watchdog &watchdog,
                 OutputWriter &writer,
                 const dealii::Vector<double> &u,
                 const dealii::Vector<double> *v,
                 const double t)
{
  try
  {
    watchdog.check(u, v, t);
  }
  catch (...)
  {
    try
    {
      writer.flush(); // whole rows only: the check comes before a row
    }
    catch (...)
    {
      // the divergence is the message; a write error would hide it
    }
    throw;
  }
}

Progress::Progress(const double interval, const double end_time, const double start_time)
    : interval(interval), end_time(end_time), start_time(start_time),
      start(std::chrono::steady_clock::now()), last(start)
{
}

bool Progress::due()
{
  const auto now = std::chrono::steady_clock::now();
  if (std::chrono::duration<double>(now - last).count() < interval)
    return false;
  last = now;
  return true;
}

void Progress::print(const double t, const unsigned long step) const
{
  const double wall = wall_time();
  const double fraction =
      end_time > start_time ? (t - start_time) / (end_time - start_time) : 1.;
  const auto precision = std::cout.precision();
  std::cout << "  t = " << std::setw(12) << std::setprecision(6) << t << " s ("
            << std::setw(5) << std::fixed << std::setprecision(1) << 100. * fraction
            << " %), step " << step << ", wall " << std::setprecision(1) << wall
            << " s, remaining ~"
            << (fraction > 0. ? wall * (1. - fraction) / fraction : 0.) << " s"
            << std::defaultfloat << std::setprecision(precision) << std::endl;
}

double Progress::wall_time() const
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}
} // namespace hati
