#include <deal.II/base/data_out_base.h>
#include <deal.II/base/exceptions.h>

#include <hati/output/output_writer.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <limits>
#include <sstream>

namespace hati
{
namespace
{
std::ofstream open(const std::string &name)
{
  std::ofstream f(name);
  AssertThrow(f, ExcMessage("cannot open output file " + name + " for writing"));
  f << std::setprecision(15);
  return f;
}
} // namespace

OutputWriter::OutputWriter(const std::string &directory,
                           const DiscreteSystem &system,
                           const Model &model)
    : dir(directory), system(system), model(model)
{
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  AssertThrow(
      !ec, ExcMessage("cannot create the output directory " + dir + ": " + ec.message()));

  history = open(dir + "/history.csv");
  history << "time";
  for (const auto &m : system.monitors)
  {
    for (const auto &l : m.labels)
      history << ',' << m.name << ".u" << l;
    for (const auto &l : m.labels)
      history << ',' << m.name << ".v" << l;
  }
  history << '\n';

  contacts = open(dir + "/contacts.csv");
  contacts << "time,contact,gap,normal_velocity,impulse,force,active\n";
  for (const auto &c : system.contacts)
  {
    auto it = std::find(contact_names.begin(), contact_names.end(), c.name);
    contact_group.push_back(it - contact_names.begin());
    if (it == contact_names.end())
      contact_names.push_back(c.name);
  }
  group_was_pushing.assign(contact_names.size(), false);
  group_pushing.assign(contact_names.size(), false);

  energy = open(dir + "/energy.csv");
  energy << "time,kinetic,internal,external_work,contact_work,dissipated,interface_work,"
            "total,balance_drift,kinetic_explicit,kinetic_implicit,internal_explicit,"
            "internal_implicit\n";

  const std::string header = model.section_forces_header();
  if (!header.empty())
  {
    section_forces = open(dir + "/section_forces.csv");
    section_forces << header << '\n';
  }
}

void OutputWriter::write_history(const OutputState &s)
{
  history << s.time;
  for (const auto &m : system.monitors)
  {
    for (const auto d : m.dofs)
      history << ',' << (*s.displacement)[d];
    for (const auto d : m.dofs)
      history << ',' << (*s.velocity)[d];
  }
  history << '\n';
  if (section_forces.is_open())
    model.write_section_forces(section_forces, s.time, *s.displacement);
  if (s.contact_rows)
    write_contacts(s);
}

void OutputWriter::write_contacts(const OutputState &s)
{
  if (s.gaps.size() != system.contacts.size() || system.contacts.empty())
    return; // no contact state (implicit or static analyses)
  const unsigned int ng = contact_names.size();
  std::vector<double> gap(ng, std::numeric_limits<double>::max()), vn(ng, 0.),
      imp(ng, 0.);
  std::vector<unsigned int> n_rows(ng, 0), n_active(ng, 0);
  for (unsigned int k = 0; k < s.gaps.size(); ++k)
  {
    const unsigned int g = contact_group[k];
    gap[g] = std::min(gap[g], s.gaps[k]);
    vn[g] += s.normal_velocities[k];
    imp[g] += s.impulses[k];
    ++n_rows[g];
    n_active[g] += s.active[k] ? 1 : 0;
  }
  for (unsigned int g = 0; g < ng; ++g)
    contacts << s.time << ',' << contact_names[g] << ',' << gap[g] << ','
             << vn[g] / n_rows[g] << ',' << imp[g] << ','
             << (s.impulse_duration > 0. ? imp[g] / s.impulse_duration : 0.) << ','
             << n_active[g] << '\n';
}

void OutputWriter::track_contacts(const std::vector<double> &gaps,
                                  const std::vector<double> &impulses)
{
  // called after every step: no allocation here
  std::fill(group_pushing.begin(), group_pushing.end(), false);
  for (unsigned int k = 0; k < gaps.size(); ++k)
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
                           std::abs(e.interface_work)});
  energy << time << ',' << e.kinetic << ',' << e.internal << ',' << e.external_work << ','
         << e.contact_work << ',' << e.dissipated << ',' << e.interface_work << ','
         << total << ',' << last_drift << ',' << e.kinetic_explicit << ','
         << e.kinetic_implicit << ',' << e.internal_explicit << ',' << e.internal_implicit
         << '\n';
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
  char name[64];
  std::snprintf(name,
                sizeof(name),
                "solution-%05u.vtu",
                static_cast<unsigned int>(vtu_files.size()));
  {
    std::ofstream out(dir + "/" + name);
    AssertThrow(out, ExcMessage("cannot write " + dir + "/" + name));
    model.write_vtu(out,
                    {{"displacement", s.displacement},
                     {"velocity", s.velocity},
                     {"contact_impulse", &impulse},
                     {"contact_status", &status}},
                    s.time,
                    vtu_files.size());
  }
  vtu_files.emplace_back(s.time, name);
  std::ofstream pvd(dir + "/solution.pvd");
  DataOutBase::write_pvd_record(pvd, vtu_files);
  flush();
}

void OutputWriter::flush()
{
  history.flush();
  contacts.flush();
  energy.flush();
  if (section_forces.is_open())
    section_forces.flush();
}

std::string json_number(const double x)
{
  if (!std::isfinite(x))
    return "null";
  std::ostringstream s;
  s << std::setprecision(15) << x;
  return s.str();
}

std::string json_string(const std::string &x)
{
  std::string r = "\"";
  for (const char c : x)
  {
    if (c == '"' || c == '\\')
      r += '\\';
    r += c;
  }
  return r + "\"";
}

void write_summary(const std::string &filename,
                   const std::vector<std::pair<std::string, std::string>> &entries)
{
  std::ofstream out(filename);
  AssertThrow(out, ExcMessage("cannot write " + filename));
  out << "{\n";
  for (unsigned int i = 0; i < entries.size(); ++i)
    out << "  \"" << entries[i].first << "\": " << entries[i].second
        << (i + 1 < entries.size() ? ",\n" : "\n");
  out << "}\n";
}
} // namespace hati
