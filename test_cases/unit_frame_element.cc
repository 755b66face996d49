// Unit test of the 3D Timoshenko frame element (model/frame_element.h)
// against independent closed-form results: symmetry, rigid-body modes of a
// skew member, one-element cantilevers (exact for end loads), total mass,
// the stiffness integrated from the interdependent shape functions, the
// Przemieniecki closed-form Timoshenko mass, the Hermite mass for Phi = 0,
// the local frame and its error paths, and the section helpers against
// tabulated values. Prints every check with value, reference and tolerance;
// returns non-zero on failure.
#include "test_tools.h"

#include <deal.II/base/exceptions.h>
#include <deal.II/base/quadrature_lib.h>

#include <hati/model/frame_element.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <string>

namespace hati_unit_frame_element
{

using namespace dealii;
using namespace hati;

namespace
{
int failures = 0;

/** |value - reference| <= tolerance * max(|reference|, scale). */
void check(const std::string &what,
           const double value,
           const double reference,
           const double tolerance,
           const double scale = 0.)
{
  const double error = std::abs(value - reference);
  const bool ok = error <= tolerance * std::max(std::abs(reference), scale);
  std::cout << (ok ? "ok   " : "FAIL ") << what << ": value = " << std::setprecision(15)
            << value << ", reference = " << reference
            << ", relative tolerance = " << std::setprecision(3) << tolerance
            << (scale > 0.
                    ? " (of max(|reference|, scale = " + std::to_string(scale) + "))"
                    : "")
            << std::endl;
  failures += ok ? 0 : 1;
}

void expect(const bool ok, const std::string &what)
{
  std::cout << (ok ? "ok   " : "FAIL ") << what << std::endl;
  failures += ok ? 0 : 1;
}

double max_abs(const FullMatrix<double> &a)
{
  double m = 0.;
  for (unsigned int i = 0; i < a.m(); ++i)
    for (unsigned int j = 0; j < a.n(); ++j)
      m = std::max(m, std::abs(a(i, j)));
  return m;
}

double asymmetry(const FullMatrix<double> &a)
{
  double m = 0.;
  for (unsigned int i = 0; i < a.m(); ++i)
    for (unsigned int j = 0; j < a.n(); ++j)
      m = std::max(m, std::abs(a(i, j) - a(j, i)));
  return m / max_abs(a);
}

/** Tip displacements (local, 6) of a cantilever clamped at node 1. */
Vector<double> cantilever_tip(const FullMatrix<double> &k, const Vector<double> &tip_load)
{
  FullMatrix<double> k22(6, 6);
  for (unsigned int i = 0; i < 6; ++i)
    for (unsigned int j = 0; j < 6; ++j)
      k22(i, j) = k(6 + i, 6 + j);
  k22.gauss_jordan();
  Vector<double> u(6);
  k22.vmult(u, tip_load);
  return u;
}

Vector<double> full_displacement(const Vector<double> &tip)
{
  Vector<double> u(12);
  for (unsigned int i = 0; i < 6; ++i)
    u[6 + i] = tip[i];
  return u;
}

/** Przemieniecki's closed-form Timoshenko mass of one plane (v1, t1, v2, t2). */
FullMatrix<double>
przemieniecki_mass(const double rhoA, const double rhoI, const double Phi, const double L)
{
  const double P = Phi, P2 = Phi * Phi, d2 = (1. + Phi) * (1. + Phi);
  const double t11 = 13. / 35. + 7. / 10. * P + P2 / 3.;
  const double t12 = (11. / 210. + 11. / 120. * P + P2 / 24.) * L;
  const double t13 = 9. / 70. + 3. / 10. * P + P2 / 6.;
  const double t14 = -(13. / 420. + 3. / 40. * P + P2 / 24.) * L;
  const double t22 = (1. / 105. + P / 60. + P2 / 120.) * L * L;
  const double t24 = -(1. / 140. + P / 60. + P2 / 120.) * L * L;
  const double mt[4][4] = {{t11, t12, t13, t14},
                           {t12, t22, -t14, t24},
                           {t13, -t14, t11, -t12},
                           {t14, t24, -t12, t22}};
  const double r11 = 6. / 5., r12 = (1. / 10. - P / 2.) * L;
  const double r22 = (2. / 15. + P / 6. + P2 / 3.) * L * L;
  const double r24 = (-1. / 30. - P / 6. + P2 / 6.) * L * L;
  const double mr[4][4] = {{r11, r12, -r11, r12},
                           {r12, r22, -r12, r24},
                           {-r11, -r12, r11, -r12},
                           {r12, r24, -r12, r22}};
  FullMatrix<double> m(4, 4);
  for (unsigned int i = 0; i < 4; ++i)
    for (unsigned int j = 0; j < 4; ++j)
      m(i, j) = rhoA * L / d2 * mt[i][j] + rhoI / (d2 * L) * mr[i][j];
  return m;
}

/** Compare the plane block of a 12 x 12 matrix with a 4 x 4 plane matrix. */
void check_plane(const std::string &what,
                 const FullMatrix<double> &full,
                 const FullMatrix<double> &plane,
                 const bool xz,
                 const double tolerance)
{
  const unsigned int xy_dofs[4] = {1, 5, 7, 11}, xz_dofs[4] = {2, 4, 8, 10};
  const double xz_signs[4] = {1., -1., 1., -1.};
  double error = 0.;
  for (unsigned int i = 0; i < 4; ++i)
    for (unsigned int j = 0; j < 4; ++j)
    {
      const double value = xz ? full(xz_dofs[i], xz_dofs[j]) * xz_signs[i] * xz_signs[j]
                              : full(xy_dofs[i], xy_dofs[j]);
      error = std::max(error, std::abs(value - plane(i, j)));
    }
  check(
      what + " (max entry error / max entry)", error / max_abs(plane), 0., tolerance, 1.);
}

template <typename F> bool throws(F f)
{
  try
  {
    f();
  }
  catch (const ExceptionBase &e)
  {
    std::cout << "     (exception message: ";
    e.print_info(std::cout);
    std::cout << ")" << std::endl;
    return true;
  }
  return false;
}
} // namespace

HATI_UNIT_TEST(frame_element)
{
  // a section with significant shear deformation in both planes
  FrameSection section;
  section.A = 0.01;
  section.Iy = 2e-5;
  section.Iz = 8e-6;
  section.J = 1.5e-5;
  section.shear_area_y = 0.004;
  section.shear_area_z = 0.006;
  const FrameMaterial material{210e9, 81e9, 7850.};
  const double E = material.E, G = material.G, rho = material.rho;
  const double L = 0.8;
  const double A = section.A, Iy = section.Iy, Iz = section.Iz, J = section.J;
  const double Asy = section.shear_area_y, Asz = section.shear_area_z;
  std::cout << "Phi_y = " << shear_parameter(E, Iz, G, Asy, L)
            << ", Phi_z = " << shear_parameter(E, Iy, G, Asz, L) << std::endl;

  const FullMatrix<double> k = local_stiffness(L, section, material);
  const FullMatrix<double> m = local_consistent_mass(L, section, material);
  const std::vector<double> ml = local_lumped_mass(L, section, material);

  // skew member
  const Point<3> x1(0.3, -0.2, 0.5);
  Tensor<1, 3> dir;
  dir[0] = 1.;
  dir[1] = 2.;
  dir[2] = -0.7;
  dir /= dir.norm();
  const Point<3> x2 = x1 + L * dir;
  Tensor<1, 3> y_ref;
  y_ref[2] = 1.;
  const Tensor<2, 3> R = frame_rotation(x1, x2, y_ref);
  const FullMatrix<double> kg = to_global(k, R);
  const FullMatrix<double> mg = to_global(m, R);

  // (1) symmetry
  check("(1) local stiffness symmetric", asymmetry(k), 0., 1e-14, 1.);
  check("(1) local consistent mass symmetric", asymmetry(m), 0., 1e-14, 1.);
  check("(1) global stiffness symmetric", asymmetry(kg), 0., 1e-14, 1.);
  check("(1) global consistent mass symmetric", asymmetry(mg), 0., 1e-14, 1.);

  // (2) rigid-body modes of the skew member, in global coordinates
  {
    const double k_norm = kg.frobenius_norm();
    for (unsigned int mode = 0; mode < 6; ++mode)
    {
      Vector<double> r(12);
      if (mode < 3)
      {
        r[mode] = 1.;
        r[6 + mode] = 1.;
      }
      else
      {
        Tensor<1, 3> theta;
        theta[mode - 3] = 1.;
        const Tensor<1, 3> u2 = cross_product_3d(theta, x2 - x1);
        for (unsigned int d = 0; d < 3; ++d)
        {
          r[3 + d] = theta[d];
          r[6 + d] = u2[d];
          r[9 + d] = theta[d];
        }
      }
      Vector<double> f(12);
      kg.vmult(f, r);
      check("(2) rigid mode " + std::to_string(mode) +
                (mode < 3 ? " (translation)" : " (rotation about node 1)") +
                ": |K r| / (|K| |r|)",
            f.l2_norm() / (k_norm * r.l2_norm()),
            0.,
            1e-9,
            1.);
      if (mode < 3)
      {
        // (4) kinetic energy of a rigid translation: r^T M r = rho A L
        Vector<double> mr(12);
        mg.vmult(mr, r);
        check("(4) global consistent mass, r^T M r for rigid translation " +
                  std::to_string(mode),
              r * mr,
              rho * A * L,
              1e-13);
      }
    }
  }

  // (3) one-element cantilevers, clamped at node 1, local coordinates
  {
    const double P = 1.3e4, M = 2.1e3, T = 1.7e3;
    const double tol = 1e-12;
    Vector<double> load(6);
    load[1] = P; // tip load along local y
    Vector<double> u = cantilever_tip(k, load);
    check("(3) tip load P y: deflection v = P L^3/(3 E Iz) + P L/(G A_sy)",
          u[1],
          P * L * L * L / (3. * E * Iz) + P * L / (G * Asy),
          tol);
    check("(3) tip load P y: rotation rz = P L^2/(2 E Iz)",
          u[5],
          P * L * L / (2. * E * Iz),
          tol);
    check("(3) tip load P y: no coupling to u, w, rx, ry",
          std::max({std::abs(u[0]), std::abs(u[2]), std::abs(u[3]), std::abs(u[4])}),
          0.,
          tol,
          std::abs(u[1]));
    {
      const std::array<double, 12> s = section_forces(k, full_displacement(u));
      check("(3) tip load P y: end 1 shear Vy = P", s[1], P, tol);
      check("(3) tip load P y: end 1 moment Mz = P L", s[5], P * L, tol);
      check("(3) tip load P y: end 2 shear Vy = P", s[7], P, tol);
      check("(3) tip load P y: end 2 moment Mz = 0", s[11], 0., tol, P * L);
      check("(3) tip load P y: end 1 N = 0", s[0], 0., tol, P);
    }

    load = 0.;
    load[2] = P; // along local z
    u = cantilever_tip(k, load);
    check("(3) tip load P z: deflection w = P L^3/(3 E Iy) + P L/(G A_sz)",
          u[2],
          P * L * L * L / (3. * E * Iy) + P * L / (G * Asz),
          tol);
    check("(3) tip load P z: rotation ry = -P L^2/(2 E Iy)",
          u[4],
          -P * L * L / (2. * E * Iy),
          tol);
    {
      const std::array<double, 12> s =
          section_forces(L, section, material, full_displacement(u));
      check("(3) tip load P z: end 1 shear Vz = P", s[2], P, tol);
      check("(3) tip load P z: end 1 moment My = -P L", s[4], -P * L, tol);
      check("(3) tip load P z: end 2 moment My = 0", s[10], 0., tol, P * L);
    }

    load = 0.;
    load[5] = M; // tip moment about z
    u = cantilever_tip(k, load);
    check("(3) tip moment Mz: rotation rz = M L/(E Iz)", u[5], M * L / (E * Iz), tol);
    check("(3) tip moment Mz: deflection v = M L^2/(2 E Iz)",
          u[1],
          M * L * L / (2. * E * Iz),
          tol);

    load = 0.;
    load[4] = M; // tip moment about y
    u = cantilever_tip(k, load);
    check("(3) tip moment My: rotation ry = M L/(E Iy)", u[4], M * L / (E * Iy), tol);
    check("(3) tip moment My: deflection w = -M L^2/(2 E Iy)",
          u[2],
          -M * L * L / (2. * E * Iy),
          tol);

    load = 0.;
    load[0] = P; // axial
    u = cantilever_tip(k, load);
    check("(3) axial tip load: u = P L/(E A)", u[0], P * L / (E * A), tol);
    {
      const std::array<double, 12> s = section_forces(k, full_displacement(u));
      check("(3) axial tension: end 1 N = P > 0", s[0], P, tol);
      check("(3) axial tension: end 2 N = P > 0", s[6], P, tol);
    }

    load = 0.;
    load[3] = T; // torsion
    u = cantilever_tip(k, load);
    check("(3) tip torque: rx = T L/(G J)", u[3], T * L / (G * J), tol);
    {
      const std::array<double, 12> s = section_forces(k, full_displacement(u));
      check("(3) tip torque: end 1 T", s[3], T, tol);
    }

    // Euler-Bernoulli: shear area 0 (y) and infinity (z)
    FrameSection eb = section;
    eb.shear_area_y = 0.;
    eb.shear_area_z = std::numeric_limits<double>::infinity();
    const FullMatrix<double> k_eb = local_stiffness(L, eb, material);
    load = 0.;
    load[1] = P;
    u = cantilever_tip(k_eb, load);
    check("(3) Euler-Bernoulli (A_sy = 0): v = P L^3/(3 E Iz)",
          u[1],
          P * L * L * L / (3. * E * Iz),
          tol);
    load = 0.;
    load[2] = P;
    u = cantilever_tip(k_eb, load);
    check("(3) Euler-Bernoulli (A_sz = inf): w = P L^3/(3 E Iy)",
          u[2],
          P * L * L * L / (3. * E * Iy),
          tol);

    // skew member in global coordinates: load along the local y axis
    FullMatrix<double> kg22(6, 6);
    for (unsigned int i = 0; i < 6; ++i)
      for (unsigned int j = 0; j < 6; ++j)
        kg22(i, j) = kg(6 + i, 6 + j);
    kg22.gauss_jordan();
    Vector<double> fg(6), ug(6), u12(12);
    for (unsigned int d = 0; d < 3; ++d)
      fg[d] = P * R[1][d];
    kg22.vmult(ug, fg);
    for (unsigned int i = 0; i < 6; ++i)
      u12[6 + i] = ug[i];
    const Vector<double> ul = to_local(u12, R);
    check("(3) skew member, global solve, P along e_y: local v",
          ul[7],
          P * L * L * L / (3. * E * Iz) + P * L / (G * Asy),
          1e-10);
    check("(3) skew member, global solve, P along e_y: local rz",
          ul[11],
          P * L * L / (2. * E * Iz),
          1e-10);
    const Vector<double> back = to_global(ul, R);
    Vector<double> diff(back);
    diff -= u12;
    check("(3) to_global(to_local(u)) = u", diff.l2_norm(), 0., 1e-14, u12.l2_norm());
  }

  // (4) total translational mass per direction
  {
    const unsigned int trans[3][2] = {{0, 6}, {1, 7}, {2, 8}};
    const char *names[3] = {"x", "y", "z"};
    for (unsigned int d = 0; d < 3; ++d)
    {
      double sum = 0.;
      for (unsigned int a = 0; a < 2; ++a)
        for (unsigned int b = 0; b < 2; ++b)
          sum += m(trans[d][a], trans[d][b]);
      check(std::string("(4) consistent mass: sum of translational ") + names[d] +
                " block = rho A L",
            sum,
            rho * A * L,
            1e-13);
      check(std::string("(4) lumped mass: sum of translational ") + names[d] +
                " entries = rho A L",
            ml[trans[d][0]] + ml[trans[d][1]],
            rho * A * L,
            1e-14);
    }
    double min_lumped = ml[0];
    for (const double v : ml)
      min_lumped = std::min(min_lumped, v);
    expect(min_lumped > 0.,
           "(4) lumped mass strictly positive, min = " + std::to_string(min_lumped));
    check("(4) lumped rz = rho A L^3/78 + rho Iz L/2",
          ml[5],
          rho * A * L * L * L / 78. + rho * Iz * L / 2.,
          1e-14);
    check("(4) lumped ry = rho A L^3/78 + rho Iy L/2",
          ml[10],
          rho * A * L * L * L / 78. + rho * Iy * L / 2.,
          1e-14);
    check("(4) lumped rx = rho (Iy + Iz) L/2", ml[9], rho * (Iy + Iz) * L / 2., 1e-14);
    check("(4) consistent torsion mass rho (Iy + Iz) L/3",
          m(3, 3),
          rho * (Iy + Iz) * L / 3.,
          1e-14);
    check("(4) consistent axial coupling rho A L/6", m(0, 6), rho * A * L / 6., 1e-14);
  }

  // (5) shape functions and the stiffness integrated from them
  {
    // Phi = 0: cubic Hermite functions, Nt = dNv/dx
    double err_hermite = 0., err_rotation = 0.;
    for (const double xi : {0., 0.13, 0.5, 0.77, 1.})
    {
      const FrameBendingShapeFunctions N = frame_bending_shape_functions(xi, L, 0.);
      const double H[4] = {1. - 3. * xi * xi + 2. * xi * xi * xi,
                           L * xi * (1. - xi) * (1. - xi),
                           3. * xi * xi - 2. * xi * xi * xi,
                           L * xi * xi * (xi - 1.)};
      for (unsigned int i = 0; i < 4; ++i)
      {
        err_hermite = std::max(err_hermite, std::abs(N.Nv[i] - H[i]));
        err_rotation = std::max(err_rotation, std::abs(N.Nt[i] - N.dNv[i]));
      }
    }
    check("(5) Phi = 0: Nv = cubic Hermite", err_hermite, 0., 1e-14, 1.);
    check("(5) Phi = 0: Nt = dNv/dx", err_rotation, 0., 1e-14, 1.);

    // derivatives against central differences, Phi = 0.3
    double err_fd = 0.;
    const double h = 1e-6;
    for (const double xi : {0.1, 0.4, 0.9})
    {
      const auto N = frame_bending_shape_functions(xi, L, 0.3);
      const auto Np = frame_bending_shape_functions(xi + h, L, 0.3);
      const auto Nm = frame_bending_shape_functions(xi - h, L, 0.3);
      for (unsigned int i = 0; i < 4; ++i)
      {
        err_fd =
            std::max(err_fd, std::abs(N.dNv[i] - (Np.Nv[i] - Nm.Nv[i]) / (2. * h * L)));
        err_fd = std::max(err_fd,
                          std::abs(N.dNt[i] - (Np.Nt[i] - Nm.Nt[i]) / (2. * h * L)) * L);
      }
    }
    check("(5) Phi = 0.3: dNv/dx, L dNt/dx vs central differences", err_fd, 0., 1e-8, 1.);

    // stiffness by quadrature, Phi = 0.3 in both planes
    const double Phi = 0.3;
    FrameSection s = section;
    s.shear_area_y = 12. * E * Iz / (G * Phi * L * L);
    s.shear_area_z = 12. * E * Iy / (G * Phi * L * L);
    check(
        "(5) Phi_y set to 0.3", shear_parameter(E, Iz, G, s.shear_area_y, L), Phi, 1e-14);
    const FullMatrix<double> ks = local_stiffness(L, s, material);
    const FullMatrix<double> ms = local_consistent_mass(L, s, material);
    const QGauss<1> quadrature(5);
    for (const bool xz : {false, true})
    {
      const double EI = E * (xz ? Iy : Iz),
                   GAs = G * (xz ? s.shear_area_z : s.shear_area_y);
      FullMatrix<double> kq(4, 4);
      for (unsigned int q = 0; q < quadrature.size(); ++q)
      {
        const auto N = frame_bending_shape_functions(quadrature.point(q)[0], L, Phi);
        const double JxW = quadrature.weight(q) * L;
        for (unsigned int i = 0; i < 4; ++i)
          for (unsigned int j = 0; j < 4; ++j)
            kq(i, j) += (EI * N.dNt[i] * N.dNt[j] +
                         GAs * (N.dNv[i] - N.Nt[i]) * (N.dNv[j] - N.Nt[j])) *
                        JxW;
      }
      check_plane(std::string("(5) Phi = 0.3: quadrature stiffness = closed form, ") +
                      (xz ? "x-z plane" : "x-y plane"),
                  ks,
                  kq,
                  xz,
                  1e-13);
      // independent closed-form Timoshenko mass (Przemieniecki 1968)
      check_plane(std::string("(5) Phi = 0.3: consistent mass = Przemieniecki closed "
                              "form, ") +
                      (xz ? "x-z plane" : "x-y plane"),
                  ms,
                  przemieniecki_mass(rho * A, rho * (xz ? Iy : Iz), Phi, L),
                  xz,
                  1e-13);
    }
  }

  // (6) local frame
  {
    Tensor<2, 3> RRt = R * transpose(R);
    double err = 0.;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        err = std::max(err, std::abs(RRt[i][j] - (i == j ? 1. : 0.)));
    check("(6) R R^T = I", err, 0., 1e-14, 1.);
    check("(6) det R = 1", determinant(R), 1., 1e-15);
    check("(6) e_x = (x2 - x1)/L", (R[0] - dir).norm(), 0., 1e-14, 1.);
    check("(6) e_y orthogonal to e_x, in the plane of e_x and y_ref: e_z . y_ref",
          R[2] * y_ref,
          0.,
          1e-15,
          1.);
    check("(6) e_y . y_ref > 0", R[1] * y_ref > 0. ? 1. : 0., 1., 0.);

    Tensor<1, 3> X, Y;
    X[0] = 1.;
    Y[1] = 1.;
    const Tensor<2, 3> Rz = frame_rotation(Point<3>(1., 2., 3.), Point<3>(1., 2., 5.), X);
    check("(6) member along Z, y_reference = X: e_y = X",
          (Rz[1] - X).norm(),
          0.,
          1e-15,
          1.);
    check("(6) member along Z, y_reference = X: e_z = Y",
          (Rz[2] - Y).norm(),
          0.,
          1e-15,
          1.);
  }

  // (7) error paths
  {
    Tensor<1, 3> Z;
    Z[2] = 1.;
    expect(throws([&]() { frame_rotation(x1, x1, y_ref); }),
           "(7) zero-length member throws");
    expect(
        throws([&]() { frame_rotation(Point<3>(0., 0., 0.), Point<3>(0., 0., 2.), Z); }),
        "(7) y_reference parallel to the member throws");
    expect(throws([&]() { local_stiffness(0., section, material); }),
           "(7) local_stiffness with L = 0 throws");
    FrameSection thin = section;
    thin.Iy = thin.Iz = 0.;
    expect(throws([&]() { local_lumped_mass(L, thin, material); }),
           "(7) lumped mass with Iy + Iz = 0 throws (would not be positive)");
  }

  // (8) Euler-Bernoulli consistent mass, Phi = 0
  {
    FrameSection eb = section;
    eb.shear_area_y = 0.;
    eb.shear_area_z = 0.;
    eb.Iy = eb.Iz = 0.; // no rotary inertia
    const FullMatrix<double> me = local_consistent_mass(L, eb, material);
    const double c[4][4] = {{156., 22. * L, 54., -13. * L},
                            {22. * L, 4. * L * L, 13. * L, -3. * L * L},
                            {54., 13. * L, 156., -22. * L},
                            {-13. * L, -3. * L * L, -22. * L, 4. * L * L}};
    FullMatrix<double> classic(4, 4);
    for (unsigned int i = 0; i < 4; ++i)
      for (unsigned int j = 0; j < 4; ++j)
        classic(i, j) = rho * A * L / 420. * c[i][j];
    check_plane("(8) Phi = 0, I = 0: rho A L/420 [[156, 22L, 54, -13L], ...], x-y",
                me,
                classic,
                false,
                1e-14);
    check_plane("(8) Phi = 0, I = 0: rho A L/420 [[156, 22L, 54, -13L], ...], x-z",
                me,
                classic,
                true,
                1e-14);

    // with rotary inertia: + rho I/(30 L) [[36, 3L, -36, 3L], ...]
    eb.Iy = Iy;
    eb.Iz = Iz;
    const FullMatrix<double> mr = local_consistent_mass(L, eb, material);
    const double r[4][4] = {{36., 3. * L, -36., 3. * L},
                            {3. * L, 4. * L * L, -3. * L, -L * L},
                            {-36., -3. * L, 36., -3. * L},
                            {3. * L, -L * L, -3. * L, 4. * L * L}};
    for (const bool xz : {false, true})
    {
      FullMatrix<double> ref(classic);
      const double I = xz ? Iy : Iz;
      for (unsigned int i = 0; i < 4; ++i)
        for (unsigned int j = 0; j < 4; ++j)
          ref(i, j) += rho * I / (30. * L) * r[i][j];
      check_plane(std::string("(8) Phi = 0: Hermite + rotary rho I/(30L) [[36, 3L, "
                              "-36, 3L], ...], ") +
                      (xz ? "x-z" : "x-y"),
                  mr,
                  ref,
                  xz,
                  1e-14);
    }
  }

  // section helpers against tabulated / independent values
  {
    const FrameSection r = FrameSection::rectangle(0.1, 0.3);
    check("rectangle 0.1 x 0.3: A", r.A, 0.03, 1e-15);
    check("rectangle 0.1 x 0.3: Iz = h b^3/12", r.Iz, 0.3 * 1e-3 / 12., 1e-14);
    check("rectangle 0.1 x 0.3: Iy = b h^3/12", r.Iy, 0.1 * 0.027 / 12., 1e-14);
    check("rectangle 0.1 x 0.3: J vs tabulated 0.263 a b^3 (Timoshenko)",
          r.J,
          0.263 * 0.3 * 1e-3,
          5e-3);
    check("rectangle: shear area 5/6 A", r.shear_area_y, 5. / 6. * 0.03, 1e-15);
    const FrameSection sq = FrameSection::rectangle(0.2, 0.2);
    check("square 0.2: J vs tabulated 0.1406 a^4", sq.J, 0.1406 * 0.0016, 5e-3);

    const double b = 0.3, h = 0.5, tw = 0.012, tf = 0.02;
    const FrameSection bx = FrameSection::box(b, h, tw, tf);
    check("box: A = 2 b tf + 2 (h - 2 tf) tw",
          bx.A,
          2. * b * tf + 2. * (h - 2. * tf) * tw,
          1e-14);
    const double hw = h - 2. * tf;
    check("box: Iy by parallel axes (flanges + webs)",
          bx.Iy,
          2. * (b * tf * tf * tf / 12. + b * tf * std::pow(h / 2. - tf / 2., 2)) +
              2. * tw * hw * hw * hw / 12.,
          1e-13);
    check("box: Iz by parallel axes (webs + flanges)",
          bx.Iz,
          2. * (hw * tw * tw * tw / 12. + hw * tw * std::pow(b / 2. - tw / 2., 2)) +
              2. * tf * b * b * b / 12.,
          1e-13);
    const double bm = b - tw, hm = h - tf;
    check("box: J = 4 A_m^2 / oint ds/t (Bredt)",
          bx.J,
          4. * bm * bm * hm * hm / (2. * bm / tf + 2. * hm / tw),
          1e-14);
    const FrameSection tube = FrameSection::box(0.2, 0.2, 0.01, 0.01);
    check("square tube: J = t b_m^3", tube.J, 0.01 * std::pow(0.19, 3), 1e-14);
    check("box: A_sz = 2 t_web h_m (webs)", bx.shear_area_z, 2. * tw * hm, 1e-15);
    check("box: A_sy = 2 t_flange b_m (flanges)", bx.shear_area_y, 2. * tf * bm, 1e-15);
  }

  std::cout << (failures == 0 ? "all checks passed"
                              : std::to_string(failures) + " check(s) FAILED")
            << std::endl;
  return failures == 0 ? 0 : 1;
}
} // namespace hati_unit_frame_element
