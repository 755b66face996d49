// Unit test of the force-law interface (ForceLaw, force_law_registry(),
// doc/architecture.md "Force laws"): a law that no integrator names, a
// linear spring to the ground `F = -k u` on one DoF, is registered here and
// put into DiscreteSystem::law_data; CD-Lagrange applies it with the
// external force (A2-A3) and takes its omega^2 bound into dt_crit (A7).
//  (a) a 1-DoF mass on the law alone, released from u = A at rest, five
//      periods at dt = T/1000, against the analytical oscillation
//      A cos(omega t): the period (zero crossings, interpolated linearly)
//      within 1e-5 relative (the scheme's period error is
//      (omega dt)^2/24 = 1.6e-6, the interpolation's 1e-7 or less), the
//      amplitude (largest |u| of the last period) within 1e-5 relative (the
//      samples miss the peak by at most 1 - cos(pi/1000) = 5e-6), and the
//      whole history within 2e-4 A of A cos(omega t) (the phase drift of the
//      period error over five periods, 5 * 2 pi * 1.6e-6 = 5e-5, and the
//      scheme's amplitude error). Against the scheme's own closed form
//      `A cos(Omega t_n)`, `sin(Omega dt / 2) = omega dt / 2` (the start
//      V_1/2 of doc/theory.md 1.1 makes it exact), to 1e-10 A: the
//      round-off of 5000 steps of a neutrally stable recurrence and of
//      Omega t (~1e-12 A).
//  (b) the energy balance (E1) with the law's stored energy: constant to
//      1e-11 relative (central differences conserve
//      `1/2 V_{n-1/2} M V_{n+1/2} + 1/2 k u_n^2` exactly, the law's
//      trapezoidal work makes its stored energy `1/2 k u_n^2`; round-off of
//      the 5000 terms of the work, ~1e-13).
//  (c) dt_crit = 2/omega from the law's bound; dt = 1.01 dt_crit refused
//      with a message that names the law.
//  (d) a 2-DoF chain, a spring in K between the masses and the ground
//      spring on DoF 0 as the law, against the same system with the
//      ground spring in K: the histories agree to 1e-10 of the amplitude
//      over 20000 steps (only the order of the floating-point operations
//      differs: a round-off of 1e-16 per step, accumulated as a phase).
//  (e) a snapshot (CDLagrange::save/restore) restores the law's state: the
//      steps redone after it give the same displacement and stored energy,
//      bit for bit.
//  (f) the law's summary entry, and no law made for a system without its
//      data.
//  (g) a law of rows (A4-A6) that no integrator names either: a bilateral
//      row `u_0 = 0` on DoF 0 of a 2-DoF chain (spring k between the
//      masses), its impulse `lambda = -W^-1 L V_free`, `W = L M^-1 L^T`,
//      solved by the law. Started at rest at u = 0 with a velocity v0 on
//      DoF 1 (G_0 = 0: the first half step needs no row), DoF 0 stays at 0
//      to 1e-12 of the amplitude (the round-off of `V_free + M^-1 lambda`
//      with `lambda = -m V_free`) and DoF 1 oscillates on the spring alone:
//      against (v0/omega) sin(omega t), omega = sqrt(k/m_1), within 2e-4 of
//      the amplitude over five periods at dt = T/1000 (the same error budget
//      as (a)), against the scheme's closed form
//      `v0 dt sin(Omega t_n) / sin(Omega dt)` to 1e-10 of it (round-off),
//      and the row's impulse is the support reaction of the step,
//      `lambda = -dt k u_1(t_{n+1})`, to 1e-12 of its largest value.
//  (h) the decomposition (extract_subsystem(), HATI's subdomains): the
//      ground spring on DoF 2 of a 3-DoF system, renumbered by the law
//      (ForceLaw::part_data()) into the part of DoFs {1, 2} as its DoF 1,
//      the part's CD-Lagrange makes the law with the part's mass in its
//      bound; the part {0, 1} holds none of it; a law without part_data()
//      (the holding row) and data of no registered law are refused with
//      messages that name them.
//  (i) a whole run of the bouncing ball through Problem and the time loop
//      (run_time_loop()) with the ground spring added to its system: the
//      law's LawOutput (ForceLaw::make_output()) sees every step and writes
//      its summary.json entries and its own file, add_summary() its entry,
//      next to the contacts' entries; Newmark and event-driven refuse the
//      law by its name (on the 1-DoF oscillator) (ForceLaw::refusal(),
//      check_force_laws()). Adding a law is its class and one registration, nothing else.
// Every check prints value, reference and tolerance; returns non-zero on
// failure.
#include <deal.II/base/mpi.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>

