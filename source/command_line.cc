#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <boost/program_options.hpp>

#include <hati/base/input_file.h>
#include <hati/base/version.h>
#include <hati/output/run_directory.h>
#include <hati/run/mpi_consensus.h>
#include <hati/run/record_generation.h>
#include <hati/run/simulation.h>
#include <hati/run/suite_plan.h>
#include <hati/run/suite_runner.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace hati
{
void apply_override(ParameterHandler &prm, const std::string &assignment)
{
  const auto eq = assignment.find('=');
  AssertThrow(
      eq != std::string::npos && eq > 0,
      ExcMessage("--set '" + assignment + "': expected \"Subsection/Entry=value\""));
  const std::string path = Utilities::trim(assignment.substr(0, eq));
  const std::string value = Utilities::trim(assignment.substr(eq + 1));
  std::vector<std::string> parts;
  std::string::size_type start = 0, slash;
  while ((slash = path.find('/', start)) != std::string::npos)
  {
    parts.push_back(Utilities::trim(path.substr(start, slash - start)));
    start = slash + 1;
  }
  const std::string entry = Utilities::trim(path.substr(start));
  constexpr unsigned int max_depth = 64;
  AssertThrow(parts.size() <= max_depth,
              ExcMessage("--set '" + assignment.substr(0, 60) + "...': " +
                         std::to_string(parts.size()) + " subsection levels, at most " +
                         std::to_string(max_depth) + " (see hati --print-parameters)"));

  for (const auto &p : parts)
    prm.enter_subsection(p);
  std::string problem;
  try
  {
    prm.set(entry, value);
  }
  catch (const ParameterHandler::ExcEntryUndeclared &)
  {
    problem = "no parameter '" + path + "' is declared";
  }
  catch (const std::exception &e)
  {
    problem = "the value '" + value + "' does not match the pattern of '" + path + "'";
    // deal.II's exception holds the pattern: name it (the bounds, with units
    // in --print-parameters)
    if (const auto *d = dynamic_cast<const ExceptionBase *>(&e))
    {
      std::ostringstream info;
      d->print_info(info);
      const std::string text = info.str();
      const std::string given = "given pattern <";
      const auto open = text.find(given), close = text.rfind('>');
      if (open != std::string::npos && close > open + given.size())
        problem += " " + text.substr(open + given.size(), close - open - given.size());
    }
  }
  for (unsigned int i = 0; i < parts.size(); ++i)
    prm.leave_subsection();
  AssertThrow(problem.empty(),
              ExcMessage("--set '" + assignment + "': " + problem +
                         " (see hati --print-parameters)"));
}

void read_parameter_file(ParameterHandler &prm, const std::string &file)
{
  AssertThrow(std::filesystem::exists(file),
              ExcMessage("parameter file '" + file + "' does not exist"));
  // a FIFO would block the reader, a device never end: refused unopened
  require_regular_file(file, "", "parameter");
  const std::string extension = std::filesystem::path(file).extension().string();
  if (extension == ".json" || extension == ".xml")
  {
    // Boost's parser errors name "<unspecified file>(line)": name the file
    try
    {
      prm.parse_input(file);
    }
    catch (const std::exception &e)
    {
      std::string message = one_line_message(e);
      const std::string unnamed = "<unspecified file>(";
      for (auto at = message.find(unnamed); at != std::string::npos;
           at = message.find(unnamed))
      {
        const auto close = message.find(')', at);
        message.replace(
            at,
            close - at + 1,
            "line " + message.substr(at + unnamed.size(), close - at - unnamed.size()));
      }
      AssertThrow(false, ExcMessage("parameter file '" + file + "': " + message));
    }
  }
  else
  {
    // .prm: accept a UTF-8 byte-order mark (editors on Windows write one)
    std::ifstream in(file);
    AssertThrow(in, ExcMessage("cannot read the parameter file '" + file + "'"));
    char bom[3] = {0, 0, 0};
    in.read(bom, 3);
    if (!(in.gcount() == 3 && bom[0] == '\xEF' && bom[1] == '\xBB' && bom[2] == '\xBF'))
    {
      in.clear();
      in.seekg(0);
    }
    prm.parse_input(in, file);
  }
}

int run_command_line(int argc, char **argv)
{
  namespace po = boost::program_options;
  po::options_description options(
      "hati: nonsmooth structural dynamics: CD-Lagrange contact/impact, Newmark, "
      "static and modal analyses of bars, solids and 3D frames\n"
      "Usage: hati file.prm [options]\nOptions");
  options.add_options()("help,h", "print this help and exit")(
      "version", "print the git commit hati was built from and exit")(
      "print-parameters", "print every parameter with its default and documentation")(
      "set",
      po::value<std::vector<std::string>>()->composing(),
      "override a parameter, \"Subsection/Entry=value\" (repeatable)")(
      "parameter-file", po::value<std::string>(), "the .prm file to run");
  po::positional_options_description positional;
  positional.add("parameter-file", 1);
  ignore_broken_pipes();

  std::unique_ptr<Simulation> simulation;
  try
  {
    po::variables_map vm;
    po::store(
        po::command_line_parser(argc, argv).options(options).positional(positional).run(),
        vm);
    po::notify(vm);

    ParameterHandler prm;
    Simulation::declare_parameters(prm);

    if (vm.count("help"))
    {
      std::cout << options << std::endl;
      return 0;
    }
    if (vm.count("version"))
    {
      std::cout << "hati, git commit " << hati_git_commit() << std::endl;
      return 0;
    }
    if (vm.count("print-parameters"))
    {
      prm.print_parameters(std::cout, ParameterHandler::PRM);
      return 0;
    }
    if (!vm.count("parameter-file"))
    {
      std::cerr << "hati: error: no parameter file given (hati file.prm; hati --help)"
                << std::endl;
      return 2;
    }
    const std::string file = vm["parameter-file"].as<std::string>();
    std::vector<std::string> overrides;
    if (vm.count("set"))
      overrides = vm["set"].as<std::vector<std::string>>();
    SuiteParameters suite;
    std::unique_ptr<SuiteRunner> runner;
    // every rank reads the same parameters; under mpirun a refusal is
    // agreed, so that rank 0 alone prints it and no rank waits for another
    std::unique_ptr<RecordGeneration> generation;
    agree(MPI_COMM_WORLD,
          [&]
          {
            read_parameter_file(prm, file);
            for (const auto &s : overrides)
              apply_override(prm, s);
            generation = std::make_unique<RecordGeneration>(prm, file);
          });
    agree(MPI_COMM_WORLD,
          [&]
          {
            suite.parse_parameters(prm, generation->suite_records());
            if (suite.active()) // one Simulation per member (run/suite_runner.h)
              runner = std::make_unique<SuiteRunner>(
                  prm, file, overrides, suite, MPI_COMM_WORLD);
          });
    // the artificial records are written by rank 0 once the suite is
    // checked (a refused suite writes nothing) and before any rank reads them
    if (generation->active())
      agree(
          MPI_COMM_WORLD, [&] { generation->write(); }, true);
    if (runner)
      return runner->run();

    // one run needs one rank: under mpirun the others would only find its
    // output directory locked (a Suite spreads its members over the ranks)
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
      return 0;
    simulation = std::make_unique<Simulation>(prm, file);
    // a target that neither a suite's check nor artificial records take
    if (!generation->active() &&
        prm.get(std::vector<std::string>{"Analysis"}, "Type") != "response spectrum" &&
        prm.get(std::vector<std::string>{"Design spectrum"}, "Type") != "none")
      simulation->warn("subsection Design spectrum is ignored: a single run checks no "
                       "spectrum (a subsection Suite with Records or Scale factors is "
                       "checked against it, Artificial records/Number > 0 generates "
                       "records that match it)");
    if (n_ranks > 1)
      simulation->warn(
          std::to_string(n_ranks) +
          " MPI ranks for a single run: it runs on rank 0 and " +
          (n_ranks == 2 ? std::string("the other rank stays")
                        : "the other " + std::to_string(n_ranks - 1) + " ranks stay") +
          " idle (a subsection Suite spreads the records of a suite over "
          "the ranks)");
    simulation->run();
    if (stop_requested())
    {
      std::cerr << "hati: interrupted by "
                << (stop_signal() == SIGINT ? "SIGINT" : "SIGTERM")
                << " after a complete step; the outputs are flushed and summary.json "
                   "says \"status\": \"interrupted\""
                << std::endl;
      return 128 + stop_signal();
    }
    return 0;
  }
  catch (const AgreedError &e)
  {
    // every rank has it: printed once
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::cerr << "hati: error: " << e.what() << std::endl;
    return 1;
  }
  catch (const std::exception &e)
  {
    const std::string message = one_line_message(e);
    if (simulation)
      simulation->record_failure(message);
    std::cerr << "hati: error: " << message << std::endl;
    return 1;
  }
}
} // namespace hati
