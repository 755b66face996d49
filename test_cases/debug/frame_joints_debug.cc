// Frames with joints where three and four members meet, built and solved
// against deal.II's Debug library (its assertions check what the Release
// library accepts silently: deal.II 9.4 cannot share a vertex between three
// or more line cells, so hati ties separate member ends with constraints).
// Only the model library is built against the Debug library for this test
// (test_cases/CMakeLists.txt): the frame's mesh, DoFs, constraints and
// matrices, the part the assertions guard. The static solution K U = F is
// solved here with UMFPACK. References: hand solutions of the plane cross
// and the T-joint of parameter_files/frame_joints.prm (the checks of
// test_cases/frame_joints.py): four fixed-guided members meeting at C,
// w_C = -P L^3 / (48 E Iy) and no rotation; the T-joint's (w, ry) at C from
// its 2 x 2 stiffness [[36 EI/L^3, 6 EI/L^2], [6 EI/L^2, 4 EI/L + 2 GJ/L]].
#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/sparse_direct.h>

#include "../test_tools.h"

#include <hati/model/discrete_system.h>
#include <hati/model/frame.h>
#include <hati/model/frame_parser.h>

#include <cmath>
#include <iostream>

using namespace hati;
using namespace hati_test;

namespace
{

/** The static displacement of the monitor node C (ux, uy, uz, rx, ry, rz). */
std::vector<double> solve_frame(const std::string &members, const std::string &supports)
{
  ParameterHandler prm;
  FrameParameters::declare_parameters(prm);
  prm.parse_input_from_string(
      "set Nodes = C: 0, 0, 0; E: 2, 0, 0; W: -2, 0, 0; N: 0, 2, 0; S: 0, -2, 0\n"
      "set Materials = steel: 2.1e11, 0.3, 7850\n"
      "set Sections = s: general, 5e-3, 4.1666666666667e-6, 1.0416666666667e-6, "
      "2.86e-6, 0, 0\n"
      "set Members = " +
      members + "\nset Supports = " + supports +
      "\nset Nodal loads = C: 0, 0, -1000\nset Monitor nodes = C\n");
  FrameParameters parameters;
  parameters.parse_parameters(prm);
  Frame frame(parameters.description);
  CommonModelParameters common;
  common.gravity = Tensor<1, 3>();
  DiscreteSystem system;
  frame.build(common, system);
  Vector<double> U(system.n_dofs()), F(system.constant_force);
  SparseDirectUMFPACK solver;
  solver.initialize(system.stiffness);
  solver.vmult(U, F);
  std::vector<double> c;
  for (unsigned int i = 0; i < system.monitors[0].dofs.size(); ++i)
    c.push_back(system.monitors[0].value(i, U));
  return c;
}
} // namespace

int main()
{
  const double E = 2.1e11, nu = 0.3, G = E / (2. * (1. + nu));
  const double Iy = 4.1666666666667e-6, J = 2.86e-6, L = 2., P = 1000.;
  const auto cross = solve_frame(
      "east: C, E, s, steel, 3; west: C, W, s, steel, 3; north: C, N, s, steel, "
      "3; south: C, S, s, steel, 3",
      "E: clamped; W: clamped; N: clamped; S: clamped");
  const double w = -P * L * L * L / (48. * E * Iy);
  check("cross: w_C (m)", cross[2], w, 1e-9 * std::abs(w));
  check("cross: no rotation at C (rad)",
        std::abs(cross[3]) + std::abs(cross[4]),
        0.,
        1e-15);

  const auto tee = solve_frame(
      "east: C, E, s, steel, 3; north: C, N, s, steel, 3; south: C, S, s, steel, 3",
      "E: clamped; N: clamped; S: clamped");
  const double EI = E * Iy, a = 36. * EI / (L * L * L), b = 6. * EI / (L * L),
               d = 4. * EI / L + 2. * G * J / L, det = a * d - b * b;
  const double w_t = d * P / det, th_t = -b * P / det;
  check("T-joint: |w_C| (m)", std::abs(tee[2]), std::abs(w_t), 1e-9 * std::abs(w_t));
  check("T-joint: |ry_C| (rad)", std::abs(tee[4]), std::abs(th_t), 1e-9 * std::abs(th_t));
  check("T-joint: rx_C (rad)", tee[3], 0., 1e-15);
  return finish();
}
