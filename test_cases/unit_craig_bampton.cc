// Craig-Bampton reduction (C1, doc/theory.md 12.1) of the box-girder
// cantilever of parameter_files/box_girder_cantilever.prm (a 6 m box girder
// of FE_Q(2) plates clamped at x = 0, a beam stub tied to its tip face,
// 10 kN down at the stub's node), coarse plates (0.6 m). The boundary DoFs
// are the DoFs that carry the tip load (C1: the DoFs with a point load).
// References, independent of the reduction:
// - the static solution K U = F of the unreduced system (one sparse direct
//   solve): the constraint modes make the reduced one exact for loads on
//   the boundary DoFs (1e-8 of the largest displacement);
// - the unreduced free-interface frequencies (compute_modes() on the whole
//   system): the reduced ones below half the cut-off within 0.5 %, and above
//   them, never below (the reduced model is a Rayleigh-Ritz one);
// - the fixed-interface frequencies of the modes kept: the modal block of
//   (K_r, M_r) gives them back to 1e-6 (the reduced matrices assembled
//   right), and that block of M_r is the identity (mass-normalised modes);
// - a cut-off beyond Reduction maximum modes is refused, naming it;
// - spectrum slicing (Lanczos runs of few modes around successive shifts):
//   the fixed-interface modes against one Lanczos run of all of them
//   (compute_modes() with the boundary rows held), frequencies 1e-8
//   relative, the kept modes M-orthonormal (1e-8) and K-orthogonal, on the
//   box girder and on a cantilever of square box section whose bending
//   modes come in exact pairs (several run sizes: with 4 modes per run the
//   first slice ends inside the pair at 185.9 Hz);
// - modal damping of the reduced part (Reduction modal damping ratio,
//   doc/theory.md 12.3), zeta = 0.05: the eigenvalues of the damped reduced
//   system's state-space matrix (LAPACK's nonsymmetric solver, not the
//   construction's symmetric one) have the ratio -Re/|lambda| = zeta in every
//   mode and |lambda| equal to the undamped frequencies (1e-6: measured
//   4e-9 and 9e-8, the nonsymmetric solver's round-off on a spectrum spread
//   over three decades); and
//   Newmark on the reduced part, from the first mode's shape about the static
//   state, one damped period later: the modal amplitude
//   exp(-2 pi zeta / sqrt(1 - zeta^2)) of the damped oscillator (within
//   1e-4, measured 1.3e-5: Newmark's period error at 400 steps a period is
//   2e-5; without the damping matrix in Newmark the ratio would be 1/0.73).
#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include "test_tools.h"

#include <hati/analysis/craig_bampton.h>
#include <hati/analysis/modal_analysis.h>
#include <hati/analysis/reduced_part.h>
#include <hati/base/mpi_environment.h>
#include <hati/linear_algebra/direct_solver.h>
#include <hati/model/decomposition.h>
#include <hati/run/problem.h>
#include <hati/time/newmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <iostream>

