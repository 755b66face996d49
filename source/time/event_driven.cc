#include <deal.II/base/exceptions.h>
#include <deal.II/lac/full_matrix.h>

#include <hati/contact/lcp_solver.h>
#include <hati/time/event_driven.h>
#include <hati/time/unilateral_contacts.h>

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <cmath>
#include <sstream>

namespace hati
{
struct EventDriven::Cvode
{
  SUNContext context = nullptr;
  void *memory = nullptr;
  N_Vector y = nullptr;
  SUNMatrix matrix = nullptr;
  SUNLinearSolver solver = nullptr;
  ~Cvode()
  {
    if (memory)
      CVodeFree(&memory);
    if (solver)
      SUNLinSolFree(solver);
    if (matrix)
      SUNMatDestroy(matrix);
    if (y)
      N_VDestroy(y);
    if (context)
      SUNContext_Free(&context);
  }
};

namespace
{
int cvode_rhs(realtype t, N_Vector y, N_Vector ydot, void *user_data)
{
  static_cast<const EventDriven *>(user_data)->rhs(
      t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot));
  return 0;
}

int cvode_roots(realtype, N_Vector y, realtype *g, void *user_data)
{
  static_cast<const EventDriven *>(user_data)->gap_functions(N_VGetArrayPointer(y), g);
  return 0;
}

void check(const int flag, const char *what)
{
  if (flag < 0)
  {
    std::ostringstream s;
    s << "event-driven integration: CVODE failed in " << what << " (flag " << flag << ")";
    AssertThrow(false, ExcMessage(s.str()));
  }
}
} // namespace

EventDriven::EventDriven(const DiscreteSystem &system,
                         const TimeIntegrationParameters &parameters)
    : system(system), parameters(parameters), cvode(std::make_unique<Cvode>())
{
  const unsigned int n = system.n_dofs();
  if (n > parameters.max_event_driven_dofs)
  {
    std::ostringstream s;
    s << "Time integration/Method = event-driven is a reference for small systems: the "
      << "model has " << n << " DoFs, more than 'Maximum number of DoFs' = "
      << parameters.max_event_driven_dofs << ". Use CD-Lagrange.";
    AssertThrow(false, ExcMessage(s.str()));
  }
  U = system.initial_displacement;
  U0 = U;
  V = system.initial_velocity;
  for (unsigned int i = 0; i < n; ++i)
    if (system.fixed[i])
      V[i] = 0.;
  work_f.reinit(n);
  work_u.reinit(n);
  work_ku.reinit(n);
  lambda.assign(system.contacts.size(), 0.);
  is_active.assign(system.contacts.size(), false);
  // friction and bilateral rows refused as by the contacts' law (also when
  // the integrator is built without run_event_driven()'s check_force_laws())
  const std::string refusal =
      UnilateralContacts::refusal_of(system.contacts, "event-driven");
  AssertThrow(refusal.empty(), ExcMessage(refusal));

  check(SUNContext_Create(nullptr, &cvode->context), "SUNContext_Create");
  cvode->y = N_VNew_Serial(2 * n, cvode->context);
  double *y = N_VGetArrayPointer(cvode->y);
  for (unsigned int i = 0; i < n; ++i)
  {
    y[i] = U[i];
    y[n + i] = V[i];
  }
  cvode->memory = CVodeCreate(CV_ADAMS, cvode->context);
  check(CVodeInit(cvode->memory, cvode_rhs, 0., cvode->y), "CVodeInit");
  check(CVodeSetUserData(cvode->memory, this), "CVodeSetUserData");
  check(CVodeSStolerances(
            cvode->memory, parameters.relative_tolerance, parameters.absolute_tolerance),
        "CVodeSStolerances");
  check(CVodeSetMaxNumSteps(cvode->memory, 1000000), "CVodeSetMaxNumSteps");
  cvode->matrix = SUNDenseMatrix(2 * n, 2 * n, cvode->context);
  cvode->solver = SUNLinSol_Dense(cvode->y, cvode->matrix, cvode->context);
  check(CVodeSetLinearSolver(cvode->memory, cvode->solver, cvode->matrix),
        "CVodeSetLinearSolver");
  if (!system.contacts.empty())
  {
    check(CVodeRootInit(cvode->memory, system.contacts.size(), cvode_roots),
          "CVodeRootInit");
    std::vector<int> direction(system.contacts.size(), -1); // gap decreasing
    check(CVodeSetRootDirection(cvode->memory, direction.data()),
          "CVodeSetRootDirection");
  }
}

EventDriven::~EventDriven() = default;

void EventDriven::rhs(const double time, const double *y, double *ydot) const
{
  const unsigned int n = system.n_dofs();
  for (unsigned int i = 0; i < n; ++i)
    work_u[i] = y[i];
  system.external_force(time, work_f);
  if (system.has_stiffness())
    system.stiffness.vmult(work_ku, work_u);
  for (unsigned int i = 0; i < n; ++i)
  {
    ydot[i] = system.fixed[i] ? 0. : y[n + i];
    ydot[n + i] = system.fixed[i] ? 0. : (work_f[i] - work_ku[i]) / system.lumped_mass[i];
  }
}

