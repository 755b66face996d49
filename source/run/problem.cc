#include <deal.II/base/exceptions.h>

#include <hati/analysis/modal_damping.h>
#include <hati/analysis/static_analysis.h>
#include <hati/base/names.h>
#include <hati/loading/accelerogram.h>
#include <hati/loading/artificial_records.h>
#include <hati/loading/base_excitation.h>
#include <hati/loading/design_spectrum.h>
#include <hati/output/response_spectra.h>
#include <hati/output/state_file.h>
#include <hati/run/analysis_registry.h>
#include <hati/run/entry_warnings.h>
#include <hati/run/problem.h>
#include <hati/run/run_state.h>
#include <hati/run/run_tools.h>
#include <hati/run/suite_plan.h>
#include <hati/time/cd_lagrange.h>
#include <hati/time/damping.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace hati
{
void Problem::declare_parameters(ParameterHandler &prm)
{
  declare_model_parameters(prm);
  AnalysisParameters::declare_parameters(
      prm, {analysis_registry().selection(), analysis_registry().join("; ", "; ", true)});
  TimeIntegrationParameters::declare_parameters(
      prm, {method_registry().selection(), method_registry().join(" ", " ", true)});
  prm.enter_subsection("Time integration");
  prm.enter_subsection("Newmark");
  NewmarkParameters::declare_parameters(prm);
  prm.leave_subsection();
  prm.enter_subsection("Damping");
  declare_damping_parameters(prm);
  prm.leave_subsection();
  prm.enter_subsection("HATI");
  HATIParameters::declare_parameters(prm);
  prm.leave_subsection();
  prm.leave_subsection();
  OutputParameters::declare_parameters(prm);
  SuiteParameters::declare_parameters(prm);
  DesignSpectrumParameters::declare_parameters(prm);
  ArtificialRecordParameters::declare_parameters(prm);
  ResponseSpectrumParameters::declare_parameters(prm);
  QualificationParameters::declare_parameters(prm);
}

Problem::Problem(ParameterHandler &prm, const ConditionalOStream &out) : out(out)
{
  analysis_parameters.parse_parameters(prm);
  time_parameters.parse_parameters(prm);
  prm.enter_subsection("Time integration");
  prm.enter_subsection("Newmark");
  newmark_parameters.parse_parameters(prm);
  prm.leave_subsection();
  if (analysis_parameters.type == "transient" &&
      (time_parameters.method == "Newmark" || time_parameters.method == "HATI"))
    newmark_parameters.check_unconditional_stability();
  prm.enter_subsection("Damping");
  damping = parse_damping_parameters(prm);
  prm.leave_subsection();
  prm.enter_subsection("HATI");
  hati_parameters.parse_parameters(prm);
  prm.leave_subsection();
  prm.leave_subsection();
  prm.enter_subsection("Model");
  prm.enter_subsection("Decomposition");
  decomposition_parameters.parse_parameters(prm);
  prm.leave_subsection();
  prm.leave_subsection();
  output_parameters.parse_parameters(prm);
  AssertThrow(output_parameters.state_interval == 0. ||
                  time_parameters.method != "event-driven",
              ExcMessage("Output/State interval: Method = event-driven writes no state "
                         "file (CD-Lagrange, Newmark and HATI do); set it to 0"));
  common_parameters.parse_parameters(prm);
  model_identity(prm, state_identity);
  // the explicit scheme enforces ties and rigid links as bilateral rows; the
  // other analyses eliminate them (doc/theory.md 11.2)
  common_parameters.links_as_rows =
      analysis_parameters.type == "transient" && time_parameters.method == "CD-Lagrange";
  if (analysis_parameters.type == "response spectrum")
  {
    AssertThrow(analysis_parameters.initial_state != "file",
                ExcMessage("Analysis/Initial state = file: a response-spectrum analysis "
                           "starts from the static state of its model, not from a state "
                           "file; set Initial state = given"));
    design_spectrum_parameters.parse_parameters(prm);
    AssertThrow(design_spectrum_parameters.active(),
                ExcMessage("Analysis/Type = response spectrum needs a target spectrum: "
                           "Design spectrum/Type is none (give an EC8 type or a table)"));
    response_spectrum_parameters.parse_parameters(prm);
  }
  qualification_parameters.parse_parameters(prm);
  model = create_model(prm);
  warn_inapplicable_entries(prm, *this);
  // a stress check needs every checked member's extreme fibres
  if (qualification_parameters.yield_strength > 0. &&
      (analysis_parameters.type == "transient" ||
       analysis_parameters.type == "response spectrum"))
  {
    const auto members = model->members_without_stresses();
    AssertThrow(
        members.empty(),
        ExcMessage("Qualification/Yield strength: member '" +
                   (members.empty() ? std::string() : members.front()) +
                   "' has a general section without its extreme fibre distances: "
                   "give them as 'general, A, Iy, Iz, J, Asy, Asz, c_y, c_z' (m), "
                   "or set Yield strength = 0 (stresses not checked)"));
  }
}

void Problem::build_system()
{
  model->build(common_parameters, system);
  for (const auto &w : system.warnings)
    warn(w);
  AssertThrow(
      system.lumped_mass_refusal.empty() || !(analysis_parameters.type == "transient" &&
                                              ((time_parameters.method == "Newmark" &&
                                                newmark_parameters.mass == "lumped") ||
                                               time_parameters.method == "event-driven")),
      ExcMessage(
          system.lumped_mass_refusal +
          " (Time integration/Method = event-driven, or Newmark with Mass = lumped)"));
  check_finite(system);
  system.fill_default_mass_influence();
}

void Problem::add_loads()
{
  auto acceleration = base_acceleration_step(common_parameters.base_acceleration,
                                             common_parameters.base_acceleration_start);
  for (unsigned int d = 0; d < 3; ++d)
    if (!common_parameters.accelerogram_files[d].empty())
    {
      const auto record = std::make_shared<Accelerogram>(
          Accelerogram::read(common_parameters.accelerogram_files[d],
                             common_parameters.accelerogram_units,
                             common_parameters.accelerogram_scale,
                             std::string("Loading/Accelerogram ") + "XYZ"[d]));
      const auto [peak, at] = record->peak();
      out << "  accelerogram along "
          << "xyz"[d] << ": " << common_parameters.accelerogram_files[d] << ", "
          << record->values().size() << " samples to t = " << record->times().back()
          << " s, peak " << peak << " m/s^2 (" << peak / standard_gravity
          << " g) at t = " << at << " s" << std::endl;
      warn_if_outside_run(*record, d);
      const auto step = acceleration[d];
      acceleration[d] = [record, step](const double t)
      { return (*record)(t) + (step ? step(t) : 0.); };
    }
  add_base_excitation(system, acceleration);
  ground_acceleration = acceleration;
  if (!common_parameters.excited_members.empty())
  {
    out << "  base excitation on the members:";
    for (const auto &m : common_parameters.excited_members)
      out << ' ' << m;
    out << std::endl;
  }
}

void Problem::warn_if_outside_run(const Accelerogram &record, const unsigned int d)
{
  const double first = record.times().front(), last = record.times().back();
  const double end = time_parameters.end_time;
  if (analysis_parameters.type != "transient" || (last > 0. && first < end))
    return;
  std::ostringstream s;
  s << "Loading/Accelerogram "
    << "XYZ"[d] << ": the record '" << printable(common_parameters.accelerogram_files[d])
    << "' runs from t = " << first << " s to t = " << last
    << " s, wholly outside the run from t = 0 to End time = " << end
    << " s: it excites nothing";
  warn(s.str());
}

void Problem::decompose()
{
  decomposition = std::make_unique<Decomposition>();
  if (decomposition_parameters.boxes.empty() && decomposition_parameters.members.empty())
  {
    // the model's explicit cells, with the reduction asked for
    DecompositionParameters cells = model->default_decomposition();
    decomposition_parameters.boxes = cells.boxes;
    decomposition_parameters.members = cells.members;
  }
  hati::decompose(*model, common_parameters, decomposition_parameters, *decomposition);
  for (auto &part : decomposition->parts)
    add_base_excitation(part.system, ground_acceleration);
}

void Problem::prepare_transient()
{
  check_spectrum_request();
  apply_default_frequency_range_damping();
  AssertThrow(!damping.frequency_range() || time_parameters.method == "CD-Lagrange" ||
                  time_parameters.method == "Newmark" || time_parameters.method == "HATI",
              ExcMessage("Time integration/Damping/Type = frequency range is applied by "
                         "the CD-Lagrange, Newmark and HATI integrators only (not by "
                         "Method = " +
                         time_parameters.method + "): use Type = Rayleigh."));
  if (analysis_parameters.initial_state == "file")
    set_file_initial_state();
  if (time_parameters.method == "HATI")
    decompose(); // the subdomains' initial state is copied below
  if (analysis_parameters.initial_state == "static")
  {
    check_explicit_step();
    const auto start = std::chrono::steady_clock::now();
    set_static_initial_state();
    initial_state_summary.emplace_back(
        "static_state_wall_time",
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  // a tied node may be free in a subdomain (a state file has its value)
  if (decomposition && analysis_parameters.initial_state != "file")
    model->complete_solution(system.initial_displacement);
  if (decomposition)
    for (auto &part : decomposition->parts)
    {
      part.system.start_time = system.start_time;
      for (unsigned int i = 0; i < part.global_dofs.size(); ++i)
      {
        part.system.initial_displacement[i] =
            system.initial_displacement[part.global_dofs[i]];
        part.system.initial_velocity[i] = system.initial_velocity[part.global_dofs[i]];
      }
    }
  if (decomposition && system.initial_contact_reaction.size() == system.n_dofs())
    for (auto &part : decomposition->parts)
    {
      part.system.initial_contact_reaction.reinit(part.global_dofs.size());
      for (unsigned int i = 0; i < part.global_dofs.size(); ++i)
        part.system.initial_contact_reaction[i] =
            system.initial_contact_reaction[part.global_dofs[i]];
    }
  if (decomposition && system.initial_contact_reaction.size() == system.n_dofs() &&
      analysis_parameters.initial_state == "static")
  {
    add_eliminated_contact_reactions();
    add_explicit_link_reactions();
  }
  const DefaultDamping defaults = model->default_damping();
  if (!damping.frequency_range() && defaults.type == "Rayleigh")
    for (const auto &entry : apply_default_damping(defaults.ratio,
                                                   system,
                                                   time_parameters.method,
                                                   newmark_parameters.linear_solver,
                                                   damping.rayleigh))
      initial_state_summary.push_back(entry);
  AssertThrow(time_parameters.method != "event-driven" ||
                  (damping.rayleigh.a0 == 0. && damping.rayleigh.a1 == 0.),
              ExcMessage("Time integration/Damping: Rayleigh damping is applied by the "
                         "CD-Lagrange and Newmark integrators only; remove it for "
                         "Method = event-driven."));
  add_damping_summary();
  if (decomposition && decomposition_parameters.implicit_reduction == "Craig-Bampton")
    reduce_implicit_part();
  // a HATI state of the same coupling (interface and implicit part): it
  // goes on from its multiplier (G3'), otherwise Lambda_0 is solved
  // (doc/theory.md 9.5)
  if (decomposition && restart_multiplier.size() > 0)
  {
    if (restart_interface == coupling_signature(*decomposition))
    {
      decomposition->initial_multiplier = restart_multiplier;
      // the implicit side's own interface values (the whole model's are the
      // explicit side's)
      const std::vector<unsigned int> shared = shared_implicit_dofs(*decomposition);
      DiscreteSystem &implicit = decomposition->parts[1].system;
      if (restart_implicit_interface.size() == 2 * shared.size())
        for (unsigned int s = 0; s < shared.size(); ++s)
        {
          implicit.initial_displacement[shared[s]] = restart_implicit_interface[s];
          implicit.initial_velocity[shared[s]] =
              restart_implicit_interface[shared.size() + s];
        }
    }
    else
      out << "  the state's interface multiplier belongs to another coupling: "
             "Lambda_0 from the acceleration continuity"
          << std::endl;
  }
}

void Problem::set_file_initial_state()
{
  const std::string parameter = "Analysis/Initial state file";
  AssertThrow(time_parameters.method != "event-driven",
              ExcMessage("Analysis/Initial state = file: Method = event-driven starts "
                         "from t = 0 only; restart with CD-Lagrange, Newmark or HATI"));
  state_identity.model = model->description();
  const RunState state = read_state_file(
      analysis_parameters.initial_state_file, system.n_dofs(), state_identity, parameter);
  AssertThrow(state.time < time_parameters.end_time,
              ExcMessage(parameter + " = " +
                         printable(analysis_parameters.initial_state_file) +
                         ": the state is at t = " + std::to_string(state.time) +
                         " s, not before Time integration/End time = " +
                         std::to_string(time_parameters.end_time) + " s"));
  system.initial_displacement = state.displacement;
  system.initial_velocity = state.velocity;
  system.start_time = state.time;
  restart_multiplier = state.interface_multiplier;
  restart_interface = state.interface_signature;
  restart_implicit_interface = state.implicit_interface;
  if (state.contact_force.linfty_norm() > 0.)
    system.initial_contact_reaction = state.contact_force;
  // a single-domain run: the DoFs its system holds fixed (supports, and the
  // slave DoFs it eliminates, which another method's run may have kept
  // free) at zero, as its integrator holds them; HATI's parts take the
  // state's values of their DoFs as they are
  for (unsigned int i = 0; i < system.n_dofs(); ++i)
    if (system.fixed[i] && time_parameters.method != "HATI")
    {
      system.initial_displacement[i] = 0.;
      system.initial_velocity[i] = 0.;
      if (system.initial_contact_reaction.size() == system.n_dofs())
        system.initial_contact_reaction[i] = 0.;
    }
  out << "  initial state from " << analysis_parameters.initial_state_file
      << " at t = " << state.time << " s" << std::endl;
  initial_state_summary.emplace_back("start_time", state.time);
  if (damping.frequency_range())
    warn("Analysis/Initial state = file: the memory variables of frequency-range "
         "damping start at zero at t = " +
         std::to_string(state.time) +
         " s (the state file holds displacements and velocities only)");
}

void Problem::check_explicit_step() const
{
  // an unstable explicit step refused before the static solve, which takes
  // minutes on large solids; the integrator checks it again with the run's
  // final damping (a default Rayleigh damping is added after the static
  // state and can only lower dt_crit)
  const DiscreteSystem *explicit_part =
      time_parameters.method == "CD-Lagrange" ? &system
      : time_parameters.method == "HATI" && decomposition && !decomposition->parts.empty()
          ? &decomposition->parts[0].system
          : nullptr;
  if (explicit_part != nullptr)
    CDLagrange::stability_limit(*explicit_part,
                                time_parameters.time_step,
                                time_parameters.safety_factor,
                                damping.rayleigh,
                                damping.branches);
}

void Problem::check_spectrum_request() const
{
  if (output_parameters.spectra.empty())
    return;
  AssertThrow(time_parameters.method != "event-driven",
              ExcMessage("Output/Spectra: response spectra are computed by the "
                         "CD-Lagrange, Newmark and HATI runs only (not by Method = "
                         "event-driven)"));
  // the history rows: every step or every History interval, in (macro) steps
  const double step = time_parameters.method == "HATI"
                          ? time_parameters.time_step * hati_parameters.time_step_ratio
                          : time_parameters.time_step;
  ResponseSpectra::check_request(output_parameters,
                                 system,
                                 steps_between(output_parameters.history_interval, step) *
                                     step);
}

void Problem::apply_default_frequency_range_damping()
{
  const DefaultDamping defaults = model->default_damping();
  if (damping.given() || defaults.type != "frequency range" || defaults.ratio <= 0.)
    return;
  if (time_parameters.method == "event-driven")
  {
    out << "  no default damping (" << defaults.ratio
        << ") with Method = event-driven: undamped" << std::endl;
    return;
  }
  damping = frequency_range_damping(
      defaults.ratio, defaults.lower_frequency, defaults.upper_frequency, 3);
  std::ostringstream s;
  s << defaults.entries << ": 3 Maxwell branches fit the damping ratio " << defaults.ratio
    << " over " << defaults.lower_frequency << " to " << defaults.upper_frequency
    << " Hz only within " << 100. * damping.fit_error
    << " % (at most 10 % accepted): narrow the band";
  AssertThrow(damping.fit_acceptable(), ExcMessage(s.str()));
  out << "  default damping of the model (" << defaults.entries << "):" << std::endl;
}

void Problem::add_damping_summary()
{
  // summary.json: the damping model of every transient run
  SummaryValue alpha = SummaryValue::list(), tau = SummaryValue::list();
  for (unsigned int l = 0; l < damping.branches.alpha.size(); ++l)
  {
    alpha.push_back(damping.branches.alpha[l]);
    tau.push_back(damping.branches.tau[l]);
  }
  SummaryValue branches = SummaryValue::object();
  branches.set("alpha", alpha);
  branches.set("tau", tau);
  initial_state_summary.emplace_back("damping_type", damping.type);
  initial_state_summary.emplace_back("damping_branches", branches);
  initial_state_summary.emplace_back("damping_fit_error", damping.fit_error);
  if (damping.frequency_range())
    out << "  frequency-range damping " << damping.ratio << " over "
        << damping.lower_frequency << " to " << damping.upper_frequency
        << " Hz: " << damping.branches.alpha.size()
        << " Maxwell branches, sum alpha = " << damping.branches.alpha_sum()
        << ", fit within " << 100. * damping.fit_error << " %" << std::endl;
}

void Problem::set_static_initial_state()
{
  out << "  initial state: static equilibrium under the constant loads" << std::endl;
  // under the loads the integrators apply: CD-Lagrange (and the explicit
  // subdomain of HATI) applies gravity with the lumped mass, so that its
  // first steps start at rest (doc/theory.md 1.1)
  Vector<double> correction(system.n_dofs());
  if (time_parameters.method == "CD-Lagrange")
    correction = system.lumped_gravity_correction();
  else if (time_parameters.method == "HATI")
  {
    const auto &E = decomposition->parts[0];
    const Vector<double> c = E.system.lumped_gravity_correction();
    for (unsigned int i = 0; i < c.size(); ++i)
      correction[E.global_dofs[i]] += c[i];
    // on a node the whole system eliminates (a rail node tied to a solid
    // across the interface): through its constraint line, as the assembly
    // condenses the loads (doc/theory.md 6.1)
    model->condense_force(correction);
  }
  system.constant_force += correction;
  std::vector<double> forces;
  solve_static(system,
               0.,
               system.initial_displacement,
               newmark_parameters.linear_solver,
               true,
               &forces,
               &static_tangent_forces);
  set_static_contact_reaction(forces);
  static_forces = forces;
  system.constant_force -= correction;
  system.initial_velocity = 0.;
  const SummaryValue entry = report_static_contact_forces(forces);
  if (entry.kind() != SummaryValue::Kind::null)
    initial_state_summary.emplace_back("static_contact_forces", entry);
  const SummaryValue friction = report_static_friction_forces(static_tangent_forces);
  if (friction.kind() != SummaryValue::Kind::null)
    initial_state_summary.emplace_back("static_friction_forces", friction);
  if (!system.ropes.empty())
    initial_state_summary.emplace_back("static_rope_tension",
                                       report_rope_tensions(system.initial_displacement));
}

void Problem::set_static_contact_reaction(const std::vector<double> &forces)
{
  // the DoFs of the closed contacts' rows (normal and, with friction, tangent)
  const unsigned int n = system.n_dofs();
  std::vector<bool> touched(n, false);
  bool any = false;
  for (unsigned int k = 0; k < system.contacts.size(); ++k)
  {
    const ContactRow &c = system.contacts[k];
    if (k >= forces.size() || forces[k] == 0.)
      continue;
    any = true;
    for (const auto i : c.dofs)
      touched[i] = true;
    for (const SparseRow &t : c.tangents)
      for (const auto i : t.dofs)
        touched[i] = true;
  }
  if (!any)
    return;
  // R_c = K U_0 - F_ext(0) - F_r(U_0) on those DoFs: what the contacts carry
  // at equilibrium, under the loads the explicit integrator applies (the
  // lumped gravity correction is in constant_force while this runs)
  Vector<double> f(system.constant_force), reaction(n);
  for (const Rope &rope : system.ropes)
    rope.add_force(system.initial_displacement, f);
  system.stiffness.vmult(reaction, system.initial_displacement);
  reaction -= f;
  for (unsigned int i = 0; i < n; ++i)
    if (!touched[i] || system.fixed[i])
      reaction[i] = 0.;
  system.initial_contact_reaction = reaction;
}

void Problem::add_eliminated_contact_reactions()
{
  auto &E = decomposition->parts[0];
  const std::vector<ContactRow> &whole = system.contacts;
  // the part's rows are the whole system's, in order, some left out (two
  // rows of one two-sided contact share its name)
  unsigned int k = 0;
  for (const ContactRow &row : E.system.contacts)
  {
    while (k < whole.size() && whole[k].name != row.name)
      ++k;
    if (k == whole.size())
      break;
    // the normal row, then the tangent rows of a sticking contact (A9)
    auto add = [&](const SparseRow &part_row, const SparseRow &whole_row, const double f)
    {
      if (f == 0.)
        return;
      for (unsigned int j = 0; j < part_row.dofs.size(); ++j)
      {
        const auto g = E.global_dofs[part_row.dofs[j]];
        if (std::find(whole_row.dofs.begin(), whole_row.dofs.end(), g) ==
            whole_row.dofs.end())
          E.system.initial_contact_reaction[part_row.dofs[j]] +=
              f * part_row.coefficients[j];
      }
    };
    if (k < static_forces.size())
      add(row, whole[k], static_forces[k]);
    if (k < static_tangent_forces.size())
      for (unsigned int t = 0;
           t < row.tangents.size() && t < whole[k].tangents.size() && t < 2;
           ++t)
        add(row.tangents[t], whole[k].tangents[t], static_tangent_forces[k][t]);
    ++k;
  }
}

void Problem::add_explicit_link_reactions()
{
  auto &E = decomposition->parts[0];
  const unsigned int n = E.global_dofs.size();
  // the DoFs of the explicit part's constraint rows (rigid links and ties
  // inside it, eliminated in the whole system's static solve), not on the
  // interface (whose rows carry the implicit part's share)
  std::vector<bool> touched(n, false);
  bool any = false;
  for (const ContactRow &row : E.system.contacts)
    if (row.constraint)
    {
      any = true;
      for (const auto i : row.dofs)
        touched[i] = true;
    }
  if (!any || E.system.initial_contact_reaction.size() != n)
    return;
  for (const SparseRow &row : decomposition->rows[0])
    for (const auto i : row.dofs)
      touched[i] = false;
  // R_E = K_E U_0 - F_E - F_r(U_0) under the explicit part's loads (the
  // lumped gravity correction of the static state): every row's force on
  // these DoFs, the constraints' and the contacts' at once
  Vector<double> f(E.system.constant_force), reaction(n);
  f += E.system.lumped_gravity_correction();
  for (const Rope &rope : E.system.ropes)
    rope.add_force(E.system.initial_displacement, f);
  E.system.stiffness.vmult(reaction, E.system.initial_displacement);
  reaction -= f;
  for (unsigned int i = 0; i < n; ++i)
    if (touched[i] && !E.system.fixed[i])
      E.system.initial_contact_reaction[i] = reaction[i];
}

SummaryValue Problem::report_rope_tensions(const Vector<double> &U)
{
  out << "  static rope tension (N):\n";
  SummaryValue json = SummaryValue::object();
  for (const Rope &rope : system.ropes)
  {
    const double T = rope.tension(U);
    out << "    " << std::left << std::setw(28) << rope.name << std::right
        << std::setw(16) << std::setprecision(10) << T << std::endl;
    json.set(rope.name, T);
  }
  return json;
}

void Problem::warn(const std::string &message)
{
  warnings.push_back(message);
  if (out.is_active())
    std::cerr << "hati: warning: " << message << std::endl;
}

namespace
{
/**
 * The per-row @p values of the closed contacts that @p take selects (zero
 * initial gap, not a tie or a link row), summed per contact name, in the
 * order of the names' first rows.
 */
std::vector<std::pair<std::string, double>>
sums_by_name(const std::vector<ContactRow> &contacts,
             const std::vector<double> &values,
             const std::function<bool(const ContactRow &)> &take)
{
  std::vector<std::pair<std::string, double>> sums;
  for (unsigned int k = 0; k < contacts.size() && k < values.size(); ++k)
  {
    const ContactRow &c = contacts[k];
    if (c.initial_gap != 0. || c.constraint || !take(c))
      continue;
    const auto it = std::find_if(
        sums.begin(), sums.end(), [&](const auto &e) { return e.first == c.name; });
    if (it == sums.end())
      sums.emplace_back(c.name, values[k]);
    else
      it->second += values[k];
  }
  return sums;
}

/** Print one line `name value` of a static force table (N). */
void print_force_line(const ConditionalOStream &out,
                      const std::string &name,
                      const double value)
{
  out << "    " << std::left << std::setw(28) << name << std::right << std::setw(16)
      << std::setprecision(8) << value << std::endl;
}
} // namespace

SummaryValue Problem::report_static_contact_forces(const std::vector<double> &forces)
{
  // closed rows: zero initial gap (solve_static); sums per name, in order
  const auto sums =
      sums_by_name(system.contacts, forces, [](const ContactRow &) { return true; });
  if (sums.empty())
    return {};
  out << "  static contact forces (closed contacts, N):\n";
  SummaryValue json = SummaryValue::object();
  double total = 0.;
  for (const auto &[name, sum] : sums)
  {
    print_force_line(out, name, sum);
    json.set(name, sum);
    static_contact_forces[name] = sum;
    total += sum;
  }
  print_force_line(out, "sum", total);
  return json;
}

SummaryValue Problem::report_static_friction_forces(
    const std::vector<std::array<double, 2>> &tangent_forces)
{
  std::vector<double> magnitudes;
  for (const auto &t : tangent_forces)
    magnitudes.push_back(std::hypot(t[0], t[1]));
  const auto sums = sums_by_name(
      system.contacts, magnitudes, [](const ContactRow &c) { return c.frictional(); });
  if (sums.empty())
    return {};
  out << "  static friction forces (sticking contacts, settled, N):\n";
  SummaryValue json = SummaryValue::object();
  for (const auto &[name, sum] : sums)
  {
    print_force_line(out, name, sum);
    json.set(name, sum);
  }
  return json;
}
} // namespace hati
