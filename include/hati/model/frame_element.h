#ifndef hati_model_frame_element_h
#define hati_model_frame_element_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <vector>

namespace hati
{
using namespace dealii;

/**
 * Cross-section properties of a straight frame (beam) member, in the local
 * axes (x along the member, y and z the principal axes of the section).
 *
 * - `A`: area (m^2);
 * - `Iy`: second moment of area about local y, `int z^2 dA` (m^4), used for
 *   bending in the x-z plane (w, ry);
 * - `Iz`: second moment of area about local z, `int y^2 dA` (m^4), used for
 *   bending in the x-y plane (v, rz);
 * - `J`: torsion constant (m^4), torsional stiffness G J;
 * - `shear_area_y`, `shear_area_z`: shear areas `A_sy = k_y A`, `A_sz = k_z A`
 *   for shear forces along local y and z (m^2). A shear area of 0 or +infinity
 *   means no shear deformation (Euler-Bernoulli) in that direction.
 */
struct FrameSection
{
  double A = 0., Iy = 0., Iz = 0., J = 0.;
  double shear_area_y = 0., shear_area_z = 0.;

  /** The kind of section: its stresses (beam_stresses.h) depend on it. */
  enum class Shape
  {
    general,
    rectangle,
    box
  };
  Shape shape = Shape::general;
  /**
   * Rectangle and box: outer width along local y and height along local z
   * (m); box: the wall thicknesses of its webs and flanges (m).
   */
  double b = 0., h = 0., t_web = 0., t_flange = 0.;
  /**
   * Extreme fibre distances from the centroid along local y and z (m): b /
   * 2 and h / 2 of a rectangle or a box; of a `general` section given
   * optionally (0: unknown, no stresses).
   */
  double c_y = 0., c_z = 0.;

  /**
   * Solid rectangle, width `b` along local y and height `h` along local z:
   * A = b h, Iy = b h^3/12, Iz = h b^3/12, shear areas 5/6 A, and the torsion
   * constant of the usual series approximation (Roark)
   *
   *   J = a c^3 (1/3 - 0.21 (c/a) (1 - (c/a)^4/12)),  a = max(b, h),
   *   c = min(b, h),
   *
   * accurate to about 0.5 % for all aspect ratios.
   */
  static FrameSection rectangle(const double b, const double h);

