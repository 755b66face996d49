#ifndef hati_run_analysis_registry_h
#define hati_run_analysis_registry_h

#include <hati/base/registry.h>

#include <functional>

namespace hati
{
class Problem;
class RunDirectory;

/**
 * Runs one analysis or time integration method on a Problem that has built
 * its system and loads (Problem::build_system(), Problem::add_loads()),
 * writing its outputs into the RunDirectory (begun by the runner once its
 * input is checked).
 */
using AnalysisRunner = std::function<void(Problem &, RunDirectory &)>;

/**
 * The analyses of `Analysis/Type` (transient, static, modal, response spectrum),
 * registered in source/run/analysis_registry.cc.
 */
const Registry<AnalysisRunner> &analysis_registry();

/**
 * The time integration methods of `Time integration/Method` (CD-Lagrange,
 * event-driven, Newmark, HATI) that the transient analysis runs,
 * registered in source/run/analysis_registry.cc.
 */
const Registry<AnalysisRunner> &method_registry();

/** @name The runners, one file each in source/run/ */
/** @{ */
void run_transient_analysis(Problem &problem, RunDirectory &directory);
void run_static_analysis(Problem &problem, RunDirectory &directory);
void run_modal_analysis(Problem &problem, RunDirectory &directory);
void run_response_spectrum_analysis(Problem &problem, RunDirectory &directory);
void run_cd_lagrange(Problem &problem, RunDirectory &directory);
void run_event_driven(Problem &problem, RunDirectory &directory);
void run_newmark(Problem &problem, RunDirectory &directory);
void run_hati(Problem &problem, RunDirectory &directory);
/** @} */
} // namespace hati

#endif
