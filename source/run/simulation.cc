#include <hati/output/run_directory.h>
#include <hati/run/analysis_registry.h>
#include <hati/run/problem.h>
#include <hati/run/qualification_run.h>
#include <hati/run/simulation.h>

#include <filesystem>
#include <iostream>
#include <sstream>

namespace hati
{
void Simulation::declare_parameters(ParameterHandler &prm)
{
  Problem::declare_parameters(prm);
}

Simulation::Simulation(ParameterHandler &prm, const std::string &parameter_file)
    : problem(std::make_unique<Problem>(prm)), parameter_file(parameter_file)
{
  output_directory = problem->output_parameters.directory;
  if (output_directory.empty())
    output_directory = "output/" + std::filesystem::path(parameter_file).stem().string();
  // the directory is not touched before the analysis begins (RunDirectory)
  std::ostringstream used;
  prm.print_parameters(used, ParameterHandler::PRM);
  run_directory = std::make_unique<RunDirectory>(output_directory, used.str());
}

Simulation::~Simulation() = default;

void Simulation::record_failure(const std::string &message) noexcept
{
  if (run_directory)
    run_directory->fail(message, problem->warnings);
}

void Simulation::run()
{
  problem->build_system();
  std::cout << "hati: " << parameter_file
            << "\n  model: " << problem->model->description()
            << "\n  DoFs: " << problem->system.n_dofs()
            << ", contacts: " << n_contacts(problem->system.contacts)
            << "\n  output: " << output_directory << "/" << std::endl;
  problem->add_loads();
  analysis_registry()
      .get(problem->analysis_parameters.type)
      .create(*problem, *run_directory);
  const std::string &type = problem->analysis_parameters.type;
  if (!suite_member && (type == "transient" || type == "response spectrum"))
    write_qualification_report(problem->qualification_parameters, output_directory);
  // the verdicts last: the run's closing line
  if (problem->qualification_parameters.enabled() &&
      (type == "transient" || type == "response spectrum"))
    print_qualification(problem->verdicts, std::cout);
}
void Simulation::check()
{
  run_directory->dry_run = true;
  try
  {
    run();
  }
  catch (const RunDirectory::DryRunEnd &)
  {
  }
}

void Simulation::when_output_begins(std::function<void(RunDirectory &)> hook)
{
  run_directory->after_begin = std::move(hook);
}

void Simulation::warn(const std::string &message) { problem->warn(message); }
} // namespace hati
