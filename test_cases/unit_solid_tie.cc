// The beam-to-solid tie (spec B1, doc/theory.md B1) and the solid element.
//
// 1. Face moments of the face x = 2 of the box [2, 4] x [-0.2, 0.2] x
//    [-0.15, 0.15] (FE_Q(2)^3, 4 x 2 x 2 cells) against the closed forms of a
//    0.4 x 0.3 rectangle: S = b h, G its centre, I_G = diag(b h (b^2 + h^2) /
//    12, b h^3 / 12, h b^3 / 12) (1e-12 relative).
// 2. Tie kinematics: a rigid translation c and a rigid rotation theta about a
//    point p of the face give the tied node P (off the centroid) U_P = c +
//    theta x (P - p) and theta exactly (1e-12).
// 3. The dual: the nodal forces of a beam force F and moment M at P = G are
//    the consistent loads of the traction t = F / S + (I_G^-1 M) x (x - G),
//    integrated here with the test's own face quadrature (1e-12 relative).
// 4. Patch tests through the one set-up path (Problem) and the static
//    solver: a prism (FE_Q(2), 4 x 2 x 2) tied at both ends to beams, one
//    clamped, the other loaded at its free end by an axial force, then by a
//    bending moment about y, then about z. Exact elasticity (a uniform
//    stress, pure bending: quadratic displacements, in FE_Q(2)): sigma_xx =
//    N / A, M_y z / I_y, -M_z y / I_z and every other component zero at every
//    quadrature point, to 1e-8 of the largest stress.
// 5. A box girder's end face (0.4 x 0.3 m, webs 12 mm, flanges 16 mm, end
//    diaphragms): whole, the full rectangle b h (the end diaphragm's face
//    and the walls' ends); with `walls`, the box section alone, S = b h -
//    b_i h_i and I_G = diag(I_y + I_z, I_y, I_z) with I_y = (b h^3 - b_i
//    h_i^3) / 12, I_z = (h b^3 - h_i b_i^3) / 12 (b_i = b - 2 t_w, h_i = h -
//    2 t_f; 1e-12 relative).
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>

#include <hati/analysis/static_analysis.h>
#include <hati/base/mpi_environment.h>
#include <hati/model/frame.h>
#include <hati/model/frame_solids.h>
#include <hati/model/solid_mesh.h>
#include <hati/model/solid_tie.h>
#include <hati/run/problem.h>

#include "test_tools.h"

#include <map>

namespace hati_unit_solid_tie
{

using namespace hati;
using hati_test::check;

namespace
{
constexpr double b = 0.4, h = 0.3;

/** U = sum_j rows[c][j] u_j. */
double row_times(const std::vector<std::pair<types::global_dof_index, double>> &row,
                 const Vector<double> &u)
{
  double s = 0.;
  for (const auto &[j, a] : row)
    s += a * u[j];
  return s;
}

void face_checks()
{
  Triangulation<3> tria;
  GridGenerator::subdivided_hyper_rectangle(
      tria, {4, 2, 2}, Point<3>(2., -0.5 * b, -0.5 * h), Point<3>(4., 0.5 * b, 0.5 * h));
  FESystem<3> fe(FE_Q<3>(2), 3);
  DoFHandler<3> dofs(tria);
  dofs.distribute_dofs(fe);
  SolidDescription::FacePlane plane;
  plane.axis = 0;
  plane.value = 2.;
  const FaceMoments face = face_moments(dofs, 0, plane, Point<3>(), 1e-9, 0);
  std::cout << "face x = 2: " << face.n_faces << " cell faces, " << face.dofs.size()
            << " DoFs" << std::endl;
  check("S (m^2)", face.area, b * h, 1e-12 * b * h);
  check("G_x (m)", face.centroid[0], 2., 1e-12);
  check("G_y (m)", face.centroid[1], 0., 1e-12);
  check("G_z (m)", face.centroid[2], 0., 1e-12);
  const double Iyy = b * h * h * h / 12., Izz = h * b * b * b / 12.;
  check("I_G xx (m^4)", face.inertia[0][0], Iyy + Izz, 1e-12 * (Iyy + Izz));
  check("I_G yy (m^4)", face.inertia[1][1], Iyy, 1e-12 * Iyy);
  check("I_G zz (m^4)", face.inertia[2][2], Izz, 1e-12 * Izz);
  check("I_G yz (m^4)", face.inertia[1][2], 0., 1e-12 * Izz);

  // rigid motions of the whole solid, read by the tie rows of a node off G
  std::map<types::global_dof_index, Point<3>> points;
  DoFTools::map_dofs_to_support_points(MappingQ1<3>(), dofs, points);
  const Point<3> P(2., 0.05, -0.03), p(1., 0.3, -0.2);
  const auto rows = tie_rows(face, P, "test");
  const Tensor<1, 3> c({0.5, -0.2, 0.9}), theta({0.3, -0.7, 1.1});
  Vector<double> translation(dofs.n_dofs()), rotation(dofs.n_dofs());
  std::vector<unsigned int> component(dofs.n_dofs());
  {
    std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dofs.active_cell_iterators())
    {
      cell->get_dof_indices(cell_dofs);
      for (unsigned int i = 0; i < cell_dofs.size(); ++i)
        component[cell_dofs[i]] = fe.system_to_component_index(i).first;
    }
  }
  for (const auto &[j, x] : points)
  {
    translation[j] = c[component[j]];
    rotation[j] = cross_product_3d(theta, x - p)[component[j]];
  }
  const Tensor<1, 3> U_rotation = cross_product_3d(theta, P - p);
  double e_translation = 0., e_rotation = 0.;
  for (unsigned int k = 0; k < 3; ++k)
  {
    e_translation = std::max({e_translation,
                              std::abs(row_times(rows[k], translation) - c[k]),
                              std::abs(row_times(rows[3 + k], translation))});
    e_rotation = std::max({e_rotation,
                           std::abs(row_times(rows[k], rotation) - U_rotation[k]),
                           std::abs(row_times(rows[3 + k], rotation) - theta[k])});
  }
  check("rigid translation -> (c, 0), largest error", e_translation, 0., 1e-12);
  check("rigid rotation about p -> (theta x (P - p), theta), largest error",
        e_rotation,
        0.,
        1e-12);

