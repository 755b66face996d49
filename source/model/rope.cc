#include <hati/model/rope.h>
#include <hati/model/rope_diagnostics.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace hati
{
namespace
{
/** U at @p dof, 0 for a held DoF. */
inline double value_at(const Vector<double> &U, const types::global_dof_index dof)
{
  return dof == numbers::invalid_dof_index ? 0. : U[dof];
}
} // namespace

Tensor<1, 3> Rope::chord(const Vector<double> &U) const
{
  Tensor<1, 3> c = reference_chord;
  for (unsigned int d = 0; d < 3; ++d)
    c[d] += value_at(U, load_dofs[d]) - value_at(U, hook_dofs[d]);
  return c;
}

double Rope::tension(const Vector<double> &U) const
{
  // (R1) T = max(0, k (|x_p - x_h| - L0))
  return std::max(0., stiffness * (chord(U).norm() - rest_length));
}

double Rope::strain_energy(const Vector<double> &U) const
{
  const double stretch = std::max(0., chord(U).norm() - rest_length);
  return 0.5 * stiffness * stretch * stretch;
}

double Rope::add_force(const Vector<double> &U,
                       Vector<double> &f,
                       const Vector<double> *scale) const
{
  const Tensor<1, 3> c = chord(U);
  const double l = c.norm();
  const double T = std::max(0., stiffness * (l - rest_length));
  if (T == 0.)
    return 0.;
  // (R1) +T e on the hook point, -T e on the load
  for (unsigned int d = 0; d < 3; ++d)
  {
    const double fd = T * c[d] / l;
    if (hook_dofs[d] != numbers::invalid_dof_index)
      f[hook_dofs[d]] += (scale ? (*scale)[hook_dofs[d]] : 1.) * fd;
    if (load_dofs[d] != numbers::invalid_dof_index)
      f[load_dofs[d]] -= (scale ? (*scale)[load_dofs[d]] : 1.) * fd;
  }
  return T;
}

FullMatrix<double> Rope::tangent(const Vector<double> &U,
                                 const double slack_tension) const
{
  FullMatrix<double> K(6, 6);
  const Tensor<1, 3> c = chord(U);
  const double l = c.norm();
  if (l == 0.)
    return K;
  const Tensor<1, 3> e = c / l;
  // taut (l >= L0, the right derivative at l = L0):
  //   K_r = k e e^T + (T / l) (I - e e^T), T = k (l - L0);
  // slack: 0, or (slack_tension / l) I to regularise a Newton step
  const bool taut = l >= rest_length;
  const double axial = taut ? stiffness : 0.;
  const double T =
      taut ? std::max(stiffness * (l - rest_length), slack_tension) : slack_tension;
  for (unsigned int a = 0; a < 3; ++a)
    for (unsigned int b = 0; b < 3; ++b)
    {
      const double identity = a == b ? 1. : 0.;
      const double k = taut ? axial * e[a] * e[b] + (T / l) * (identity - e[a] * e[b])
                            : (T / l) * identity;
      K(a, b) = K(3 + a, 3 + b) = k;
      K(a, 3 + b) = K(3 + a, b) = -k;
    }
  return K;
}

std::array<types::global_dof_index, 6> Rope::dofs() const
{
  return {{hook_dofs[0],
           hook_dofs[1],
           hook_dofs[2],
           load_dofs[0],
           load_dofs[1],
           load_dofs[2]}};
}

void add_rope_tangents(const std::vector<Rope> &ropes,
                       const Vector<double> &U,
                       SparseMatrix<double> &K,
                       const double slack_tension)
{
  for (const Rope &rope : ropes)
  {
    const FullMatrix<double> k = rope.tangent(U, slack_tension);
    const auto dofs = rope.dofs();
    for (unsigned int a = 0; a < 6; ++a)
      for (unsigned int b = 0; b < 6; ++b)
        if (dofs[a] != numbers::invalid_dof_index &&
            dofs[b] != numbers::invalid_dof_index && k(a, b) != 0.)
          K.add(dofs[a], dofs[b], k(a, b));
  }
}

double rope_omega_squared_bound(const std::vector<Rope> &ropes,
                                const Vector<double> &mass,
                                const std::vector<bool> &fixed)
{
  // the largest 1/m over the free translations of each node
  const auto inverse_mass = [&](const std::array<types::global_dof_index, 3> &dofs)
  {
    double w = 0.;
    for (const auto i : dofs)
      if (i != numbers::invalid_dof_index && !fixed[i] && mass[i] > 0.)
        w = std::max(w, 1. / mass[i]);
    return w;
  };
  double bound = 0.;
  for (const Rope &rope : ropes)
    bound +=
        rope.stiffness * (inverse_mass(rope.hook_dofs) + inverse_mass(rope.load_dofs));
  return bound;
}

void rethrow_naming_slack_rope(const ExceptionBase &e,
                               const std::string &prefix,
                               const std::vector<Rope> &ropes,
                               const Vector<double> &U)
{
  std::ostringstream info;
  e.print_info(info);
  std::string message = info.str();
  message.erase(0, message.find_first_not_of(" \n"));
  message.erase(message.find_last_not_of(" \n") + 1);
  if (message.rfind(prefix, 0) != 0)
    return;
  for (const Rope &rope : ropes)
    if (rope.chord(U).norm() < (1. - 1e-9) * rope.rest_length)
    {
      std::ostringstream m;
      m << message << " The rope '" << rope.name << "' is slack (length "
        << rope.chord(U).norm() << " m, rest length " << rope.rest_length
        << " m): it holds nothing in the static state; check its rest length and what "
           "it should hold.";
      AssertThrow(false, ExcMessage(m.str()));
    }
}
} // namespace hati
