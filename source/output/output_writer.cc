#include <deal.II/base/data_out_base.h>
#include <deal.II/base/exceptions.h>

#include <hati/output/output_writer.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>
#include <sstream>

namespace hati
{
namespace
{
/** Flush the CSV files at least this often (s of wall time). */
constexpr double flush_interval = 2.;
/** ... and when their buffers hold this many bytes. */
constexpr std::size_t flush_size = 1 << 20;

/** The file of snapshot @p cycle of the VTU series @p series: `<series>-NNNNN.vtu`. */
std::string snapshot_name(const std::string &series, const unsigned int cycle)
{
  char number[32];
  std::snprintf(number, sizeof(number), "-%05u.vtu", cycle);
  return series + number;
}
} // namespace

OutputWriter::OutputWriter(RunDirectory &run,
                           const DiscreteSystem &system,
                           const Model &model)
    : run(run), dir(run.path()), system(system), model(model),
      friction(has_friction(system.contacts)),
      last_flush(std::chrono::steady_clock::now()), last_pvd_sync(last_flush),
      series(model.vtu_series()), envelope_files(model.envelope_files())
{
  run.begin();
  use_shortest_numbers(section_rows);

  history.open(run.open("history.csv"));
  history << "time";
  for (const auto &m : system.monitors)
  {
    for (const auto &l : m.labels)
      history << ',' << m.name << ".u" << l;
    for (const auto &l : m.labels)
      history << ',' << m.name << ".v" << l;
  }
  // the ropes' tensions (R1), N
  for (const Rope &rope : system.ropes)
    history << ',' << rope.name << ".tension";
  history << '\n';

  contacts.open(run.open("contacts.csv"));
  contacts << "time,contact,gap,normal_velocity,impulse,force,active";
  if (friction)
    contacts << ",tangential_impulse,slip_velocity,state";
  contacts << '\n';
  for (const auto &c : system.contacts)
  {
    if (c.constraint) // the rows of ties and rigid links follow the contacts
      break;
    auto it = std::find(contact_names.begin(), contact_names.end(), c.name);
    contact_group.push_back(it - contact_names.begin());
    if (it == contact_names.end())
      contact_names.push_back(c.name);
  }
  group_was_pushing.assign(contact_names.size(), false);
  group_pushing.assign(contact_names.size(), false);

  energy.open(run.open("energy.csv"));
  energy << "time,kinetic,internal,external_work,contact_work,dissipated,interface_work,"
            "total,balance_drift,kinetic_explicit,kinetic_implicit,internal_explicit,"
            "internal_implicit,damping_stored";
  if (friction)
    energy << ",friction_dissipated";
  energy << '\n';

  const std::string header = model.section_forces_header();
  if (!header.empty())
  {
    section_forces.open(run.open("section_forces.csv"));
    section_forces << header << '\n';
  }
  flush();
}

void OutputWriter::write_history(const OutputState &s)
{
  history << s.time;
  for (const auto &m : system.monitors)
  {
    for (unsigned int i = 0; i < m.dofs.size(); ++i)
      history << ',' << m.value(i, *s.displacement);
    for (unsigned int i = 0; i < m.dofs.size(); ++i)
      history << ',' << m.value(i, *s.velocity);
  }
  for (const Rope &rope : system.ropes)
    history << ',' << rope.tension(*s.displacement);
  history << '\n';
  if (section_forces.is_open())
  {
    section_rows.str("");
    model.write_section_forces(s.section_force_rows ? &section_rows : nullptr,
                               s.time,
                               *s.displacement,
                               s.output_functionals);
    if (s.section_force_rows)
      section_forces << section_rows.str();
  }
  if (s.section_force_rows && !s.envelope_deferred)
    model.update_envelopes(s.time, *s.displacement);
  if (s.contact_rows)
    write_contacts(s);
  flush_if_due();
}

void OutputWriter::write_contacts(const OutputState &s)
{
  // the contacts come first in every contact list, the rows of ties and
  // rigid links after them: HATI's explicit subdomain has the model's
  // contacts but only its own constraint rows
  if (contact_group.empty() || s.gaps.size() < contact_group.size())
    return; // no contact state (implicit or static analyses)
  const unsigned int ng = contact_names.size();
  auto &gap = group_gap, &vn = group_velocity, &imp = group_impulse;
  auto &force = group_force;
  auto &n_rows = group_rows, &n_active = group_active;
  const bool static_forces = s.forces.size() == s.gaps.size();
  gap.assign(ng, std::numeric_limits<double>::max());
  vn.assign(ng, 0.);
  imp.assign(ng, 0.);
  force.assign(ng, 0.);
  n_rows.assign(ng, 0);
  n_active.assign(ng, 0);
  for (unsigned int k = 0; k < contact_group.size(); ++k)
  {
    const unsigned int g = contact_group[k];
    gap[g] = std::min(gap[g], s.gaps[k]);
    vn[g] += s.normal_velocities[k];
    imp[g] += s.impulses[k];
    if (static_forces)
      force[g] += s.forces[k];
    ++n_rows[g];
    n_active[g] += s.active[k] ? 1 : 0;
  }
  const bool with_friction = friction && s.friction_states.size() == s.gaps.size();
  if (with_friction)
    group_friction(s);
  for (unsigned int g = 0; g < ng; ++g)
  {
    contacts << s.time << ',' << contact_names[g] << ',' << gap[g] << ','
             << vn[g] / n_rows[g] << ',' << imp[g] << ','
             << (static_forces             ? force[g]
                 : s.impulse_duration > 0. ? imp[g] / s.impulse_duration
                                           : 0.)
             << ',' << n_active[g];
    if (with_friction)
    {
      static const char *const state_names[] = {"open", "stick", "slip"};
      contacts << ',' << std::hypot(group_tangential[2 * g], group_tangential[2 * g + 1])
               << ',' << group_slip[g] << ','
               << state_names[static_cast<int>(group_state[g])];
    }
    else if (friction)
      contacts << ",,,"; // the header's friction columns, empty: no friction state
    contacts << '\n';
  }
  flush_if_due();
}

void OutputWriter::group_friction(const OutputState &s)
{
  // per contact name: the tangential impulses summed (the rows of a name
  // share their tangents), the largest slip velocity, and stick if a row
  // sticks, else slip if a row slides, else open
  const unsigned int ng = contact_names.size();
  group_tangential.assign(2 * ng, 0.);
  group_slip.assign(ng, 0.);
  group_state.assign(ng, FrictionState::open);
  for (unsigned int k = 0; k < contact_group.size(); ++k)
  {
    const unsigned int g = contact_group[k];
    group_tangential[2 * g] += s.tangential_impulses[2 * k];
    group_tangential[2 * g + 1] += s.tangential_impulses[2 * k + 1];
    group_slip[g] = std::max(group_slip[g], s.slip_velocities[k]);
    const FrictionState f = s.friction_states[k];
    if (f == FrictionState::stick ||
        (f == FrictionState::slip && group_state[g] == FrictionState::open))
      group_state[g] = f;
  }
}

void OutputWriter::set_initial_contacts(const std::vector<double> &initial_gaps)
{
  for (unsigned int k = 0; k < initial_gaps.size() && k < contact_group.size(); ++k)
    if (initially_touching(initial_gaps[k]))
      group_was_pushing[contact_group[k]] = true;
}

void OutputWriter::track_contacts(const std::vector<double> &gaps,
                                  const std::vector<double> &impulses)
{
  // called after every step: no allocation here
  std::fill(group_pushing.begin(), group_pushing.end(), false);
  for (unsigned int k = 0; k < contact_group.size(); ++k)
  {
    penetration = std::max(penetration, -gaps[k]);
    if (impulses[k] > 0.)
      group_pushing[contact_group[k]] = true;
  }
  for (unsigned int g = 0; g < group_pushing.size(); ++g)
  {
    if (group_pushing[g] && !group_was_pushing[g])
      ++impacts;
    group_was_pushing[g] = group_pushing[g];
  }
}

void OutputWriter::write_energy(const double time, const Energies &e)
{
  const double total = e.total();
  if (!have_energy)
  {
    energy0 = total;
    have_energy = true;
  }
  last_drift = total - energy0;
  energy_scale = std::max({energy_scale,
                           std::abs(e.kinetic),
                           std::abs(e.internal),
                           std::abs(e.external_work),
                           std::abs(e.contact_work),
                           std::abs(e.interface_work),
                           std::abs(e.damping_stored),
                           std::abs(e.friction_dissipated)});
  energy << time << ',' << e.kinetic << ',' << e.internal << ',' << e.external_work << ','
         << e.contact_work << ',' << e.dissipated << ',' << e.interface_work << ','
         << total << ',' << last_drift << ',' << e.kinetic_explicit << ','
         << e.kinetic_implicit << ',' << e.internal_explicit << ',' << e.internal_implicit
         << ',' << e.damping_stored;
  if (friction)
    energy << ',' << e.friction_dissipated;
  energy << '\n';
  flush_if_due();
}

void OutputWriter::write_vtu(const OutputState &s)
{
  // nodal contact fields: L^T lambda (impulse, N s) and L^T active
  const unsigned int n = system.n_dofs();
  Vector<double> impulse(n), status(n);
  for (unsigned int k = 0; k < system.contacts.size(); ++k)
  {
    const auto &c = system.contacts[k];
    for (unsigned int i = 0; i < c.dofs.size(); ++i)
    {
      impulse[c.dofs[i]] += c.coefficients[i] * s.impulses[k];
      if (s.active[k])
        status[c.dofs[i]] += std::abs(c.coefficients[i]);
    }
  }
  const unsigned int cycle = vtu_files.size();
  const VtuSnapshot snapshot{{{"displacement", s.displacement},
                              {"velocity", s.velocity},
                              {"contact_impulse", &impulse},
                              {"contact_status", &status}},
                             s.time,
                             cycle};
  const std::string name = snapshot_name("solution", cycle);
  {
    OutputStream out(run.open(name));
    model.write_vtu(out, snapshot);
    out.close();
  }
  // the other series' snapshots (the solids': most of a snapshot's time)
  // are written by a second thread while the run goes on, one snapshot at
  // a time: the previous one is complete first (its index then names it)
  wait_for_series();
  if (!series.empty())
  {
    auto files = std::make_shared<std::vector<OutputFile>>();
    for (const auto &other : series)
      files->push_back(run.open(snapshot_name(other, cycle)));
    // the fields the series read, copied (the run changes them meanwhile)
    auto fields = std::make_shared<std::vector<std::pair<std::string, Vector<double>>>>();
    for (const auto &[field, values] : snapshot.fields)
      fields->emplace_back(field, *values);
    const double time = s.time;
    pending_series = std::async(std::launch::async,
                                [this, files, fields, time, cycle]()
                                {
                                  VtuSnapshot copy{{}, time, cycle};
                                  for (const auto &[field, values] : *fields)
                                    copy.fields.emplace_back(field, &values);
                                  for (unsigned int k = 0; k < series.size(); ++k)
                                  {
                                    OutputStream out(std::move((*files)[k]));
                                    model.write_series_vtu(series[k], out, copy);
                                    out.close();
                                  }
                                });
  }
  // the indices name complete snapshots only, and are replaced atomically
  vtu_files.emplace_back(s.time, name);
  std::ostringstream pvd;
  DataOutBase::write_pvd_record(pvd, vtu_files);
  // durable (fsync, about 1 ms) at most every flush_interval from the start:
  // snapshots of a small model take less than that; finish() syncs the last
  const auto now = std::chrono::steady_clock::now();
  pvd_durable =
      std::chrono::duration<double>(now - last_pvd_sync).count() >= flush_interval;
  run.replace("solution.pvd", pvd.str(), pvd_durable);
  if (pvd_durable)
    last_pvd_sync = now;
  write_envelopes(false);
  flush();
}

void OutputWriter::wait_for_series()
{
  if (!pending_series.valid())
    return;
  pending_series.get(); // rethrows the writer's error
  // the series' indices: every snapshot up to the one just completed
  const unsigned int complete = vtu_files.size();
  for (const auto &other : series)
  {
    std::vector<std::pair<double, std::string>> files;
    for (unsigned int k = 0; k < complete; ++k)
      files.emplace_back(vtu_files[k].first, snapshot_name(other, k));
    std::ostringstream index;
    DataOutBase::write_pvd_record(index, files);
    run.replace(other + ".pvd", index.str(), pvd_durable);
  }
}

void OutputWriter::update_envelopes(const double time, const Vector<double> &displacement)
{
  model.update_envelopes(time, displacement);
}

void OutputWriter::write_envelopes(const bool durable)
{
  for (const auto &name : envelope_files)
  {
    std::ostringstream content;
    model.write_envelope_file(name, content);
    run.replace(name, content.str(), durable);
  }
}

void OutputWriter::finish()
{
  wait_for_series();
  flush();
  if (!pvd_durable)
  {
    run.sync("solution.pvd");
    for (const auto &other : series)
      run.sync(other + ".pvd");
  }
  pvd_durable = true;
  write_envelopes(true);
}

void OutputWriter::flush_if_due()
{
  const auto now = std::chrono::steady_clock::now();
  if (history.buffered() + contacts.buffered() + energy.buffered() +
              section_forces.buffered() >=
          flush_size ||
      std::chrono::duration<double>(now - last_flush).count() >= flush_interval)
    flush();
}

void OutputWriter::flush()
{
  std::error_code ec;
  AssertThrow(std::filesystem::is_directory(dir, ec),
              ExcMessage("the output directory " + dir +
                         " has vanished (deleted or unmounted during the run)"));
  history.flush();
  contacts.flush();
  energy.flush();
  section_forces.flush();
  last_flush = std::chrono::steady_clock::now();
}

} // namespace hati
