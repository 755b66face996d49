#include <deal.II/base/exceptions.h>
#include <deal.II/base/quadrature_lib.h>

#include <hati/model/frame_element.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace hati
{
namespace
{
/** DoFs (translation, rotation) of node 1 and node 2 of one bending plane. */
constexpr std::array<unsigned int, 4> xy_plane_dofs = {{1, 5, 7, 11}};
constexpr std::array<unsigned int, 4> xz_plane_dofs = {{2, 4, 8, 10}};
/** theta = dv/dx = rz in the x-y plane, theta = dw/dx = -ry in the x-z plane. */
constexpr std::array<double, 4> xy_plane_signs = {{1., 1., 1., 1.}};
constexpr std::array<double, 4> xz_plane_signs = {{1., -1., 1., -1.}};

void check_length(const double L)
{
  AssertThrow(
      std::isfinite(L) && L > 0.,
      ExcMessage("Frame element: the length L = " + std::to_string(L) + " must be > 0."));
}

void check_section(const FrameSection &s)
{
  AssertThrow(std::isfinite(s.A) && s.A > 0.,
              ExcMessage("Frame element: the section area A must be > 0."));
  AssertThrow(std::isfinite(s.Iy) && std::isfinite(s.Iz) && std::isfinite(s.J) &&
                  s.Iy >= 0. && s.Iz >= 0. && s.J >= 0.,
              ExcMessage("Frame element: Iy, Iz and J must be finite and >= 0."));
  AssertThrow(s.shear_area_y >= 0. && s.shear_area_z >= 0.,
              ExcMessage("Frame element: the shear areas must be >= 0 (0 or "
                         "infinity: no shear deformation)."));
}

void check_elastic(const FrameMaterial &m)
{
  AssertThrow(std::isfinite(m.E) && std::isfinite(m.G) && m.E > 0. && m.G > 0.,
              ExcMessage("Frame element: E and G must be finite and > 0."));
}

void check_density(const FrameMaterial &m)
{
  AssertThrow(std::isfinite(m.rho) && m.rho >= 0.,
              ExcMessage("Frame element: the density rho must be finite and >= 0."));
}

/** Add the 4 x 4 plane matrix `p` into `k` at `dofs`, with theta = sign * dof. */
void add_plane(FullMatrix<double> &k,
               const FullMatrix<double> &p,
               const std::array<unsigned int, 4> &dofs,
               const std::array<double, 4> &signs)
{
  for (unsigned int i = 0; i < 4; ++i)
    for (unsigned int j = 0; j < 4; ++j)
      k(dofs[i], dofs[j]) += signs[i] * signs[j] * p(i, j);
}

/** Add c [[1, -1], [-1, 1]] (or c [[2, 1], [1, 2]] if `mass`) at dofs a, b. */
void add_two_node(FullMatrix<double> &k,
                  const unsigned int a,
                  const unsigned int b,
                  const double c,
                  const bool mass)
{
  k(a, a) += (mass ? 2. : 1.) * c;
  k(b, b) += (mass ? 2. : 1.) * c;
  k(a, b) += (mass ? 1. : -1.) * c;
  k(b, a) += (mass ? 1. : -1.) * c;
}

/** Closed-form Timoshenko bending stiffness of one plane on (v1, t1, v2, t2). */
FullMatrix<double> plane_stiffness(const double EI, const double Phi, const double L)
{
  const double c = EI / ((1. + Phi) * L * L * L);
  const double a = (4. + Phi) * L * L, b = (2. - Phi) * L * L;
  const double k[4][4] = {{12., 6. * L, -12., 6. * L},
                          {6. * L, a, -6. * L, b},
                          {-12., -6. * L, 12., -6. * L},
                          {6. * L, b, -6. * L, a}};
  FullMatrix<double> p(4, 4);
  for (unsigned int i = 0; i < 4; ++i)
    for (unsigned int j = 0; j < 4; ++j)
      p(i, j) = c * k[i][j];
  return p;
}

/** int_0^L rhoA Nv^T Nv + rhoI Nt^T Nt dx of one plane, 5-point Gauss. */
FullMatrix<double>
plane_mass(const double rhoA, const double rhoI, const double Phi, const double L)
{
  const QGauss<1> quadrature(5);
  FullMatrix<double> p(4, 4);
  for (unsigned int q = 0; q < quadrature.size(); ++q)
  {
    const FrameBendingShapeFunctions N =
        frame_bending_shape_functions(quadrature.point(q)[0], L, Phi);
    const double JxW = quadrature.weight(q) * L;
    for (unsigned int i = 0; i < 4; ++i)
      for (unsigned int j = 0; j < 4; ++j)
        p(i, j) += (rhoA * N.Nv[i] * N.Nv[j] + rhoI * N.Nt[i] * N.Nt[j]) * JxW;
  }
  return p;
}

/** T = diag(R, R, R, R) as a 12 x 12 matrix. */
FullMatrix<double> transformation(const Tensor<2, 3> &R)
{
  FullMatrix<double> T(12, 12);
  for (unsigned int b = 0; b < 4; ++b)
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        T(3 * b + i, 3 * b + j) = R[i][j];
  return T;
}
} // namespace

FrameSection FrameSection::rectangle(const double b, const double h)
{
  AssertThrow(std::isfinite(b) && std::isfinite(h) && b > 0. && h > 0.,
              ExcMessage("rectangle section: b and h must be > 0 (m)."));
  FrameSection s;
  s.A = b * h;
  s.Iy = b * h * h * h / 12.;
  s.Iz = h * b * b * b / 12.;
  const double a = std::max(b, h), c = std::min(b, h), r = c / a;
  s.J = a * c * c * c * (1. / 3. - 0.21 * r * (1. - r * r * r * r / 12.));
  s.shear_area_y = 5. / 6. * s.A;
  s.shear_area_z = 5. / 6. * s.A;
  s.shape = Shape::rectangle;
  s.b = b;
  s.h = h;
  s.c_y = 0.5 * b;
  s.c_z = 0.5 * h;
  return s;
}

FrameSection FrameSection::box(const double b,
                               const double h,
                               const double t_web,
                               const double t_flange)
{
  AssertThrow(std::isfinite(b) && std::isfinite(h) && b > 0. && h > 0. && t_web > 0. &&
                  t_flange > 0. && 2. * t_web < b && 2. * t_flange < h,
              ExcMessage("box section: need b, h, t_web, t_flange > 0 (m), "
                         "2 t_web < b and 2 t_flange < h."));
  const double bi = b - 2. * t_web, hi = h - 2. * t_flange; // inner opening
  const double bm = b - t_web, hm = h - t_flange;           // centre lines
  FrameSection s;
  s.A = b * h - bi * hi;
  s.Iy = (b * h * h * h - bi * hi * hi * hi) / 12.;
  s.Iz = (h * b * b * b - hi * bi * bi * bi) / 12.;
  s.J = 2. * t_web * t_flange * bm * bm * hm * hm /
        (b * t_web + h * t_flange - t_web * t_web - t_flange * t_flange);
  s.shear_area_y = 2. * t_flange * bm;
  s.shear_area_z = 2. * t_web * hm;
  s.shape = Shape::box;
  s.b = b;
  s.h = h;
  s.t_web = t_web;
  s.t_flange = t_flange;
  s.c_y = 0.5 * b;
  s.c_z = 0.5 * h;
  return s;
}

double shear_parameter(const double E,
                       const double I,
                       const double G,
                       const double shear_area,
                       const double L)
{
  if (shear_area == 0. || std::isinf(shear_area) || I == 0.)
    return 0.;
  return 12. * E * I / (G * shear_area * L * L);
}

FrameBendingShapeFunctions
frame_bending_shape_functions(const double xi, const double L, const double Phi)
{
  const double d = 1. + Phi, x2 = xi * xi, x3 = x2 * xi;
  FrameBendingShapeFunctions N;
  N.Nv = {{(2. * x3 - 3. * x2 - Phi * xi + 1. + Phi) / d,
           L * (x3 - (2. + Phi / 2.) * x2 + (1. + Phi / 2.) * xi) / d,
           (-2. * x3 + 3. * x2 + Phi * xi) / d,
           L * (x3 - (1. - Phi / 2.) * x2 - Phi / 2. * xi) / d}};
  N.Nt = {{6. * (x2 - xi) / (d * L),
           (3. * x2 - (4. + Phi) * xi + 1. + Phi) / d,
           -6. * (x2 - xi) / (d * L),
           (3. * x2 - (2. - Phi) * xi) / d}};
  // d/dx = (1/L) d/dxi
  N.dNv = {{(6. * x2 - 6. * xi - Phi) / (d * L),
            (3. * x2 - (4. + Phi) * xi + 1. + Phi / 2.) / d,
            (-6. * x2 + 6. * xi + Phi) / (d * L),
            (3. * x2 - (2. - Phi) * xi - Phi / 2.) / d}};
  N.dNt = {{6. * (2. * xi - 1.) / (d * L * L),
            (6. * xi - 4. - Phi) / (d * L),
            -6. * (2. * xi - 1.) / (d * L * L),
            (6. * xi - 2. + Phi) / (d * L)}};
  return N;
}

namespace
{
/**
 * The shear parameters `Phi_y`, `Phi_z` of the xy and xz planes of an
 * element (shear_parameter()), after checking its length, section and
 * elastic constants.
 */
std::array<double, 2> checked_shear_parameters(const double L,
                                               const FrameSection &section,
                                               const FrameMaterial &material)
{
  check_length(L);
  check_section(section);
  check_elastic(material);
  const double E = material.E, G = material.G;
  return {{shear_parameter(E, section.Iz, G, section.shear_area_y, L),
           shear_parameter(E, section.Iy, G, section.shear_area_z, L)}};
}
} // namespace

FullMatrix<double> local_stiffness(const double L,
                                   const FrameSection &section,
                                   const FrameMaterial &material)
{
  const auto [Phi_y, Phi_z] = checked_shear_parameters(L, section, material);
  const double E = material.E, G = material.G;
  FullMatrix<double> k(12, 12);
  add_two_node(k, 0, 6, E * section.A / L, false);
  add_two_node(k, 3, 9, G * section.J / L, false);
  add_plane(k, plane_stiffness(E * section.Iz, Phi_y, L), xy_plane_dofs, xy_plane_signs);
  add_plane(k, plane_stiffness(E * section.Iy, Phi_z, L), xz_plane_dofs, xz_plane_signs);
  return k;
}

FullMatrix<double> local_consistent_mass(const double L,
                                         const FrameSection &section,
                                         const FrameMaterial &material)
{
  const auto [Phi_y, Phi_z] = checked_shear_parameters(L, section, material);
  check_density(material);
  const double rho = material.rho;
  FullMatrix<double> m(12, 12);
  add_two_node(m, 0, 6, rho * section.A * L / 6., true);
  add_two_node(m, 3, 9, rho * (section.Iy + section.Iz) * L / 6., true);
  add_plane(m,
            plane_mass(rho * section.A, rho * section.Iz, Phi_y, L),
            xy_plane_dofs,
            xy_plane_signs);
  add_plane(m,
            plane_mass(rho * section.A, rho * section.Iy, Phi_z, L),
            xz_plane_dofs,
            xz_plane_signs);
  return m;
}

std::vector<double> local_lumped_mass(const double L,
                                      const FrameSection &section,
                                      const FrameMaterial &material)
{
  check_length(L);
  check_section(section);
  check_density(material);
  AssertThrow(material.rho > 0. && section.Iy + section.Iz > 0.,
              ExcMessage("Frame element: the lumped mass needs rho > 0 and "
                         "Iy + Iz > 0 to be positive definite."));
  const double rho = material.rho, A = section.A;
  const double translation = rho * A * L / 2.;
  const double hrz = rho * A * L * L * L / 78.; // (4L^2 rhoAL/420) (420/312)
  std::vector<double> m(12);
  for (unsigned int n = 0; n < 2; ++n)
  {
    m[6 * n + 0] = translation;
    m[6 * n + 1] = translation;
    m[6 * n + 2] = translation;
    m[6 * n + 3] = rho * (section.Iy + section.Iz) * L / 2.;
    m[6 * n + 4] = hrz + rho * section.Iy * L / 2.;
    m[6 * n + 5] = hrz + rho * section.Iz * L / 2.;
  }
  return m;
}

Tensor<2, 3>
frame_rotation(const Point<3> &x1, const Point<3> &x2, const Tensor<1, 3> &y_reference)
{
  const Tensor<1, 3> d = x2 - x1;
  const double L = d.norm();
  AssertThrow(L > 0. && L > 1e-12 * (x1.norm() + x2.norm()),
              ExcMessage("frame member: the member has zero length (its two "
                         "nodes coincide)."));
  const Tensor<1, 3> ex = d / L;
  const Tensor<1, 3> y_perp = y_reference - (y_reference * ex) * ex;
  const double y_norm = y_perp.norm();
  AssertThrow(y_norm > 1e-10 * y_reference.norm() && y_norm > 0.,
              ExcMessage("frame_rotation: the reference vector for the local y "
                         "axis is zero or parallel to the member axis."));
  const Tensor<1, 3> ey = y_perp / y_norm;
  const Tensor<1, 3> ez = cross_product_3d(ex, ey);
  Tensor<2, 3> R;
  for (unsigned int j = 0; j < 3; ++j)
  {
    R[0][j] = ex[j];
    R[1][j] = ey[j];
    R[2][j] = ez[j];
  }
  return R;
}

FullMatrix<double> to_global(const FullMatrix<double> &local, const Tensor<2, 3> &R)
{
  AssertThrow(local.m() == 12 && local.n() == 12,
              ExcMessage("to_global: the local matrix must be 12 x 12."));
  const FullMatrix<double> T = transformation(R);
  FullMatrix<double> global(12, 12);
  global.triple_product(local, T, T, true, false);
  return global;
}

namespace
{
/**
 * `T^T x` (@p to_global: local to global axes) or `T x` (global to local)
 * for the 12 end values @p x of an element, T = transformation(R).
 */
Vector<double>
rotate(const Vector<double> &x, const Tensor<2, 3> &R, const bool to_global)
{
  AssertThrow(x.size() == 12,
              ExcMessage(std::string(to_global ? "to_global: the local"
                                               : "to_local: the global") +
                         " vector must have 12 entries."));
  Vector<double> y(12);
  if (to_global)
    transformation(R).Tvmult(y, x);
  else
    transformation(R).vmult(y, x);
  return y;
}
} // namespace

Vector<double> to_global(const Vector<double> &local12, const Tensor<2, 3> &R)
{
  return rotate(local12, R, true);
}

Vector<double> to_local(const Vector<double> &global12, const Tensor<2, 3> &R)
{
  return rotate(global12, R, false);
}

void to_local(const Vector<double> &global12,
              const Tensor<2, 3> &R,
              Vector<double> &local12)
{
  AssertThrow(global12.size() == 12 && local12.size() == 12,
              ExcMessage("to_local: the vectors must have 12 entries."));
  // T = diag(R, R, R, R) in a matrix of this thread, the product as
  // transformation(R).vmult() forms it
  thread_local FullMatrix<double> T(12, 12);
  for (unsigned int b = 0; b < 4; ++b)
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        T(3 * b + i, 3 * b + j) = R[i][j];
  T.vmult(local12, global12);
}

std::array<double, 12> section_forces(const Vector<double> &local_end_forces)
{
  AssertThrow(local_end_forces.size() == 12,
              ExcMessage("section_forces: need 12 local end forces."));
  std::array<double, 12> s;
  for (unsigned int i = 0; i < 6; ++i)
  {
    s[i] = -local_end_forces[i];
    s[6 + i] = local_end_forces[6 + i];
  }
  return s;
}

std::array<double, 12> section_forces(const FullMatrix<double> &local_stiffness,
                                      const Vector<double> &local_displacement)
{
  AssertThrow(local_stiffness.m() == 12 && local_stiffness.n() == 12 &&
                  local_displacement.size() == 12,
              ExcMessage("section_forces: need a 12 x 12 stiffness and 12 "
                         "displacements."));
  Vector<double> f(12);
  local_stiffness.vmult(f, local_displacement);
  return section_forces(f);
}

std::array<double, 12> section_forces(const double L,
                                      const FrameSection &section,
                                      const FrameMaterial &material,
                                      const Vector<double> &local_displacement)
{
  return section_forces(local_stiffness(L, section, material), local_displacement);
}
} // namespace hati
