#ifndef hati_model_memory_estimate_h
#define hati_model_memory_estimate_h

#include <array>
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
 * Refuse a model whose estimated_memory() plus @p factorization (bytes, the
 * direct solver's factor: factorization_memory(); 0 if none is estimated)
 * exceeds available_memory(), with a one-line message naming @p entry (the
 * parameter that sets the size), the figures and what to reduce
 * (@p remedy; empty: @p entry).
 */
void check_memory_estimate(const std::string &entry,
                           const double n_cells,
                           const double n_dofs,
                           const double n_nonzeros,
                           const double factorization = 0.,
                           const std::string &remedy = "");

/** DoFs and stiffness nonzeros of a mesh of hexahedra (hexahedra_size()). */
struct HexahedraSize
{
  double n_dofs = 0., n_nonzeros = 0.;
};

/**
 * The size of a structured box of @p cells[0] x @p cells[1] x @p cells[2]
 * hexahedra of degree @p degree with 3 displacement components, exact:
 * per axis p n + 1 nodes, n (p^2 + 2p) + 1 pairs of nodes that share a
 * cell, 3 x 3 nonzeros per pair of nodes.
 */
HexahedraSize box_size(const std::array<double, 3> &cells, const unsigned int degree);

/**
 * An upper estimate of the size of @p n_cells hexahedra of degree @p degree
 * in an unstructured mesh or a thin-walled solid (plates one cell thick,
 * where most nodes lie on a surface): 3 p^2 (p + 1) DoFs and
 * 2 x 9 (p^2 + 2p)^3 nonzeros per cell.
 */
HexahedraSize hexahedra_size(const double n_cells, const unsigned int degree);

/**
 * The memory of the sparse direct factorisation (MUMPS, L D L^T; bytes) of
 * a 3D solid of @p n_dofs DoFs of degree @p degree, estimated from nested
 * dissection's fill (the separators' fronts grow as n^(2/3)): about
 * 8 B x n^(4/3) x (p + 1) / 2 entries (measured on boxes of degree 2 to 4;
 * doc/architecture.md, "Memory before work").
 */
double factorization_memory(const double n_dofs, const unsigned int degree);
} // namespace hati

#endif
