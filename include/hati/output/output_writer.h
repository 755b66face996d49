#ifndef hati_output_output_writer_h
#define hati_output_output_writer_h

#include <deal.II/lac/vector.h>

#include <hati/contact/friction_solver.h>
#include <hati/model/discrete_system.h>
#include <hati/model/model.h>
#include <hati/output/csv_file.h>
#include <hati/output/run_directory.h>
#include <hati/parameters/run_parameters.h>
#include <hati/time/energies.h>

#include <chrono>
#include <future>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace hati
{
using namespace dealii;

/**
 * The state of a run at one output time, whatever the integrator.
 * Contact vectors follow the order of `DiscreteSystem::contacts`.
 */
struct OutputState
{
  double time = 0.;
  const Vector<double> *displacement = nullptr;
  const Vector<double> *velocity = nullptr;
  std::vector<double> gaps;
  std::vector<double> normal_velocities;
  std::vector<double> impulses;
  std::vector<bool> active;
  /** Duration over which the impulses act (s): dt for CD-Lagrange. */
  double impulse_duration = 0.;
  /**
   * The contact forces (N, per row) of a state without impulses (the static
   * analysis): the `force` column is their sum per contact name; empty: the
   * impulses divided by impulse_duration.
   */
  std::vector<double> forces;
  /**
   * With friction (A9; empty otherwise): the tangential impulses (N s, two
   * per row, along its tangent rows), the slip velocity `||T_k V||` of each
   * touching row (m/s, 0 when open or frictionless) and its state.
   */
  std::vector<double> tangential_impulses, slip_velocities;
  std::vector<FrictionState> friction_states;
  /**
   * Whether write_history() also writes the contacts.csv rows (false when
   * they are written at another resolution with write_contacts(), HATI).
   */
  bool contact_rows = true;
  /**
   * Whether write_history() writes the section_forces.csv rows (false
   * between two rows of `Output/Section force interval`: the envelope is
   * still updated).
   */
  bool section_force_rows = true;
  /**
   * Whether a section_forces.csv row leaves the model's stress envelopes to
   * a later update_envelopes() (a reduced implicit part expands them by
   * batches): `displacement` then holds only the DoFs the rows read.
   */
  bool envelope_deferred = false;
  /**
   * The values of Model::output_functionals() for `displacement`, or null
   * (write_section_forces() then reads the displacement).
   */
  const Vector<double> *output_functionals = nullptr;
};

/**
 * Writes every output file of a run into its RunDirectory (doc/user_guide.md):
 * `history.csv` (monitor points, then each rope's tension `<name>.tension`,
 * N, R1), `contacts.csv` (one row per contact name
 * and output time: smallest gap, mean normal velocity, summed impulse, mean
 * force = impulse / duration (the summed static force in a static
 * analysis), number of active rows; with friction the tangential impulse,
 * slip velocity and state, on every row), `energy.csv`,
 * `solution.pvd` + `solution-NNNNN.vtu` and the model's other VTU series
 * with the same cycles and times (Model::vtu_series(), e.g. `solids.pvd` +
 * `solids-NNNNN.vtu`), `section_forces.csv` when the model writes section
 * forces, the model's envelope files (Model::envelope_files(), e.g.
 * `stress_envelope.vtu`: its envelopes are updated at the section force
 * rows, the files replaced at every VTU snapshot and at the end), and
 * `summary.json` at the end.
 * It also counts impacts (a contact name going from no impulse to a
 * positive impulse) and the largest penetration.
 *
 * The CSV rows are formatted into buffers (CsvFile, shortest round-trip
 * numbers) and the files are flushed together, at every VTU snapshot, when
 * the buffers hold 1 MiB and at least every 2 s of wall time: every CSV
 * ends on a complete line at every instant. `solution.pvd` is replaced
 * atomically after its snapshot is complete, and made durable (fsync) at
 * most every 2 s and by finish(); so are the indices of the other series.
 * The other series' snapshots (the solids': evaluating and compressing
 * their stresses takes most of a snapshot's time) are written by a second
 * thread while the run goes on, one at a time; their indices name a
 * snapshot once it is complete (at the next snapshot or in finish()).
 */
class OutputWriter
{
public:
  /**
   * Begin the run in @p run (RunDirectory::begin(): nothing is written
   * before) and open the CSV files with their headers.
   */
  OutputWriter(RunDirectory &run, const DiscreteSystem &system, const Model &model);

  /** Rows of history.csv and contacts.csv at @p state.time. */
  void write_history(const OutputState &state);
  /** Rows of contacts.csv at @p state.time (one per contact name). */
  void write_contacts(const OutputState &state);
  /** A row of energy.csv; the drift is relative to the first row. */
  void write_energy(const double time, const Energies &energies);
  /**
   * A VTU snapshot of every series and the updated PVD indices; the
   * envelope files replaced (not made durable).
   */
  void write_vtu(const OutputState &state);
  /** Update the model's envelopes (Model::update_envelopes()) with a deferred row. */
  void update_envelopes(const double time, const Vector<double> &displacement);
  /**
   * Track impacts and the largest penetration from the gaps and impulses
   * of the contacts (call after every step; touches contacts only).
   */
  void track_contacts(const std::vector<double> &gaps,
                      const std::vector<double> &impulses);
  /**
   * The contacts touching in the initial state (@p initial_gaps <= 0, m)
   * count as pushing before the first step: a start at rest on them is no
   * impact (as in ContactStatistics).
   */
  void set_initial_contacts(const std::vector<double> &initial_gaps);
  /**
   * Write every buffered row to its file, checking the writes and that the
   * directory still exists; throws a one-line message naming the file and
   * the system error.
   */
  void flush();
  /**
   * flush() at the end of a run (completed or interrupted), make
   * `solution.pvd` and the other indices durable if their last replacement
   * was not (sync_file()), and write the envelope files durably.
   */
  void finish();

  unsigned int n_impacts() const { return impacts; }
  double max_penetration() const { return penetration; }
  /** Last energy balance error (J) and the largest energy seen (J). */
  std::pair<double, double> energy_balance() const { return {last_drift, energy_scale}; }
  const std::string &directory() const { return dir; }

private:
  /** flush() when the buffers are large or 2 s have passed since the last one. */
  void flush_if_due();
  /** The friction columns of write_contacts() per contact name (A9). */
  void group_friction(const OutputState &state);
  /** Replace the model's envelope files by their current content. */
  void write_envelopes(const bool durable);
  /**
   * Wait until the snapshot of the other series being written is complete
   * (rethrowing its error), then replace their indices to name it.
   */
  void wait_for_series();

  RunDirectory &run;
  const std::string dir;
  const DiscreteSystem &system;
  const Model &model;
  CsvFile history, contacts, energy, section_forces;
  /** Rows of Model::write_section_forces() before they go to section_forces. */
  std::ostringstream section_rows;
  /** Scratch of write_contacts() per contact name. */
  std::vector<double> group_gap, group_velocity, group_impulse, group_force;
  std::vector<unsigned int> group_rows, group_active;
  /** Whether a contact has friction: the friction columns are written (A9). */
  const bool friction;
  /** Scratch of write_contacts() with friction: t1, t2 sums, slip, state. */
  std::vector<double> group_tangential, group_slip;
  std::vector<FrictionState> group_state;
  std::chrono::steady_clock::time_point last_flush;
  /** When solution.pvd was last replaced durably; whether its last version is. */
  std::chrono::steady_clock::time_point last_pvd_sync;
  bool pvd_durable = true;
  std::vector<std::string> contact_names;
  std::vector<unsigned int> contact_group;
  std::vector<bool> group_was_pushing, group_pushing;
  unsigned int impacts = 0;
  double penetration = 0.;
  bool have_energy = false;
  double energy0 = 0., last_drift = 0., energy_scale = 0.;
  std::vector<std::pair<double, std::string>> vtu_files;
  /** The model's VTU series besides `solution` and its envelope files. */
  const std::vector<std::string> series, envelope_files;
  /**
   * The snapshot of the other series being written by a second thread
   * (write_vtu(); at most one at a time: wait_for_series()). Declared last:
   * destroyed first, its destructor waits for the thread, which uses the
   * members above.
   */
  std::future<void> pending_series;
};

} // namespace hati

#endif
