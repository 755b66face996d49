#ifndef hati_output_law_output_h
#define hati_output_law_output_h

#include <hati/base/summary_value.h>
#include <hati/model/discrete_system.h>
#include <hati/model/model.h>
#include <hati/output/run_directory.h>
#include <hati/parameters/run_parameters.h>
#include <hati/time/force_law.h>

#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace hati
{
/**
 * What a law's output may use (ForceLaw::make_output()): the system in the
 * model's numbering (under HATI the whole one, not the explicit part whose
 * integrator holds the law; their contact rows are the same, in the same
 * order), the model, the Output parameters, the run's end time and
 * directory, and the run's warnings (Problem::warn()).
 */
struct LawOutputContext
{
  const DiscreteSystem &system;
  const Model &model;
  const OutputParameters &parameters;
  /** The run's End time (s). */
  double end_time;
  RunDirectory &directory;
  /** Adds a warning to the run (summary.json `warnings` and the terminal). */
  std::function<void(const std::string &)> warn;
};

/** The wall times of a run that a law's summary may report (s). */
struct LawOutputTimes
{
  /** The integrator's resolution of the rows (CDLagrange::contact_seconds()). */
  double rows = 0.;
  /** The laws' outputs of every step (LawOutput::add_step()). */
  double outputs = 0.;
};

/**
 * A force law's share of the outputs of a transient run (doc/architecture.md,
 * "Force laws"), made by ForceLaw::make_output(): the time loop hands it the
 * law's sample (ForceLaw::sample()) after every step of CD-Lagrange and
 * every micro step of HATI (the final pass of a redone macro step), and at
 * the end asks for its summary.json entries, its lines of the terminal
 * summary and its files. E.g. the contacts' statistics (ContactOutput:
 * impacts, peak forces, episodes, friction counts).
 */
class LawOutput
{
public:
  virtual ~LawOutput() = default;

  /**
   * Account for one step of length @p dt (s) whose state is @p sample (its
   * time is the step's end). Called every step: no allocation here.
   */
  virtual void add_step(const LawSample &sample, const double dt) = 0;

  /**
   * After the run: the law's summary.json entries added to @p summary, its
   * lines of the terminal summary on @p out, its files written, with the
   * run's wall times @p times.
   */
  virtual void
  finish(SummaryEntries &summary, std::ostream &out, const LawOutputTimes &times) = 0;
};

/**
 * The outputs of the laws @p laws that have one (ForceLaw::make_output()),
 * in registration order, and one sample of their state reused from step to
 * step: what the time loop and a test drive.
 */
class LawOutputs
{
public:
  LawOutputs(const std::vector<std::unique_ptr<ForceLaw>> &laws,
             const LawOutputContext &context);

  /** Whether no law has an output (then nothing needs a sample per step). */
  bool empty() const { return outputs.empty(); }

  /**
   * The laws' sample of a step (LawSample::every_step) at the integrator's
   * state of time @p time (s) and velocity @p V (ForceLaw::sample()), into
   * sample().
   */
  const LawSample &take_sample(const double time, const Vector<double> &V);
  /** The last sample of take_sample(). */
  const LawSample &sample() const { return current; }

  /** LawOutput::add_step() of every output with @p sample and the step @p dt (s). */
  void add_step(const LawSample &sample, const double dt);

  /** LawOutput::finish() of every output, in registration order. */
  void finish(SummaryEntries &summary, std::ostream &out, const LawOutputTimes &times);

private:
  const std::vector<std::unique_ptr<ForceLaw>> &laws;
  std::vector<std::unique_ptr<LawOutput>> outputs;
  LawSample current;
};
} // namespace hati

#endif