#include "test_tools.h"

#include <hati/base/mpi_environment.h>
#include <hati/contact/sparse_rows.h>
#include <hati/model/decomposition.h>
#include <hati/model/discrete_system.h>
#include <hati/output/law_output.h>
#include <hati/output/run_directory.h>
#include <hati/run/problem.h>
#include <hati/run/time_loop.h>
#include <hati/time/cd_lagrange.h>
#include <hati/time/force_law.h>

#include <algorithm>
#include <any>
#include <cmath>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace hati_unit_force_law
{

using namespace dealii;
using namespace hati;
using namespace hati_test;

namespace
{
/** What a model puts into DiscreteSystem::law_data["ground spring"]. */
struct GroundSpringData
{
  types::global_dof_index dof = 0;
  /** Stiffness (N/m). */
  double stiffness = 0.;
};

class GroundSpring;

/**
 * The ground spring's outputs (a LawOutput, (i)): the steps it saw, the
 * time of the last one and the largest force at the end of a step, as the
 * summary.json entries `ground_spring_steps`, `ground_spring_last_time`
 * and the file `ground_spring.csv`.
 */
class GroundSpringOutput : public LawOutput
{
public:
  GroundSpringOutput(const GroundSpring &law, const LawOutputContext &context)
      : law(law), directory(context.directory)
  {
  }

  void add_step(const LawSample &sample, const double dt) override;

  void
  finish(SummaryEntries &summary, std::ostream &out, const LawOutputTimes &times) override
  {
    (void)times;
    summary.emplace_back("ground_spring_steps", steps);
    summary.emplace_back("ground_spring_last_time", last_time);
    std::ostringstream csv;
    csv << "steps,largest_force\n" << steps << ',' << largest << '\n';
    directory.replace("ground_spring.csv", csv.str(), true);
    out << "  ground spring: " << steps << " steps" << std::endl;
  }

private:
  const GroundSpring &law;
  RunDirectory &directory;
  unsigned long steps = 0;
  double last_time = 0., largest = 0.;
};

/** `F = -k u` on one DoF, with the law's work and statistics (a test law). */
class GroundSpring : public ForceLaw
{
public:
  GroundSpring(const GroundSpringData &data, const double mass) : data(data), mass(mass)
  {
  }

  static Registry<ForceLawFactory>::Entry registration()
  {
    return {"ground spring",
            "a linear spring from one DoF to the ground (unit test)",
            {},
            [](const DiscreteSystem &system) -> std::unique_ptr<ForceLaw>
            {
              const auto it = system.law_data.find("ground spring");
              if (it == system.law_data.end())
                return nullptr;
              const auto &d = std::any_cast<const GroundSpringData &>(it->second);
              return std::make_unique<GroundSpring>(d, system.lumped_mass[d.dof]);
            }};
  }

  std::string name() const override { return "ground spring"; }

  bool adds_forces() const override { return true; }

  void start(const Vector<double> &U, Vector<double> &f) override
  {
    state.force = -data.stiffness * U[data.dof];
    state.work = 0.;
    state.max_force = std::abs(state.force);
    initial_energy = 0.5 * data.stiffness * U[data.dof] * U[data.dof];
    f[data.dof] += state.force;
  }

  void step(const Vector<double> &U,
            const Vector<double> &V,
            const Vector<double> &dt_minv,
            const double dt,
            double *a) override
  {
    const double force = -data.stiffness * U[data.dof];
    state.work += 0.5 * dt * V[data.dof] * (state.force + force);
    a[data.dof] += dt_minv[data.dof] * force;
    state.force = force;
    state.max_force = std::max(state.max_force, std::abs(force));
  }

  double stored_energy() const override { return initial_energy - state.work; }

  std::vector<types::global_dof_index> nonlinear_dofs() const override { return {}; }

  double omega_squared_bound() const override { return data.stiffness / mass; }

  void save(std::any &s) const override { s = state; }
  void restore(const std::any &s) override { state = std::any_cast<const State &>(s); }

  /** Its DoF renumbered; none for a part without it (the decomposition, (h)). */
  std::any part_data(const std::vector<int> &local,
                     const std::vector<bool> &fixed) const override
  {
    (void)fixed;
    if (local[data.dof] < 0)
      return {};
    return GroundSpringData{static_cast<types::global_dof_index>(local[data.dof]),
                            data.stiffness};
  }

  void add_summary(SummaryEntries &summary, std::ostream &out) const override
  {
    summary.emplace_back("ground_spring_max_force", state.max_force);
    out << "  ground spring: largest force " << state.max_force << " N" << std::endl;
  }

  std::unique_ptr<LawOutput> make_output(const LawOutputContext &context) const override
  {
    return std::make_unique<GroundSpringOutput>(*this, context);
  }

  /** The force at the end of the last step (N). */
  double force() const { return state.force; }

private:
  struct State
  {
    double force = 0., work = 0., max_force = 0.;
  };
  const GroundSpringData data;
  const double mass;
  State state;
  double initial_energy = 0.;
};

void GroundSpringOutput::add_step(const LawSample &sample, const double dt)
{
  (void)dt;
  ++steps;
  last_time = sample.time;
  largest = std::max(largest, std::abs(law.force()));
}

/** What a model puts into DiscreteSystem::law_data["holding row"]. */
struct HoldingRowData
{
  types::global_dof_index dof = 0;
};

/**
 * A bilateral row `L = e_dof`, `L V = 0` after every step (A5 as an
 * equality), solved by the law itself: `W = L M^-1 L^T`, `lambda = -W^-1 L
 * V_free`, `V_{n+3/2} = V_free + M^-1 L^T lambda` (a test law).
 */
class HoldingRow : public ForceLaw
{
public:
  explicit HoldingRow(const HoldingRowData &data)
  {
    row.dofs = {data.dof};
    row.coefficients = {1.};
  }

  static Registry<ForceLawFactory>::Entry registration()
  {
    return {"holding row",
            "a bilateral velocity-level row on one DoF (unit test)",
            {},
            [](const DiscreteSystem &system) -> std::unique_ptr<ForceLaw>
            {
              const auto it = system.law_data.find("holding row");
              if (it == system.law_data.end())
                return nullptr;
              return std::make_unique<HoldingRow>(
                  std::any_cast<const HoldingRowData &>(it->second));
            }};
  }

  std::string name() const override { return "holding row"; }

  bool has_rows() const override { return true; }

  void apply_impulses(const Vector<double> &U,
                      const Vector<double> &v_before,
                      const Vector<double> &inverse_mass,
                      Vector<double> &v) override
  {
    (void)U;
    (void)v_before;
    const FullMatrix<double> W = delassus<SparseRow>({&row}, inverse_mass);
    impulse = -row.apply(v) / W(0, 0);
    row.add_transpose(impulse, inverse_mass, v);
  }

  void save(std::any &state) const override { state = impulse; }
  void restore(const std::any &state) override { impulse = std::any_cast<double>(state); }

  /** The impulse of the last step (N s). */
  double last_impulse() const { return impulse; }

private:
  SparseRow row;
  double impulse = 0.;
};

/** A mass @p m (kg) on DoF 0 alone, with the ground spring @p k (N/m) as the law. */
void make_oscillator(DiscreteSystem &s, const double m, const double k, const double A)
{
  s.reinit(1);
  s.lumped_mass[0] = m;
  s.initial_displacement[0] = A;
  s.law_data["ground spring"] = GroundSpringData{0, k};
}

/**
 * Two masses @p m0, @p m1 (kg), a spring @p k1 (N/m) between them in K, and
 * the ground spring @p k0 on DoF 0: as the law (@p as_law) or in K.
 */
void make_chain(DiscreteSystem &s,
                const double m0,
                const double m1,
                const double k0,
                const double k1,
                const bool as_law)
{
  s.reinit(2);
  s.lumped_mass[0] = m0;
  s.lumped_mass[1] = m1;
  DynamicSparsityPattern dsp(2, 2);
  for (unsigned int a = 0; a < 2; ++a)
    for (unsigned int b = 0; b < 2; ++b)
      dsp.add(a, b);
  s.stiffness_pattern.copy_from(dsp);
  s.stiffness.reinit(s.stiffness_pattern);
  s.stiffness.set(0, 0, k1 + (as_law ? 0. : k0));
  s.stiffness.set(0, 1, -k1);
  s.stiffness.set(1, 0, -k1);
  s.stiffness.set(1, 1, k1);
  s.initial_displacement[0] = 0.01;
  s.initial_velocity[1] = -0.3;
  if (as_law)
    s.law_data["ground spring"] = GroundSpringData{0, k0};
}

/** The law called @p name of @p cd (nullptr if none). */
const ForceLaw *law_of(const CDLagrange &cd, const std::string &name)
{
  for (const auto &law : cd.force_laws())
    if (law->name() == name)
      return law.get();
  return nullptr;
}

void test_oscillator()
{
  const double m = 2., k = 800., A = 0.01, omega = std::sqrt(k / m),
               T = 2. * numbers::PI / omega, dt = T / 1000.;
  DiscreteSystem s;
  make_oscillator(s, m, k, A);
  CDLagrange cd(s, dt, 1.);
  expect(law_of(cd, "ground spring") != nullptr,
         "(a) the integrator holds the registered law it does not name");
  const double Omega = 2. / dt * std::asin(0.5 * omega * dt);
  // the scheme's invariant `1/2 V_{n-1/2} M V_{n+1/2} + 1/2 k u_n^2` at t = 0
  // (V_{-1/2} and V_{1/2} from the start of doc/theory.md 1.1)
  const Energies e0 = cd.energies();
  const double E0 = e0.kinetic + e0.internal;
  double error_exact = 0., error_scheme = 0., energy_error = 0., amplitude = 0.;
  std::vector<double> crossings; // down- and up-crossings of u = 0
  double u_prev = A, t_prev = 0.;
  const unsigned int n_steps = 5000;
  for (unsigned int n = 1; n <= n_steps; ++n)
  {
    cd.step();
    const double t = cd.time(), u = cd.displacement()[0];
    error_exact = std::max(error_exact, std::abs(u - A * std::cos(omega * t)));
    error_scheme = std::max(error_scheme, std::abs(u - A * std::cos(Omega * t)));
    if ((u_prev > 0.) != (u > 0.))
      crossings.push_back(t_prev + dt * u_prev / (u_prev - u));
    if (n > n_steps - 1000)
      amplitude = std::max(amplitude, std::abs(u));
    const Energies e = cd.energies();
    energy_error = std::max(energy_error, std::abs(e.kinetic + e.internal - E0));
    u_prev = u;
    t_prev = t;
  }
  // a period spans two crossings: the first and the last one of the run
  const double period =
      2. * (crossings.back() - crossings.front()) / double(crossings.size() - 1);
  check("(a) period (s) from " + std::to_string(crossings.size()) + " zero crossings",
        period,
        T,
        1e-5 * T);
  check("(a) amplitude (m) over the fifth period", amplitude, A, 1e-5 * A);
  check("(a) max |u - A cos(omega t)| (m) over five periods", error_exact, 0., 2e-4 * A);
  check("(a) max |u - A cos(Omega t_n)| (m), the scheme's closed form",
        error_scheme,
        0.,
        1e-10 * A);
  check("(b) max |E_kin + E_stored - E_0| (J)", energy_error, 0., 1e-11 * E0);
}

void test_critical_step()
{
  const double m = 2., k = 800.;
  DiscreteSystem s;
  make_oscillator(s, m, k, 0.01);
  const double dt_crit = 2. / std::sqrt(k / m);
  check("(c) dt_crit (s) = 2/omega from the law's bound",
        CDLagrange(s, 1e-3, 1.).critical_time_step(),
        dt_crit,
        1e-14 * dt_crit);
  std::string what;
  try
  {
    CDLagrange refused(s, 1.01 * dt_crit, 1.);
  }
  catch (const std::exception &e)
  {
    what = message_of(e);
  }
  std::cout << "     message: " << what << std::endl;
  expect(what.find("stability limit") != std::string::npos &&
             what.find("'ground spring'") != std::string::npos,
         "(c) dt = 1.01 dt_crit refused, the message names the law");
}

void test_chain_and_snapshot()
{
  const double m0 = 1.5, m1 = 0.7, k0 = 3000., k1 = 1200.;
  DiscreteSystem with_law, in_k;
  make_chain(with_law, m0, m1, k0, k1, true);
  make_chain(in_k, m0, m1, k0, k1, false);
  const double dt = 1e-4;
  CDLagrange a(with_law, dt, 0.9), b(in_k, dt, 0.9);
  check("(d) dt_crit with the law's bound added is at most the chain's",
        std::min(0., b.critical_time_step() - a.critical_time_step()),
        0.,
        0.);
  double difference = 0., scale = 0.;
  for (unsigned int n = 0; n < 20000; ++n)
  {
    a.step();
    b.step();
    for (unsigned int i = 0; i < 2; ++i)
    {
      difference =
          std::max(difference, std::abs(a.displacement()[i] - b.displacement()[i]));
      scale = std::max(scale, std::abs(b.displacement()[i]));
    }
  }
  check("(d) 2 DoFs, law against K: max |U_law - U_K| (m) over 2 s",
        difference,
        0.,
        1e-10 * scale);

  CDLagrange::Snapshot snapshot;
  a.save(snapshot);
  for (unsigned int n = 0; n < 37; ++n)
    a.step();
  const Vector<double> U = a.displacement();
  const double stored = law_of(a, "ground spring")->stored_energy();
  a.restore(snapshot);
  for (unsigned int n = 0; n < 37; ++n)
    a.step();
  bool same = law_of(a, "ground spring")->stored_energy() == stored;
  for (unsigned int i = 0; i < 2; ++i)
    same = same && a.displacement()[i] == U[i];
  expect(same, "(e) 37 steps redone after restore(): U and the stored energy bitwise");

  SummaryEntries summary;
  std::ostringstream out;
  law_of(a, "ground spring")->add_summary(summary, out);
  expect(summary.size() == 1 && summary[0].first == "ground_spring_max_force",
         "(f) the law's summary entry");
  DiscreteSystem plain;
  make_oscillator(plain, 1., 1., 0.);
  plain.law_data.clear();
  bool none = true;
  for (const auto &law : make_force_laws(plain))
    none = none && law->name() != "ground spring";
  expect(none, "(f) no ground spring for a system without its data");
}
/** The message of the exception thrown by @p f (empty if none). */
template <class F> std::string refusal_of(F f)
{
  try
  {
    f();
  }
  catch (const std::exception &e)
  {
    return message_of(e);
  }
  return "";
}

void test_decomposition()
{
  // a chain of three masses, the ground spring on DoF 2; the part holds 1, 2
  const double k = 800., m2 = 3.;
  DiscreteSystem s;
  s.reinit(3);
  for (unsigned int i = 0; i < 3; ++i)
    s.lumped_mass[i] = 1. + i;
  s.law_data["ground spring"] = GroundSpringData{2, k};
  DiscreteSystem part;
  extract_subsystem(s, {1, 2}, part);
  const auto it = part.law_data.find("ground spring");
  expect(it != part.law_data.end() &&
             std::any_cast<const GroundSpringData &>(it->second).dof == 1 &&
             std::any_cast<const GroundSpringData &>(it->second).stiffness == k,
         "(h) the part's law data: the ground spring on the part's DoF 1 (global 2)");
  CDLagrange cd(part, 1e-3, 1.);
  const ForceLaw *law = law_of(cd, "ground spring");
  check("(h) the part's law: its omega^2 bound k/m (rad^2/s^2)",
        law ? law->omega_squared_bound() : 0.,
        k / m2,
        1e-14 * k / m2);
  DiscreteSystem other;
  extract_subsystem(s, {0, 1}, other);
  expect(other.law_data.empty(), "(h) a part without the spring's DoF holds none of it");

  // a law that does not renumber its data, and data of no registered law
  DiscreteSystem rows;
  rows.reinit(2);
  rows.lumped_mass = 1.;
  rows.law_data["holding row"] = HoldingRowData{0};
  std::string what = refusal_of([&] { extract_subsystem(rows, {0}, part); });
  std::cout << "     message: " << what << std::endl;
  expect(what.find("'holding row' cannot be split") != std::string::npos,
         "(h) a law without part_data() refused, the message names the law");
  rows.law_data.clear();
  rows.law_data["no such law"] = 1.;
  what = refusal_of([&] { extract_subsystem(rows, {0}, part); });
  std::cout << "     message: " << what << std::endl;
  expect(what.find("'no such law'") != std::string::npos,
         "(h) data of no registered law refused, the message names it");
}

/** The text of the file @p path (empty if it cannot be read). */
std::string read_text(const std::string &path)
{
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void test_run()
{
  // the bouncing ball (parameter_files/bouncing_ball.prm) for 0.05 s with
  // the test's ground spring on its vertical DoF, through Problem and the
  // time loop of a run (run_time_loop(), as run_cd_lagrange() calls it)
  ParameterHandler prm;
  Problem::declare_parameters(prm);
  prm.parse_input_from_string("subsection Model\n"
                              "  set Type = point mass\n"
                              "  subsection Point mass\n"
                              "    set Initial height = 0.001\n"
                              "  end\n"
                              "end\n"
                              "subsection Loading\n"
                              "  set Gravity = 0, 0, -9.81\n"
                              "end\n"
                              "subsection Contact\n"
                              "  set Name = ground\n"
                              "end\n"
                              "subsection Analysis\n"
                              "  set Type = transient\n"
                              "end\n"
                              "subsection Time integration\n"
                              "  set Method = CD-Lagrange\n"
                              "  set Time step = 1e-4\n"
                              "  set End time = 0.05\n"
                              "end\n"
                              "subsection Output\n"
                              "  set History interval = 0.01\n"
                              "  set Output interval = 0\n"
                              "end\n");
  Problem problem(prm, ConditionalOStream(std::cout, false));
  problem.build_system();
  problem.add_loads();
  const double k = 100.;
  problem.system.law_data["ground spring"] = GroundSpringData{2, k};
  problem.prepare_transient();
  DiscreteSystem oscillator; // the law alone: no contact is refused first
  make_oscillator(oscillator, 1., k, 0.01);
  for (const std::string method : {"Newmark", "event-driven"})
  {
    const std::string what = refusal_of([&] { check_force_laws(oscillator, method); });
    std::cout << "     message: " << what << std::endl;
    expect(what.find("Time integration/Method = " + method +
                     ": the force law 'ground spring'") != std::string::npos,
           "(i) " + method + " refuses the law, naming it");
  }
  const std::string path = "unit_force_law_run";
  {
    RunDirectory directory(path, "");
    TimerOutput timer(std::cout, TimerOutput::never, TimerOutput::wall_times);
    CDLagrange integrator(problem.system, 1e-4, 1.);
    run_time_loop(integrator, problem, directory, timer, {{"method", "CD-Lagrange"}});
  }
  const std::string summary = read_text(path + "/summary.json");
  const auto has = [&](const std::string &text)
  { return summary.find(text) != std::string::npos; };
  expect(has("\"ground_spring_max_force\": ") && has("\"ground_spring_steps\": 500,"),
         "(i) summary.json: the law's entries (add_summary(), its LawOutput: 500 steps)");
  expect(has("\"ground_spring_last_time\": 0.05") && has("\"contacts\": {"),
         "(i) summary.json: the last step at the End time, the contacts' entries too");
  const std::string csv = read_text(path + "/ground_spring.csv");
  std::cout << "     ground_spring.csv: " << csv;
  expect(csv.rfind("steps,largest_force\n500,", 0) == 0,
         "(i) the law's own file ground_spring.csv");
}

void test_row_law()
{
  const double m0 = 1.5, m1 = 0.7, k = 1200., v0 = 0.3, omega = std::sqrt(k / m1),
               T = 2. * numbers::PI / omega, dt = T / 1000.;
  DiscreteSystem s;
  s.reinit(2);
  s.lumped_mass[0] = m0;
  s.lumped_mass[1] = m1;
  DynamicSparsityPattern dsp(2, 2);
  for (unsigned int a = 0; a < 2; ++a)
    for (unsigned int b = 0; b < 2; ++b)
      dsp.add(a, b);
  s.stiffness_pattern.copy_from(dsp);
  s.stiffness.reinit(s.stiffness_pattern);
  s.stiffness.set(0, 0, k);
  s.stiffness.set(0, 1, -k);
  s.stiffness.set(1, 0, -k);
  s.stiffness.set(1, 1, k);
  s.initial_velocity[1] = v0;
  s.law_data["holding row"] = HoldingRowData{0};
  CDLagrange cd(s, dt, 1.);
  const auto *row = dynamic_cast<const HoldingRow *>(law_of(cd, "holding row"));
  expect(row != nullptr, "(g) the integrator holds the registered law of rows");
  if (!row)
    return;
  const double Omega = 2. / dt * std::asin(0.5 * omega * dt);
  const double amplitude = v0 / omega;
  double u0_max = 0., error_exact = 0., error_scheme = 0., reaction_error = 0.,
         largest_impulse = 0.;
  for (unsigned int n = 1; n <= 5000; ++n)
  {
    cd.step();
    const double t = cd.time(), u1 = cd.displacement()[1];
    u0_max = std::max(u0_max, std::abs(cd.displacement()[0]));
    error_exact = std::max(error_exact, std::abs(u1 - amplitude * std::sin(omega * t)));
    error_scheme =
        std::max(error_scheme,
                 std::abs(u1 - v0 * dt * std::sin(Omega * t) / std::sin(Omega * dt)));
    reaction_error =
        std::max(reaction_error, std::abs(row->last_impulse() + dt * k * u1));
    largest_impulse = std::max(largest_impulse, std::abs(row->last_impulse()));
  }
  check("(g) max |u_0| (m), held by the row", u0_max, 0., 1e-12 * amplitude);
  check("(g) max |u_1 - (v0/omega) sin(omega t)| (m) over five periods",
        error_exact,
        0.,
        2e-4 * amplitude);
  check("(g) max |u_1 - v0 dt sin(Omega t_n)/sin(Omega dt)| (m), the scheme's form",
        error_scheme,
        0.,
        1e-10 * amplitude);
  check("(g) max |lambda + dt k u_1| (N s), the support reaction",
        reaction_error,
        0.,
        1e-12 * largest_impulse);
}
} // namespace

HATI_UNIT_TEST(force_law)
{
  const hati::MpiEnvironment mpi_environment; // own Open MPI session folder
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // the registration: one line, as for a law of the code (source/time/force_law.cc)
  force_law_registry().add(GroundSpring::registration());
  force_law_registry().add(HoldingRow::registration());
  test_oscillator();
  test_critical_step();
  test_chain_and_snapshot();
  test_row_law();
  test_decomposition();
  test_run();
  return finish();
}
} // namespace hati_unit_force_law
