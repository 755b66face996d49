#ifndef hati_analysis_craig_bampton_h
#define hati_analysis_craig_bampton_h

#include <deal.II/base/array_view.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <hati/contact/sparse_rows.h>
#include <hati/model/discrete_system.h>

#include <array>
#include <string>
#include <vector>

namespace hati
{
using namespace dealii;

/**
 * `y = M x` with the mass a reduction uses (C1): the consistent mass of
 * @p system if it has one, else its lumped diagonal.
 */
void reduction_mass_vmult(const DiscreteSystem &system,
                          const Vector<double> &x,
                          Vector<double> &y);

/** One unit row per DoF of @p dofs: DoFs as boundary rows of a reduction. */
std::vector<SparseRow> unit_rows(const std::vector<unsigned int> &dofs);

/**
 * Modes per shift-invert Lanczos run of the spectrum slicing of the
 * fixed-interface modes (CraigBamptonSettings::modes_per_run). ARPACK's
 * orthogonalisation costs O(n ncv^2) per restart (ncv = 2 nev + 2), each
 * run one factorisation of `K - sigma M`. The 182 modes below 150 Hz of
 * the 3D crane's implicit part (54186 DoFs, reference BLAS, a shared
 * machine): 100-127 s in 3 runs of 64, 130-145 s in 4 runs of 48, 384 s in
 * a run of 12 then one of 220 before the slicing.
 */
constexpr unsigned int default_modes_per_run = 64;

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
  /**
   * Modes per shift-invert Lanczos run (-), at least 4: the fixed-interface
   * modes come in slices of this many (fewer for the last ones), each
   * around its own shift.
   */
  unsigned int modes_per_run = default_modes_per_run;
};

/**
 * The Craig-Bampton reduction of a linear system (C1, doc/theory.md 12.1)
 * on boundary rows `g_k = L_k U` (the implicit side's interface rows of
 * G3'': one row a DoF for a Boolean interface, six rows for a tie whatever
 * its face; a unit row holds a DoF with a point load): the constraint modes
 * `Psi_k`, the static displacements with `L Psi_k = e_k` and no other load
 * (one sparse solve each with one factorisation of the stiffness
 * condensed on `L U = 0`), the fixed-interface modes `K phi = omega^2 M phi`
 * on `L phi = 0` up to the cut-off (spectrum slicing: shift-invert
 * Lanczos runs of CraigBamptonSettings::modes_per_run modes around
 * successive shifts, ModalProblem with the rows held), the basis `T = [Psi,
 * Phi]` and the dense reduced matrices `M_r = T^T M T`, `K_r = T^T K T`.
 * Reduced coordinates `q = (g, eta)`: the boundary values first, then the
 * modal amplitudes; an interface force `L^T Lambda` reduces to `(Lambda,
 * 0)`. Fixed DoFs are zero in every column. Exact for static loads `L^T f`;
 * below the cut-off the dynamics are those of the unreduced system up to
 * the truncation.
 *
 * The system's consistent mass is used if it has one, else its lumped mass.
 */
class CraigBamptonReduction
{
public:
  /**
   * Reduce @p system on the boundary rows @p boundary (over its DoFs,
   * linearly independent on its free DoFs) as @p settings say. Throws
   * ExcMessage for dependent rows, and when the cut-off needs more than
   * settings.maximum_modes modes, naming `Model/Decomposition/Reduction
   * maximum modes`.
   */
  CraigBamptonReduction(const DiscreteSystem &system,
                        const std::vector<SparseRow> &boundary,
                        const CraigBamptonSettings &settings);

  /** Number of boundary rows (-). */
  unsigned int n_boundary() const { return boundary.size(); }
  /** Number of fixed-interface modes kept (-). */
  unsigned int n_modes() const { return modal_frequencies.size(); }
  /** Number of reduced coordinates, boundary DoFs plus modes (-). */
  unsigned int size() const { return n_columns; }
  /** The boundary rows, in the order of the reduced coordinates. */
  const std::vector<SparseRow> &boundary_rows() const { return boundary; }

