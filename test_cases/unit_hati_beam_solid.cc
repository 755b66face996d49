// Stability of the coupling across a beam-to-solid tie (G3'', doc/theory.md
// 11.3): the spectral radius of one macro step of the real code path,
// HATICoupling::step(), applied to every unit state (the method of
// unit_hati_stability.cc and of the numpy prototype gc_beam_solid_macro.py,
// which measured <= 1 + 1.1e-10 for m = 1 ... 100). The model: beam 'a'
// clamped at A0 and tied at A1 to the end x = 0 of a solid prism 2 x 0.4 x
// 0.3 m (2 x 1 x 1 quadratic hexahedra), beam 'b' tied at B0 to its end
// x = 2, a point mass with rotary inertia at B1; beam 'b' explicit, the rest
// implicit: the tie at B0 crosses the interface (six general rows: +1 on
// the beam node's DoF, minus the B1 row on the face), the tie at A1 is
// eliminated in the implicit part. Then the reverse: the solid explicit,
// both beams implicit: both ties cross (twelve rows, general on the explicit
// side, C_E the face's B1 rows). Undamped, zero load: the radius must be
// <= 1 + 1e-9 for every m = 1 ... 50 (stable) and >= 1 - 1e-8 (no
// artificial damping of the coupled modes) each way round. The limit is the
// round-off of LAPACK's eigenvalues of this non-normal map: measured up to
// 1 + 1.1e-10 with numpy, 1 + 0.996e-10 with Debian's reference BLAS and
// 1 + 1.9e-10 (m = 21) with OpenBLAS; the unstable G3 variant gives 1.0006
// to 1.064 on a frame (unit_hati_stability.cc).
#include "test_tools.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <hati/base/mpi_environment.h>
#include <hati/model/decomposition.h>
#include <hati/run/problem.h>
#include <hati/time/hati_coupling.h>

#include <iomanip>
#include <iostream>

namespace hati_unit_hati_beam_solid
{

using namespace hati;

namespace
{
const char *const prm_text =
    "subsection Model\n  set Type = frame\n  subsection Frame\n"
    "    set Nodes = A0: -1, 0, 0; A1: 0, 0, 0; B0: 2, 0, 0; B1: 3, 0, 0\n"
    "    set Materials = steel: 2.1e11, 0.3, 7850\n"
    "    set Sections = rod: general, 1.2e-2, 2e-4, 1e-4, 2e-4, 5e-3, 5e-3\n"
    "    set Members = a: A0, A1, rod, steel, 2; b: B0, B1, rod, steel, 2\n"
    "    set Supports = A0: clamped\n"
    "    set Solids = prism: box, 0, -0.2, -0.15, 2, 0.2, 0.15, 2, 1, 1, steel\n"
    "    set Ties = ta: A1, prism, x=0; tb: B0, prism, x=2\n"
    "    set Point masses = B1: 200, 20, 20, 20\n"
    "  end\n  subsection Decomposition\n    set Explicit members = EXPLICIT\n  end\n"
    "end\nsubsection Loading\n  set Gravity = 0, 0, 0\nend\n"
    "subsection Time integration\n  set Method = HATI\nend\n";

double spectral_radius(HATICoupling &coupling)
{
  const unsigned int N = coupling.state_size();
  LAPACKFullMatrix<double> G(N, N);
  Vector<double> x(N), y(N);
  for (unsigned int k = 0; k < N; ++k)
  {
    x = 0.;
    x[k] = 1.;
    coupling.set_state(x);
    coupling.step();
    coupling.get_state(y);
    for (unsigned int i = 0; i < N; ++i)
      G(i, k) = y[i];
  }
  G.compute_eigenvalues();
  double rho = 0.;
  for (unsigned int i = 0; i < N; ++i)
    rho = std::max(rho, std::abs(G.eigenvalue(i)));
  return rho;
}
} // namespace

HATI_UNIT_TEST(hati_beam_solid)
{
  const hati::MpiEnvironment mpi_environment;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  unsigned int failures = 0;
  for (const std::string explicit_part : {"b", "prism"})
  {
    std::string text = prm_text;
    text.replace(text.find("EXPLICIT"), 8, explicit_part);
    ParameterHandler prm;
    Problem::declare_parameters(prm);
    prm.parse_input_from_string(text);
    Problem problem(prm, ConditionalOStream(std::cout, false));
    problem.build_system();
    problem.decompose();
    const Decomposition &decomposition = *problem.decomposition;
    const double dt_crit = 2. / decomposition.parts[0].system.highest_frequency_bound();
    std::cout << "explicit '" << explicit_part
              << "': " << decomposition.parts[0].system.n_dofs() << " DoFs, implicit "
              << decomposition.parts[1].system.n_dofs() << " DoFs, interface rows "
              << decomposition.n_interface_dofs() << ", dt_crit " << dt_crit << " s"
              << std::endl;
    // the face's side: implicit with the beam explicit, explicit with the solid
    const unsigned int face_side = explicit_part == "b" ? 1 : 0;
    unsigned int face_entries = 0;
    for (const auto &row : decomposition.rows[face_side])
      face_entries = std::max<unsigned int>(face_entries, row.dofs.size());
    const unsigned int n_rows = explicit_part == "b" ? 6 : 12;
    const bool rows_ok = decomposition.n_interface_dofs() == n_rows && face_entries > 1;
    failures += rows_ok ? 0 : 1;
    std::cout << (rows_ok ? "ok   " : "FAIL ") << n_rows
              << " interface rows, general on the face's side (up to " << face_entries
              << " face DoFs a row)" << std::endl;
    for (unsigned int m = 1; m <= 50; ++m)
    {
      HATIParameters parameters;
      parameters.time_step_ratio = m;
      HATICoupling coupling(decomposition,
                            problem.system.n_dofs(),
                            0.9 * dt_crit,
                            1.,
                            parameters,
                            NewmarkParameters());
      const double rho = spectral_radius(coupling);
      const bool ok = rho <= 1. + 1e-9 && rho >= 1. - 1e-8;
      failures += ok ? 0 : 1;
      std::cout << (ok ? "ok   " : "FAIL ") << "explicit '" << explicit_part
                << "', m = " << m << ": spectral radius " << std::setprecision(15) << rho
                << " (limit 1 + 1e-9, undamped: >= 1 - 1e-8)" << std::setprecision(6)
                << std::endl;
    }
  }
  std::cout << (failures ? std::to_string(failures) + " check(s) failed"
                         : std::string("all checks passed"))
            << std::endl;
  return failures == 0 ? 0 : 1;
}
} // namespace hati_unit_hati_beam_solid
