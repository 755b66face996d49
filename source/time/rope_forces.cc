#include <hati/model/discrete_system.h>
#include <hati/time/rope_forces.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>

namespace hati
{
Registry<ForceLawFactory>::Entry RopeForces::registration()
{
  return {"ropes",
          "ropes (R1): tension-only bars between two nodes",
          {},
          [](const DiscreteSystem &system) -> std::unique_ptr<ForceLaw>
          {
            if (system.ropes.empty())
              return nullptr;
            return std::make_unique<RopeForces>(system.ropes);
          }};
}

double RopeForces::force_of(const unsigned int r,
                            const Vector<double> &U,
                            std::array<double, 6> &force) const
{
  const Rope &rope = ropes[r];
  const Tensor<1, 3> c = rope.chord(U);
  const double l = c.norm();
  // (R1) T = max(0, k (l - L0)); +T e on the hook point, -T e on the load
  const double T = std::max(0., rope.stiffness * (l - rope.rest_length));
  for (unsigned int d = 0; d < 3; ++d)
  {
    const double f = T > 0. ? T * c[d] / l : 0.;
    force[d] = rope.hook_dofs[d] != numbers::invalid_dof_index ? f : 0.;
    force[3 + d] = rope.load_dofs[d] != numbers::invalid_dof_index ? -f : 0.;
  }
  return T;
}

void RopeForces::start(const Vector<double> &U, Vector<double> &f)
{
  const unsigned int n = ropes.size();
  current.force.assign(n, {});
  current.tension.assign(n, 0.);
  current.slack_time.assign(n, 0.);
  current.work = 0.;
  initial_energy = 0.;
  for (unsigned int r = 0; r < n; ++r)
  {
    current.tension[r] = force_of(r, U, current.force[r]);
    initial_energy += ropes[r].strain_energy(U);
    const auto dofs = ropes[r].dofs();
    for (unsigned int a = 0; a < 6; ++a)
      if (dofs[a] != numbers::invalid_dof_index)
        f[dofs[a]] += current.force[r][a];
  }
  current.min_tension = current.tension;
  current.max_tension = current.tension;
}

void RopeForces::step(const Vector<double> &U,
                      const Vector<double> &V,
                      const Vector<double> &dt_minv,
                      const double dt,
                      double *a)
{
  std::array<double, 6> force;
  for (unsigned int r = 0; r < ropes.size(); ++r)
  {
    const double T = force_of(r, U, force);
    const auto dofs = ropes[r].dofs();
    for (unsigned int k = 0; k < 6; ++k)
      if (dofs[k] != numbers::invalid_dof_index)
      {
        // the work on dU = dt V_{n+1/2}, trapezoidal (E1)
        current.work += 0.5 * dt * V[dofs[k]] * (current.force[r][k] + force[k]);
        a[dofs[k]] += dt_minv[dofs[k]] * force[k];
      }
    current.force[r] = force;
    current.tension[r] = T;
    current.min_tension[r] = std::min(current.min_tension[r], T);
    current.max_tension[r] = std::max(current.max_tension[r], T);
    if (T == 0.)
      current.slack_time[r] += dt;
  }
}

std::vector<types::global_dof_index> RopeForces::nonlinear_dofs() const
{
  std::vector<types::global_dof_index> dofs;
  for (const Rope &rope : ropes)
    for (const auto dof : rope.dofs())
      dofs.push_back(dof);
  return dofs;
}

void RopeForces::applied_force(double *f) const
{
  // before start(): no force yet
  for (unsigned int r = 0; r < ropes.size(); ++r)
    for (unsigned int a = 0; a < 6; ++a)
      f[6 * r + a] = r < current.force.size() ? current.force[r][a] : 0.;
}

double RopeForces::relative_force_change(const double du) const
{
  if (du == 0.)
    return 0.;
  double change = 0.;
  for (unsigned int r = 0; r < ropes.size(); ++r)
  {
    const double scale = r < current.max_tension.size() ? current.max_tension[r] : 0.;
    if (!(scale > 0.))
      return std::numeric_limits<double>::infinity();
    change = std::max(change, 2. * std::sqrt(3.) * ropes[r].stiffness * du / scale);
  }
  return change;
}

void RopeForces::save(std::any &state) const
{
  // copied into the State a previous save left there (no allocation)
  if (State *s = std::any_cast<State>(&state))
    *s = current;
  else
    state = current;
}

void RopeForces::restore(const std::any &state)
{
  current = std::any_cast<const State &>(state);
}

void RopeForces::add_summary(SummaryEntries &summary, std::ostream &out) const
{
  SummaryValue json = SummaryValue::object();
  out << "  rope tension (N): min, max, slack time (s)" << std::endl;
  for (unsigned int r = 0; r < ropes.size(); ++r)
  {
    SummaryValue entry = SummaryValue::object();
    entry.set("min", current.min_tension[r]);
    entry.set("max", current.max_tension[r]);
    entry.set("slack_time", current.slack_time[r]);
    json.set(ropes[r].name, entry);
    out << "    " << std::left << std::setw(20) << ropes[r].name << std::right
        << std::setw(16) << std::setprecision(8) << current.min_tension[r]
        << std::setw(16) << current.max_tension[r] << std::setw(12)
        << current.slack_time[r] << std::endl;
  }
  summary.emplace_back("rope_tension", json);
}
std::string RopeForces::refusal(const std::string &method) const
{
  if (method == "Newmark")
    return "Time integration/Method = Newmark: the rope '" + ropes[0].name +
           "' is a nonlinear (tension-only) element, which needs the explicit "
           "CD-Lagrange integrator (or HATI with the rope in the explicit subdomain).";
  if (method == "event-driven")
    return "Time integration/Method = event-driven: the rope '" + ropes[0].name +
           "' needs the CD-Lagrange integrator (or HATI).";
  return ForceLaw::refusal(method);
}
} // namespace hati
