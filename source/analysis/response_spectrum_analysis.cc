// The response-spectrum analysis (doc/theory.md 14): the modes of the
// linearised model up to the cut-off, each quantity's response per mode
// from the mode shape, the missing mass, the combinations.

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <deal.II/base/utilities.h>
#include <hati/analysis/modal_analysis.h>
#include <hati/analysis/response_spectrum_analysis.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <map>
#include <sstream>

namespace hati
{
namespace
{
/** @p text as a finite number, or one line naming @p entry. */
double parse_number(const std::string &text, const std::string &entry)
{
  const std::string t = Utilities::trim(text);
  char *end = nullptr;
  const double value = std::strtod(t.c_str(), &end);
  AssertThrow(!t.empty() && end == t.c_str() + t.size() && std::isfinite(value),
              ExcMessage(entry + ": '" + t + "' is not a number"));
  return value;
}
} // namespace

void ResponseSpectrumParameters::declare_parameters(ParameterHandler &prm)
{
  prm.enter_subsection("Response spectrum");
  prm.declare_entry(
      "Directions",
      "X, Y, Z",
      Patterns::Anything(),
      "The excitation directions of Analysis/Type = response spectrum, a list of X, Y "
      "and Z (global axes), each with its spectrum of subsection Design spectrum "
      "(Z: the EC8 vertical spectrum, or a table).");
  prm.declare_entry(
      "Modal combination",
      "CQC",
      Patterns::Selection("CQC|SRSS"),
      "How the modes' peaks are combined (doc/theory.md 14, RS1-RS2): CQC, the "
      "complete quadratic combination with Der Kiureghian's correlation coefficient on "
      "the ratio of the frequencies at the spectrum's Damping ratio; SRSS, the square "
      "root of the sum of the squares.");
  prm.declare_entry("Cutoff frequency",
                    "33",
                    Patterns::Anything(),
                    "Modes up to this frequency (Hz, > 0) are combined: every one of "
                    "them is computed (counted first, RS5), however many Analysis/Number "
                    "of modes asks for.");
  prm.declare_entry("Maximum modes",
                    "500",
                    Patterns::Integer(1),
                    "The most modes computed (-): a cut-off that needs more is refused "
                    "with the count it needs.");
  prm.declare_entry(
      "Missing mass",
      "true",
      Patterns::Bool(),
      "Add the static response to the inertia the kept modes leave out, K^-1 (M r - "
      "sum Gamma_k M phi_k) times the spectrum's zero-period acceleration, to the modal "
      "part by SRSS (RS3; EN 1998-1 4.3.3.3, US NRC RG 1.92 method A).");
  prm.declare_entry(
      "Rigid response",
      "none",
      Patterns::Selection("none|Gupta"),
      "Gupta: the rigid part alpha_k R_k of the modes between the Gupta frequencies "
      "(alpha_k = ln(f/f1) / ln(f2/f1), 0 below f1, 1 above f2) is summed "
      "algebraically with the missing mass (RS3, US NRC RG 1.92); none: alpha = 0.");
  prm.declare_entry("Gupta frequencies",
                    "",
                    Patterns::Anything(),
                    "f1, f2 (Hz, 0 < f1 < f2) of Rigid response = Gupta.");
  prm.declare_entry(
      "Directional combination",
      "SRSS",
      Patterns::Selection("SRSS|100-40-40|100-30-30"),
      "How the directions' peaks are combined (RS4): SRSS; 100-40-40 (ASCE 4, ASME "
      "NOG-1 practice) or 100-30-30 (EN 1998-1 4.3.3.5.2), the largest of R_i + c (R_j "
      "+ R_k).");
  prm.declare_entry(
      "Clearance contacts",
      "closed",
      Patterns::Selection("closed|open"),
      "Two-sided contacts with a clearance (the wheel flanges' lateral play): closed, "
      "held as bilateral supports at their centred position (the flanges engaged); "
      "open, left free as in the modal analysis (the default crane then has modes of "
      "zero frequency along its play, which are refused as mechanisms).");
  prm.leave_subsection();
}

void ResponseSpectrumParameters::parse_parameters(ParameterHandler &prm)
{
  prm.enter_subsection("Response spectrum");
  directions.clear();
  for (const std::string &item : Utilities::split_string_list(prm.get("Directions"), ','))
  {
    const std::string axis = Utilities::trim(item);
    AssertThrow(axis == "X" || axis == "Y" || axis == "Z",
                ExcMessage("Response spectrum/Directions: '" + axis +
                           "': a list of X, Y and Z is expected"));
    const unsigned int d = axis[0] - 'X';
    AssertThrow(std::find(directions.begin(), directions.end(), d) == directions.end(),
                ExcMessage("Response spectrum/Directions: " + axis + " is given twice"));
    directions.push_back(d);
  }
  AssertThrow(!directions.empty(),
              ExcMessage("Response spectrum/Directions: empty; a list of X, Y and Z is "
                         "expected"));
  std::sort(directions.begin(), directions.end());
  modal_combination = parse_modal_combination(prm.get("Modal combination"));
  directional_combination =
      parse_directional_combination(prm.get("Directional combination"));
  cutoff_frequency =
      parse_number(prm.get("Cutoff frequency"), "Response spectrum/Cutoff frequency");
  AssertThrow(
      cutoff_frequency > 0.,
      ExcMessage("Response spectrum/Cutoff frequency: " + prm.get("Cutoff frequency") +
                 " Hz; a frequency > 0 is expected"));
  maximum_modes = prm.get_integer("Maximum modes");
  missing_mass = prm.get_bool("Missing mass");
  gupta = prm.get("Rigid response") == "Gupta";
  const std::string frequencies = prm.get("Gupta frequencies");
  if (gupta)
  {
    const std::vector<std::string> items = Utilities::split_string_list(frequencies, ',');
    AssertThrow(items.size() == 2,
                ExcMessage("Response spectrum/Gupta frequencies: '" + frequencies +
                           "': two frequencies f1, f2 (Hz) are expected with Rigid "
                           "response = Gupta"));
    for (unsigned int i = 0; i < 2; ++i)
      gupta_frequencies[i] =
          parse_number(items[i], "Response spectrum/Gupta frequencies");
    AssertThrow(gupta_frequencies[0] > 0. && gupta_frequencies[1] > gupta_frequencies[0],
                ExcMessage("Response spectrum/Gupta frequencies: '" + frequencies +
                           "': 0 < f1 < f2 (Hz) is expected"));
  }
  clearance_closed = prm.get("Clearance contacts") == "closed";
  prm.leave_subsection();
}

namespace
{
/** The seconds since @p start. */
double seconds_since(const std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/** The dot product of two sparse rows. */
double row_product(const SparseRow &a, const SparseRow &b)
{
  double s = 0.;
  for (unsigned int i = 0; i < a.dofs.size(); ++i)
    for (unsigned int j = 0; j < b.dofs.size(); ++j)
      if (a.dofs[i] == b.dofs[j])
        s += a.coefficients[i] * b.coefficients[j];
  return s;
}

/**
 * The contacts of a system as the response-spectrum analysis holds them:
 * every contact name with its rows, which rows are held (zero gap, and the
 * clearance rows when they are closed) and their multipliers (RS6): the
 * forces `mu` with `L^T mu = K U - F` for a displacement U in equilibrium
 * with the load F on the constrained space, the minimum-norm solution
 * `mu = (L L^T)^+ L (K U - F)` (a pair of opposite rows shares its force).
 */
class HeldContacts
{
public:
  HeldContacts(const DiscreteSystem &system, const bool clearance_closed)
      : n(system.n_dofs()), fixed(system.fixed)
  {
    std::map<std::string, unsigned int> index;
    for (unsigned int k = 0; k < system.contacts.size(); ++k)
    {
      const ContactRow &row = system.contacts[k];
      if (row.constraint)
        continue;
      const auto [it, added] = index.emplace(row.name, names.size());
      if (added)
      {
        names.push_back(row.name);
        members.emplace_back();
      }
      members[it->second].push_back(k);
    }
    two_sided.assign(names.size(), false);
    for (unsigned int c = 0; c < names.size(); ++c)
    {
      const std::vector<unsigned int> &m = members[c];
      const ContactRow &first = system.contacts[m[0]];
      // a two-sided contact: two opposite rows of one name
      if (m.size() == 2)
      {
        const ContactRow &second = system.contacts[m[1]];
        const double ab = row_product(first, second), aa = row_product(first, first),
                     bb = row_product(second, second);
        two_sided[c] = ab < 0. && std::abs(ab * ab - aa * bb) <= 1e-12 * aa * bb;
      }
      for (const unsigned int k : m)
      {
        const ContactRow &row = system.contacts[k];
        const bool closed = row.initial_gap == 0.;
        const bool clearance = two_sided[c] && row.initial_gap > 0.;
        if (closed || (clearance && clearance_closed))
        {
          add_row(row, c, row_product(row, first) >= 0. ? 1. : -1.);
          if (closed)
            ++n_closed;
          else
            ++n_clearance;
          if (clearance)
            held_clearance.push_back(row);
        }
        // a closed frictional contact sticks: its tangents are held too (A9)
        if (closed && row.frictional())
          for (const SparseRow &tangent : row.tangents)
            add_row(tangent, names.size(), 0.);
      }
    }
    // (L L^T)^+ on the free DoFs
    const unsigned int m = rows.size();
    if (m == 0)
      return;
    LAPACKFullMatrix<double> G(m, m);
    for (unsigned int i = 0; i < m; ++i)
      for (unsigned int j = i; j < m; ++j)
        G(i, j) = G(j, i) = row_product(rows[i], rows[j]);
    G.compute_inverse_svd(1e-10);
    pseudo_inverse.reinit(m, m);
    for (unsigned int i = 0; i < m; ++i)
      for (unsigned int j = 0; j < m; ++j)
        pseudo_inverse(i, j) = G(i, j);
  }

  /** The clearance rows to hold (ModalProblem's held rows). */
  const std::vector<SparseRow> &clearance_rows() const { return held_clearance; }

  /**
   * The force of every contact name (N, along its first row's normal) for
   * the residual @p residual = K U - F (zero on fixed DoFs), appended to
   * @p forces.
   */
  void forces(const Vector<double> &residual, std::vector<double> &forces) const
  {
    const unsigned int m = rows.size();
    std::vector<double> Lr(m, 0.);
    for (unsigned int i = 0; i < m; ++i)
      Lr[i] = rows[i].apply(residual);
    const std::size_t first = forces.size();
    forces.resize(first + names.size(), 0.);
    for (unsigned int i = 0; i < m; ++i)
      if (contact[i] < names.size())
      {
        double mu = 0.;
        for (unsigned int j = 0; j < m; ++j)
          mu += pseudo_inverse(i, j) * Lr[j];
        forces[first + contact[i]] += sign[i] * mu;
      }
  }

  std::vector<std::string> names;
  std::vector<std::vector<unsigned int>> members;
  std::vector<bool> two_sided;
  unsigned int n_closed = 0, n_clearance = 0;

private:
  /** Add @p row (its fixed DoFs left out) for the contact @p c with @p s. */
  void add_row(const SparseRow &row, const std::size_t c, const double s)
  {
    SparseRow free;
    for (unsigned int i = 0; i < row.dofs.size(); ++i)
      if (!fixed[row.dofs[i]] && row.coefficients[i] != 0.)
      {
        free.dofs.push_back(row.dofs[i]);
        free.coefficients.push_back(row.coefficients[i]);
      }
    rows.push_back(free);
    contact.push_back(c);
    sign.push_back(s);
  }

  const unsigned int n;
  const std::vector<bool> &fixed;
  std::vector<SparseRow> rows, held_clearance;
  /** Per row: its contact name (names.size() for a tangent) and sign. */
  std::vector<std::size_t> contact;
  std::vector<double> sign;
  FullMatrix<double> pseudo_inverse;
};

/** What a value of the displacement block is: its row and the kind of row. */
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
} // namespace

ResponseSpectrumAnalysis::ResponseSpectrumAnalysis(
    const DiscreteSystem &system,
    const Model &model,
    const ResponseSpectrumParameters &parameters,
    const DesignSpectrum &spectrum,
    const Vector<double> &rope_state,
    const std::string &linear_solver)
    : model(model)
{
  const auto start = std::chrono::steady_clock::now();
  const unsigned int n = system.n_dofs();
  const std::vector<unsigned int> &directions = parameters.directions;
  const double xi = spectrum.parameters().damping_ratio;
  for (const unsigned int d : directions)
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
  const std::array<Vector<double>, 3> Mr =
      influence_masses(system, problem.mass(), masses);
  for (const unsigned int d : directions)
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
  std::vector<Eigenpair> pairs = problem.modes_near(problem.lowest_shift(), n_below);
  wall_times[0] = seconds_since(start);

  // the modes: Gamma, S_a, the mechanism check
  const auto per_mode_start = std::chrono::steady_clock::now();
  std::vector<double> omega;
  std::vector<std::array<double, 3>> gamma;
  std::vector<const Eigenpair *> kept;
  std::array<double, 3> cumulative{{0., 0., 0.}};
  for (const Eigenpair &pair : pairs)
  {
    SpectralMode mode;
    mode.frequency = std::sqrt(std::max(pair.lambda, 0.)) / (2. * M_PI);
    std::array<double, 3> g{{0., 0., 0.}};
    for (unsigned int d = 0; d < 3; ++d)
      if (Mr[d].size() == n && masses[d] > 0.)
      {
        g[d] = pair.phi * Mr[d];
        mode.participation[d] = g[d];
        mode.effective_mass_ratio[d] = g[d] * g[d] / masses[d];
      }
    if (mode.frequency < 0.01)
    {
      for (const unsigned int d : directions)
        if (mode.effective_mass_ratio[d] > 1e-9)
        {
          unsigned int largest = 0;
          for (unsigned int i = 0; i < n; ++i)
            if (std::abs(pair.phi[i]) > std::abs(pair.phi[largest]))
              largest = i;
          const DofDescription what = model.describe_dof(largest);
          std::ostringstream s;
          s << "response spectrum: along "
            << "XYZ"[d] << " a mode of " << mode.frequency << " Hz moves " << g[d] * g[d]
            << " kg (" << std::setprecision(3) << 100. * mode.effective_mass_ratio[d]
            << " % of the mass) freely: nothing holds "
            << (what.component.empty() ? "DoF " + std::to_string(largest)
                                       : what.component)
            << (what.location.empty() ? std::string() : " at " + what.location)
            << " (a mechanism or a rigid-body motion; add a support, or Response "
               "spectrum/Clearance contacts = closed for the flanges' play)";
          AssertThrow(false, ExcMessage(s.str()));
        }
      continue; // a zero-frequency mode without mass along the directions: no response
    }
    mode.period = 1. / mode.frequency;
    for (const unsigned int d : directions)
    {
      mode.spectral_acceleration[d] = spectrum(mode.period, d);
      cumulative[d] += mode.effective_mass_ratio[d];
      mode.cumulative_mass_ratio[d] = cumulative[d];
    }
    if (parameters.gupta)
      mode.rigid_fraction = gupta_rigid_fraction(mode.frequency,
                                                 parameters.gupta_frequencies[0],
                                                 parameters.gupta_frequencies[1]);
    kept_modes.push_back(mode);
    omega.push_back(2. * M_PI * mode.frequency);
    gamma.push_back(g);
    kept.push_back(&pair);
  }
  effective_ratio = cumulative;
  for (const unsigned int d : directions)
    zpa[d] = spectrum.zero_period_value(d);

  // the layout: monitors' displacements, the model's groups, the contacts
  // (the displacement block, from U and its load), then the monitors'
  // accelerations and the base reaction
  std::vector<RowLayout> rows_layout;
  std::size_t n_values = 0;
  const auto add_row = [&](const std::string &name,
                           const std::string &unit,
                           const std::size_t size,
                           const bool stress)
  {
    rows_layout.push_back({name, unit, n_values, size, stress});
    layout.push_back({n_values, size, stress});
    n_values += size;
  };
  // the monitors' translations (their rotations are not reported)
  std::vector<std::pair<const MonitorPoint *, unsigned int>> components;
  for (const MonitorPoint &m : system.monitors)
    for (unsigned int i = 0; i < m.labels.size(); ++i)
      if (m.labels[i] == "x" || m.labels[i] == "y" || m.labels[i] == "z")
      {
        components.emplace_back(&m, i);
        add_row(m.name + ".u" + m.labels[i], "m", 1, false);
      }
  const std::vector<ResponseGroup> groups = model.response_groups();
  first_group_value = n_values;
  for (const ResponseGroup &g : groups)
    add_row(g.name, g.unit, g.size, g.stress);
  const std::size_t first_contact_value = n_values;
  n_group_values = first_contact_value - first_group_value;
  for (const std::string &name : contacts.names)
    add_row(name + ".force", "N", 1, false);
  const std::size_t n_displacement_values = n_values;
  const std::size_t n_monitor_components = components.size();

  // the values of the displacement block for a displacement U and its load F
  std::vector<double> group_values;
  const auto evaluate = [&](const Vector<double> &U, const Vector<double> &F, double *out)
  {
    for (std::size_t j = 0; j < components.size(); ++j)
      out[j] = components[j].first->value(components[j].second, U);
    model.response_values(U, group_values);
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
  };
  const auto monitor_values = [&](const Vector<double> &U, double *out)
  {
    for (std::size_t j = 0; j < components.size(); ++j)
      out[j] = components[j].first->value(components[j].second, U);
  };

  // each mode's values once (RS6): mode k's response along d is its values
  // times Gamma_kd S_a,kd / omega_k^2 (displacements and forces) or times
  // Gamma_kd S_a,kd (accelerations)
  const std::size_t n_modes = kept.size();
  std::vector<double> modal_values(n_modes * n_displacement_values),
      modal_accelerations(n_modes * n_monitor_components);
  for (std::size_t k = 0; k < n_modes; ++k)
  {
    Vector<double> F(n);
    problem.mass().vmult(F, kept[k]->phi);
    F *= kept[k]->lambda;
    evaluate(kept[k]->phi, F, modal_values.data() + k * n_displacement_values);
    monitor_values(kept[k]->phi, modal_accelerations.data() + k * n_monitor_components);
  }
  wall_times[1] = seconds_since(per_mode_start);

  // the missing mass per direction (RS3): U = K^-1 (M r - sum Gamma M phi) a_0
  const auto missing_start = std::chrono::steady_clock::now();
  std::array<std::vector<double>, 3> missing_values, missing_accelerations;
  std::array<std::array<double, 3>, 3> missing_base{};
  for (const unsigned int d : directions)
  {
    missing_values[d].assign(n_displacement_values, 0.);
    missing_accelerations[d].assign(n_monitor_components, 0.);
    Vector<double> F(Mr[d]),
        shape(system.influence[d].size() == n ? system.influence[d] : Vector<double>(n));
    for (std::size_t k = 0; k < n_modes; ++k)
    {
      Vector<double> Mphi(n);
      problem.mass().vmult(Mphi, kept[k]->phi);
      F.add(-gamma[k][d], Mphi);
      shape.add(-gamma[k][d], kept[k]->phi);
    }
    missing_ratio[d] =
        system.influence[d].size() == n ? system.influence[d] * F / masses[d] : 0.;
    // the base reaction of the missing mass: the resultant of its load
    for (unsigned int e = 0; e < 3; ++e)
      missing_base[d][e] =
          system.influence[e].size() == n ? system.influence[e] * F * zpa[d] : 0.;
    if (!parameters.missing_mass)
      continue;
    Vector<double> condensed(F);
    problem.condense_load(condensed);
    const Vector<double> U = problem.solve_static(condensed);
    evaluate(U, F, missing_values[d].data());
    monitor_values(shape, missing_accelerations[d].data());
    for (double &v : missing_values[d])
      v *= zpa[d];
    for (double &v : missing_accelerations[d])
      v *= zpa[d];
  }
  if (!parameters.missing_mass)
    for (auto &row : missing_base)
      row = {{0., 0., 0.}};
  wall_times[2] = seconds_since(missing_start);

  // the combinations (RS2-RS4), value by value
  const auto combine_start = std::chrono::steady_clock::now();
  std::vector<double> alpha;
  if (parameters.gupta)
    for (const SpectralMode &mode : kept_modes)
      alpha.push_back(mode.rigid_fraction);
  const ModalCorrelation correlation(omega, xi, parameters.modal_combination, alpha);
  // per direction the modal coordinate's peak (displacement) and its
  // acceleration's
  std::array<std::vector<double>, 3> q_peak, a_peak;
  for (const unsigned int d : directions)
    for (std::size_t k = 0; k < n_modes; ++k)
    {
      a_peak[d].push_back(gamma[k][d] * kept_modes[k].spectral_acceleration[d]);
      q_peak[d].push_back(a_peak[d].back() / (omega[k] * omega[k]));
    }
  std::vector<double> modal(n_modes);
  // the peak along d of the value j of a block of values per mode
  const auto combined = [&](const std::vector<double> &values,
                            const std::size_t stride,
                            const std::size_t j,
                            const std::vector<double> &scale,
                            const double missing)
  {
    for (std::size_t k = 0; k < n_modes; ++k)
      modal[k] = values[k * stride + j] * scale[k];
    return correlation.combine(modal.data(), missing);
  };
  // the rows of the displacement block
  combined_values.assign(n_displacement_values, 0.);
  for (const RowLayout &row : rows_layout)
  {
    SpectralQuantity q{row.name, row.unit, {{0., 0., 0.}}, 0.};
    if (row.stress)
    {
      envelopes.emplace_back(row.size / 6, 0.);
      for (std::size_t p = 0; p < row.size / 6; ++p)
      {
        std::array<std::array<double, 6>, 3> peaks{};
        std::array<double, 6> total{};
        for (unsigned int c = 0; c < 6; ++c)
        {
          const std::size_t j = row.first + 6 * p + c;
          for (const unsigned int d : directions)
            peaks[d][c] = combined(
                modal_values, n_displacement_values, j, q_peak[d], missing_values[d][j]);
          total[c] = combine_directions({{peaks[0][c], peaks[1][c], peaks[2][c]}},
                                        parameters.directional_combination);
          combined_stress.push_back(total[c]);
        }
        for (const unsigned int d : directions)
          q.peak[d] = std::max(q.peak[d], von_mises_of(peaks[d].data()));
        envelopes.back()[p] = von_mises_of(total.data());
        q.combined = std::max(q.combined, envelopes.back()[p]);
      }
    }
    else
      for (std::size_t j = row.first; j < row.first + row.size; ++j)
      {
        std::array<double, 3> peak{{0., 0., 0.}};
        for (const unsigned int d : directions)
          peak[d] = combined(
              modal_values, n_displacement_values, j, q_peak[d], missing_values[d][j]);
        for (unsigned int d = 0; d < 3; ++d)
          q.peak[d] = std::max(q.peak[d], peak[d]);
        combined_values[j] = combine_directions(peak, parameters.directional_combination);
        q.combined = std::max(q.combined, combined_values[j]);
      }
    rows.push_back(q);
  }
  // the contacts' rows become their summary entries
  for (std::size_t c = 0; c < contacts.names.size(); ++c)
  {
    SpectralContact contact;
    contact.name = contacts.names[c];
    contact.change = rows[rows_layout.size() - contacts.names.size() + c].combined;
    contact.two_sided = contacts.two_sided[c];
    contact_results.push_back(contact);
    contact_rows.push_back(contacts.members[c]);
  }
  // the monitors' absolute accelerations: the pseudo-accelerations and the
  // missing mass at the zero-period acceleration
  for (std::size_t j = 0; j < components.size(); ++j)
  {
    const MonitorPoint &m = *components[j].first;
    SpectralQuantity q{
        m.name + ".a" + m.labels[components[j].second], "m/s^2", {{0., 0., 0.}}, 0.};
    for (const unsigned int d : directions)
      q.peak[d] = combined(modal_accelerations,
                           n_monitor_components,
                           j,
                           a_peak[d],
                           missing_accelerations[d][j]);
    q.combined = combine_directions(q.peak, parameters.directional_combination);
    rows.push_back(q);
  }
  // the base reaction: mode k along d gives Gamma_ke Gamma_kd S_a,kd along e
  for (unsigned int e = 0; e < 3; ++e)
  {
    SpectralQuantity q{std::string("base.F") + "xyz"[e], "N", {{0., 0., 0.}}, 0.};
    for (const unsigned int d : directions)
    {
      for (std::size_t k = 0; k < n_modes; ++k)
        modal[k] = gamma[k][e] * a_peak[d][k];
      q.peak[d] = correlation.combine(modal.data(), missing_base[d][e]);
    }
    q.combined = combine_directions(q.peak, parameters.directional_combination);
    rows.push_back(q);
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
  model.response_values(U, values, true);
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
