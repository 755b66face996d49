#ifndef hati_model_memory_estimate_h
#define hati_model_memory_estimate_h

#include <string>

namespace hati
{
/**
 * Estimated memory of a model (bytes) from its size, before anything is
 * allocated: @p n_cells cells (mesh, DoF handler: 400 B each), @p n_dofs DoFs
 * (the vectors of the system, the integrator and the output: 40 doubles
 * each) and @p n_nonzeros nonzeros (sparsity pattern, stiffness and mass
 * matrices, the dynamic pattern they are built from: 28 B each).
 */
double
estimated_memory(const double n_cells, const double n_dofs, const double n_nonzeros);

/**
 * Memory this process may use (bytes): MemAvailable of /proc/meminfo, or
 * the cgroup limit if smaller; 0 if unknown.
 */
double available_memory();

/**
 * Refuse a model whose estimated_memory() exceeds available_memory(), with
 * a one-line message naming @p entry (the parameter that sets the size) and
 * both numbers.
 */
void check_memory_estimate(const std::string &entry,
                           const double n_cells,
                           const double n_dofs,
                           const double n_nonzeros);
} // namespace hati

#endif
