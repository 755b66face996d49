// Analysis/Type = response spectrum: the static state, the analysis
// (analysis/response_spectrum_analysis.h), its files, summary and table.

#include <deal.II/base/exceptions.h>

#include <hati/analysis/response_spectrum_analysis.h>
#include <hati/analysis/static_analysis.h>
#include <hati/base/messages.h>
#include <hati/output/csv_file.h>
#include <hati/output/run_directory.h>
#include <hati/output/summary.h>
#include <hati/run/analysis_registry.h>
#include <hati/run/problem.h>
#include <hati/run/qualification_run.h>

#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace hati
{
namespace
{
/**
 * EN 1998-1 4.3.3.3: the modes taken into account carry at least 90 % of
 * the mass in each direction.
 */
constexpr double ec8_mass_fraction = 0.9;

/** The modes' table (response_spectrum_modes.csv). */
std::string modes_csv(const ResponseSpectrumAnalysis &rsa,
                      const std::vector<unsigned int> &directions)
{
  std::ostringstream csv;
  use_shortest_numbers(csv);
  csv << "mode,frequency,period";
  for (const unsigned int d : directions)
    for (const char *column :
         {".Sa", ".participation", ".effective_mass_ratio", ".cumulative_mass_ratio"})
      csv << ',' << "XYZ"[d] << column;
  csv << '\n';
  for (std::size_t k = 0; k < rsa.modes().size(); ++k)
  {
    const SpectralMode &m = rsa.modes()[k];
    csv << k + 1 << ',' << m.frequency << ',' << m.period;
    for (const unsigned int d : directions)
      csv << ',' << m.spectral_acceleration[d] << ',' << m.participation[d] << ','
          << m.effective_mass_ratio[d] << ',' << m.cumulative_mass_ratio[d];
    csv << '\n';
  }
  return csv.str();
}

/** The combined quantities (response_spectrum.csv). */
std::string quantities_csv(const ResponseSpectrumAnalysis &rsa)
{
  std::ostringstream csv;
  use_shortest_numbers(csv);
  csv << "quantity,unit,X,Y,Z,combined\n";
  for (const SpectralQuantity &q : rsa.quantities())
    csv << q.name << ',' << q.unit << ',' << q.peak[0] << ',' << q.peak[1] << ','
        << q.peak[2] << ',' << q.combined << '\n';
  return csv.str();
}

/**
 * The combined value of the row @p name of @p rsa (-1 if it has none), with
 * @p with_static its SpectralQuantity::with_static.
 */
double combined_value(const ResponseSpectrumAnalysis &rsa,
                      const std::string &name,
                      const bool with_static = false)
{
  for (const SpectralQuantity &q : rsa.quantities())
    if (q.name == name)
      return with_static ? q.with_static : q.combined;
  return -1.;
}

/**
 * What a transient run's summary.json gives too, for the comparison with a
 * suite, with the static state as a time history's envelope has it:
 * `section_force_envelope` (N, My, Mz: the largest |static| + combined
 * value over the model's section force members, with the member),
 * `max_absolute_acceleration` per monitor (the length of the vector of its
 * combined component peaks: an upper bound, they do not occur at once) and
 * `max_von_mises` per solid (static and combined, SpectralQuantity::with_static).
 */
void add_comparable_entries(const ResponseSpectrumAnalysis &rsa,
                            const Problem &problem,
                            SummaryValue &entry)
{
  // static + combined: the time histories' envelopes hold the static state
  const std::vector<std::string> members = problem.model->section_force_members();
  if (!members.empty())
  {
    SummaryValue envelope = SummaryValue::object();
    for (const char *force : {"N", "My", "Mz"})
    {
      double largest = -1.;
      std::string where;
      for (const std::string &m : members)
      {
        const double v = combined_value(rsa, m + "." + force, true);
        if (v > largest)
        {
          largest = v;
          where = m;
        }
      }
      if (largest >= 0.)
        envelope.set(force,
                     SummaryValue::object().set("max_abs", largest).set("member", where));
    }
    entry.set("section_force_envelope", envelope);
  }
  SummaryValue accelerations = SummaryValue::object();
  for (const MonitorPoint &m : problem.system.monitors)
  {
    double sum = 0.;
    bool any = false;
    for (const char *c : {".ax", ".ay", ".az"})
    {
      const double v = combined_value(rsa, m.name + c);
      if (v >= 0.)
      {
        sum += v * v;
        any = true;
      }
    }
    if (any)
      accelerations.set(m.name, std::sqrt(sum));
  }
  entry.set("max_absolute_acceleration", accelerations);
  SummaryValue solids = SummaryValue::object();
  const std::string suffix = ".max_von_mises";
  for (const SpectralQuantity &q : rsa.quantities())
    if (q.name.size() > suffix.size() &&
        q.name.compare(q.name.size() - suffix.size(), suffix.size(), suffix) == 0)
      solids.set(q.name.substr(0, q.name.size() - suffix.size()), q.with_static);
  entry.set("max_von_mises", solids);
}

/**
 * What the qualification checks (Q1) of a response-spectrum analysis:
 * `beam_stresses` per member (S1-S3 of the largest |static| + combined
 * value of each section force over the member's stations, taken together:
 * a bound, they need not meet at one station) and `solids` per solid (its
 * largest static and combined von Mises stress). A linear analysis has no
 * uplift height, slip or rope slack to check.
 */
SummaryEntries qualification_entries(const ResponseSpectrumAnalysis &rsa,
                                     const Problem &problem)
{
  static const char *const forces[6] = {"N", "Vy", "Vz", "T", "My", "Mz"};
  SummaryValue beams = SummaryValue::object(), solids = SummaryValue::object();
  std::vector<std::string> members;
  for (const SpectralQuantity &q : rsa.quantities())
  {
    const auto dot = q.name.rfind('.');
    if (dot != std::string::npos && q.name.substr(dot + 1) == "N")
      members.push_back(q.name.substr(0, dot));
    if (dot != std::string::npos && q.name.substr(dot + 1) == "max_von_mises")
      solids.set(q.name.substr(0, dot),
                 SummaryValue::object().set("max_von_mises",
                                            SummaryValue::object()
                                                .set("value", q.with_static)
                                                .set("where", "static + combined")));
  }
  bool any_beam = false;
  for (const std::string &m : members)
  {
    std::array<double, 6> s;
    for (unsigned int k = 0; k < 6; ++k)
      s[k] = std::max(0., combined_value(rsa, m + "." + forces[k], true));
    double normal = 0., von_mises = 0.;
    if (!problem.model->member_stress(m, s, normal, von_mises))
      continue;
    any_beam = true;
    const char *where = "static + combined, each section force at its largest station";
    beams.set(
        m,
        SummaryValue::object()
            .set("max_normal_stress",
                 SummaryValue::object().set("value", normal).set("where", where))
            .set("max_von_mises",
                 SummaryValue::object().set("value", von_mises).set("where", where)));
  }
  SummaryEntries entries;
  if (any_beam)
    entries.emplace_back("beam_stresses", beams);
  if (!solids.members().empty())
    entries.emplace_back("solids", solids);
  return entries;
}

/** The `response_spectrum` entry of summary.json. */
SummaryValue summary_entry(const ResponseSpectrumAnalysis &rsa,
                           const ResponseSpectrumParameters &parameters)
{
  SummaryValue entry = SummaryValue::object();
  entry.set("modal_combination", name_of(parameters.modal_combination));
  entry.set("directional_combination", name_of(parameters.directional_combination));
  entry.set("cutoff_frequency", parameters.cutoff_frequency);
  entry.set("modes_used", static_cast<unsigned int>(rsa.modes().size()));
  entry.set("highest_frequency_used",
            rsa.modes().empty() ? SummaryValue() : rsa.modes().back().frequency);
  entry.set("missing_mass", SummaryValue::boolean(parameters.missing_mass));
  entry.set("rigid_response", parameters.gupta ? "Gupta" : "none");
  SummaryValue effective = SummaryValue::object(), missing = SummaryValue::object(),
               zpa = SummaryValue::object(), total = SummaryValue::object();
  for (const unsigned int d : parameters.directions)
  {
    const std::string axis(1, "XYZ"[d]);
    effective.set(axis, rsa.effective_mass_ratio()[d]);
    missing.set(axis, rsa.missing_mass_ratio()[d]);
    zpa.set(axis, rsa.zero_period_acceleration()[d]);
    total.set(axis, rsa.total_mass()[d]);
  }
  entry.set("total_mass", total);
  entry.set("effective_mass_ratio", effective);
  entry.set("missing_mass_ratio", missing);
  entry.set("zero_period_acceleration", zpa);
  SummaryValue contacts = SummaryValue::object();
  for (const SpectralContact &c : rsa.contacts())
    contacts.set(c.name,
                 SummaryValue::object()
                     .set("static_force", c.static_force)
                     .set("max_force", c.max_force())
                     .set("min_force", c.min_force())
                     .set("uplift_predicted", SummaryValue::boolean(c.uplift_predicted()))
                     .set("two_sided", SummaryValue::boolean(c.two_sided)));
  entry.set("contacts", contacts);
  return entry;
}
} // namespace

void run_response_spectrum_analysis(Problem &problem, RunDirectory &directory)
{
  const DiscreteSystem &system = problem.system;
  const ResponseSpectrumParameters &parameters = problem.response_spectrum_parameters;
  const auto start = std::chrono::steady_clock::now();
  // the static state under the constant loads: the ropes' tangent (before
  // the modes) and the contacts' static forces (max_force, min_force). A
  // model without ropes gets its modes first, so that a mechanism is
  // refused as one (its static state does not exist either)
  Vector<double> U(system.n_dofs());
  std::vector<double> forces;
  double static_time = 0.;
  const auto static_state = [&]
  {
    const auto static_start = std::chrono::steady_clock::now();
    try
    {
      solve_static(
          system, 0., U, problem.newmark_parameters.linear_solver, true, &forces);
    }
    catch (const std::exception &e)
    {
      AssertThrow(false,
                  ExcMessage(std::string("response spectrum: no static state to start "
                                         "from: ") +
                             one_line_message(e)));
    }
    static_time =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - static_start)
            .count();
  };
  if (!system.ropes.empty())
    static_state();
  const DesignSpectrum spectrum(problem.design_spectrum_parameters);
  const Model &model = *problem.model;
  ResponseModel quantities;
  quantities.groups = model.response_groups();
  quantities.values = [&model](const Vector<double> &u,
                               std::vector<double> &values,
                               const bool own_weight)
  { model.response_values(u, values, own_weight); };
  quantities.describe_dof = [&model](const types::global_dof_index dof)
  {
    const DofDescription d = model.describe_dof(dof);
    return d.component + (d.location.empty() ? std::string() : " at " + d.location);
  };
  ResponseSpectrumAnalysis rsa(system,
                               quantities,
                               parameters,
                               spectrum,
                               U,
                               problem.newmark_parameters.linear_solver);
  if (system.ropes.empty())
    static_state();
  rsa.set_static_state(U, forces);
  const auto output_start = std::chrono::steady_clock::now();

  std::cout << "  response spectrum: " << name_of(parameters.modal_combination)
            << " of the " << rsa.modes().size() << " modes up to "
            << parameters.cutoff_frequency << " Hz";
  if (rsa.n_closed_rows() + rsa.n_held_clearance_rows() > 0)
    std::cout << " (" << rsa.n_closed_rows() << " zero-gap contact rows closed, "
              << rsa.n_held_clearance_rows() << " clearance rows held)";
  std::cout << ", directions";
  for (const unsigned int d : parameters.directions)
    std::cout << ' ' << "XYZ"[d] << " (" << spectrum.description(d) << ")";
  std::cout << ", " << name_of(parameters.directional_combination) << "\n"
            << "   mode  frequency (Hz)   cumulative mass ratio";
  for (const unsigned int d : parameters.directions)
    std::cout << "      "
              << "XYZ"[d];
  std::cout << '\n';
  for (std::size_t k = 0; k < rsa.modes().size(); ++k)
  {
    const SpectralMode &m = rsa.modes()[k];
    std::cout << std::setw(7) << k + 1 << std::setw(16) << std::setprecision(6)
              << m.frequency << std::setw(24) << "" << std::fixed << std::setprecision(4);
    for (const unsigned int d : parameters.directions)
      std::cout << std::setw(7) << m.cumulative_mass_ratio[d];
    std::cout << std::defaultfloat << '\n';
  }
  std::cout << "  missing mass (" << (parameters.missing_mass ? "added" : "left out")
            << "):";
  for (const unsigned int d : parameters.directions)
    std::cout << ' ' << "XYZ"[d] << ' ' << std::setprecision(4)
              << 100. * rsa.missing_mass_ratio()[d] << " %";
  std::cout << std::endl;
  for (const unsigned int d : parameters.directions)
    if (rsa.effective_mass_ratio()[d] < ec8_mass_fraction)
    {
      std::ostringstream s;
      s << "response spectrum: the " << rsa.modes().size() << " modes up to "
        << parameters.cutoff_frequency << " Hz carry " << std::setprecision(3)
        << 100. * rsa.effective_mass_ratio()[d] << " % of the mass along "
        << "XYZ"[d] << ", less than the 90 % of EN 1998-1 4.3.3.3"
        << (parameters.missing_mass ? " (the missing mass adds the rest statically)"
                                    : " (raise the Cutoff frequency or set Missing mass "
                                      "= true)");
      problem.warn(s.str());
    }

  directory.begin();
  directory.replace(
      "response_spectrum_modes.csv", modes_csv(rsa, parameters.directions), true);
  directory.replace("response_spectrum.csv", quantities_csv(rsa), true);
  for (const std::string &name : problem.model->response_envelope_files())
  {
    std::ostringstream file;
    problem.model->write_response_envelope(name, rsa.stress_envelopes(), file);
    directory.replace(name, file.str(), true);
  }

  // the table: every quantity but the stations' detail
  std::cout << "  " << std::left << std::setw(36) << "quantity" << std::setw(7) << "unit"
            << std::right;
  for (const char *column : {"X", "Y", "Z", "combined"})
    std::cout << std::setw(13) << column;
  std::cout << '\n';
  for (const SpectralQuantity &q : rsa.quantities())
  {
    std::cout << "  " << std::left << std::setw(36) << q.name << std::setw(7) << q.unit
              << std::right << std::setprecision(5);
    for (unsigned int d = 0; d < 3; ++d)
      std::cout << std::setw(13) << q.peak[d];
    std::cout << std::setw(13) << q.combined << '\n';
  }
  if (!rsa.contacts().empty())
  {
    std::cout << "  contact forces (N): static, max = static + combined, min = static - "
                 "combined\n";
    for (const SpectralContact &c : rsa.contacts())
      std::cout << "  " << std::left << std::setw(30) << c.name << std::right
                << std::setprecision(6) << std::setw(13) << c.static_force
                << std::setw(13) << c.max_force() << std::setw(13) << c.min_force()
                << (c.uplift_predicted() ? "  uplift predicted" : "") << '\n';
  }
  const double output_time =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - output_start)
          .count();
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  SummaryValue rsa_entry = summary_entry(rsa, parameters);
  add_comparable_entries(rsa, problem, rsa_entry);
  SummaryEntries summary{{"analysis", "response spectrum"},
                         {"model", problem.model->description()},
                         {"n_dofs", system.n_dofs()},
                         {"response_spectrum", rsa_entry},
                         {"wall_time", wall},
                         {"wall_time_parts",
                          SummaryValue::object()
                              .set("static_state", static_time)
                              .set("modes", rsa.wall_times[0])
                              .set("per_mode_quantities", rsa.wall_times[1])
                              .set("missing_mass", rsa.wall_times[2])
                              .set("combination", rsa.wall_times[3])
                              .set("output", output_time)}};
  for (auto &entry : qualification_entries(rsa, problem))
    summary.push_back(std::move(entry));
  add_qualification(problem, directory, summary);
  write_summary(directory.path() + "/summary.json", summary, problem.warnings);
  std::cout << "  wall time " << std::setprecision(3) << wall << " s (static state "
            << static_time << ", modes " << rsa.wall_times[0] << ", per-mode quantities "
            << rsa.wall_times[1] << ", missing mass " << rsa.wall_times[2]
            << ", combination " << rsa.wall_times[3] << ", output " << output_time
            << "); response_spectrum.csv, response_spectrum_modes.csv and summary.json "
               "in "
            << directory.path() << "/" << std::endl;
}
} // namespace hati