  // the dual at P = G: f_j = C^T (F, M) against int N_j t dS
  const auto rows_G = tie_rows(face, face.centroid, "test");
  const Tensor<1, 3> F({2e4, 1e4, -3e4}), M({5e3, -4e3, 6e3});
  std::map<types::global_dof_index, double> f;
  for (unsigned int k = 0; k < 3; ++k)
  {
    for (const auto &[j, a] : rows_G[k])
      f[j] += a * F[k];
    for (const auto &[j, a] : rows_G[3 + k])
      f[j] += a * M[k];
  }
  const Tensor<1, 3> w = invert(face.inertia) * M;
  std::map<types::global_dof_index, double> consistent;
  const QGauss<2> quadrature(4);
  FEFaceValues<3> values(
      fe, quadrature, update_values | update_quadrature_points | update_JxW_values);
  std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
  for (const auto &cell : dofs.active_cell_iterators())
    for (const unsigned int fi : cell->face_indices())
      if (cell->face(fi)->at_boundary() &&
          std::abs(cell->face(fi)->center()[0] - 2.) < 1e-12)
      {
        values.reinit(cell, fi);
        cell->get_dof_indices(cell_dofs);
        for (unsigned int q = 0; q < quadrature.size(); ++q)
        {
          const Tensor<1, 3> t =
              F / (b * h) +
              cross_product_3d(w, values.quadrature_point(q) - face.centroid);
          for (unsigned int i = 0; i < cell_dofs.size(); ++i)
            consistent[cell_dofs[i]] += values.shape_value(i, q) *
                                        t[fe.system_to_component_index(i).first] *
                                        values.JxW(q);
        }
      }
  double e_force = 0., largest = 0.;
  for (const auto &[j, value] : consistent)
  {
    largest = std::max(largest, std::abs(value));
    e_force = std::max(e_force, std::abs(value - (f.count(j) ? f[j] : 0.)));
  }
  check("nodal forces of (F, M) against int N_j (F / S + (I_G^-1 M) x r) dS, relative",
        e_force / largest,
        0.,
        1e-12);
}

std::string prism_prm(const std::string &load)
{
  return "subsection Analysis\n  set Type = static\nend\n"
         "subsection Model\n  set Type = frame\n  subsection Frame\n"
         "    set Nodes = A0: -1, 0, 0; A1: 0, 0, 0; B0: 2, 0, 0; B1: 3, 0, 0\n"
         "    set Materials = steel: 2.1e11, 0.3, 7850\n"
         "    set Sections = rod: general, 1.2e-2, 2e-4, 1e-4, 2e-4, 5e-3, 5e-3\n"
         "    set Members = a: A0, A1, rod, steel, 2; b: B0, B1, rod, steel, 2\n"
         "    set Supports = A0: clamped\n"
         "    set Solids = prism: box, 0, -0.2, -0.15, 2, 0.2, 0.15, 4, 2, 2, steel\n"
         "    set Ties = ta: A1, prism, x=0; tb: B0, prism, x=2\n"
         "    set Nodal loads = B1: " +
         load +
         "\n  end\nend\n"
         "subsection Loading\n  set Gravity = 0, 0, 0\nend\n";
}

/**
 * The static patch test with the load @p load at B1: the largest deviation
 * of the stresses from @p exact (sigma_xx at a point), relative to the largest
 * stress.
 */
void patch_test(const std::string &name,
                const std::string &load,
                const std::function<double(const Point<3> &)> &exact)
{
  ParameterHandler prm;
  Problem::declare_parameters(prm);
  prm.parse_input_from_string(prism_prm(load));
  Problem problem(prm, ConditionalOStream(std::cout, false));
  problem.build_system();
  Vector<double> U(problem.system.n_dofs());
  solve_static(problem.system, 0., U);
  const auto *frame = dynamic_cast<const Frame *>(problem.model.get());
  std::vector<SymmetricTensor<2, 3>> stress;
  std::vector<Point<3>> points;
  frame->solid_part()->stresses(U, stress, points);
  double largest = 0., error = 0.;
  for (unsigned int q = 0; q < stress.size(); ++q)
  {
    SymmetricTensor<2, 3> reference;
    reference[0][0] = exact(points[q]);
    largest = std::max(largest, std::abs(reference[0][0]));
    error = std::max(error, (stress[q] - reference).norm());
  }
  std::cout << name << ": " << stress.size() << " quadrature points, largest stress "
            << largest << " Pa" << std::endl;
  check(name + ": largest |sigma - sigma_exact| / max |sigma_exact|",
        error / largest,
        0.,
        1e-8);
}
/** 5: the end face of a box girder, whole and its walls alone. */
void box_girder_walls()
{
  SolidDescription d;
  SolidDescription::Solid g;
  g.name = "g";
  g.kind = "box girder";
  g.x0 = Point<3>(0., 0., 0.);
  g.x1 = Point<3>(2., 0., 0.);
  g.width = b;
  g.height = h;
  g.web_thickness = 0.012;
  g.flange_thickness = 0.016;
  g.element_size = 0.1;
  g.diaphragm_spacing = 1.;
  g.material = "steel";
  d.solids.push_back(g);
  Triangulation<3> tria;
  create_solid_mesh(d, tria);
  FESystem<3> fe(FE_Q<3>(2), 3);
  DoFHandler<3> dofs(tria);
  dofs.distribute_dofs(fe);
  SolidDescription::FacePlane plane;
  plane.axis = 0;
  plane.value = 2.;
  const FaceMoments whole = face_moments(dofs, 0, plane, Point<3>(), 1e-9, 0);
  check("box girder end face, whole: S (m^2) = b h", whole.area, b * h, 1e-12 * b * h);
  const FaceMoments walls =
      face_moments(dofs,
                   0,
                   plane,
                   Point<3>(),
                   1e-9,
                   0,
                   [&](const Point<3> &x) { return in_box_girder_hollow(g, x, 1e-9); });
  const double bi = b - 2. * g.web_thickness, hi = h - 2. * g.flange_thickness;
  const double A = b * h - bi * hi, Iy = (b * h * h * h - bi * hi * hi * hi) / 12.,
               Iz = (h * b * b * b - hi * bi * bi * bi) / 12.;
  std::cout << "box girder end face: " << whole.n_faces << " cell faces, the walls "
            << walls.n_faces << std::endl;
  check("walls: S (m^2) = b h - b_i h_i", walls.area, A, 1e-12 * A);
  check("walls: G_y (m)", walls.centroid[1], 0., 1e-12);
  check("walls: G_z (m)", walls.centroid[2], 0., 1e-12);
  check("walls: I_G xx (m^4)", walls.inertia[0][0], Iy + Iz, 1e-12 * (Iy + Iz));
  check("walls: I_G yy (m^4) = I_y of the box", walls.inertia[1][1], Iy, 1e-12 * Iy);
  check("walls: I_G zz (m^4) = I_z of the box", walls.inertia[2][2], Iz, 1e-12 * Iz);
}
} // namespace

HATI_UNIT_TEST(solid_tie)
{
  const hati::MpiEnvironment mpi_environment;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try
  {
    face_checks();
    box_girder_walls();
    const double A = b * h, Iy = b * h * h * h / 12., Iz = h * b * b * b / 12.;
    patch_test("axial force N = 1e5 N",
               "1e5, 0, 0, 0, 0, 0",
               [&](const Point<3> &) { return 1e5 / A; });
    patch_test("moment M_y = 2e4 N m",
               "0, 0, 0, 0, 2e4, 0",
               [&](const Point<3> &x) { return 2e4 * x[2] / Iy; });
    patch_test("moment M_z = 3e4 N m",
               "0, 0, 0, 0, 0, 3e4",
               [&](const Point<3> &x) { return -3e4 * x[1] / Iz; });
  }
  catch (const std::exception &e)
  {
    std::cout << "FAIL exception: " << hati_test::message_of(e) << std::endl;
    return 1;
  }
  return hati_test::finish();
}
} // namespace hati_unit_solid_tie
