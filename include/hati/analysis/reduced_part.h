#ifndef hati_analysis_reduced_part_h
#define hati_analysis_reduced_part_h

#include <deal.II/lac/vector.h>

#include <hati/analysis/craig_bampton.h>
#include <hati/model/decomposition.h>
#include <hati/model/discrete_system.h>

#include <vector>

namespace hati
{
using namespace dealii;

/**
 * The implicit subdomain of HATI in Craig-Bampton coordinates (C1,
 * doc/theory.md 12.1; `Model/Decomposition/Implicit reduction =
 * Craig-Bampton`): a DiscreteSystem of size `n_b + n_modes` that Newmark
 * integrates like any other (N1-N4 on the dense reduced matrices, its
 * Rayleigh or frequency-range damping built from them), and the interface
 * rows of G3'/G3'' in those coordinates.
 *
 * The boundary rows are the implicit side's interface rows (for a tie the
 * 6 rows of B1, whatever the face) and a unit row for each DoF of a point
 * load: a time-dependent load that is not a base excitation and acts on at
 * most 6 DoFs, or the constant force less its gravity part on at most 60
 * DoFs. The boundary coordinates are the values of those
 * rows, so the interface rows become unit rows on the first coordinates
 * (`C_I T = [I 0]`) and an interface force reduces to `(Lambda, 0)`. Loads
 * reduce to `T^T f` (base excitation: `T^T M r`); the initial state to the
 * coordinates of the full one, `g = L U`, `eta = (Phi^T M Phi)^-1 Phi^T M (U
 * - Psi g)`, which for a static state are the reduced static state (the
 * interface forces of the full static solution balance the boundary rows
 * exactly, doc/theory.md 12.1).
 */
class ReducedImplicitPart
{
public:
  /**
   * Reduce @p full, the implicit subdomain with its initial state, loads
   * and base excitation, on its interface rows @p interface_rows and its
   * point loads, with @p settings. Throws what
   * CraigBamptonReduction throws.
   */
  ReducedImplicitPart(const DiscreteSystem &full,
                      const std::vector<SparseRow> &interface_rows,
                      const CraigBamptonSettings &settings);

  /** The reduced system (its DoFs are the reduced coordinates). */
  const DiscreteSystem &system() const { return reduced; }
  /** The interface rows in reduced coordinates: unit rows on the first ones. */
  const std::vector<SparseRow> &interface_rows() const { return rows; }
  /** The reduction: basis, frequencies, set-up time. */
  const CraigBamptonReduction &reduction() const { return basis; }
  /** Number of boundary rows that hold a point load (not interface rows). */
  unsigned int n_point_load_rows() const { return n_load_rows; }

  /**
   * Modal damping of the reduced part (`Reduction modal damping ratio`,
   * doc/theory.md 12.3): the damping matrix `C = M Z diag(2 zeta omega_k) Z^T
   * M` of the reduced system, with `(omega_k^2, Z)` the eigenpairs of the
   * reduced `(K, M)` (`Z^T M Z = I`), so that each of its modes has the
   * damping ratio @p ratio (rigid-body modes, omega_k = 0, none). The run
   * then gives the reduced part no other damping (HATICoupling).
   */
  void set_modal_damping(const double ratio);

  /** `u = T q`: the full subdomain's DoF values from reduced coordinates. */
  void expand(const Vector<double> &q, Vector<double> &u) const { basis.expand(q, u); }

  /**
   * The reduced coordinates of a full DoF vector @p u (displacements or
   * velocities): `g = L u` and the mass projection of the interior part
   * on the kept modes (exact for u in the span of T).
   */
  void coordinates(const Vector<double> &u, Vector<double> &q) const;

private:
  /** The boundary rows: interface rows, then the point-load DoFs. */
  static std::vector<SparseRow> boundary_rows(const DiscreteSystem &full,
                                              const std::vector<SparseRow> &interface,
                                              unsigned int &n_load_rows);
  /** Fill `reduced` from the basis (matrices, loads, influence, state). */
  void build_system(const DiscreteSystem &full);

  unsigned int n_load_rows = 0;
  CraigBamptonReduction basis;
  /** The full subdomain's mass times the modes, `M Phi` (coordinates()). */
  std::vector<Vector<double>> mass_modes;
  /** `(Phi^T M Phi)^-1` (the identity for mass-normalised modes, to round-off). */
  FullMatrix<double> modal_mass_inverse;
  DiscreteSystem reduced;
  std::vector<SparseRow> rows;
};

/** The system HATI's implicit integrator steps: the reduced one if any. */
const DiscreteSystem &implicit_system(const Decomposition &decomposition);
/** The implicit interface rows over implicit_system()'s DoFs. */
const std::vector<SparseRow> &implicit_rows(const Decomposition &decomposition);
} // namespace hati

#endif
