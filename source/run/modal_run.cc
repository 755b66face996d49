#include <deal.II/base/data_out_base.h>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/timer.h>

#include <hati/analysis/modal_analysis.h>
#include <hati/analysis/static_analysis.h>
#include <hati/output/csv_file.h>
#include <hati/output/output_writer.h>
#include <hati/output/run_directory.h>
#include <hati/output/summary.h>
#include <hati/run/analysis_registry.h>
#include <hati/run/problem.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>

namespace hati
{
void run_modal_analysis(Problem &problem, RunDirectory &directory)
{
  const DiscreteSystem &system = problem.system;
  const auto start = std::chrono::steady_clock::now();
  TimerOutput timer(std::cout, TimerOutput::never, TimerOutput::wall_times);
  ModalResult r;
  // with ropes (R1): their tangent at the static state under the constant
  // loads (doc/theory.md 10.4)
  Vector<double> rope_state(system.n_dofs());
  SummaryValue tensions = SummaryValue::object();
  if (!system.ropes.empty())
  {
    TimerOutput::Scope scope(timer, "static state of the ropes");
    solve_static(system, 0., rope_state, problem.newmark_parameters.linear_solver, true);
    std::cout << "  static rope tension (N):";
    for (const Rope &rope : system.ropes)
    {
      tensions.set(rope.name, rope.tension(rope_state));
      std::cout << "  " << rope.name << " " << std::setprecision(10)
                << rope.tension(rope_state);
    }
    std::cout << std::endl;
  }
  {
    TimerOutput::Scope scope(timer, "eigenvalue solve");
    r = compute_modes(system,
                      problem.analysis_parameters.n_modes,
                      true,
                      &rope_state,
                      problem.newmark_parameters.linear_solver);
  }
  TimerOutput::Scope scope(timer, "output");
  directory.begin();
  // modes.csv is replaced atomically at the end: never a part of it
  std::ostringstream csv;
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
  std::map<std::string, std::vector<std::pair<double, std::string>>> series_files;
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
    OutputStream out(directory.open(name));
    problem.model->write_vtu(out,
                             {{{"displacement", &r.modes[k]}}, double(k + 1), k + 1});
    out.close();
    files.emplace_back(k + 1, name);
    // the model's other series (a frame's solids): <series>-mode-NNN.vtu
    for (const std::string &series : problem.model->vtu_series())
    {
      const std::string file = series + "-" + std::string(name);
      OutputStream series_out(directory.open(file));
      problem.model->write_series_vtu(
          series, series_out, {{{"displacement", &r.modes[k]}}, double(k + 1), k + 1});
      series_out.close();
      series_files[series].emplace_back(k + 1, file);
    }
  }
  directory.replace("modes.csv", csv.str(), true);
  std::ostringstream pvd;
  DataOutBase::write_pvd_record(pvd, files);
  directory.replace("modes.pvd", pvd.str(), true);
  for (const auto &[series, list] : series_files)
  {
    std::ostringstream series_pvd;
    DataOutBase::write_pvd_record(series_pvd, list);
    directory.replace(series + "_modes.pvd", series_pvd.str(), true);
  }

  SummaryValue list = SummaryValue::list();
  for (const double f : r.frequencies)
    list.push_back(f);
  SummaryEntries summary{{"analysis", "modal"},
                         {"model", problem.model->description()},
                         {"n_dofs", system.n_dofs()},
                         {"frequencies", list},
                         {"n_closed_contact_rows", r.n_closed_contacts}};
  if (!system.ropes.empty())
    summary.emplace_back("static_rope_tension", tensions);
  if (problem.damping.frequency_range())
  {
    // the damping ratio the fitted branches give each mode (A8)
    std::cout << "  frequency-range damping (Time integration/Damping), ratio per mode:";
    SummaryValue ratios = SummaryValue::list();
    for (unsigned int k = 0; k < r.frequencies.size(); ++k)
    {
      const double xi = problem.damping.branches.damping_ratio(r.frequencies[k]);
      ratios.push_back(xi);
      std::cout << (k % 6 == 0 ? "\n   " : "") << std::setw(5) << k + 1 << ": "
                << std::fixed << std::setprecision(4) << xi << std::defaultfloat;
    }
    std::cout << std::endl;
    summary.emplace_back("damping_ratios", ratios);
  }
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  summary.emplace_back("wall_time", wall);
  write_summary(directory.path() + "/summary.json", summary, problem.warnings);
  std::cout << "  modes.csv and mode shapes (modes.pvd: 'time' = mode number";
  for (const auto &entry : series_files)
    std::cout << "; " << entry.first << "_modes.pvd";
  std::cout << ") in " << directory.path() << "/" << std::endl;
}
} // namespace hati
