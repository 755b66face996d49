#ifndef hati_output_state_file_h
#define hati_output_state_file_h

#include <deal.II/lac/vector.h>

#include <string>
#include <vector>

namespace hati
{
using namespace dealii;

/**
 * The state of a transient run at one time, as `state.bin` holds it
 * (Output/State interval) and a run restarts from it (Analysis/Initial
 * state = file; doc/theory.md 1.1, "Restart"): the time, the displacement
 * and the velocity of every DoF of the whole model at that time, and what
 * identifies the model (its number of DoFs, its description, its
 * parameters and the digests of its mesh files).
 *
 * The velocity is the integer-time one: Newmark's `V_n`, CD-Lagrange's
 * `(V_{n-1/2} + V_{n+1/2}) / 2` (which holds half of the step's contact
 * impulses: the velocity of HATI's continuity, G3'), and HATI's whole
 * model at a macro-step end from both. With the forces of the last
 * step's impulses, a CD-Lagrange run restarted with its own step goes on
 * as it would have (to round-off). What else a run carries (the memory
 * variables of frequency-range damping) is not part of it: a restart takes
 * it up afresh.
 */
struct RunState
{
  double time = 0.; ///< s
  /** Model::description() of the run that wrote the state. */
  std::string model;
  /**
   * The model's parameters as `Model/.../Entry = value` lines, those that
   * make its mesh, DoFs, mass and stiffness (model_identity(): not the
   * decomposition, the outputs, the damping or the initial conditions),
   * and its mesh files as `<entry> = <file>: fnv1a64 <digest>, <n> bytes`.
   */
  std::vector<std::string> model_parameters, model_files;
  Vector<double> displacement; ///< m (rad for rotations), per DoF
  Vector<double> velocity;     ///< m/s (rad/s), per DoF
  /**
   * The forces of the contacts' and the bilateral rows' impulses of the
   * last step (N, CDLagrange::contact_force(); zero without contacts): the
   * restart adds them to its first half step as a static start adds the
   * static contact forces (DiscreteSystem::initial_contact_reaction), so
   * that a closed contact does not move into its support.
   */
  Vector<double> contact_force;
  /**
   * HATI's interface multiplier Lambda_n (N, one per interface row; empty
   * for the other methods): a HATI restart with the same interface starts
   * its coupling from it (Decomposition::initial_multiplier).
   */
  Vector<double> interface_multiplier;
  /** interface_signature() of the interface it belongs to. */
  std::string interface_signature;
  /**
   * HATI with an unreduced implicit part: the implicit part's own
   * displacements, then velocities, of the DoFs both parts hold (the
   * interface DoFs of G3', in the implicit part's order; m, m/s): the
   * whole model's vectors hold the explicit side's values there, and G3'
   * makes the two sides' velocities continuous, not their displacements.
   * A HATI restart of the same coupling gives them back to its implicit
   * part. Empty otherwise.
   */
  Vector<double> implicit_interface;
};

/** @p description on one line (line breaks as spaces): the header's `model` line. */
std::string state_model_line(const std::string &description);

/**
 * The bytes of `state.bin` for @p state: a text header (`hati state 2`, a
 * `checksum` line with the FNV-1a digest of everything after it, `time`,
 * `n_dofs`, `model`, `parameters <n>` and its n lines, `files <n>` and its
 * n lines, with HATI's multiplier an `interface` line with its size and
 * signature, with HATI's implicit interface values an `implicit_interface`
 * line with their number, and `data`) and the displacement, the velocity,
 * the contact force, the multiplier and the implicit interface values as
 * native doubles.
 */
std::string state_file_content(const RunState &state);

/**
 * Read the state file @p path for the model of @p expected (its number of
 * DoFs, RunState::model, model_parameters and model_files; the vectors
 * are not looked at). A missing file or one that is not a regular file
 * (a FIFO, a device, a directory: refused before it is opened), another
 * format, a checksum that does not match (any byte changed), another
 * model (the first differing parameters or mesh files named, with both
 * values), a truncated file or a value that is not finite is a one-line
 * message naming @p parameter and the file.
 */
RunState read_state_file(const std::string &path,
                         const unsigned int n_dofs,
                         const RunState &expected,
                         const std::string &parameter);
} // namespace hati

#endif
