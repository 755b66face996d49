#ifndef hati_run_run_state_h
#define hati_run_run_state_h

#include <deal.II/base/parameter_handler.h>

#include <hati/output/state_file.h>

#include <string>
#include <vector>

namespace hati
{
class Problem;
struct Decomposition;

/**
 * The state of @p integrator (CDLagrange, Newmark or HATICoupling, at a step
 * end) as `state.bin` holds it (RunState, doc/theory.md 1.1 "Restart"): its
 * time, the whole model's displacement, integer-time velocity and the
 * forces of the last step's contact impulses (CDLagrange::contact_force(),
 * HATICoupling::contact_force(); none for Newmark). The DoFs that HATI's
 * and Newmark's whole system eliminates (the slaves of ties and rigid
 * links) and that no part of HATI holds are filled from their masters
 * (Model::complete_solution()), as a CD-Lagrange run keeps them.
 */
template <class Integrator>
RunState current_run_state(const Integrator &integrator, const Problem &problem);

/**
 * What identifies the interface of @p decomposition (its explicit rows in
 * the whole model's numbering: DoFs and coefficients, and the number of
 * DoFs or reduced coordinates of the implicit part as it is stepped) as 16
 * hexadecimal digits (FNV-1a): a restart takes a state's interface
 * multiplier only for the coupling it was written for (RunState).
 */
std::string coupling_signature(const Decomposition &decomposition);

/**
 * The implicit part's DoFs (its own numbering) that the explicit part holds
 * too (the interface DoFs of G3'), in increasing order; empty where the
 * implicit part is stepped reduced (its coordinates are not DoFs):
 * RunState::implicit_interface holds their values.
 */
std::vector<unsigned int> shared_implicit_dofs(const Decomposition &decomposition);

/**
 * What identifies the model of @p prm in a state file
 * (RunState::model_parameters and model_files): every entry of
 * `subsection Model` as `Model/.../Entry = value`, but for those a restart
 * may change without changing the state's meaning: the decomposition
 * (`Model/Decomposition`: a state restarts with another method), the
 * outputs (`Monitor nodes`, `Section force members`, `Solid cuts`), the
 * crane's damping (`Damping type`, `Damping ratio`, `Damping band`) and
 * the initial conditions the state replaces (`Initial velocity`, `Initial
 * height`); and the digest of every mesh file they name (a value or a
 * comma-, semicolon- or space-separated word of one ending in `.msh`).
 */
void model_identity(const dealii::ParameterHandler &prm, RunState &identity);

} // namespace hati

#endif
