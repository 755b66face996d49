#ifndef hati_model_decomposition_h
#define hati_model_decomposition_h

#include <hati/model/discrete_system.h>
#include <hati/model/model.h>

#include <array>
#include <memory>
#include <vector>

namespace hati
{
class ReducedImplicitPart;

/**
 * One subdomain of a decomposed model: its own DiscreteSystem, numbered
 * from 0, holding the free DoFs of the model that its cells touch, and the
 * model's (global) index of each of them.
 */
struct Subdomain
{
  DiscreteSystem system;
  std::vector<types::global_dof_index> global_dofs;
};

/**
 * A model split into an explicit (0) and an implicit (1) subdomain for the
 * coupling (doc/architecture.md, "Subdomains"). The subdomains are DoF
 * subsets of the model's one DoFHandler, each assembled from its own cells
 * only (Model::select_part()), so an interface DoF, a free DoF touched by
 * cells of both sides, has a copy on each side holding that side's share of
 * mass and stiffness. Interface row k is `rows[0][k] U^E + rows[1][k] U^I =
 * 0` in the subdomains' numberings (G3'', doc/theory.md 11.3): for a shared
 * DoF the signed Boolean rows `C_E = +1`, `C_I = -1`; for a beam node of the
 * explicit side tied to a solid face of the implicit side (Model::
 * interface_rows()) `+1` on the node's DoF and minus the B1 row on the face
 * DoFs. The explicit row is always one DoF with coefficient 1.
 */
struct Decomposition
{
  std::array<Subdomain, 2> parts;
  std::array<std::vector<SparseRow>, 2> rows;
  /** Subdomain (0, 1) of every active cell of the model. */
  std::vector<unsigned char> cell_parts;

  /** Number of interface rows. */
  unsigned int n_interface_dofs() const { return rows[0].size(); }

  /**
   * The implicit subdomain in Craig-Bampton coordinates (C1,
   * doc/theory.md 12.1; include/hati/analysis/reduced_part.h), set after
   * the initial state when `Implicit reduction = Craig-Bampton`; null: HATI
   * steps parts[1] itself (implicit_system(), implicit_rows()).
   */
  std::shared_ptr<const ReducedImplicitPart> reduced;
  /**
   * The interface multiplier to start from (N, one per row of rows[0]):
   * that of the state a run restarts from (Analysis/Initial state = file),
   * with which the coupling goes on as the run that wrote it; empty: solved
   * from the acceleration continuity (InterfaceProblem::initial_multiplier()).
   */
  Vector<double> initial_multiplier;
};

/**
 * Decompose @p model (already built) along @p parameters: assemble each
 * subdomain (the model rebuilds its matrices from the selected cells), keep
 * the free DoFs it touches, find the interface DoFs. Throws one-line errors
 * for an empty subdomain, no interface, or a contact in the implicit
 * subdomain. The model keeps the cell parts for its VTU `subdomain` field.
 */
void decompose(Model &model,
               const CommonModelParameters &common,
               const DecompositionParameters &parameters,
               Decomposition &decomposition);

/**
 * The restriction of @p full to the DoFs @p dofs (sorted, free in @p full):
 * matrices, masses, loads, influence vectors, initial state, contacts (all of
 * whose DoFs must be kept: throws naming the contact otherwise), ropes and
 * the force laws' data (DiscreteSystem::law_data, renumbered by each law:
 * ForceLaw::part_data(), extract_law_data()). Monitors are not copied
 * (outputs use the model's numbering).
 */
void extract_subsystem(const DiscreteSystem &full,
                       const std::vector<types::global_dof_index> &dofs,
                       DiscreteSystem &sub);
} // namespace hati

#endif