  /**
   * Thin-walled closed rectangular box, outer width `b` along local y and
   * outer height `h` along local z. The two webs are the walls parallel to
   * z (height h, thickness `t_web`), the two flanges the walls parallel to y
   * (width b, thickness `t_flange`); requires 2 t_web < b and
   * 2 t_flange < h.
   *
   * - A = b h - (b - 2 t_web)(h - 2 t_flange);
   * - Iy = (b h^3 - (b - 2 t_web)(h - 2 t_flange)^3)/12,
   *   Iz = (h b^3 - (h - 2 t_flange)(b - 2 t_web)^3)/12 (exact for the
   *   hollow rectangle);
   * - J by Bredt's formula J = 4 A_m^2 / (oint ds/t) on the wall centre
   *   lines (b_m = b - t_web, h_m = h - t_flange):
   *   J = 2 t_web t_flange b_m^2 h_m^2 / (b t_web + h t_flange - t_web^2
   *   - t_flange^2);
   * - shear areas: the webs carry shear along z, A_sz = 2 t_web h_m; the
   *   flanges carry shear along y, A_sy = 2 t_flange b_m (centre-line wall
   *   lengths).
   */
  static FrameSection
  box(const double b, const double h, const double t_web, const double t_flange);
};

/** Linear elastic isotropic material of a frame member. */
struct FrameMaterial
{
  double E = 0.;   ///< Young's modulus (Pa)
  double G = 0.;   ///< shear modulus (Pa)
  double rho = 0.; ///< density (kg/m^3)
};

/**
 * Shear deformation parameter Phi = 12 E I / (G A_s L^2) of one bending plane
 * (Przemieniecki); 0 if `shear_area` is 0 or infinite (Euler-Bernoulli).
 */
double shear_parameter(const double E,
                       const double I,
                       const double G,
                       const double shear_area,
                       const double L);

/**
 * Interdependent interpolation (Friedman & Kosmatka 1993) of a Timoshenko
 * beam in one bending plane, on the DoFs (v1, theta1, v2, theta2) with
 * theta = dv/dx for Euler-Bernoulli, at xi = x/L in [0, 1]:
 *
 *   Nv1 = (2xi^3 - 3xi^2 - Phi xi + 1 + Phi)/(1+Phi),
 *   Nv2 = L (xi^3 - (2 + Phi/2) xi^2 + (1 + Phi/2) xi)/(1+Phi),
 *   Nv3 = (-2xi^3 + 3xi^2 + Phi xi)/(1+Phi),
 *   Nv4 = L (xi^3 - (1 - Phi/2) xi^2 - (Phi/2) xi)/(1+Phi),
 *   Nt1 = 6 (xi^2 - xi)/((1+Phi) L),  Nt2 = (3xi^2 - (4+Phi) xi + 1 + Phi)/(1+Phi),
 *   Nt3 = -6 (xi^2 - xi)/((1+Phi) L), Nt4 = (3xi^2 - (2-Phi) xi)/(1+Phi).
 *
 * They solve the homogeneous Timoshenko equations exactly (constant shear
 * strain v' - theta, linear moment), reduce to the cubic Hermite functions
 * with Nt = dNv/dx for Phi = 0. The derivatives are with respect to x.
 */
struct FrameBendingShapeFunctions
{
  std::array<double, 4> Nv;  ///< transverse displacement v
  std::array<double, 4> Nt;  ///< section rotation theta
  std::array<double, 4> dNv; ///< dv/dx
  std::array<double, 4> dNt; ///< dtheta/dx
};

/** Evaluate the shape functions of FrameBendingShapeFunctions at xi = x/L. */
FrameBendingShapeFunctions
frame_bending_shape_functions(const double xi, const double L, const double Phi);

/**
 * Local 12 x 12 stiffness matrix of the 3D Timoshenko frame element with exact
 * (interdependent) interpolation, DoFs (u1, v1, w1, rx1, ry1, rz1, u2, v2,
 * w2, rx2, ry2, rz2), x from node 1 to node 2 (Przemieniecki 1968):
 *
 * - axial EA/L [[1, -1], [-1, 1]] on (u1, u2), torsion GJ/L on (rx1, rx2);
 * - x-y plane on (v1, rz1, v2, rz2), rz = dv/dx (Euler-Bernoulli),
 *   Phi_y = 12 E Iz / (G A_sy L^2):
 *   E Iz/((1+Phi_y) L^3) [[12, 6L, -12, 6L], [6L, (4+Phi_y)L^2, -6L,
 *   (2-Phi_y)L^2], [-12, -6L, 12, -6L], [6L, (2-Phi_y)L^2, -6L, (4+Phi_y)L^2]];
 * - x-z plane on (w1, ry1, w2, ry2), ry = -dw/dx, Phi_z = 12 E Iy/(G A_sz L^2):
 *   the same matrix with E Iy, Phi_z and the sign of the w-ry coupling terms
 *   flipped.
 *
 * Exact (no locking) for end-loaded members.
 */
FullMatrix<double> local_stiffness(const double L,
                                   const FrameSection &section,
                                   const FrameMaterial &material);

/**
 * Local 12 x 12 consistent mass matrix from the same interdependent shape
 * functions (Friedman & Kosmatka 1993), same DoF order as local_stiffness():
 *
 * - axial rho A L/6 [[2, 1], [1, 2]], torsion rho (Iy + Iz) L/6 [[2, 1], [1, 2]];
 * - each bending plane M = int_0^L rho A Nv^T Nv + rho I Nt^T Nt dx (translational
 *   and rotary inertia, I = Iz for x-y, Iy for x-z), evaluated by 5-point Gauss
 *   quadrature (exact for these polynomials); the x-z plane maps theta = -ry.
 *
 * For Phi = 0 and I = 0 this is the classic rho A L/420 [[156, 22L, 54, -13L],
 * ...] Hermite mass.
 */
FullMatrix<double> local_consistent_mass(const double L,
                                         const FrameSection &section,
                                         const FrameMaterial &material);

/**
 * Diagonal (lumped) local mass for the explicit integrator, 12 entries in the
 * DoF order of local_stiffness(), all strictly positive:
 *
 * - translations: rho A L/2;
 * - bending rotations ry, rz: HRZ lumping of the Euler-Bernoulli consistent
 *   mass (diagonal 156, 4L^2, 156, 4L^2 times rho A L/420, scaled so that
 *   the translational diagonal sums to rho A L, i.e. by 420/312) gives
 *   rho A L^3/78, plus the rotary inertia rho I L/2 (I = Iy for ry, Iz for
 *   rz);
 * - torsion rx: rho (Iy + Iz) L/2.
 *
 * Throws if rho <= 0 or Iy + Iz <= 0.
 */
std::vector<double> local_lumped_mass(const double L,
                                      const FrameSection &section,
                                      const FrameMaterial &material);

/**
 * Rotation from global to local axes, u_local = R u_global: the rows of R are
 * the local unit vectors e_x = (x2 - x1)/|x2 - x1|, e_y = the part of
 * `y_reference` orthogonal to e_x, normalised, and e_z = e_x x e_y.
 * Throws if the member has zero length or `y_reference` is (nearly) parallel
 * to it.
 */
Tensor<2, 3>
frame_rotation(const Point<3> &x1, const Point<3> &x2, const Tensor<1, 3> &y_reference);

/**
 * Global 12 x 12 matrix T^T k T from a local one, with T = diag(R, R, R, R)
 * acting on (translation 1, rotation 1, translation 2, rotation 2).
 */
FullMatrix<double> to_global(const FullMatrix<double> &local, const Tensor<2, 3> &R);

/** Global 12-vector T^T f of a local one (forces or displacements). */
Vector<double> to_global(const Vector<double> &local12, const Tensor<2, 3> &R);

/** Local 12-vector T u of a global one, T = diag(R, R, R, R). */
Vector<double> to_local(const Vector<double> &global12, const Tensor<2, 3> &R);

/**
 * The same into @p local12 (of size 12), without allocating: the output
 * rows' section forces call it for every element.
 */
void to_local(const Vector<double> &global12,
              const Tensor<2, 3> &R,
              Vector<double> &local12);

/**
 * Internal forces (stress resultants) at both ends of an element without span
 * loads, from the local end displacements u (12) and the local stiffness k:
 * entries 0..5 are (N, Vy, Vz, T, My, Mz) at end 1, equal to -(k u)[0..5],
 * entries 6..11 the same at end 2, equal to +(k u)[6..11].
 *
 * Sign convention: resultants on the cross-section face whose outward normal
 * is +e_x (the action of the part of the member beyond the section on the part
 * before it), in local axes; N > 0 in tension, T = Mx. A cantilever clamped at
 * node 1 with tip load P e_y has Vy = P and Mz(x) = P (L - x).
 */
std::array<double, 12> section_forces(const FullMatrix<double> &local_stiffness,
                                      const Vector<double> &local_displacement);

/**
 * section_forces() from the local end forces f (12) that the rest of the
 * structure applies to the element: (N, Vy, Vz, T, My, Mz) = -f[0..5] at
 * end 1 and +f[6..11] at end 2. With span loads F_span (e.g. gravity),
 * f = k u - F_span.
 */
std::array<double, 12> section_forces(const Vector<double> &local_end_forces);

/** section_forces() with the local stiffness built from L, section, material. */
std::array<double, 12> section_forces(const double L,
                                      const FrameSection &section,
                                      const FrameMaterial &material,
                                      const Vector<double> &local_displacement);
} // namespace hati

#endif
