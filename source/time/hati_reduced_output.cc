#include <deal.II/base/exceptions.h>

#include <hati/analysis/reduced_part.h>
#include <hati/time/hati_coupling.h>

#include <algorithm>
#include <cmath>

// HATI's outputs of a Craig-Bampton reduced implicit part (C1,
// doc/theory.md 12.2): the whole model's state, the history rows' DoFs and
// the model's output functionals from the reduced coordinates.

namespace hati
{
namespace
{
/** Whether every entry of @p v is finite (else the full expansion shows the watchdog
 * where). */
bool all_finite(const Vector<double> &v)
{
  return std::all_of(v.begin(), v.end(), [](const double x) { return std::isfinite(x); });
}
} // namespace

const Vector<double> &HATICoupling::whole_state(const Vector<double> &state,
                                                const Vector<double> &explicit_part,
                                                Vector<double> &buffer,
                                                Vector<double> &global,
                                                const PartialExpansion *partial) const
{
  if (!decomposition.reduced)
    return to_global(state, explicit_part, global);
  // C1: the full subdomain's values from the reduced coordinates, u = T q
  const auto &I = decomposition.parts[1].global_dofs,
             &E = decomposition.parts[0].global_dofs;
  if (partial != nullptr && buffer.size() == I.size() && all_finite(state))
  {
    // only the rows the history reads; the others keep the last full values
    // in buffer and in global (which a full call filled from buffer): only
    // these rows and the explicit part change there (the explicit copy of
    // an interface DoF last, as in to_global())
    partial->values.reinit(partial->rows.size());
    partial->basis.vmult(partial->values, state);
    for (unsigned int i = 0; i < partial->rows.size(); ++i)
    {
      buffer[partial->rows[i]] = partial->values[i];
      global[I[partial->rows[i]]] = partial->values[i];
    }
    for (unsigned int i = 0; i < E.size(); ++i)
      global[E[i]] = explicit_part[i];
    return global;
  }
  decomposition.reduced->expand(state, buffer);
  return to_global(buffer, explicit_part, global);
}

const Vector<double> &HATICoupling::displacement(const bool history_dofs_only) const
{
  return whole_state(implicit.displacement(),
                     explicit_integrator.displacement(),
                     expanded_U,
                     global_U,
                     history_dofs_only ? &history_displacement : nullptr);
}

const Vector<double> &HATICoupling::velocity(const bool history_dofs_only) const
{
  return whole_state(implicit.velocity(),
                     explicit_integrator.velocity(),
                     expanded_V,
                     global_V,
                     history_dofs_only ? &history_velocity : nullptr);
}

const Vector<double> &HATICoupling::integer_velocity() const
{
  Vector<double> explicit_velocity;
  explicit_integrator.integer_velocity(explicit_velocity);
  return whole_state(
      implicit.velocity(), explicit_velocity, expanded_V, global_V, nullptr);
}

Vector<double> HATICoupling::contact_force() const
{
  // the last micro step's force less the interface force it applied,
  // C_E^T Lambda_{n+m} (G2 at j = m), which a restart takes up again (Lambda_0)
  Vector<double> explicit_force;
  explicit_integrator.contact_force(explicit_force);
  const std::vector<SparseRow> &rows = interface->explicit_rows();
  for (unsigned int k = 0; k < rows.size(); ++k)
    for (unsigned int i = 0; i < rows[k].dofs.size(); ++i)
      explicit_force[rows[k].dofs[i]] -= rows[k].coefficients[i] * lambda_n[k];
  const auto &E = decomposition.parts[0].global_dofs;
  Vector<double> force(global_U.size());
  for (unsigned int i = 0; i < E.size(); ++i)
    force[E[i]] = explicit_force[i];
  return force;
}

void HATICoupling::set_history_dofs(
    const std::vector<types::global_dof_index> &displacement_dofs,
    const std::vector<types::global_dof_index> &velocity_dofs)
{
  if (!decomposition.reduced)
    return;
  const auto &implicit_global = decomposition.parts[1].global_dofs;
  const auto set =
      [&](const std::vector<types::global_dof_index> &dofs, PartialExpansion &partial)
  {
    std::vector<bool> wanted(global_U.size(), false);
    for (const auto dof : dofs)
    {
      AssertThrow(dof < wanted.size(),
                  ExcMessage("HATICoupling::set_history_dofs: a DoF out of range"));
      wanted[dof] = true;
    }
    partial.rows.clear();
    for (unsigned int i = 0; i < implicit_global.size(); ++i)
      if (wanted[implicit_global[i]])
        partial.rows.push_back(i);
    partial.basis = decomposition.reduced->reduction().basis_rows(partial.rows);
  };
  set(displacement_dofs, history_displacement);
  set(velocity_dofs, history_velocity);
}

bool HATICoupling::set_output_functionals(const std::vector<SparseRow> &rows)
{
  functionals.explicit_rows.clear();
  if (!decomposition.reduced || rows.empty())
    return false;
  // where each global DoF lives: the explicit copy first (to_global())
  const auto &E = decomposition.parts[0].global_dofs,
             &I = decomposition.parts[1].global_dofs;
  std::vector<int> explicit_index(global_U.size(), -1),
      implicit_index(global_U.size(), -1);
  for (unsigned int i = 0; i < E.size(); ++i)
    explicit_index[E[i]] = i;
  for (unsigned int i = 0; i < I.size(); ++i)
    implicit_index[I[i]] = i;
  const CraigBamptonReduction &T = decomposition.reduced->reduction();
  functionals.implicit_basis.reinit(rows.size(), T.size());
  functionals.explicit_rows.resize(rows.size());
  for (unsigned int r = 0; r < rows.size(); ++r)
    for (unsigned int j = 0; j < rows[r].dofs.size(); ++j)
    {
      const auto dof = rows[r].dofs[j];
      AssertThrow(dof < global_U.size(),
                  ExcMessage("HATICoupling::set_output_functionals: a DoF out of range"));
      const double c = rows[r].coefficients[j];
      if (explicit_index[dof] >= 0)
      {
        functionals.explicit_rows[r].dofs.push_back(explicit_index[dof]);
        functionals.explicit_rows[r].coefficients.push_back(c);
      }
      else if (implicit_index[dof] >= 0) // (L_I T): the row of T times c
        for (unsigned int k = 0; k < T.size(); ++k)
          functionals.implicit_basis(r, k) += c * T.column(k)[implicit_index[dof]];
      // a fixed DoF: zero displacement
    }
  functionals.values.reinit(rows.size());
  return true;
}

const Vector<double> *HATICoupling::output_functionals() const
{
  if (functionals.explicit_rows.empty())
    return nullptr;
  const Vector<double> &q = implicit.displacement();
  if (!all_finite(q))
    return nullptr; // the full expansion shows the watchdog where
  functionals.implicit_basis.vmult(functionals.values, q);
  const Vector<double> &u = explicit_integrator.displacement();
  for (unsigned int r = 0; r < functionals.explicit_rows.size(); ++r)
    functionals.values[r] += functionals.explicit_rows[r].apply(u);
  return &functionals.values;
}

bool HATICoupling::defer_displacement()
{
  if (!decomposition.reduced)
    return false;
  const Vector<double> &q = implicit.displacement();
  if (!all_finite(q))
    return false;
  deferred.times.push_back(time());
  deferred.coordinates.insert(deferred.coordinates.end(), q.begin(), q.end());
  deferred.explicit_displacements.push_back(explicit_integrator.displacement());
  return true;
}

void HATICoupling::expand_deferred(
    const std::function<void(double, const Vector<double> &)> &f)
{
  const unsigned int m = deferred.times.size();
  if (m == 0)
    return;
  // C1: U = T Q, one pass of T through memory for the m states
  std::vector<double> U;
  decomposition.reduced->reduction().expand_many(deferred.coordinates, m, U);
  const std::size_t n = U.size() / m;
  Vector<double> implicit_part(n), global(global_U.size());
  for (unsigned int j = 0; j < m; ++j)
  {
    std::copy(U.begin() + j * n, U.begin() + (j + 1) * n, implicit_part.begin());
    f(deferred.times[j],
      to_global(implicit_part, deferred.explicit_displacements[j], global));
  }
  deferred.times.clear();
  deferred.coordinates.clear();
  deferred.explicit_displacements.clear();
}
} // namespace hati
