#ifndef hati_analysis_craig_bampton_h
#define hati_analysis_craig_bampton_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <hati/model/discrete_system.h>

#include <string>
#include <vector>

namespace hati
{
using namespace dealii;

/** What a Craig-Bampton reduction keeps (CraigBamptonReduction). */
struct CraigBamptonSettings
{
  /** The fixed-interface modes kept: every one up to this frequency (Hz). */
  double cutoff_frequency = 150.;
  /** At most this many fixed-interface modes (-); a cut-off that needs more is refused.
   */
  unsigned int maximum_modes = 500;
  /**
   * `Time integration/Newmark/Linear solver` (auto, KLU, MUMPS, direct or
   * iterative): the factorisations of `K_ii` and of the shift-invert.
   */
  std::string linear_solver = "auto";
};

/**
 * The Craig-Bampton reduction of a linear system (C1, doc/theory.md 12.1):
 * boundary DoFs `b` (given: the interface DoFs of the implicit part), the
 * free DoFs `i` that remain, the constraint modes `Psi = -K_ii^-1 K_ib` (one
 * static solve per boundary DoF with one factorisation of `K_ii`), the
 * fixed-interface modes `K_ii phi = omega^2 M_ii phi` up to the cut-off
 * (shift-invert Lanczos, compute_modes() with the boundary held), the basis
 * `T = [[I, 0], [Psi, Phi]]` and the dense reduced matrices `M_r = T^T M T`,
 * `K_r = T^T K T`. Reduced coordinates `q = (u_b, eta)`: the boundary
 * displacements first, then the modal amplitudes. Fixed DoFs are zero in
 * every column. Exact for static loads at the boundary; below the cut-off
 * the dynamics are those of the unreduced system up to the truncation.
 *
 * The system's consistent mass is used if it has one, else its lumped mass.
 */
class CraigBamptonReduction
{
public:
  /**
   * Reduce @p system with the boundary DoFs @p boundary (indices into the
   * system, none fixed, no duplicates) as @p settings say. Throws ExcMessage
   * when the cut-off needs more than settings.maximum_modes modes, naming
   * `Model/Decomposition/Reduction maximum modes`.
   */
  CraigBamptonReduction(const DiscreteSystem &system,
                        const std::vector<unsigned int> &boundary,
                        const CraigBamptonSettings &settings);

  /** Number of boundary DoFs (-). */
  unsigned int n_boundary() const { return boundary.size(); }
  /** Number of fixed-interface modes kept (-). */
  unsigned int n_modes() const { return modal_frequencies.size(); }
  /** Number of reduced coordinates, boundary DoFs plus modes (-). */
  unsigned int size() const { return columns.size(); }
  /** The boundary DoFs, in the order of the reduced coordinates. */
  const std::vector<unsigned int> &boundary_dofs() const { return boundary; }

  /** `M_r = T^T M T` (kg, kg m, ... per pair of coordinates). */
  const FullMatrix<double> &mass() const { return reduced_mass; }
  /** `K_r = T^T K T`. */
  const FullMatrix<double> &stiffness() const { return reduced_stiffness; }
  /** Column @p k of `T` on the system's DoFs (a constraint mode, then the modes). */
  const Vector<double> &column(const unsigned int k) const { return columns[k]; }

  /** Frequencies of the kept fixed-interface modes (Hz), ascending. */
  const std::vector<double> &fixed_interface_frequencies() const
  {
    return modal_frequencies;
  }

  /** `u = T q` (m): the system's displacements from reduced coordinates. */
  void expand(const Vector<double> &q, Vector<double> &u) const;

  /** `r = T^T f`: a load on the system's DoFs as reduced load. */
  void project(const Vector<double> &f, Vector<double> &r) const;

  /**
   * The @p n lowest free-interface frequencies of the reduced system (Hz),
   * from `K_r x = omega^2 M_r x` (dense LAPACK), to compare with the
   * unreduced system's below the cut-off.
   */
  std::vector<double> frequencies(const unsigned int n) const;

  /** Wall time of the reduction (s): factorisation, solves, modes, products. */
  double set_up_time() const { return seconds; }

private:
  std::vector<unsigned int> boundary;
  std::vector<Vector<double>> columns;
  std::vector<double> modal_frequencies;
  FullMatrix<double> reduced_mass, reduced_stiffness;
  double seconds = 0.;

  /** The constraint modes `Psi` (one column per boundary DoF). */
  void add_constraint_modes(const DiscreteSystem &system, const std::string &package);
  /** The fixed-interface modes up to the cut-off. */
  void add_fixed_interface_modes(const DiscreteSystem &system,
                                 const CraigBamptonSettings &settings);
  /** `M_r` and `K_r` from the columns. */
  void assemble_reduced_matrices(const DiscreteSystem &system);
};
} // namespace hati

#endif
