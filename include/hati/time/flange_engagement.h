#ifndef hati_time_flange_engagement_h
#define hati_time_flange_engagement_h

#include <deal.II/lac/vector.h>

#include <hati/model/discrete_system.h>
#include <hati/model/wheel_flange.h>
#include <hati/time/force_law.h>

#include <vector>

namespace hati
{
using namespace dealii;

/**
 * Wheel flanges that pass over their rail head (doc/theory.md D1-D2), a
 * ForceLaw registered as `flanges` for a system whose
 * DiscreteSystem::law_data holds WheelFlange data (Model/Frame/Flanges,
 * Model/Bridge crane/Flange depth).
 *
 * A law of conditions on the contacts' rows, with no force and no rows of
 * its own (gate_rows()): at every step it takes each wheel's uplift `z`
 * (the gap of its tread row at `U_{n+1}`) and switches the two rows of its
 * flange contact off while `z` exceeds the flange depth (D1), so that the
 * contacts' law (UnilateralContacts) leaves them out of the active set;
 * a wheel whose flanges are off and whose lateral offset `|g_+ - g_-| / 2`
 * exceeds its derailment offset has left its rail (D2): run_end() gives
 * the `derailed` end and the time loop stops after that step. Static and
 * modal analyses take the flanges as engaged (they do not run the laws).
 */
class FlangeEngagement : public ForceLaw
{
public:
  /** What a step changes (CDLagrange::Snapshot). */
  struct State
  {
    /** Per wheel: whether its flanges were off at the last step. */
    std::vector<bool> off;
    /** Per wheel: the time its flanges were off (s), the first such time (s; < 0: never).
     */
    std::vector<double> off_time, first_off;
    /** The time of the last step (s). */
    double time = 0.;
    /** The derailment (RunEnd::status empty: none yet). */
    RunEnd end;
    /** The derailed wheel's index, uplift (m) and lateral offset (m). */
    unsigned int wheel = 0;
    double uplift = 0., offset = 0.;
  };

  /** The registration: an instance for a system with flanges. */
  static Registry<ForceLawFactory>::Entry registration();

  /** The flanges @p flanges over the rows of @p system (both kept by reference). */
  FlangeEngagement(const DiscreteSystem &system, const std::vector<WheelFlange> &flanges);

  std::string name() const override { return "flanges"; }

  bool gates_rows() const override { return true; }

  /**
   * (D1) each wheel's flange rows off in @p off while its uplift at @p U
   * exceeds the flange depth; (D2) the first wheel off its flanges beyond
   * its derailment offset ends the run (at @p t).
   */
  void
  gate_rows(const double t, const Vector<double> &U, std::vector<bool> &off) override;

  /** The derailment, or nullptr while every wheel is on its rail. */
  const RunEnd *run_end() const override
  {
    return current.end.status.empty() ? nullptr : &current.end;
  }

  void save(std::any &state) const override;
  void restore(const std::any &state) override;

  /**
   * summary.json `flanges.<wheel>.{disengaged_time, first_disengaged_time}`
   * (s; the latter null if never) and, after a derailment, `derailment`
   * (wheel, time, uplift, lateral_offset, flange_depth, derailment_offset;
   * s and m).
   */
  void add_summary(SummaryEntries &summary, std::ostream &out) const override;

  /**
   * The data unchanged: a HATI subsystem keeps every contact row of the
   * part built in its order (extract_subsystem()), so the row indices hold.
   */
  std::any part_data(const std::vector<int> &local,
                     const std::vector<bool> &fixed) const override;

private:
  /** The gap of row @p k of the contacts at @p U (m). */
  double gap(const unsigned int k, const Vector<double> &U) const;

  const std::vector<ContactRow> &contacts;
  const std::vector<WheelFlange> &flanges;
  State current;
};
} // namespace hati

#endif