void EventDriven::gap_functions(const double *y, double *g) const
{
  for (unsigned int k = 0; k < system.contacts.size(); ++k)
  {
    const auto &c = system.contacts[k];
    g[k] = c.initial_gap;
    for (unsigned int i = 0; i < c.dofs.size(); ++i)
      g[k] += c.coefficients[i] * y[c.dofs[i]];
  }
}

std::vector<double> EventDriven::gaps() const
{
  std::vector<double> g(system.contacts.size());
  for (unsigned int k = 0; k < g.size(); ++k)
    g[k] = system.contacts[k].initial_gap + system.contacts[k].apply(U);
  return g;
}

std::vector<double> EventDriven::normal_velocities() const
{
  std::vector<double> w(system.contacts.size());
  for (unsigned int k = 0; k < w.size(); ++k)
    w[k] = system.contacts[k].apply(V);
  return w;
}

void EventDriven::advance_to(const double t_out, const std::function<void()> &on_event)
{
  const unsigned int n = system.n_dofs();
  std::fill(lambda.begin(), lambda.end(), 0.);
  std::fill(is_active.begin(), is_active.end(), false);
  while (t < t_out)
  {
    double t_reached = t;
    const int flag = CVode(cvode->memory, t_out, cvode->y, &t_reached, CV_NORMAL);
    check(flag, "CVode");
    const double *y = N_VGetArrayPointer(cvode->y);
    for (unsigned int i = 0; i < n; ++i)
    {
      U[i] = y[i];
      V[i] = y[n + i];
    }
    t = t_reached;
    if (flag == CV_ROOT_RETURN)
    {
      std::vector<int> roots(system.contacts.size());
      check(CVodeGetRootInfo(cvode->memory, roots.data()), "CVodeGetRootInfo");
      apply_impact(roots);
      on_event();
      std::fill(lambda.begin(), lambda.end(), 0.);
      std::fill(is_active.begin(), is_active.end(), false);
    }
    else
      t = t_out;
  }
}

void EventDriven::apply_impact(const std::vector<int> &roots)
{
  ++events;
  if (events > parameters.max_events)
  {
    std::ostringstream s;
    s.precision(10);
    s << "event-driven integration: more than 'Maximum number of events' = "
      << parameters.max_events << " impacts by t = " << t
      << " s (Zeno accumulation: an event-driven scheme cannot pass the accumulation "
      << "point). Reduce End time or use CD-Lagrange.";
    AssertThrow(false, ExcMessage(s.str()));
  }
  // contacts at the event: the roots found and any other closed contact
  std::vector<unsigned int> set;
  const std::vector<double> g = gaps();
  for (unsigned int k = 0; k < roots.size(); ++k)
    if (roots[k] != 0 || g[k] <= 0.)
      set.push_back(k);
  const unsigned int m = set.size();
  std::vector<const ContactRow *> rows(m);
  Vector<double> q(m);
  for (unsigned int a = 0; a < m; ++a)
  {
    rows[a] = &system.contacts[set[a]];
    q[a] = (1. + rows[a]->restitution) * rows[a]->apply(V); // w = W lambda + (1 + e) L V-
  }
  Vector<double> inverse_mass(system.n_dofs());
  for (unsigned int i = 0; i < inverse_mass.size(); ++i)
    inverse_mass[i] = system.fixed[i] ? 0. : 1. / system.lumped_mass[i];
  const FullMatrix<double> W = delassus(rows, inverse_mass);
  const Vector<double> l = solve_lcp(W, q);
  const Vector<double> v_before(V);
  for (unsigned int a = 0; a < m; ++a)
  {
    const auto &c = system.contacts[set[a]];
    lambda[set[a]] = l[a];
    is_active[set[a]] = true;
    c.add_transpose(l[a], inverse_mass, V);
  }
  // work of the impulses: lambda . L (V- + V+) / 2
  for (unsigned int a = 0; a < m; ++a)
  {
    const auto &c = system.contacts[set[a]];
    contact_work += 0.5 * l[a] * (c.apply(v_before) + c.apply(V));
    if (l[a] > 0. &&
        std::abs(c.apply(V)) <= 1e-9 * std::max(1., std::abs(c.apply(v_before))))
    {
      std::ostringstream s;
      s.precision(10);
      s << "event-driven integration: contact '" << c.name << "' stays closed after the "
        << "impact at t = " << t << " s (zero rebound velocity): persistent contact is "
        << "not handled by the event-driven reference. Use CD-Lagrange.";
      AssertThrow(false, ExcMessage(s.str()));
    }
  }
  const unsigned int n = system.n_dofs();
  double *y = N_VGetArrayPointer(cvode->y);
  for (unsigned int i = 0; i < n; ++i)
    y[n + i] = V[i];
  check(CVodeReInit(cvode->memory, t, cvode->y), "CVodeReInit");
}

Energies EventDriven::energies() const
{
  Energies e;
  for (unsigned int i = 0; i < V.size(); ++i)
    e.kinetic += 0.5 * system.lumped_mass[i] * V[i] * V[i];
  if (system.has_stiffness())
    e.internal = 0.5 * system.stiffness.matrix_norm_square(U);
  Vector<double> du(U);
  du -= U0;
  AssertThrow(system.time_dependent_loads.empty(),
              ExcMessage("event-driven: time-dependent loads are not supported yet"));
  e.external_work = system.constant_force * du;
  e.contact_work = contact_work;
  return e;
}
} // namespace hati
