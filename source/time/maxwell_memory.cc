#include <deal.II/base/exceptions.h>

#include <hati/base/cpu_clones.h>
#include <hati/time/maxwell_memory.h>

#include <cmath>
#include <string>

namespace hati
{
MaxwellMemory::MaxwellMemory(const MaxwellBranches &branches,
                             const double dt,
                             const unsigned int n_dofs)
    : alpha(branches.alpha), dt(dt), tau(branches.tau)
{
  AssertThrow(
      branches.alpha.size() == branches.tau.size(),
      ExcMessage("frequency-range damping: as many alpha_l as tau_l are needed."));
  AssertThrow(branches.alpha.size() <= max_branches,
              ExcMessage("frequency-range damping: at most " +
                         std::to_string(max_branches) + " Maxwell branches, got " +
                         std::to_string(branches.alpha.size()) + "."));
  for (unsigned int l = 0; l < alpha.size(); ++l)
  {
    AssertThrow(alpha[l] >= 0. && std::isfinite(alpha[l]) && tau[l] > 0. &&
                    std::isfinite(tau[l]),
                ExcMessage("frequency-range damping: the branches need alpha_l >= 0 "
                           "and tau_l > 0, finite."));
    const double e = std::exp(-dt / tau[l]);
    decay.push_back(e);
    // tau (1 - e) = tau (1 - exp(-dt/tau)) without cancellation
    gain.push_back(-tau[l] * std::expm1(-dt / tau[l]));
  }
  q.assign(alpha.size(), Vector<double>(n_dofs));
  S.reinit(active() ? n_dofs : 0);
}

double MaxwellMemory::alpha_sum() const
{
  double s = 0.;
  for (const double a : alpha)
    s += a;
  return s;
}

double MaxwellMemory::stiffness_factor() const
{
  double s = 0.;
  for (unsigned int l = 0; l < alpha.size(); ++l)
    s += alpha[l] * gain[l];
  return s / dt;
}

void MaxwellMemory::reset()
{
  for (auto &ql : q)
    ql = 0.;
  S = 0.;
  branch_work = 0.;
}

HATI_AVX2_CLONES void MaxwellMemory::update(const Vector<double> &v)
{
  const unsigned int n = S.size(), L = alpha.size();
  const double *__restrict vv = v.data();
  double *__restrict s = S.data();
  // one pass over the DoFs, the branches inside (at most max_branches, the
  // constructor): q_l and S stay in cache
  double *ql[max_branches];
  double e[max_branches], g[max_branches], a[max_branches];
  for (unsigned int l = 0; l < L; ++l)
  {
    ql[l] = q[l].data();
    e[l] = decay[l];
    g[l] = gain[l];
    a[l] = alpha[l];
  }
  for (unsigned int i = 0; i < n; ++i)
  {
    double si = 0.;
    for (unsigned int l = 0; l < L; ++l)
    {
      const double x = e[l] * ql[l][i] + g[l] * vv[i];
      ql[l][i] = x;
      si += a[l] * x;
    }
    s[i] = si;
  }
}

void MaxwellMemory::history(Vector<double> &h) const
{
  // h = sum_l alpha_l e_l q_l
  const unsigned int n = S.size(), L = alpha.size();
  if (h.size() != n)
    h.reinit(n, true);
  double c[max_branches];
  for (unsigned int l = 0; l < L; ++l)
    c[l] = alpha[l] * decay[l];
  weighted_sum(c, h);
}

void MaxwellMemory::add_energies(Energies &e, const SparseMatrix<double> &K) const
{
  if (!active())
    return;
  e.damping_stored = stored_energy(K);
  e.dissipated += branch_work - e.damping_stored;
}

double MaxwellMemory::stored_energy(const SparseMatrix<double> &K) const
{
  double e = 0.;
  if (K.empty())
    return 0.;
  for (unsigned int l = 0; l < alpha.size(); ++l)
    e += 0.5 * alpha[l] * K.matrix_norm_square(q[l]);
  return e;
}

void MaxwellMemory::set_memory(const std::vector<Vector<double>> &memory,
                               const double work)
{
  AssertThrow(memory.size() == q.size(),
              ExcMessage("MaxwellMemory::set_memory: wrong number of branches."));
  for (unsigned int l = 0; l < q.size(); ++l)
    AssertThrow(memory[l].size() == q[l].size(),
                ExcMessage("MaxwellMemory::set_memory: a branch's memory has " +
                           std::to_string(memory[l].size()) + " entries, expected " +
                           std::to_string(q[l].size()) + "."));
  q = memory;
  sum_branches();
  branch_work = work;
}

void MaxwellMemory::sum_branches()
{
  // S = sum_l alpha_l q_l (the superposition changes q every macro step)
  weighted_sum(alpha.data(), S);
}

HATI_AVX2_CLONES void MaxwellMemory::weighted_sum(const double *weight,
                                                  Vector<double> &out) const
{
  // summed in the order of the branches, in one serial pass: the same sums
  // as out = 0, out.add(weight_l, q_l) for each l, without the task
  // scheduler of each deal.II vector operation
  const unsigned int n = out.size(), L = alpha.size();
  const double *ql[max_branches];
  for (unsigned int l = 0; l < L; ++l)
  {
    AssertDimension(q[l].size(), n);
    ql[l] = q[l].data();
  }
  double *__restrict o = out.data();
  for (unsigned int i = 0; i < n; ++i)
  {
    double x = 0.;
    for (unsigned int l = 0; l < L; ++l)
      x += weight[l] * ql[l][i];
    o[i] = x;
  }
}
} // namespace hati
