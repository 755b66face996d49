// The response-spectrum analysis (doc/theory.md 14): the modes of the
// linearised model up to the cut-off, each quantity's response per mode
// from the mode shape, the missing mass, the combinations.

#include <deal.II/base/exceptions.h>

#include <hati/analysis/held_contacts.h>
#include <hati/analysis/modal_analysis.h>
#include <hati/analysis/response_spectrum_analysis.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace hati
{
namespace
{
/** The seconds since @p start. */
double seconds_since(const std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/** A row of the displacement block: its name, unit and values. */
struct RowLayout
{
  std::string name, unit;
  /** The first value and the number of values of the row. */
  std::size_t first = 0, size = 1;
  bool stress = false;
};

/** The von Mises stress of the components (xx, yy, zz, xy, yz, xz) at @p s. */
double von_mises_of(const double *s)
{
  const double a = s[0] - s[1], b = s[1] - s[2], c = s[2] - s[0];
  return std::sqrt(0.5 * (a * a + b * b + c * c) +
                   3. * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
}

/**
 * What the analysis works on from one step to the next: the model, its
 * eigenproblem, the kept modes, the layout of the values and each mode's
 * and the missing mass's values.
 */
struct Work
{
  Work(const DiscreteSystem &system,
       const ResponseModel &model,
       const ResponseSpectrumParameters &parameters,
       const DesignSpectrum &spectrum,
       const HeldContacts &contacts,
       const ModalProblem &problem)
      : system(system), model(model), parameters(parameters), spectrum(spectrum),
        contacts(contacts), problem(problem), n(system.n_dofs())
  {
  }

  const DiscreteSystem &system;
  const ResponseModel &model;
  const ResponseSpectrumParameters &parameters;
  const DesignSpectrum &spectrum;
  const HeldContacts &contacts;
  const ModalProblem &problem;
  const unsigned int n;
  /** M r_d and the masses m_d (influence_masses()). */
  std::array<Vector<double>, 3> Mr;
  std::array<double, 3> masses{{0., 0., 0.}};
  std::vector<Eigenpair> pairs;
  /** The kept modes, their omega (rad/s), Gamma per axis and eigenpairs. */
  std::vector<SpectralMode> modes;
  std::vector<double> omega;
  std::vector<std::array<double, 3>> gamma;
  std::vector<const Eigenpair *> kept;
  /** The displacement block: the monitors, the model's groups, the contacts. */
  std::vector<RowLayout> layout;
  std::size_t first_group_value = 0, first_contact_value = 0, n_values = 0;
  /** The monitors' translations (the accelerations' block). */
  std::vector<std::pair<const MonitorPoint *, unsigned int>> components;
  /** Per mode (rows of n_values, of components.size()). */
  std::vector<double> modal_values, modal_accelerations;
  /** Per axis: the missing mass's values at S_a(0), base reaction, mass ratio. */
  std::array<std::vector<double>, 3> missing_values, missing_accelerations;
  std::array<std::array<double, 3>, 3> missing_base{};
  std::array<double, 3> missing_ratio{{0., 0., 0.}}, zpa{{0., 0., 0.}};

  /** The displacement block's values for U and its load F into @p out. */
  void evaluate(const Vector<double> &U, const Vector<double> &F, double *out) const
  {
    monitor_values(U, out);
    std::vector<double> group_values;
    model.values(U, group_values, false);
    AssertThrow(group_values.size() == first_contact_value - first_group_value,
                ExcInternalError());
    std::copy(group_values.begin(), group_values.end(), out + first_group_value);
    Vector<double> residual(n);
    problem.stiffness().vmult(residual, U);
    residual -= F;
    for (unsigned int i = 0; i < n; ++i)
      if (system.fixed[i])
        residual[i] = 0.;
    std::vector<double> forces;
    contacts.forces(residual, forces);
    std::copy(forces.begin(), forces.end(), out + first_contact_value);
  }

  /** The monitors' translations for @p U into @p out. */
  void monitor_values(const Vector<double> &U, double *out) const
  {
    for (std::size_t j = 0; j < components.size(); ++j)
      out[j] = components[j].first->value(components[j].second, U);
  }
};

/**
 * Keep the modes with a response (RS5): Gamma, S_a and the rigid fraction
 * of each; a mode below 0.01 Hz with mass along a direction is refused,
 * one without it left out.
 */
void select_modes(Work &w)
{
  std::array<double, 3> cumulative{{0., 0., 0.}};
  for (const Eigenpair &pair : w.pairs)
  {
    SpectralMode mode;
    mode.frequency = std::sqrt(std::max(pair.lambda, 0.)) / (2. * M_PI);
    std::array<double, 3> g{{0., 0., 0.}};
    for (unsigned int d = 0; d < 3; ++d)
      if (w.Mr[d].size() == w.n && w.masses[d] > 0.)
      {
        g[d] = pair.phi * w.Mr[d];
        mode.participation[d] = g[d];
        mode.effective_mass_ratio[d] = g[d] * g[d] / w.masses[d];
      }
    if (mode.frequency < 0.01)
    {
      for (const unsigned int d : w.parameters.directions)
        if (mode.effective_mass_ratio[d] > 1e-9)
        {
          unsigned int largest = 0;
          for (unsigned int i = 0; i < w.n; ++i)
            if (std::abs(pair.phi[i]) > std::abs(pair.phi[largest]))
              largest = i;
          const std::string what =
              w.model.describe_dof ? w.model.describe_dof(largest) : std::string();
          std::ostringstream s;
          s << "response spectrum: along "
            << "XYZ"[d] << " a mode of " << mode.frequency << " Hz moves " << g[d] * g[d]
            << " kg (" << std::setprecision(3) << 100. * mode.effective_mass_ratio[d]
            << " % of the mass) freely: nothing holds "
            << (what.empty() ? "DoF " + std::to_string(largest) : what)
            << " (a mechanism or a rigid-body motion; add a support, or Response "
               "spectrum/Clearance contacts = closed for the flanges' play)";
          AssertThrow(false, ExcMessage(s.str()));
        }
      continue; // a zero-frequency mode without mass along the directions: no response
    }
    mode.period = 1. / mode.frequency;
    for (const unsigned int d : w.parameters.directions)
    {
      mode.spectral_acceleration[d] = w.spectrum(mode.period, d);
      cumulative[d] += mode.effective_mass_ratio[d];
      mode.cumulative_mass_ratio[d] = cumulative[d];
    }
    if (w.parameters.gupta)
      mode.rigid_fraction = gupta_rigid_fraction(mode.frequency,
                                                 w.parameters.gupta_frequencies[0],
                                                 w.parameters.gupta_frequencies[1]);
    w.modes.push_back(mode);
    w.omega.push_back(2. * M_PI * mode.frequency);
    w.gamma.push_back(g);
    w.kept.push_back(&pair);
  }
}

/**
 * The layout of the values: the monitors' translations (their rotations are
 * not reported), the model's groups, the contacts (the displacement block,
 * from U and its load); the monitors' accelerations come apart.
 */
void lay_out(Work &w)
{
  const auto add_row = [&](const std::string &name,
                           const std::string &unit,
                           const std::size_t size,
                           const bool stress)
  {
    w.layout.push_back({name, unit, w.n_values, size, stress});
    w.n_values += size;
  };
  for (const MonitorPoint &m : w.system.monitors)
    for (unsigned int i = 0; i < m.labels.size(); ++i)
      if (m.labels[i] == "x" || m.labels[i] == "y" || m.labels[i] == "z")
      {
        w.components.emplace_back(&m, i);
        add_row(m.name + ".u" + m.labels[i], "m", 1, false);
      }
  w.first_group_value = w.n_values;
  for (const ResponseGroup &g : w.model.groups)
    add_row(g.name, g.unit, g.size, g.stress);
  w.first_contact_value = w.n_values;
  for (const std::string &name : w.contacts.names)
    add_row(name + ".force", "N", 1, false);
}

/**
 * Each mode's values once (RS6), at unit modal coordinate: the mode shape
 * and its inertia omega^2 M phi; a direction only scales them.
 */
void evaluate_modes(Work &w)
{
  const std::size_t n_modes = w.kept.size(), n_components = w.components.size();
  w.modal_values.resize(n_modes * w.n_values);
  w.modal_accelerations.resize(n_modes * n_components);
  for (std::size_t k = 0; k < n_modes; ++k)
  {
    Vector<double> F(w.n);
    w.problem.mass().vmult(F, w.kept[k]->phi);
    F *= w.kept[k]->lambda;
    w.evaluate(w.kept[k]->phi, F, w.modal_values.data() + k * w.n_values);
    w.monitor_values(w.kept[k]->phi, w.modal_accelerations.data() + k * n_components);
  }
}

/**
 * The missing mass per direction (RS3, RS6): the load F_0 = M r - sum
 * Gamma M phi, its mass ratio and base reaction, and with Missing mass its
 * static response K^-1 F_0 and rigid acceleration (r - sum Gamma phi), at
 * the zero-period acceleration.
 */
void add_missing_mass(Work &w)
{
  for (const unsigned int d : w.parameters.directions)
  {
    w.missing_values[d].assign(w.n_values, 0.);
    w.missing_accelerations[d].assign(w.components.size(), 0.);
    const Vector<double> &r = w.system.influence[d];
    Vector<double> F(w.Mr[d]), shape(r.size() == w.n ? r : Vector<double>(w.n));
    for (std::size_t k = 0; k < w.kept.size(); ++k)
    {
      Vector<double> Mphi(w.n);
      w.problem.mass().vmult(Mphi, w.kept[k]->phi);
      F.add(-w.gamma[k][d], Mphi);
      shape.add(-w.gamma[k][d], w.kept[k]->phi);
    }
    w.missing_ratio[d] = r.size() == w.n ? r * F / w.masses[d] : 0.;
    if (!w.parameters.missing_mass)
      continue;
    // the base reaction of the missing mass: the resultant of its load
    for (unsigned int e = 0; e < 3; ++e)
      w.missing_base[d][e] =
          w.system.influence[e].size() == w.n ? w.system.influence[e] * F * w.zpa[d] : 0.;
    Vector<double> condensed(F);
    w.problem.condense_load(condensed);
    const Vector<double> U = w.problem.solve_static(condensed);
    w.evaluate(U, F, w.missing_values[d].data());
    w.monitor_values(shape, w.missing_accelerations[d].data());
    for (double &v : w.missing_values[d])
      v *= w.zpa[d];
    for (double &v : w.missing_accelerations[d])
      v *= w.zpa[d];
  }
}

/**
 * The peak along a direction of one value from its per-mode values (RS2,
 * RS3): the modal responses scaled by the mode's peak coordinate, combined
 * with the kept coefficients and the missing mass.
 */
class ModalPeaks
{
public:
  explicit ModalPeaks(const Work &w)
      : n_modes(w.kept.size()), correlation(w.omega,
                                            w.spectrum.parameters().damping_ratio,
                                            w.parameters.modal_combination,
                                            rigid_fractions(w)),
        modal(n_modes)
  {
    for (const unsigned int d : w.parameters.directions)
      for (std::size_t k = 0; k < n_modes; ++k)
      {
        acceleration[d].push_back(w.gamma[k][d] * w.modes[k].spectral_acceleration[d]);
        coordinate[d].push_back(acceleration[d].back() / (w.omega[k] * w.omega[k]));
      }
  }

  /**
   * The value @p j of @p values (n_modes rows of @p stride) along @p d: a
   * displacement-block value (coordinate scale) or an acceleration.
   */
  double peak(const std::vector<double> &values,
              const std::size_t stride,
              const std::size_t j,
              const unsigned int d,
              const bool is_acceleration,
              const double missing) const
  {
    const std::vector<double> &scale = is_acceleration ? acceleration[d] : coordinate[d];
    for (std::size_t k = 0; k < n_modes; ++k)
      modal[k] = values[k * stride + j] * scale[k];
    return correlation.combine(modal.data(), missing);
  }

  /** The base reaction along @p e excited along @p d: Gamma_ke Gamma_kd S_a,kd. */
  double base(const Work &w, const unsigned int e, const unsigned int d) const
  {
    for (std::size_t k = 0; k < n_modes; ++k)
      modal[k] = w.gamma[k][e] * acceleration[d][k];
    return correlation.combine(modal.data(), w.missing_base[d][e]);
  }

private:
  static std::vector<double> rigid_fractions(const Work &w)
  {
    std::vector<double> alpha;
    if (w.parameters.gupta)
      for (const SpectralMode &mode : w.modes)
        alpha.push_back(mode.rigid_fraction);
    return alpha;
  }

  const std::size_t n_modes;
  const ModalCorrelation correlation;
  /** Per axis and mode: the peak modal coordinate and its acceleration. */
  std::array<std::vector<double>, 3> coordinate, acceleration;
  mutable std::vector<double> modal;
};
/** What the combinations give (RS2-RS4). */
struct Combination
{
  /** The rows of response_spectrum.csv, in order. */
  std::vector<SpectralQuantity> rows;
  /** The combined value of every value of the displacement block (stresses: 0). */
  std::vector<double> values;
  /** The combined components of every stress point (6 per point). */
  std::vector<double> stress;
  /** Per stress group, the combined von Mises stress at each point. */
  std::vector<std::vector<double>> envelopes;
};

/** The rows of the displacement block, combined value by value. */
void combine_displacement_block(const Work &w, const ModalPeaks &peaks, Combination &c)
{
  const std::vector<unsigned int> &directions = w.parameters.directions;
  const DirectionalCombination rule = w.parameters.directional_combination;
  const auto peak = [&](const std::size_t j, const unsigned int d)
  { return peaks.peak(w.modal_values, w.n_values, j, d, false, w.missing_values[d][j]); };
  c.values.assign(w.n_values, 0.);
  for (const RowLayout &row : w.layout)
  {
    SpectralQuantity q{row.name, row.unit, {{0., 0., 0.}}, 0.};
    if (row.stress)
    {
      // component by component, then the von Mises stress of the peaks
      c.envelopes.emplace_back(row.size / 6, 0.);
      for (std::size_t p = 0; p < row.size / 6; ++p)
      {
        std::array<std::array<double, 6>, 3> by_direction{};
        std::array<double, 6> total{};
        for (unsigned int k = 0; k < 6; ++k)
        {
          const std::size_t j = row.first + 6 * p + k;
          for (const unsigned int d : directions)
            by_direction[d][k] = peak(j, d);
          total[k] = combine_directions(
              {{by_direction[0][k], by_direction[1][k], by_direction[2][k]}}, rule);
          c.stress.push_back(total[k]);
        }
        for (const unsigned int d : directions)
          q.peak[d] = std::max(q.peak[d], von_mises_of(by_direction[d].data()));
        c.envelopes.back()[p] = von_mises_of(total.data());
        q.combined = std::max(q.combined, c.envelopes.back()[p]);
      }
    }
    else
      // station by station, the largest reported
      for (std::size_t j = row.first; j < row.first + row.size; ++j)
      {
        std::array<double, 3> by_direction{{0., 0., 0.}};
        for (const unsigned int d : directions)
          by_direction[d] = peak(j, d);
        for (unsigned int d = 0; d < 3; ++d)
          q.peak[d] = std::max(q.peak[d], by_direction[d]);
        c.values[j] = combine_directions(by_direction, rule);
        q.combined = std::max(q.combined, c.values[j]);
      }
    c.rows.push_back(q);
  }
}

/**
 * The combinations: the displacement block, the monitors' absolute
 * accelerations (the pseudo-accelerations and the missing mass at the
 * zero-period acceleration), the base reaction.
 */
Combination combine(const Work &w)
{
  const ModalPeaks peaks(w);
  Combination c;
  combine_displacement_block(w, peaks, c);
  const DirectionalCombination rule = w.parameters.directional_combination;
  for (std::size_t j = 0; j < w.components.size(); ++j)
  {
    const MonitorPoint &m = *w.components[j].first;
    SpectralQuantity q{
        m.name + ".a" + m.labels[w.components[j].second], "m/s^2", {{0., 0., 0.}}, 0.};
    for (const unsigned int d : w.parameters.directions)
      q.peak[d] = peaks.peak(w.modal_accelerations,
                             w.components.size(),
                             j,
                             d,
                             true,
                             w.missing_accelerations[d][j]);
    q.combined = combine_directions(q.peak, rule);
    c.rows.push_back(q);
  }
  for (unsigned int e = 0; e < 3; ++e)
  {
    SpectralQuantity q{std::string("base.F") + "xyz"[e], "N", {{0., 0., 0.}}, 0.};
    for (const unsigned int d : w.parameters.directions)
      q.peak[d] = peaks.base(w, e, d);
    q.combined = combine_directions(q.peak, rule);
    c.rows.push_back(q);
  }
  return c;
}
} // namespace

ResponseSpectrumAnalysis::ResponseSpectrumAnalysis(
    const DiscreteSystem &system,
    const ResponseModel &model,
    const ResponseSpectrumParameters &parameters,
    const DesignSpectrum &spectrum,
    const Vector<double> &rope_state,
    const std::string &linear_solver)
    : model(model)
{
  const auto start = std::chrono::steady_clock::now();
  for (const unsigned int d : parameters.directions)
    AssertThrow(!(d == 2 && spectrum.parameters().type != "table" &&
                  !spectrum.parameters().vertical),
                ExcMessage("Response spectrum/Directions: Z has no spectrum (Design "
                           "spectrum/Vertical = false with an EC8 type); set Vertical = "
                           "true or leave Z out"));
  // the contacts held: zero gap, and the clearance rows when closed
  const HeldContacts contacts(system, parameters.clearance_closed);
  n_closed = contacts.n_closed;
  n_held = contacts.n_clearance;
  const ModalProblem problem(
      system, true, &rope_state, linear_solver, &contacts.clearance_rows());
  Work w(system, model, parameters, spectrum, contacts, problem);
  w.Mr = influence_masses(system, problem.mass(), w.masses);
  masses = w.masses;
  for (const unsigned int d : parameters.directions)
    AssertThrow(masses[d] > 0.,
                ExcMessage(std::string("Response spectrum/Directions: the model has no "
                                       "mass that moves along ") +
                           "XYZ"[d] + " (its free DoFs carry none); leave " + "XYZ"[d] +
                           " out"));

  // every mode up to the cut-off, counted by the inertia of K - omega_c^2 M (RS5)
  const double omega_c = 2. * M_PI * parameters.cutoff_frequency;
  n_below = problem.count_below(omega_c * omega_c);
  {
    std::ostringstream s;
    s << "Response spectrum/Cutoff frequency: " << parameters.cutoff_frequency
      << " Hz needs " << n_below << " modes, more than Response spectrum/Maximum modes = "
      << parameters.maximum_modes << " (raise it, or lower the cut-off)";
    AssertThrow(n_below <= parameters.maximum_modes, ExcMessage(s.str()));
  }
  w.pairs = problem.modes_near(problem.lowest_shift(), n_below);
  wall_times[0] = seconds_since(start);

  const auto per_mode_start = std::chrono::steady_clock::now();
  select_modes(w);
  kept_modes = w.modes;
  for (const unsigned int d : parameters.directions)
  {
    effective_ratio[d] =
        kept_modes.empty() ? 0. : kept_modes.back().cumulative_mass_ratio[d];
    zpa[d] = w.zpa[d] = spectrum.zero_period_value(d);
  }
  lay_out(w);
  first_group_value = w.first_group_value;
  n_group_values = w.first_contact_value - w.first_group_value;
  for (const RowLayout &row : w.layout)
    layout.push_back({row.first, row.size, row.stress});
  evaluate_modes(w);
  wall_times[1] = seconds_since(per_mode_start);

  const auto missing_start = std::chrono::steady_clock::now();
  add_missing_mass(w);
  missing_ratio = w.missing_ratio;
  wall_times[2] = seconds_since(missing_start);

  const auto combine_start = std::chrono::steady_clock::now();
  Combination c = combine(w);
  rows = std::move(c.rows);
  combined_values = std::move(c.values);
  combined_stress = std::move(c.stress);
  envelopes = std::move(c.envelopes);
  // the contacts' rows become their summary entries
  for (std::size_t k = 0; k < contacts.names.size(); ++k)
  {
    SpectralContact contact;
    contact.name = contacts.names[k];
    contact.change = rows[w.layout.size() - contacts.names.size() + k].combined;
    contact.two_sided = contacts.two_sided[k];
    contact_results.push_back(contact);
    contact_rows.push_back(contacts.members[k]);
  }
  wall_times[3] = seconds_since(combine_start);
}

void ResponseSpectrumAnalysis::set_static_state(const Vector<double> &U,
                                                const std::vector<double> &static_forces)
{
  for (std::size_t c = 0; c < contact_results.size(); ++c)
  {
    contact_results[c].static_force = 0.;
    for (const unsigned int k : contact_rows[c])
      contact_results[c].static_force += k < static_forces.size() ? static_forces[k] : 0.;
  }
  // the static values of the model's groups (with the members' own weight);
  // the monitors' and contacts' rows are changes about it
  std::vector<double> values;
  model.values(U, values, true);
  AssertThrow(values.size() == n_group_values, ExcInternalError());
  std::size_t stress_point = 0;
  for (std::size_t r = 0; r < layout.size(); ++r)
  {
    const Row &row = layout[r];
    SpectralQuantity &q = rows[r];
    const bool in_group =
        row.first >= first_group_value && row.first < first_group_value + n_group_values;
    if (!in_group)
    {
      q.with_static = q.combined;
      continue;
    }
    q.with_static = 0.;
    const double *s = values.data() + (row.first - first_group_value);
    if (row.stress)
      for (std::size_t p = 0; p < row.size / 6; ++p, ++stress_point)
      {
        std::array<double, 6> moved;
        for (unsigned int c = 0; c < 6; ++c)
        {
          const double st = s[6 * p + c], comb = combined_stress[6 * stress_point + c];
          moved[c] = st + (st < 0. ? -comb : comb);
        }
        q.with_static = std::max(q.with_static, von_mises_of(moved.data()));
      }
    else
      for (std::size_t j = 0; j < row.size; ++j)
        q.with_static =
            std::max(q.with_static, std::abs(s[j]) + combined_values[row.first + j]);
  }
}
} // namespace hati