namespace hati_unit_craig_bampton
{

using namespace hati;
using namespace hati_test;

namespace
{
const char *const prm_text =
    "subsection Model\n  set Type = frame\n  subsection Frame\n"
    "    set Nodes = tip: 6, 0, 0; stub: 6.1, 0, 0\n"
    "    set Materials = steel: 2.1e11, 0.3, 7850; light: 2.1e11, 0.3, 1\n"
    "    set Sections = box: box, 0.4, 0.6, 0.012, 0.016\n"
    "    set Members = stub: tip, stub, box, light, 1, 0, 1, 0\n"
    "    set Solids = girder: box girder, 0, 0, 0, 6, 0, 0, 0.4, 0.6, 0.012, 0.016, "
    "0.6, steel, 6\n"
    "    set Solid element degree = 2\n"
    "    set Solid supports = girder: x=0\n"
    "    set Ties = end: tip, girder, x=6\n"
    "    set Nodal loads = tip: 0, 0, -10000\n"
    "  end\nend\n"
    "subsection Loading\n  set Gravity = 0, 0, 0\nend\n"
    "subsection Time integration\n  set Method = Newmark\nend\n";

/**
 * The implicit side of the tie (the stub explicit, HATI): the reduction on
 * its six B1 rows L (G3''). References: the unreduced static solution
 * under an interface force L^T f (1e-8), L Psi = I, and the unreduced
 * free-interface frequencies of the part (0.5 % below half the cut-off).
 */
void check_tie_rows()
{
  std::string text = prm_text;
  text.replace(text.find("Method = Newmark"), 16, "Method = HATI");
  text.replace(text.find("  end\nend\n"),
               10,
               "  end\n  subsection Decomposition\n    set Explicit members = stub\n"
               "  end\nend\n");
  ParameterHandler prm;
  Problem::declare_parameters(prm);
  prm.parse_input_from_string(text);
  Problem problem(prm, ConditionalOStream(std::cout, false));
  problem.build_system();
  problem.decompose();
  const Decomposition &decomposition = *problem.decomposition;
  const DiscreteSystem &system = decomposition.parts[1].system;
  std::vector<SparseRow> rows = decomposition.rows[1];
  const unsigned int n = system.n_dofs(), nb = rows.size();
  expect(nb == 6, "six interface rows (one tie)");
  expect(system.has_consistent_mass(), "the implicit part has a consistent mass");
  unsigned int face_entries = 0;
  for (const SparseRow &row : rows)
    face_entries = std::max<unsigned int>(face_entries, row.dofs.size());
  CraigBamptonSettings settings;
  settings.cutoff_frequency = 400.;
  const CraigBamptonReduction reduction(system, rows, settings);
  std::cout << "tie rows: " << n << " DoFs, " << nb << " rows of up to " << face_entries
            << " face DoFs, " << reduction.n_modes() << " modes" << std::endl;

  double identity_error = 0.;
  for (unsigned int k = 0; k < nb; ++k)
    for (unsigned int l = 0; l < nb; ++l)
      identity_error = std::max(identity_error,
                                std::abs(rows[k].apply(reduction.column(l)) - (k == l)));
  check("tie rows: L Psi against the identity", identity_error, 0., 1e-10);

  // an interface force L^T f: unreduced K U = L^T f against K_r q = (f, 0)
  const std::array<double, 6> f = {{1e3, -2e3, -1e4, 5e2, -3e3, 4e2}};
  Vector<double> F(n), U(n);
  for (unsigned int k = 0; k < nb; ++k)
    for (unsigned int j = 0; j < rows[k].dofs.size(); ++j)
      F[rows[k].dofs[j]] += f[k] * rows[k].coefficients[j];
  DirectSolver solver(direct_solver_package("auto", n));
  solver.factorize(system.stiffness, "static solve");
  solver.solve(U, F);
  Vector<double> residual(n), correction(n);
  system.stiffness.vmult(residual, U);
  residual.sadd(-1., F);
  solver.solve(correction, residual);
  U += correction;
  const unsigned int r = reduction.size();
  Vector<double> Fr, q(r), Ur(n);
  reduction.project(F, Fr);
  double projection_error = 0.;
  for (unsigned int k = 0; k < r; ++k)
    projection_error = std::max(projection_error, std::abs(Fr[k] - (k < nb ? f[k] : 0.)));
  check(
      "tie rows: T^T L^T f against (f, 0), relative", projection_error / 1e4, 0., 1e-10);
  LAPACKFullMatrix<double> Kr(r, r);
  Kr = reduction.stiffness();
  Kr.compute_lu_factorization();
  q = Fr;
  Kr.solve(q);
  reduction.expand(q, Ur);
  Ur -= U;
  check("tie rows: static solution, max |U_r - U| / max |U|",
        Ur.linfty_norm() / U.linfty_norm(),
        0.,
        1e-8);

  const std::vector<double> reduced = reduction.frequencies(r);
  const ModalResult full = compute_modes(system, 6, false);
  for (unsigned int k = 0; k < full.frequencies.size(); ++k)
    if (full.frequencies[k] < 0.5 * settings.cutoff_frequency)
      check("tie rows: mode " + std::to_string(k + 1) + " relative difference",
            (reduced[k] - full.frequencies[k]) / full.frequencies[k],
            0.,
            5e-3);
}

/**
 * The fixed-interface modes of @p system on @p rows up to @p cutoff (Hz),
 * sliced in Lanczos runs of @p per_run modes, against one run of all of
 * them: the same count, frequencies within 1e-8 relative, the modal block
 * of M_r the identity and that of K_r diagonal (1e-8 of its largest entry).
 * Returns the number of double eigenvalues below the cut-off.
 */
unsigned int check_slicing(const std::string &name,
                           const DiscreteSystem &system,
                           const std::vector<SparseRow> &rows,
                           const double cutoff,
                           const unsigned int per_run)
{
  CraigBamptonSettings settings;
  settings.cutoff_frequency = cutoff;
  settings.modes_per_run = per_run;
  const CraigBamptonReduction reduction(system, rows, settings);
  const std::vector<double> &f = reduction.fixed_interface_frequencies();
  const unsigned int nb = reduction.n_boundary(), nm = reduction.n_modes();
  const std::string what = name + ", " + std::to_string(per_run) + " modes per run: ";
  std::cout << what << nm << " modes up to " << cutoff << " Hz in "
            << reduction.lanczos_runs() << " Lanczos runs" << std::endl;
  expect(reduction.lanczos_runs() >= 3, what + "at least three Lanczos runs");

  // the reference: one run with a few modes above the cut-off
  const ModalResult single = compute_modes(system, nm + 4, false, nullptr, "auto", &rows);
  unsigned int n_reference = 0, n_pairs = 0;
  for (unsigned int k = 0; k < single.frequencies.size(); ++k)
  {
    n_reference += single.frequencies[k] <= cutoff;
    if (k > 0 && single.frequencies[k] <= cutoff &&
        single.frequencies[k] - single.frequencies[k - 1] < 1e-8 * single.frequencies[k])
      ++n_pairs;
  }
  std::cout << "  single run: " << n_reference << " modes up to " << cutoff << " Hz, "
            << n_pairs << " double eigenvalues" << std::endl;
  expect(nm == n_reference, what + "as many modes as the single run");
  double frequency_error = 0.;
  for (unsigned int k = 0; k < std::min(nm, n_reference); ++k)
    frequency_error = std::max(
        frequency_error, std::abs(f[k] - single.frequencies[k]) / single.frequencies[k]);
  check(what + "frequencies against the single run, relative", frequency_error, 0., 1e-8);

  double mass_error = 0., coupling = 0., largest = 0.;
  for (unsigned int a = 0; a < nm; ++a)
  {
    largest = std::max(largest, reduction.stiffness()(nb + a, nb + a));
    for (unsigned int b = 0; b < nm; ++b)
    {
      mass_error = std::max(
          mass_error, std::abs(reduction.mass()(nb + a, nb + b) - (a == b ? 1. : 0.)));
      if (a != b)
        coupling = std::max(coupling, std::abs(reduction.stiffness()(nb + a, nb + b)));
    }
  }
  check(what + "modal block of M_r against the identity", mass_error, 0., 1e-8);
  check(what + "off-diagonal modal block of K_r, relative", coupling / largest, 0., 1e-8);
  return n_pairs;
}

/**
 * A cantilever of square box section (40 beam elements, 4 m), its tip's
 * translations the boundary DoFs (held: clamped-pinned both ways): its
 * bending modes come in exact pairs.
 */
void check_slicing_with_pairs()
{
  const char *const text = "subsection Model\n  set Type = frame\n  subsection Frame\n"
                           "    set Nodes = A: 0, 0, 0; B: 4, 0, 0\n"
                           "    set Materials = steel: 2.1e11, 0.3, 7850\n"
                           "    set Sections = square: box, 0.2, 0.2, 0.01, 0.01\n"
                           "    set Members = beam: A, B, square, steel, 40\n"
                           "    set Supports = A: clamped\n"
                           "    set Nodal loads = B: 1000, 1000, 1000\n"
                           "  end\nend\n"
                           "subsection Loading\n  set Gravity = 0, 0, 0\nend\n"
                           "subsection Time integration\n  set Method = Newmark\nend\n";
  ParameterHandler prm;
  Problem::declare_parameters(prm);
  prm.parse_input_from_string(text);
  Problem problem(prm, ConditionalOStream(std::cout, false));
  problem.build_system();
  const DiscreteSystem &system = problem.system;
  std::vector<unsigned int> boundary;
  for (unsigned int i = 0; i < system.n_dofs(); ++i)
    if (system.constant_force[i] != 0. && !system.fixed[i])
      boundary.push_back(i);
  expect(boundary.size() == 3, "square cantilever: three boundary DoFs (the tip's)");
  for (const unsigned int per_run : {4u, 5u, 7u, 16u})
  {
    const unsigned int n_pairs =
        check_slicing("square cantilever", system, unit_rows(boundary), 3000., per_run);
    expect(n_pairs >= 5, "square cantilever: double eigenvalues below the cut-off");
  }
}

/** The modal damping of the reduced part (see the file's comment). */
void check_modal_damping(const DiscreteSystem &system,
                         const std::vector<unsigned int> &boundary)
{
  CraigBamptonSettings settings;
  settings.cutoff_frequency = 400.;
  ReducedImplicitPart part(system, unit_rows(boundary), settings);
  const double zeta = 0.05;
  part.set_modal_damping(zeta);
  const DiscreteSystem &s = part.system();
  const unsigned int r = s.n_dofs();
  expect(s.has_damping_matrix(), "the reduced part has a damping matrix");
  // state space [0 I; -M^-1 K, -M^-1 C]
  FullMatrix<double> M(r, r), K(r, r), C(r, r), MK(r, r), MC(r, r);
  M.copy_from(s.consistent_mass);
  K.copy_from(s.stiffness);
  C.copy_from(s.damping_matrix);
  FullMatrix<double> M_inverse(r, r);
  M_inverse.invert(M);
  M_inverse.mmult(MK, K);
  M_inverse.mmult(MC, C);
  LAPACKFullMatrix<double> A(2 * r, 2 * r);
  for (unsigned int i = 0; i < r; ++i)
  {
    A(i, r + i) = 1.;
    for (unsigned int j = 0; j < r; ++j)
    {
      A(r + i, j) = -MK(i, j);
      A(r + i, r + j) = -MC(i, j);
    }
  }
  A.compute_eigenvalues();
  std::vector<double> omega;
  double ratio_error = 0.;
  for (unsigned int k = 0; k < 2 * r; ++k)
  {
    const std::complex<double> lambda = A.eigenvalue(k);
    if (lambda.imag() <= 0.)
      continue;
    omega.push_back(std::abs(lambda));
    ratio_error =
        std::max(ratio_error, std::abs(-lambda.real() / std::abs(lambda) - zeta));
  }
  std::sort(omega.begin(), omega.end());
  expect(omega.size() == r, "every mode of the reduced part is underdamped (r pairs)");
  check("modal damping: largest |ratio - zeta| over the modes", ratio_error, 0., 1e-6);
  const std::vector<double> undamped = part.reduction().frequencies(r);
  double frequency_error = 0.;
  for (unsigned int k = 0; k < std::min<std::size_t>(r, omega.size()); ++k)
    frequency_error =
        std::max(frequency_error, std::abs(omega[k] / (2. * M_PI) / undamped[k] - 1.));
  check(
      "modal damping: |lambda| / undamped omega - 1, largest", frequency_error, 0., 1e-6);

  // Newmark: free decay of the first mode about the static state
  LAPACKFullMatrix<double> Ks(r, r), Ms(r, r);
  Ks = K;
  Ms = M;
  std::vector<Vector<double>> Z(r, Vector<double>(r));
  Ks.compute_generalized_eigenvalues_symmetric(Ms, Z);
  unsigned int first = 0;
  for (unsigned int k = 1; k < r; ++k)
    if (Ks.eigenvalue(k).real() < Ks.eigenvalue(first).real())
      first = k;
  const double w = std::sqrt(Ks.eigenvalue(first).real());
  const double period = 2. * M_PI / (w * std::sqrt(1. - zeta * zeta));
  const unsigned int steps = 400;
  NewmarkParameters parameters;
  parameters.mass = "consistent";
  Newmark newmark(s, period / steps, parameters, RayleighDamping(), MaxwellBranches());
  Vector<double> q_static(r), U0(r), V0(r);
  LAPACKFullMatrix<double> Klu(r, r);
  Klu = K;
  Klu.compute_lu_factorization();
  q_static = s.constant_force;
  Klu.solve(q_static);
  U0 = q_static;
  U0 += Z[first];
  newmark.set_initial_state(U0, V0);
  for (unsigned int n = 0; n < steps; ++n)
    newmark.step();
  Vector<double> deviation(newmark.displacement()), Md(r);
  deviation -= q_static;
  M.vmult(Md, deviation);
  const double amplitude = Z[first] * Md; // Z^T M Z = I
  check("Newmark free decay of mode 1 over a damped period / exp(-2 pi zeta / "
        "sqrt(1 - zeta^2))",
        amplitude / std::exp(-2. * M_PI * zeta / std::sqrt(1. - zeta * zeta)),
        1.,
        1e-4);
}
} // namespace

HATI_UNIT_TEST(craig_bampton)
{
  const hati::MpiEnvironment mpi_environment;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  ParameterHandler prm;
  Problem::declare_parameters(prm);
  prm.parse_input_from_string(prm_text);
  Problem problem(prm, ConditionalOStream(std::cout, false));
  problem.build_system();
  const DiscreteSystem &system = problem.system;
  const unsigned int n = system.n_dofs();
  expect(system.has_consistent_mass(), "the system has a consistent mass");

  std::vector<unsigned int> boundary;
  for (unsigned int i = 0; i < n; ++i)
    if (system.constant_force[i] != 0. && !system.fixed[i])
      boundary.push_back(i);
  std::cout << n << " DoFs, " << boundary.size() << " boundary DoFs (the tip load's)"
            << std::endl;
  expect(!boundary.empty(), "the tip load acts on free DoFs");

  CraigBamptonSettings settings;
  settings.cutoff_frequency = 400.;
  const CraigBamptonReduction reduction(system, unit_rows(boundary), settings);
  std::cout << reduction.n_modes() << " fixed-interface modes up to "
            << settings.cutoff_frequency << " Hz (highest kept "
            << reduction.fixed_interface_frequencies().back() << " Hz), set-up "
            << reduction.set_up_time() << " s" << std::endl;
  expect(reduction.n_modes() >= 4, "at least four modes below the cut-off");

  // statics: K U = F unreduced against K_r q = T^T F, U = T q
  Vector<double> U(n), F(system.constant_force);
  {
    DirectSolver solver(direct_solver_package("auto", n));
    solver.factorize(system.stiffness, "static solve");
    solver.solve(U, F);
    Vector<double> residual(n), correction(n); // one step of iterative refinement
    system.stiffness.vmult(residual, U);
    residual.sadd(-1., F);
    solver.solve(correction, residual);
    U += correction;
  }
  const unsigned int r = reduction.size();
  Vector<double> Fr, q(r), Ur(n);
  reduction.project(F, Fr);
  LAPACKFullMatrix<double> Kr(r, r);
  Kr = reduction.stiffness();
  Kr.compute_lu_factorization();
  q = Fr;
  Kr.solve(q);
  {
    Vector<double> residual(r); // one step of iterative refinement
    reduction.stiffness().vmult(residual, q);
    residual.sadd(-1., Fr);
    Kr.solve(residual);
    q += residual;
  }
  reduction.expand(q, Ur);
  // both solutions have residuals at round-off (|K U - F| ~ 1e-8 |F|);
  // they differ by the plates' conditioning times that: measured 1.9e-9
  Ur -= U;
  check("static solution, max |U_r - U| / max |U|",
        Ur.linfty_norm() / U.linfty_norm(),
        0.,
        1e-8);

  // fixed-interface modes: the modal block of (K_r, M_r)
  const unsigned int nb = reduction.n_boundary(), nm = reduction.n_modes();
  double identity_error = 0., frequency_error = 0.;
  for (unsigned int a = 0; a < nm; ++a)
    for (unsigned int b = 0; b < nm; ++b)
    {
      identity_error =
          std::max(identity_error,
                   std::abs(reduction.mass()(nb + a, nb + b) - (a == b ? 1. : 0.)));
      if (a == b)
      {
        const double f = std::sqrt(reduction.stiffness()(nb + a, nb + a)) / (2. * M_PI);
        const double f0 = reduction.fixed_interface_frequencies()[a];
        frequency_error = std::max(frequency_error, std::abs(f - f0) / f0);
      }
    }
  check("modal block of M_r against the identity", identity_error, 0., 1e-8);
  check("fixed-interface frequencies from K_r, relative", frequency_error, 0., 1e-6);

  // free-interface frequencies against the unreduced system's
  const std::vector<double> reduced = reduction.frequencies(r);
  const ModalResult full = compute_modes(system, 8, false);
  unsigned int compared = 0;
  for (unsigned int k = 0; k < full.frequencies.size(); ++k)
  {
    const double f = full.frequencies[k], fr = reduced[k];
    std::cout << "  mode " << k + 1 << ": unreduced " << f << " Hz, reduced " << fr
              << " Hz" << std::endl;
    expect(fr >= f * (1. - 1e-9),
           "mode " + std::to_string(k + 1) + ": reduced not below");
    if (f < 0.5 * settings.cutoff_frequency)
    {
      check("mode " + std::to_string(k + 1) + " relative difference",
            (fr - f) / f,
            0.,
            5e-3);
      ++compared;
    }
  }
  expect(compared >= 3, "at least three modes compared below half the cut-off");

  // a cut-off that needs more modes than allowed is refused
  CraigBamptonSettings few = settings;
  few.maximum_modes = 2;
  try
  {
    const CraigBamptonReduction refused(system, unit_rows(boundary), few);
    expect(false, "maximum modes = 2 refused");
  }
  catch (const std::exception &e)
  {
    const std::string m = message_of(e);
    std::cout << "  refusal: " << m << std::endl;
    expect(m.find("Reduction maximum modes") != std::string::npos,
           "the refusal names Reduction maximum modes");
  }
  check_tie_rows();
  check_slicing("box girder", system, unit_rows(boundary), settings.cutoff_frequency, 4);
  check_slicing_with_pairs();
  check_modal_damping(system, boundary);
  return finish();
}
} // namespace hati_unit_craig_bampton
