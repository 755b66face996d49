// Static and modal analyses of Simulation (kept apart from the time loops).
#include <deal.II/base/data_out_base.h>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/timer.h>

#include <hati/analysis/modal_analysis.h>
#include <hati/analysis/static_analysis.h>
#include <hati/output/csv_file.h>
#include <hati/output/output_writer.h>
#include <hati/output/run_directory.h>
#include <hati/simulation.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace hati
{
void Simulation::run_static()
{
  const auto start = std::chrono::steady_clock::now();
  TimerOutput timer(std::cout, TimerOutput::never, TimerOutput::wall_times);
  Vector<double> U, V(system.n_dofs());
  std::vector<double> forces;
  {
    TimerOutput::Scope scope(timer, "static solve");
    solve_static(system, 0., U, newmark_parameters.linear_solver, false, &forces);
  }
  const std::string contact_entry = report_static_contact_forces(forces);
  OutputWriter writer(*run_directory, system, *model);
  OutputState s;
  s.time = 0.;
  s.displacement = &U;
  s.velocity = &V;
  for (const auto &c : system.contacts)
  {
    s.gaps.push_back(c.initial_gap + c.apply(U));
    s.normal_velocities.push_back(0.);
    s.impulses.push_back(0.);
    s.active.push_back(false);
  }
  writer.write_history(s);
  writer.write_vtu(s);
  writer.finish();

  std::cout << "  static analysis (K U = F_ext(0), " << newmark_parameters.linear_solver
            << " solver):\n";
  for (const auto &m : system.monitors)
  {
    std::cout << "    " << m.name << ":";
    for (unsigned int i = 0; i < m.dofs.size(); ++i)
      std::cout << "  u" << m.labels[i] << " = " << std::setprecision(8) << U[m.dofs[i]];
    std::cout << std::endl;
  }
  double umax = 0.;
  for (unsigned int d = 0; d < 3; ++d)
    for (unsigned int i = 0; i < system.influence[d].size(); ++i)
      if (system.influence[d][i] != 0.)
        umax = std::max(umax, std::abs(U[i]));
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::vector<std::pair<std::string, std::string>> summary = {
      {"analysis", json_string("static")},
      {"model", json_string(model->description())},
      {"n_dofs", std::to_string(system.n_dofs())},
      {"max_translation", json_number(umax)},
      {"wall_time", json_number(wall)}};
  if (!contact_entry.empty())
    summary.emplace_back("static_contact_forces", contact_entry);
  for (const auto &entry : model->summary_entries(static_contact_forces))
    summary.push_back(entry);
  write_summary(output_directory + "/summary.json", summary);
  std::cout << "  largest translation " << umax << " m; results in " << output_directory
            << "/ (history.csv, solution.pvd, summary.json)" << std::endl;
  timer.print_summary();
}

std::string Simulation::report_static_contact_forces(const std::vector<double> &forces)
{
  // closed rows: zero initial gap (solve_static); sums per name, in order
  std::vector<std::string> names;
  std::vector<double> sums;
  std::vector<unsigned int> n_rows;
  for (unsigned int k = 0; k < system.contacts.size() && k < forces.size(); ++k)
  {
    if (system.contacts[k].initial_gap != 0.)
      continue;
    const auto it = std::find(names.begin(), names.end(), system.contacts[k].name);
    if (it == names.end())
    {
      names.push_back(system.contacts[k].name);
      sums.push_back(forces[k]);
      n_rows.push_back(1);
    }
    else
    {
      sums[it - names.begin()] += forces[k];
      ++n_rows[it - names.begin()];
    }
  }
  if (names.empty())
    return "";
  std::cout << "  static contact forces (closed contacts, N):\n";
  std::ostringstream json;
  json << '{';
  double total = 0.;
  for (unsigned int g = 0; g < names.size(); ++g)
  {
    std::cout << "    " << std::left << std::setw(28) << names[g] << std::right
              << std::setw(16) << std::setprecision(8) << sums[g] << std::endl;
    json << (g ? ", " : "") << json_string(names[g]) << ": " << json_number(sums[g]);
    static_contact_forces[names[g]] = sums[g];
    total += sums[g];
  }
  std::cout << "    " << std::left << std::setw(28) << "sum" << std::right
            << std::setw(16) << std::setprecision(8) << total << std::endl;
  json << '}';
  return json.str();
}

void Simulation::run_modal()
{
  const auto start = std::chrono::steady_clock::now();
  TimerOutput timer(std::cout, TimerOutput::never, TimerOutput::wall_times);
  ModalResult r;
  {
    TimerOutput::Scope scope(timer, "eigenvalue solve");
    r = compute_modes(system, analysis_parameters.n_modes);
  }
  TimerOutput::Scope scope(timer, "output");
  run_directory->begin();
  std::ofstream csv(run_directory->create("modes.csv"));
  AssertThrow(csv, ExcMessage("cannot write " + output_directory + "/modes.csv"));
  use_shortest_numbers(csv);
  csv << "mode,frequency,period,participation_x,participation_y,participation_z,"
         "effective_mass_x,effective_mass_y,effective_mass_z,effective_mass_ratio_x,"
         "effective_mass_ratio_y,effective_mass_ratio_z\n";
  std::cout << "  modal analysis: " << r.frequencies.size() << " modes";
  if (r.n_closed_contacts > 0)
    std::cout << ", " << r.n_closed_contacts << " zero-gap contact rows held closed ("
              << r.n_constraints << " independent constraints)";
  std::cout << "\n"
            << "   mode  frequency (Hz)   period (s)   eff. mass ratio x      y      z\n";
  std::vector<std::pair<double, std::string>> files;
  for (unsigned int k = 0; k < r.frequencies.size(); ++k)
  {
    const double f = r.frequencies[k];
    std::array<double, 3> ratio{{0., 0., 0.}};
    for (unsigned int d = 0; d < 3; ++d)
      ratio[d] = r.total_mass[d] > 0. ? r.effective_mass[k][d] / r.total_mass[d] : 0.;
    csv << k + 1 << ',' << f << ',' << (f > 0. ? 1. / f : 0.);
    for (unsigned int d = 0; d < 3; ++d)
      csv << ',' << r.participation[k][d];
    for (unsigned int d = 0; d < 3; ++d)
      csv << ',' << r.effective_mass[k][d];
    for (unsigned int d = 0; d < 3; ++d)
      csv << ',' << ratio[d];
    csv << '\n';
    std::cout << std::setw(7) << k + 1 << std::setw(16) << std::setprecision(8) << f
              << std::setw(13) << std::setprecision(6) << (f > 0. ? 1. / f : 0.)
              << std::fixed << std::setprecision(3) << std::setw(12) << ratio[0]
              << std::setw(7) << ratio[1] << std::setw(7) << ratio[2] << std::defaultfloat
              << std::endl;

    char name[64];
    std::snprintf(name, sizeof(name), "mode-%03u.vtu", k + 1);
    std::ofstream out(run_directory->create(name));
    model->write_vtu(out, {{"displacement", &r.modes[k]}}, k + 1, k + 1);
    AssertThrow(out.flush(),
                ExcMessage("cannot write " + output_directory + "/" + name + ": " +
                           system_error_text(errno)));
    files.emplace_back(k + 1, name);
  }
  csv.close();
  AssertThrow(csv, ExcMessage("cannot write " + output_directory + "/modes.csv"));
  std::ostringstream pvd;
  DataOutBase::write_pvd_record(pvd, files);
  run_directory->create(temporary_name("modes.pvd"));
  write_file_atomically(run_directory->create("modes.pvd"), pvd.str());

  std::ostringstream list;
  list << '[';
  for (unsigned int k = 0; k < r.frequencies.size(); ++k)
    list << (k ? ", " : "") << json_number(r.frequencies[k]);
  list << ']';
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  write_summary(output_directory + "/summary.json",
                {{"analysis", json_string("modal")},
                 {"model", json_string(model->description())},
                 {"n_dofs", std::to_string(system.n_dofs())},
                 {"frequencies", list.str()},
                 {"n_closed_contact_rows", std::to_string(r.n_closed_contacts)},
                 {"wall_time", json_number(wall)}});
  std::cout << "  modes.csv and mode shapes (modes.pvd: 'time' = mode number) in "
            << output_directory << "/" << std::endl;
}
} // namespace hati
