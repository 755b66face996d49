#include <deal.II/base/exceptions.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <hati/analysis/reduced_part.h>
#include <hati/run/analysis_registry.h>
#include <hati/run/problem.h>
#include <hati/run/time_loop.h>
#include <hati/time/hati_coupling.h>
#include <hati/time/macro_aliasing.h>

#include <cmath>
#include <iostream>
#include <new>
#include <sstream>

namespace hati
{
namespace
{
/**
 * The coupling of the problem's subdomains; errors name the subdomain they
 * come from (the implicit one for Newmark's, the explicit one otherwise,
 * e.g. the critical step refusal), or the Time step ratio when the ramp
 * responses do not fit in memory.
 */
std::unique_ptr<HATICoupling> make_coupling(const Problem &problem)
{
  try
  {
    return std::make_unique<HATICoupling>(*problem.decomposition,
                                          problem.system.n_dofs(),
                                          problem.time_parameters.time_step,
                                          problem.time_parameters.safety_factor,
                                          problem.hati_parameters,
                                          problem.newmark_parameters,
                                          problem.damping);
  }
  catch (const ExceptionBase &e)
  {
    // name the subdomain in the message (e.g. the critical step refusal)
    std::ostringstream info;
    e.print_info(info);
    std::string text = info.str();
    const std::string prefix = "Additional information:";
    if (text.find(prefix) != std::string::npos)
      text = text.substr(text.find(prefix) + prefix.size());
    text = Utilities::trim(text);
    const bool implicit = text.rfind("Newmark", 0) == 0;
    AssertThrow(false,
                ExcMessage(std::string(implicit ? "HATI (implicit subdomain): "
                                                : "HATI (explicit subdomain): ") +
                           text));
  }
  catch (const std::bad_alloc &)
  {
    AssertThrow(false,
                ExcMessage("Time integration/HATI/Time step ratio = " +
                           std::to_string(problem.hati_parameters.time_step_ratio) +
                           ": the coupling's unit-ramp responses over the micro steps "
                           "of a macro step do not fit in memory; use a smaller ratio"));
  }
  return nullptr;
}
} // namespace

void run_hati(Problem &problem, RunDirectory &directory)
{
  TimerOutput timer(std::cout, TimerOutput::never, TimerOutput::wall_times);
  timer.enter_subsection("setup (factorisation, ramp response)");
  const std::unique_ptr<HATICoupling> coupling = make_coupling(problem);
  timer.leave_subsection();
  const auto &parts = problem.decomposition->parts;
  std::cout << "  HATI (" << problem.hati_parameters.coupling_method
            << ", G3'): explicit subdomain " << parts[0].system.n_dofs()
            << " DoFs (CD-Lagrange, dt = " << coupling->micro_time_step()
            << " s, dt_crit = " << coupling->critical_time_step()
            << " s), implicit subdomain " << parts[1].system.n_dofs() << " DoFs"
            << (problem.decomposition->reduced
                    ? " in " +
                          std::to_string(
                              implicit_system(*problem.decomposition).n_dofs()) +
                          " Craig-Bampton coordinates"
                    : std::string())
            << " (Newmark, DT = " << coupling->time_step()
            << " s, m = " << coupling->time_step_ratio() << "), "
            << coupling->n_interface_dofs() << " interface DoFs" << std::endl;
  {
    // macro-step aliasing (doc/theory.md 11.3): a warning, not a refusal
    const auto modes =
        free_interface_modes(parts[0].system, problem.decomposition->rows[0]);
    const double dt = coupling->micro_time_step();
    const unsigned int m = coupling->time_step_ratio();
    const std::string w =
        aliasing_warning(aliasing_modes(modes, dt, m, aliasing_phase, aliasing_share),
                         modes,
                         dt,
                         m,
                         aliasing_phase,
                         aliasing_share);
    if (modes.empty())
      std::cout << "  macro-step aliasing not checked (the explicit subdomain has more "
                   "than 2000 free DoFs)"
                << std::endl;
    else
      std::cout << "  explicit free-interface modes: " << modes.size() << ", up to "
                << modes.back().omega / (2. * M_PI) << " Hz; "
                << (w.empty() ? "none" : "some") << " with " << 100. * aliasing_share
                << " % of the interface's flexibility folds within " << aliasing_phase
                << " rad of zero frequency per macro step" << std::endl;
    if (!w.empty())
      problem.warn(w);
  }
  run_time_loop(*coupling,
                problem,
                directory,
                timer,
                {{"method", "HATI"},
                 {"coupling_method", problem.hati_parameters.coupling_method},
                 {"dt_crit", coupling->critical_time_step()}});
}
} // namespace hati