  /** `M_r = T^T M T` (kg, kg m, ... per pair of coordinates). */
  const FullMatrix<double> &mass() const { return reduced_mass; }
  /** `K_r = T^T K T`. */
  const FullMatrix<double> &stiffness() const { return reduced_stiffness; }
  /** Column @p k of `T` on the system's DoFs (a constraint mode, then the modes). */
  ArrayView<const double> column(const unsigned int k) const
  {
    return ArrayView<const double>(basis.data() + std::size_t(k) * n_rows, n_rows);
  }

  /** Frequencies of the kept fixed-interface modes (Hz), ascending. */
  const std::vector<double> &fixed_interface_frequencies() const
  {
    return modal_frequencies;
  }

  /** `u = T q` (m): the system's displacements from reduced coordinates. */
  void expand(const Vector<double> &q, Vector<double> &u) const;

  /**
   * `U = T Q` for several states at once: column `j` of @p U (size n x m,
   * column-major, resized) from column `j` of @p Q (size() x m, column-major).
   * One pass of `T` through memory for the m states (BLAS dgemm): on the 3D
   * crane 2.7 ms a state by 16 against 10 ms for one.
   */
  void expand_many(const std::vector<double> &Q,
                   const unsigned int m,
                   std::vector<double> &U) const;

  /** The rows @p rows of `T` (one per entry, in order), for a partial expand. */
  FullMatrix<double> basis_rows(const std::vector<unsigned int> &rows) const;

  /** `r = T^T f`: a load on the system's DoFs as reduced load. */
  void project(const Vector<double> &f, Vector<double> &r) const;

  /**
   * The @p n lowest free-interface frequencies of the reduced system (Hz),
   * from `K_r x = omega^2 M_r x` (dense LAPACK), to compare with the
   * unreduced system's below the cut-off.
   */
  std::vector<double> frequencies(const unsigned int n) const;

  /**
   * The free-interface modes of the reduced system, `K_r z_k = omega_k^2
   * M_r z_k` with `Z^T M_r Z = I` (dense LAPACK, in LAPACK's order): their
   * `omega_k^2` (1/s^2) and the vectors `z_k` (frequencies(), the modal
   * damping of ReducedImplicitPart).
   */
  void free_interface_modes(std::vector<double> &omega_squared,
                            std::vector<Vector<double>> &vectors) const;

  /** Wall time of the reduction (s): factorisation, solves, modes, products. */
  double set_up_time() const { return seconds; }
  /**
   * Its parts (s): the constraint modes (factorisation and one solve per
   * boundary row), the fixed-interface modes (lanczos_runs() shift-invert
   * Lanczos runs), the reduced matrices.
   */
  const std::array<double, 3> &set_up_phases() const { return phase_seconds; }
  /** Shift-invert Lanczos runs (slices) to reach the cut-off (-); 1 for a dense solve. */
  unsigned int lanczos_runs() const { return n_lanczos_runs; }

private:
  std::vector<SparseRow> boundary;
  /** The columns of `T` while the reduction is built (then moved to basis). */
  std::vector<Vector<double>> columns;
  /** `T`, column-major (n_rows x n_columns): the constructor's last step. */
  std::vector<double> basis;
  std::size_t n_rows = 0;
  unsigned int n_columns = 0;
  std::vector<double> modal_frequencies;
  FullMatrix<double> reduced_mass, reduced_stiffness;
  double seconds = 0.;
  std::array<double, 3> phase_seconds = {{0., 0., 0.}};
  unsigned int n_lanczos_runs = 0;

  /** The constraint modes `Psi` (one column per boundary row). */
  void add_constraint_modes(const DiscreteSystem &system, const std::string &package);
  /** The fixed-interface modes up to the cut-off. */
  void add_fixed_interface_modes(const DiscreteSystem &system,
                                 const CraigBamptonSettings &settings);
  /** `M_r = T^T M T` and `K_r = T^T K T` from basis (BLAS dgemm by blocks of columns). */
  void assemble_reduced_matrices(const DiscreteSystem &system);

  /** Move the columns into basis (column-major). */
  void store_basis();
};
} // namespace hati

#endif
