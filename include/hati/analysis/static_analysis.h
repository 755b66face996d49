#ifndef hati_analysis_static_analysis_h
#define hati_analysis_static_analysis_h

#include <deal.II/lac/vector.h>

#include <hati/model/discrete_system.h>

#include <array>
#include <string>
#include <vector>

namespace hati
{
using namespace dealii;

/**
 * Linear static analysis: solve `K U = F_ext(t)` with the fixed DoFs held at
 * zero (the static limit of N2 in algorithms.md section 2, `M_eff = K`).
 *
 * @param system the discrete system (stiffness, external forces, fixed DoFs).
 * @param time time t at which the external force is evaluated (s).
 * @param U the displacement (m, rad); resized to the number of DoFs.
 * @param linear_solver the value of `Time integration/Newmark/Linear solver`:
 *        "KLU" or "MUMPS" (one factorisation, Amesos_Klu or Amesos_Mumps,
 *        followed by up to two steps of iterative refinement), "auto" or
 *        "direct" (KLU below 20,000 DoFs, MUMPS at and above, and from
 *        2,000 DoFs for 3D continua, resolve_linear_solver()) or
 *        "iterative" (CG + ML AMG, relative residual 1e-12); throws naming
 *        the entry for any other value.
 * @param constant_loads_only solve under the constant loads only (gravity,
 *        nodal loads), without the time-dependent ones (base excitation):
 *        the equilibrium a transient run starts from.
 *
 * @param contact_forces if not null, resized to the number of contact rows
 *        and filled with the static contact forces (N, >= 0 pushing the
 *        bodies apart; 0 for open rows).
 * @param tangent_forces if not null, resized to the number of contact rows
 *        and filled with the static forces along each tangent row of the
 *        closed contacts with friction (N, `K U = F + ... + T^T f_t`; 0 for
 *        a tangent that a support or a parallel held row holds instead, and
 *        for every other row).
 *
 * Contacts with a zero initial gap are closed (doc/theory.md 1.2 with the
 * static limit): the saddle-point problem `[K L_c^T; L_c 0] [U; -lambda] =
 * [F; -g0_c]` on the closed rows `L_c` is factorised (KLU or MUMPS,
 * direct_solver_package(); pivoting, so that a structure supported by its
 * contacts only is solved: then `K` alone may be singular). Two closed rows that are
 * exact opposites (a two-sided contact without clearance) act as one bilateral row. A
 * two-sided contact with a clearance (two opposite rows, the same positive gap) is held
 * at its initial position (`L U = 0`): the play is a mechanism that a static state must
 * not load, so its force must vanish (`|lambda| <= 1e-9` times the largest force or nodal
 * load), otherwise the error names it; its force is reported as 0. Every other closed
 * contact must be in compression (`lambda >= -1e-9 max|lambda|`), otherwise
 * the error names it.
 *
 * With ropes (R1, doc/theory.md 10.3) the equilibrium is nonlinear: Newton
 * on the rope forces, the rest linear, each iteration one solve of the
 * above with `K + K_r(U_k)` (a few iterations; a load hanging alone gets
 * `T_0 = m g`); a one-line error if it does not converge (e.g. a load held
 * by a slack rope only).
 *
 * Throws ExcMessage with "the stiffness matrix is singular: the model can
 * move as a rigid body (check the supports)" if a rigid translation of the
 * model costs no strain energy (`K r_d = 0` for an influence vector; not
 * checked when contacts are closed), if the factorisation fails, if the
 * solution is not finite or if the residual `||K U - F|| > 1e-8 ||F||` (free
 * DoFs; the residual of the augmented system with closed contacts).
 */
void solve_static(const DiscreteSystem &system,
                  const double time,
                  Vector<double> &U,
                  const std::string &linear_solver = "auto",
                  const bool constant_loads_only = false,
                  std::vector<double> *contact_forces = nullptr,
                  std::vector<std::array<double, 2>> *tangent_forces = nullptr);
} // namespace hati

#endif
