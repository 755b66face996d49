#ifndef hati_model_rope_h
#define hati_model_rope_h

#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <string>
#include <vector>

namespace hati
{
using namespace dealii;

/**
 * A rope (doc/theory.md 10, R1): a two-node, tension-only, geometrically
 * exact element between a hook point `h` and a load `p`, with the rest
 * length `L0` and the axial stiffness `k` (`E A / L` of all falls):
 *
 *   `T = max(0, k (|x_p - x_h| - L0))`, force `+T e` on the hook point and
 *   `-T e` on the load, `e = (x_p - x_h) / |x_p - x_h|`,
 *
 * with the current positions `x = X + u` (the reference positions plus the
 * displacements). Its DoFs are the translations x, y, z of both nodes in the
 * numbering of the DiscreteSystem that holds it; a DoF that is held at zero
 * (a support) is `numbers::invalid_dof_index`.
 */
struct Rope
{
  std::string name;
  /** Translations x, y, z of the hook point and of the load (invalid: held at 0). */
  std::array<types::global_dof_index, 3> hook_dofs{{numbers::invalid_dof_index,
                                                    numbers::invalid_dof_index,
                                                    numbers::invalid_dof_index}},
      load_dofs{{numbers::invalid_dof_index,
                 numbers::invalid_dof_index,
                 numbers::invalid_dof_index}};
  /** `X_p - X_h` at zero displacement (m, global axes). */
  Tensor<1, 3> reference_chord;
  /** Axial stiffness k (N/m). */
  double stiffness = 0.;
  /** Rest length L0 (m). */
  double rest_length = 0.;

  /** The current chord `x_p - x_h` (m) for the displacement @p U. */
  Tensor<1, 3> chord(const Vector<double> &U) const;
  /** The tension T (N, >= 0) for the displacement @p U. */
  double tension(const Vector<double> &U) const;
  /** The strain energy `k/2 max(0, l - L0)^2` (J). */
  double strain_energy(const Vector<double> &U) const;
  /**
   * Add `scale_i` times the rope force on DoF i to @p f (@p scale empty:
   * 1), `+T e` on the hook point, `-T e` on the load; returns T (N).
   */
  double add_force(const Vector<double> &U,
                   Vector<double> &f,
                   const Vector<double> *scale = nullptr) const;
  /**
   * The 6 x 6 tangent stiffness (N/m) on (hook x, y, z, load x, y, z) at
   * @p U: with `K_r = k e e^T + (T / l) (I - e e^T)` it is `[K_r, -K_r;
   * -K_r, K_r]` for `l >= L0` (the right derivative at `l = L0`), zero for
   * a slack rope. With @p slack_tension (N) > 0, `max(T, slack_tension)`
   * stands for T in the geometric term and a slack rope gets
   * `(slack_tension / l) I`: a positive stiffness for the Newton steps of a
   * static state, which does not change its solution.
   */
  FullMatrix<double> tangent(const Vector<double> &U,
                             const double slack_tension = 0.) const;
  /** The six DoFs of tangent(): hook x, y, z, load x, y, z. */
  std::array<types::global_dof_index, 6> dofs() const;
};

/**
 * Add the tangents of @p ropes at @p U to @p K (its pattern holds the
 * couplings of hook point and load), with Rope::tangent()'s
 * @p slack_tension.
 */
void add_rope_tangents(const std::vector<Rope> &ropes,
                       const Vector<double> &U,
                       SparseMatrix<double> &K,
                       const double slack_tension = 0.);

/**
 * Bound of the highest `omega^2` (1/s^2) the ropes add to the explicit
 * system, from the lumped mass @p mass (a fixed DoF: 0 mass, not counted):
 * the sum over the ropes of `k (1/m_h + 1/m_p)`, the eigenvalue of a bar
 * of stiffness k between the two masses (the tangent is at most `k I`
 * since `T / l = k (1 - L0 / l) < k`).
 */
double rope_omega_squared_bound(const std::vector<Rope> &ropes,
                                const Vector<double> &mass,
                                const std::vector<bool> &fixed);
} // namespace hati

#endif
