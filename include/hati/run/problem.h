#ifndef hati_run_problem_h
#define hati_run_problem_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>

#include <hati/analysis/response_spectrum_analysis.h>
#include <hati/base/summary_value.h>
#include <hati/model/decomposition.h>
#include <hati/model/discrete_system.h>
#include <hati/model/model.h>
#include <hati/output/qualification.h>
#include <hati/output/state_file.h>
#include <hati/parameters/run_parameters.h>
#include <hati/time/damping.h>
#include <hati/time/hati_coupling.h>
#include <hati/time/newmark.h>

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace hati
{
using namespace dealii;

class Accelerogram;

/**
 * The one set-up path of hati (doc/architecture.md, section 1): turns the
 * parameters into the model, its discrete system with its loads, the
 * subdomains of the coupled method, the initial state and the damping, in
 * this order. `Simulation`, the analyses, the fuzz harnesses and the tests
 * call it; nothing else repeats the sequence.
 *
 * The constructor parses every parameter struct and creates the model
 * (model_registry()); the stages build_system(), add_loads() and
 * prepare_transient() follow. Each stage prints what it did on @p out
 * (a ConditionalOStream, silent for the harnesses).
 */
class Problem
{
public:
  /** Declare every parameter of hati (model, analysis, time integration, output). */
  static void declare_parameters(ParameterHandler &prm);

  /**
   * Parse every parameter of @p prm (already read and overridden, at its
   * top level) and create the model; throws a one-line message on bad input.
   */
  explicit Problem(ParameterHandler &prm,
                   const ConditionalOStream &out = ConditionalOStream(std::cout, true));

  /** Build the model's discrete system, check it is finite, fill the default `M r`. */
  void build_system();

  /**
   * Read the accelerograms, add the base excitation (step and records, on
   * the whole model or the Excited members) to the system: `F = -M r a_g`.
   */
  void add_loads();

  /**
   * What a transient analysis needs before its integrator: the subdomains
   * (decompose(), Method = HATI), the static initial state (Analysis/Initial
   * state = static) and the damping (the model's default when
   * Time integration/Damping is not set).
   */
  void prepare_transient();

  /**
   * The explicit and implicit subdomains of Method = HATI from
   * Model/Decomposition or, if it is empty, the model's default
   * decomposition, with the base excitation added to each.
   */
  void decompose();

  /**
   * `Model/Decomposition/Implicit reduction = Craig-Bampton` (C1,
   * doc/theory.md 12.1): reduce HATI's implicit subdomain, with its initial
   * state, to Craig-Bampton coordinates (Decomposition::reduced); print the
   * reduction, its frequency check against the unreduced part (the first
   * five flexible free-interface modes) and the `reduction` entry of
   * summary.json. Called by prepare_transient() after the initial state.
   */
  void reduce_implicit_part();

  /**
   * Print the static contact forces @p forces (N, one per contact row of
   * the system, summed per contact name) as a table, remember them
   * (static_contact_forces) and return the `static_contact_forces` entry of
   * summary.json (name -> N; null if the system has no closed contact).
   */
  SummaryValue report_static_contact_forces(const std::vector<double> &forces);
  /**
   * Print the static friction force of every closed contact with friction
   * (the magnitude of its sticking tangents' forces, settled: doc/theory.md
   * 6.2, N) from @p tangent_forces (solve_static()) and return the
   * `static_friction_forces` entry of summary.json (name -> N; null if no
   * contact has friction).
   */
  SummaryValue
  report_static_friction_forces(const std::vector<std::array<double, 2>> &tangent_forces);
  /**
   * Print the tension of every rope at @p U (R1, N) and return them as a
   * `summary.json` object (rope name -> tension).
   */
  SummaryValue report_rope_tensions(const Vector<double> &U);

  /**
   * A warning: one line `hati: warning: @p message` on stderr (unless the
   * output stream of the constructor is silent) and an entry of warnings,
   * which summary.json lists as `warnings`.
   */
  void warn(const std::string &message);

  AnalysisParameters analysis_parameters;
  /**
   * `subsection Response spectrum` and the `Design spectrum` it uses, read
   * for Analysis/Type = response spectrum only.
   */
  ResponseSpectrumParameters response_spectrum_parameters;
  DesignSpectrumParameters design_spectrum_parameters;
  TimeIntegrationParameters time_parameters;
  NewmarkParameters newmark_parameters;
  /** Time integration/Damping, with the model's default Rayleigh damping applied. */
  DampingModel damping;
  HATIParameters hati_parameters;
  DecompositionParameters decomposition_parameters;
  OutputParameters output_parameters;
  /**
   * `subsection Qualification`: the checks of a transient run, a suite or a
   * response-spectrum analysis (qualification.csv, report.html).
   */
  QualificationParameters qualification_parameters;
  /**
   * The verdicts of the run (add_qualification()), printed at its very end
   * after the report (Simulation::run()).
   */
  std::vector<QualificationRow> verdicts;
  CommonModelParameters common_parameters;

  std::unique_ptr<Model> model;
  /** The whole model's system: single-domain methods and every output. */
  DiscreteSystem system;
  /** The explicit and implicit subdomains of Method = HATI (decompose()). */
  std::unique_ptr<Decomposition> decomposition;
  /** Ground acceleration per direction (m/s^2; empty: none), for absolute accelerations.
   */
  std::array<std::function<double(double)>, 3> ground_acceleration;
  /** Static contact forces per contact name (N), filled by
   * report_static_contact_forces(). */
  std::map<std::string, double> static_contact_forces;
  /** summary.json entries of the set-up (static initial state, default damping). */
  SummaryEntries initial_state_summary;
  /** The warnings of the run so far (warn()), in order. */
  std::vector<std::string> warnings;
  /**
   * What identifies the model in a state file (model_identity(): its
   * parameters and mesh files; the vectors empty): written with every
   * state, checked against a restart's.
   */
  RunState state_identity;

private:
  /**
   * A transient run: warn if the record @p record along the axis @p d lies
   * wholly outside [0, End time] (it excites nothing).
   */
  void warn_if_outside_run(const Accelerogram &record, const unsigned int d);

  /**
   * The summary.json entries of the damping: damping_type,
   * damping_branches (alpha, tau lists; empty for Rayleigh) and
   * damping_fit_error (0 for Rayleigh).
   */
  void add_damping_summary();
  /**
   * The model's default frequency-range damping (Model::default_damping())
   * when `Time integration/Damping` is not set (not for event-driven runs).
   */
  void apply_default_frequency_range_damping();
  /**
   * Refuse an Output/Spectra request that names no monitor point or whose
   * history rows are too far apart (ResponseSpectra::check_request()).
   */
  /**
   * Refuse an unstable explicit step (CD-Lagrange, HATI's explicit part)
   * before the static initial state (CDLagrange::stability_limit()).
   */
  void check_explicit_step() const;
  void check_spectrum_request() const;
  /** The static equilibrium under the constant loads as the initial state. */
  void set_static_initial_state();
  /**
   * Analysis/Initial state = file: the displacement, velocity and time of
   * the state file (read_state_file()) as the initial state, its time the
   * system's start_time; refused for event-driven runs and past End time.
   */
  void set_file_initial_state();
  /**
   * The contact forces of the static initial state on the DoFs
   * (DiscreteSystem::initial_contact_reaction): `K U_0 - F - F_r(U_0)` on
   * the DoFs of the contacts with a nonzero static force @p forces (their
   * normal and tangent rows), zero elsewhere; not set when no contact is
   * closed.
   */
  void set_static_contact_reaction(const std::vector<double> &forces);
  /**
   * HATI: the static forces of the contact rows that the whole system
   * wrote through a constraint (at a tied node, eliminated there) added to
   * the explicit part's initial contact reaction on the DoFs its plain row
   * has and the whole system's does not (the tied node, free there): the
   * normal forces and the sticking friction forces along the tangent rows.
   */
  void add_eliminated_contact_reactions();
  /**
   * HATI: on the DoFs of the explicit part's constraint rows (rigid links
   * and ties inside it, which the whole system's static solve eliminates),
   * the explicit part's initial contact reaction is its own equilibrium
   * residual `K_E U_0 - F_E - F_r(U_0)`: the static forces of those rows and
   * of the contacts at the same DoFs, so that the part starts at rest.
   */
  void add_explicit_link_reactions();

  /** A state file's HATI interface multiplier and its interface (RunState). */
  Vector<double> restart_multiplier;
  std::string restart_interface;
  /** A state file's implicit interface values (RunState::implicit_interface). */
  Vector<double> restart_implicit_interface;
  /** The static contact force per contact row of the initial state (N). */
  std::vector<double> static_forces;
  /** The static friction force along each tangent row of a contact (N, A9). */
  std::vector<std::array<double, 2>> static_tangent_forces;

  ConditionalOStream out;
};
} // namespace hati

#endif
