#ifndef hati_model_model_h
#define hati_model_model_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>

#include <hati/base/registry.h>
#include <hati/base/summary_value.h>
#include <hati/model/discrete_system.h>
#include <hati/model/response_quantities.h>

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace hati
{
using namespace dealii;

/** Parameters shared by every model: loads and the contact law. */
struct CommonModelParameters
{
  /** Declare `Loading` and `Contact` subsections. */
  static void declare_parameters(ParameterHandler &prm);
  void parse_parameters(ParameterHandler &prm);

  /** Gravity acceleration vector (m/s^2). */
  Tensor<1, 3> gravity;
  /** Base (support) acceleration step, applied from base_acceleration_start (m/s^2). */
  Tensor<1, 3> base_acceleration;
  /** Time at which the base acceleration step starts (s). */
  double base_acceleration_start = 0.;
  /** Accelerogram files per global direction x, y, z (empty: none). */
  std::array<std::string, 3> accelerogram_files;
  /** Units of two-column accelerogram files: g, m/s^2 or cm/s^2. */
  std::string accelerogram_units = "g";
  /** Factor on every accelerogram value (-). */
  double accelerogram_scale = 1.;
  /**
   * Frame members whose inertia the base acceleration loads
   * (`Loading/Excited members`); empty: the whole model.
   */
  std::vector<std::string> excited_members;
  /** Name of the contact in contacts.csv. */
  std::string contact_name;
  /** Newton's restitution coefficient e in [0, 1]. */
  double restitution = 0.;
  /** Initial gap between the body and the obstacle (m). */
  double initial_gap = 0.;
  /**
   * Not a parameter: set by Problem for the explicit scheme (CD-Lagrange).
   * True: ties and rigid links are bilateral constraint rows
   * (ContactRow::constraint) and the tied DoFs stay free; false: they are
   * eliminated as affine constraints (static, modal, Newmark).
   */
  bool links_as_rows = false;
};

/**
 * The `Model/Decomposition` subsection: which cells form the explicit
 * subdomain of the coupled method (HATI); the rest is implicit. Ignored by
 * single-domain methods.
 */
struct DecompositionParameters
{
  /** Declare the entries in the current subsection (the caller enters it). */
  static void declare_parameters(ParameterHandler &prm);
  void parse_parameters(ParameterHandler &prm);

  /**
   * Boxes `x_min, x_max, y_min, y_max, z_min, z_max` (m); a box given with
   * two values bounds x only. A cell whose centre lies in a box is explicit.
   */
  std::vector<std::array<double, 6>> boxes;
  /** Frame members (by name) that are explicit. */
  std::vector<std::string> members;

  /**
   * `Implicit reduction`: "none" or "Craig-Bampton" (C1, doc/theory.md
   * 12.1): the implicit subdomain of HATI integrated in the reduced
   * coordinates of its interface DoFs and fixed-interface modes.
   */
  std::string implicit_reduction = "none";
  /** `Reduction cutoff frequency` (Hz): the fixed-interface modes kept. */
  double reduction_cutoff_frequency = 150.;
  /** `Reduction maximum modes` (-): a cut-off that needs more is refused. */
  unsigned int reduction_maximum_modes = 500;
  /**
   * Reduction modal damping ratio (-): every mode of the reduced part gets
   * it (doc/theory.md 12.3); empty: the run's damping.
   */
  std::optional<double> reduction_modal_damping_ratio;
};

/** A DoF vector to write, with its name. */
using NamedVector = std::pair<std::string, const Vector<double> *>;

/** What one VTU file holds: named DoF vectors at a time and a cycle. */
struct VtuSnapshot
{
  std::vector<NamedVector> fields;
  /** Time (s; the mode number of a mode shape). */
  double time = 0.;
  /** Number of the snapshot. */
  unsigned int cycle = 0;
};

/** What a DoF of a model is, for messages (the watchdog of a transient run). */
struct DofDescription
{
  /** The component, `ux`, `uy`, `uz` (m) or `rx`, `ry`, `rz` (rad); empty if unknown. */
  std::string component;
  /** Where it sits, e.g. `node 'A1'`; empty if unknown. */
  std::string location;
  /** Whether the component is a rotation (rad). */
  bool rotation = false;
};

/**
 * The damping a model gives a transient run when `Time integration/Damping`
 * is not set: a ratio reached at the first vertically and the first
 * horizontally dominated modes by Rayleigh damping (doc/theory.md 4.4), or
 * held nearly constant over a band by frequency-range damping (A8, N4).
 */
struct DefaultDamping
{
  /** Damping ratio (-); 0: undamped. */
  double ratio = 0.;
  /** `Rayleigh` or `frequency range`. */
  std::string type = "Rayleigh";
  /** `frequency range`: the band (Hz). */
  double lower_frequency = 0., upper_frequency = 0.;
  /** The entries that set it, for messages (e.g. `Model/Bridge crane/Damping ratio`). */
  std::string entries;
};

/**
 * A model turns its `.prm` description into a DiscreteSystem (mesh, DoFs,
 * lumped mass, stiffness, loads, contacts, monitors, initial state) and
 * writes DoF vectors of that system to VTU. Integrators never see a model.
 */
class Model
{
public:
  virtual ~Model() = default;

  /** Build the discrete system. */
  virtual void build(const CommonModelParameters &common, DiscreteSystem &system) = 0;

  /**
   * Write the DoF vectors of @p snapshot (displacement, velocity, contact
   * fields) as one VTU file, with its time and cycle.
   */
  virtual void write_vtu(std::ostream &out, const VtuSnapshot &snapshot) const = 0;

  /**
   * Centre of every active cell (m, padded with zeros below three
   * dimensions), in the order of the active cell index; call after build().
   */
  virtual std::vector<Point<3>> cell_centres() const = 0;

  /**
   * The size of the model (m): the diagonal of the box around its mesh
   * (call after build()); by default that of the cell centres, 0 for a
   * model without cells. The watchdog of a transient run bounds the
   * displacements by a multiple of it.
   */
  virtual double size() const;

  /** Name of the member of every active cell (frames); empty otherwise. */
  virtual std::vector<std::string> cell_members() const { return {}; }

  /**
   * Whether the model has named members (frames), which Loading/Excited
   * members and Model/Decomposition/Explicit members can select.
   */
  virtual bool has_members() const { return false; }

  /**
   * The subdomain of every active cell, 0 explicit or 1 implicit, from the
   * boxes and member names of @p parameters (call after build()). Throws if
   * a member name is unknown.
   */
  std::vector<unsigned char> cell_parts(const DecompositionParameters &parameters) const;

  /**
   * Restrict the next calls of build() to the cells whose entry in
   * @p parts equals @p part (0 explicit, 1 implicit), with the data of the
   * nodes (point masses, nodal loads and forces, spring supports, contacts)
   * on the explicit side when the node touches an explicit cell and on the
   * implicit side otherwise; @p parts is also written as the cell field
   * `subdomain` of the VTU files. @p part = -1 (or an empty @p parts) builds
   * the whole model. Virtual for models that hold another model.
   */
  virtual void select_part(const std::vector<unsigned char> &parts, const int part);

  /**
   * Interface rows other than shared DoFs (G3'', doc/theory.md 11.3): rows
   * `C U = 0` of the whole model's numbering whose DoFs lie in both
   * subdomains of the parts given to select_part(), e.g. a beam node of the
   * explicit side tied to a solid face of the implicit side (+1 on the node's
   * DoF, minus the B1 row on the face's). None by default.
   */
  virtual std::vector<SparseRow> interface_rows() const { return {}; }

  /**
   * Set the DoFs of @p U that the model eliminates as affine constraints
   * (tied nodes, slaves of rigid links, B1) from the DoFs they follow, e.g.
   * a static state before HATI's subdomains, where such a node may be
   * free, take their part of it. Nothing by default.
   */
  virtual void complete_solution(Vector<double> &U) const { (void)U; }

  /**
   * The dual of complete_solution(): move the entries of the force @p f on
   * the DoFs the model eliminates as affine constraints onto the DoFs they
   * follow, `f_j += c_ij f_i` for `u_i = sum_j c_ij u_j`, and zero them (the
   * equivalent load of the condensed system, doc/theory.md 6.1), e.g. a
   * force of HATI's explicit part on a tied node, which the whole system
   * eliminates. Nothing by default.
   */
  virtual void condense_force(Vector<double> &f) const { (void)f; }

  /** One line describing the model for the terminal and summary.json. */
  virtual std::string description() const = 0;

  /**
   * The component and the place of the DoF @p dof of the whole model's
   * system, for messages (call after build()); nothing known by default.
   */
  virtual DofDescription describe_dof(const types::global_dof_index /*dof*/) const
  {
    return {};
  }

  /**
   * Model-specific summary.json entries (key, value), given the static
   * contact forces per contact name (N; empty without a static state). None
   * by default.
   */
  virtual SummaryEntries
  summary_entries(const std::map<std::string, double> & /*static_contact_forces*/) const
  {
    return {};
  }

  /**
   * The explicit subdomain the model proposes when `Model/Decomposition` is
   * empty (Method = HATI): none by default. The bridge crane makes its
   * trolley and the zones of girder and end carriage around each wheel
   * explicit.
   */
  virtual DecompositionParameters default_decomposition() const { return {}; }

  /**
   * Names of the contacts that are wheels on rails: their statistics go to
   * summary.json as `wheels` (none by default).
   */
  virtual std::vector<std::string> wheel_contacts() const { return {}; }

  /**
   * The lateral (flange) contact of each wheel of wheel_contacts(), in its
   * order (empty for a wheel without): its gaps give the wheel's
   * `max_lateral_offset` (none by default).
   */
  virtual std::vector<std::string> wheel_lateral_contacts() const { return {}; }

  /**
   * A wheel of wheel_contacts() that stands on the runway, whose contact
   * forces are the loads handed to the building (`runway_load`,
   * runway_loads.csv): its flange contact, and which of its friction
   * tangents (ContactRow::tangents) runs along the rail and which across
   * it (-1: none, a wheel that rolls freely along the rail has no
   * longitudinal friction).
   */
  struct RunwayWheel
  {
    std::string name, lateral_contact;
    int longitudinal_tangent = -1, lateral_tangent = -1;
  };
  /** The runway wheels: none by default, the crane wheels of a bridge crane. */
  virtual std::vector<RunwayWheel> runway_wheels() const { return {}; }

  /**
   * The members whose stresses a stress check would need but whose
   * section has no extreme fibre distances (a `general` section without
   * c_y, c_z): none by default.
   */
  virtual std::vector<std::string> members_without_stresses() const { return {}; }

  /**
   * `geometry.csv`, the drawing of the model for the qualification report:
   * one row per beam element, `member,x1,y1,z1,x2,y2,z2` (m, global axes);
   * empty (no file) by default.
   */
  virtual std::string geometry_csv() const { return ""; }

  /**
   * The largest normal and von Mises stresses (Pa) at the extreme fibres of
   * the section of the member @p member under the section forces @p forces
   * (N, Vy, Vz in N; T, My, Mz in N m; doc/theory.md S1-S3) into @p normal
   * and @p von_mises; false (none) for a member without stresses and by
   * default.
   */
  virtual bool member_stress(const std::string & /*member*/,
                             const std::array<double, 6> & /*forces*/,
                             double & /*normal*/,
                             double & /*von_mises*/) const
  {
    return false;
  }

  /**
   * The damping a transient run of this model gets when
   * `Time integration/Damping` is not set (DefaultDamping; none by
   * default).
   */
  virtual DefaultDamping default_damping() const { return {}; }

  /**
   * Lines of results for the table printed at the end of a transient run
   * (e.g. the envelope of section forces); empty by default.
   */
  virtual std::string results_table() const { return ""; }

  /**
   * Header of `section_forces.csv`, or an empty string if the model writes
   * no section forces (the default).
   */
  virtual std::string section_forces_header() const { return ""; }

  /**
   * Section forces at time @p time for displacement @p U: their envelope
   * is updated, and the rows of `section_forces.csv` go to @p out unless it
   * is null (`Output/Section force interval` coarser than the history).
   * With @p functional_values, the values of output_functionals() for @p U,
   * the outputs that they give are taken from them (U is read for the
   * others).
   */
  virtual void write_section_forces(std::ostream * /*out*/,
                                    const double /*time*/,
                                    const Vector<double> & /*U*/,
                                    const Vector<double> * /*functional_values*/) const
  {
  }

  /**
   * Linear functionals of the displacement that write_section_forces()
   * can take as values instead of reading `U` (the solid cuts' section
   * forces, doc/theory.md 11.4): rows over the global DoFs, the model's
   * constraints folded in (their product with `U` before the constraints
   * are distributed). A Craig-Bampton reduced implicit part (C1) evaluates
   * them from its reduced coordinates (`(L T) q`, theory 12.2) at the
   * history rows. None by default.
   */
  virtual std::vector<SparseRow> output_functionals() const { return {}; }

  /**
   * The DoFs of `U` that write_section_forces() reads besides
   * output_functionals() (the sources of the constrained ones included): a
   * Craig-Bampton reduced implicit part (C1) recovers only these and the
   * monitors' at the history rows that write no section forces and no
   * VTU. None by default; a model that overrides write_section_forces()
   * overrides this too.
   */
  virtual std::vector<types::global_dof_index> section_force_dofs() const { return {}; }

  /**
   * Names of the VTU series the model writes next to `solution`, each as
   * `<name>.pvd` and `<name>-NNNNN.vtu` with the cycles and times of
   * `solution.pvd` (a frame with solids: `solids`); none by default.
   */
  virtual std::vector<std::string> vtu_series() const { return {}; }

  /**
   * One snapshot of the series @p series (a name of vtu_series()) from the
   * DoF vectors of @p snapshot, as write_vtu() does for `solution`.
   */
  virtual void write_series_vtu(const std::string & /*series*/,
                                std::ostream & /*out*/,
                                const VtuSnapshot & /*snapshot*/) const
  {
  }

  /**
   * Update the model's envelopes other than the section forces' (a frame
   * with solids: the largest von Mises stress) at time @p time (s) for the
   * displacement @p U: at the rows of `Output/Section force interval`.
   */
  virtual void update_envelopes(const double /*time*/, const Vector<double> & /*U*/) const
  {
  }

  /**
   * Names of the files the model writes from those envelopes (a frame with
   * solids: `stress_envelope.vtu`); none by default.
   */
  virtual std::vector<std::string> envelope_files() const { return {}; }

  /** The file @p name (a name of envelope_files()) as it stands. */
  virtual void write_envelope_file(const std::string & /*name*/,
                                   std::ostream & /*out*/) const
  {
  }

  /**
   * The groups of linear response quantities that a response-spectrum
   * analysis combines (ResponseGroup, doc/theory.md 14.6; a frame: every
   * member's six section forces at its stations). None by default.
   */
  virtual std::vector<ResponseGroup> response_groups() const { return {}; }

  /**
   * The values of response_groups() for the displacement @p U (m, the
   * model's constraints not yet distributed), one group after another in
   * @p values (resized to the sum of their sizes); with @p own_weight, the
   * members' own weight as span loads is in the section forces (the static
   * state's values; a vibration's have none).
   */
  virtual void response_values(const Vector<double> & /*U*/,
                               std::vector<double> &values,
                               const bool /*own_weight*/ = false) const
  {
    values.clear();
  }

  /**
   * The members whose section forces a transient run writes and envelopes
   * (`Section force members`; a bridge crane: its girders), for the
   * comparison of a response-spectrum analysis with them. None by default.
   */
  virtual std::vector<std::string> section_force_members() const { return {}; }

  /**
   * The files a response-spectrum analysis writes from the combined values
   * of the stress groups of response_groups() (a frame with solids:
   * `stress_envelope.vtu`); none by default.
   */
  virtual std::vector<std::string> response_envelope_files() const { return {}; }

  /**
   * The file @p name of response_envelope_files() from @p von_mises: per
   * stress group of response_groups(), in their order, the combined von
   * Mises stress (Pa) at each of its points.
   */
  virtual void
  write_response_envelope(const std::string & /*name*/,
                          const std::vector<std::vector<double>> & /*von_mises*/,
                          std::ostream & /*out*/) const
  {
  }

protected:
  /** Whether build() assembles the active cell @p index (select_part()). */
  bool cell_selected(const unsigned int index) const
  {
    return selected_part < 0 || parts[index] == selected_part;
  }

  /**
   * Whether build() adds the data of a node whose cells are @p cells (active
   * cell indices): explicit side if one of them is explicit.
   */
  bool owns_node(const std::vector<unsigned int> &cells) const;

  /** The `subdomain` cell field for VTU (empty: not decomposed). */
  Vector<float> subdomain_field() const;

  /** 0/1 per active cell, as given to select_part() (may be empty). */
  std::vector<unsigned char> parts;
  /** -1: the whole model; 0 explicit, 1 implicit. */
  int selected_part = -1;
};

/**
 * Makes a model from the parameters (@p prm in the `Model` subsection): the
 * factory enters the model's own subsection and parses it.
 */
using ModelFactory = std::function<std::unique_ptr<Model>(ParameterHandler &prm)>;

/**
 * The models of `Model/Type`, registered in source/model/model_registry.cc
 * (one line each, add_model()).
 */
const Registry<ModelFactory> &model_registry();

/**
 * Register a model as @p name whose parameters, the struct @p Parameters
 * (declare_parameters(), parse_parameters()), live in the subsection
 * @p subsection of `Model`; @p make turns parsed parameters into the model;
 * @p documentation is its part of the documentation of `Model/Type`.
 */
template <class Parameters, class Make>
void add_model(Registry<ModelFactory> &registry,
               const std::string &name,
               const std::string &subsection,
               const std::string &documentation,
               Make make)
{
  registry.add({name,
                documentation,
                [subsection](ParameterHandler &prm)
                {
                  prm.enter_subsection(subsection);
                  Parameters::declare_parameters(prm);
                  prm.leave_subsection();
                },
                [subsection, make](ParameterHandler &prm) -> std::unique_ptr<Model>
                {
                  prm.enter_subsection(subsection);
                  Parameters parameters;
                  parameters.parse_parameters(prm);
                  prm.leave_subsection();
                  return make(parameters);
                }});
}

/** add_model() for a class constructed from its `ModelType::Parameters`. */
template <class ModelType>
void add_model(Registry<ModelFactory> &registry,
               const std::string &name,
               const std::string &subsection,
               const std::string &documentation)
{
  using Parameters = typename ModelType::Parameters;
  add_model<Parameters>(registry,
                        name,
                        subsection,
                        documentation,
                        [](const Parameters &p)
                        { return std::make_unique<ModelType>(p); });
}

/** Declare the `Model` subsection with the parameters of every model type. */
void declare_model_parameters(ParameterHandler &prm);

/**
 * Create the model chosen by `Model/Type` (model_registry()) and parse its
 * parameters; @p prm at its top level.
 */
std::unique_ptr<Model> create_model(ParameterHandler &prm);
} // namespace hati

#endif
