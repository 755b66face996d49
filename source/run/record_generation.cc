#include <deal.II/base/exceptions.h>

#include <hati/output/csv_file.h>
#include <hati/output/output_file.h>
#include <hati/output/plot_script.h>
#include <hati/output/response_spectrum.h>
#include <hati/run/record_generation.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace hati
{
RecordGeneration::RecordGeneration(ParameterHandler &prm,
                                   const std::string &parameter_file)
{
  spectrum.parse_parameters(prm);
  records.parse_parameters(prm);
  AssertThrow(!active() || spectrum.active(),
              ExcMessage("Artificial records/Number: " + std::to_string(records.number) +
                         " records need a target: Design spectrum/Type is none"));
  // the shortest period of the matching needs two samples a period
  AssertThrow(
      !active() || records.time_step <= 0.5 * spectrum.period_range[0],
      ExcMessage("Artificial records/Time step: " + shortest_number(records.time_step) +
                 " s cannot hold the Design spectrum's shortest period " +
                 shortest_number(spectrum.period_range[0]) +
                 " s (Period range): a Time step of at most half of it, " +
                 shortest_number(0.5 * spectrum.period_range[0]) + " s, is expected"));
  std::string out = prm.get(std::vector<std::string>{"Output"}, "Output directory");
  if (out.empty())
    out = "output/" + std::filesystem::path(parameter_file).stem().string();
  folder = out + "/records";
}

RecordGeneration::~RecordGeneration() = default;

std::string RecordGeneration::record_name(const unsigned int index) const
{
  std::ostringstream s;
  s << "art" << std::setw(records.number >= 100 ? 3 : 2) << std::setfill('0') << index;
  return s.str();
}

std::vector<SuiteRecord> RecordGeneration::suite_records() const
{
  std::vector<SuiteRecord> list;
  for (unsigned int i = 1; i <= records.number; ++i)
  {
    SuiteRecord r;
    r.name = record_name(i);
    r.generated = true;
    for (const unsigned int d : records.components)
      r.files[d] = folder + "/" + r.name + "_" + char('X' + d) + ".AT2";
    list.push_back(r);
  }
  return list;
}

void RecordGeneration::write() const
{
  const auto start = std::chrono::steady_clock::now();
  const DesignSpectrum target(spectrum);
  refuse_linked_folder(folder);
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  AssertThrow(!ec,
              ExcMessage("Artificial records: cannot create the folder " + folder + ": " +
                         ec.message()));
  const OutputFolder out(folder);
  std::cout << "hati: artificial records: " << records.number << " x "
            << records.components.size() << " components against "
            << target.description(0) << " (seed " << records.seed << ", "
            << records.duration << " s at " << records.time_step
            << " s: " << std::lround(records.duration / records.time_step)
            << " samples a record, about " << std::setprecision(2)
            << std::max(0.1,
                        seconds_per_record_sample * records.duration / records.time_step)
            << std::setprecision(6) << " s each)\n"
            << "  record  axis  PGA (m/s^2)  target   max deviation  iterations  draws"
            << std::endl;
  const std::vector<double> periods = matching_periods(target);
  std::ostringstream table, spectra;
  use_shortest_numbers(table);
  use_shortest_numbers(spectra);
  table << "record,component,file,peak_acceleration,target_peak_acceleration,"
           "max_deviation,iterations,draws,end_velocity_ratio,end_displacement_ratio\n";
  std::vector<std::vector<double>> columns;
  std::string header = "period";
  for (const unsigned int d : records.components)
  {
    header += std::string(",target.") + char('x' + d);
    std::vector<double> t;
    for (const double T : periods)
      t.push_back(target(T, d));
    columns.push_back(t);
  }
  for (const auto &r : suite_records())
    for (const unsigned int d : records.components)
    {
      const unsigned int index = std::stoi(r.name.substr(3));
      const ArtificialRecord record = generate_record(target, records, index, d);
      const std::string axis(1, char('X' + d));
      const std::string file = r.name + "_" + axis + ".AT2";
      out.replace(file,
                  at2_text(record,
                           r.name + " " + axis,
                           "target: " + target.description(d) + "; seed " +
                               std::to_string(records.seed) + ", record " +
                               std::to_string(index) + ", axis " + axis +
                               "; spectrum within " +
                               std::to_string(record.max_deviation) + " of the target"),
                  false);
      table << r.name << ',' << axis << ',' << file << ',' << record.peak_acceleration
            << ',' << target.zero_period_value(d) << ',' << record.max_deviation << ','
            << record.iterations << ',' << record.attempts << ','
            << record.end_velocity_ratio << ',' << record.end_displacement_ratio << '\n';
      std::vector<double> times(record.acceleration.size());
      for (std::size_t i = 0; i < times.size(); ++i)
        times[i] = i * record.time_step;
      columns.push_back(pseudo_acceleration_spectrum(
          times, record.acceleration, periods, spectrum.damping_ratio));
      header += "," + r.name + "." + char('x' + d);
      std::cout << "  " << std::setw(6) << r.name << "  " << std::setw(4) << axis << "  "
                << std::setw(11) << std::setprecision(4) << record.peak_acceleration
                << "  " << std::setw(6) << target.zero_period_value(d) << "   "
                << std::setw(13) << record.max_deviation << "  " << std::setw(10)
                << record.iterations << "  " << std::setw(5) << record.attempts
                << std::endl;
    }
  spectra << header << '\n';
  for (std::size_t j = 0; j < periods.size(); ++j)
  {
    spectra << periods[j];
    for (const auto &c : columns)
      spectra << ',' << c[j];
    spectra << '\n';
  }
  out.replace("records.csv", table.str(), false);
  out.replace("records_spectra.csv", spectra.str(), false);
  const std::string warning = run_plot_script("plot_records.py", folder);
  std::cout
      << "  records: " << folder << "/ (AT2 files, records.csv, records_spectra.csv"
      << (warning.empty() ? ", records.png" : "") << ") in " << std::setprecision(3)
      << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()
      << " s" << std::endl;
  if (!warning.empty())
    std::cerr << "hati: warning: artificial records: records.png was not drawn: "
              << warning << std::endl;
}
} // namespace hati
