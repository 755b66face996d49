#ifndef hati_linear_algebra_amg_preconditioner_h
#define hati_linear_algebra_amg_preconditioner_h

#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <array>

namespace hati
{
using namespace dealii;

/**
 * The settings of Trilinos' ML algebraic multigrid for the symmetric
 * positive definite matrices of a structural model of @p n DoFs (the
 * stiffness of the static analysis with CG, the effective matrix of
 * Newmark, N2): smoothed aggregation for elliptic problems, two smoother
 * sweeps, and as near null space the rigid translations of the model where
 * it has any: one constant mode per vector of @p translations (the
 * DiscreteSystem's `influence`, 1 on the DoFs that translate along x, y,
 * z) of length @p n with a nonzero entry, true on its nonzero entries.
 */
TrilinosWrappers::PreconditionAMG::AdditionalData
structural_amg_data(const std::array<Vector<double>, 3> &translations,
                    const unsigned int n);

/**
 * `amg.initialize(matrix, data)` without output: ML's coarse solver
 * (Amesos_Klu) reports a singular coarse matrix with an `ERROR:` line on
 * the standard output and writes the matrix to `amesos-failure.dat` in the
 * working directory. Both standard streams are sent to /dev/null and the
 * working directory is a private temporary folder (removed after) while it
 * runs; the caller reports the failure (a singular matrix shows as a
 * breakdown of the solver) in its own words. Exceptions pass through.
 */
void initialize_quietly(TrilinosWrappers::PreconditionAMG &amg,
                        const TrilinosWrappers::SparseMatrix &matrix,
                        const TrilinosWrappers::PreconditionAMG::AdditionalData &data);
} // namespace hati

#endif
