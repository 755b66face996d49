#include <deal.II/lac/lapack_full_matrix.h>

#include <hati/contact/condensed_cluster.h>

#include <cmath>
#include <vector>

namespace hati
{
namespace
{
/**
 * The pseudo-inverse of a singular @p W_BB (dependent links; deal.II's SVD,
 * singular values below 1e-12 of the largest taken as zero) into @p X.
 */
void pseudo_inverse(const FullMatrix<double> &W_BB, FullMatrix<double> &X)
{
  const unsigned int n = W_BB.m();
  LAPACKFullMatrix<double> pseudo(n, n);
  pseudo = W_BB;
  pseudo.compute_inverse_svd(1e-12);
  // (its entries are now the SVD's, not the inverse's: column by column)
  X.reinit(n, n);
  Vector<double> e(n), column(n);
  for (unsigned int j = 0; j < n; ++j)
  {
    e = 0.;
    e[j] = 1.;
    pseudo.vmult(column, e);
    for (unsigned int i = 0; i < n; ++i)
      X(i, j) = column[i];
  }
}

/** @p links for the cluster @p cluster (its W, mu and bilateral flags). */
void derive_links(const FrictionalCluster &cluster, CondensedLinks &links)
{
  const FullMatrix<double> &W = cluster.W;
  const std::vector<unsigned int> &first = cluster.first;
  const unsigned int m = cluster.mu.size();
  // B: the rows of the frictionless bilateral contacts; C: the other
  // contacts' rows (kept), in the cluster's order
  links.rows_B.clear();
  links.rows_C.clear();
  links.kept.clear();
  links.condensed.clear();
  for (unsigned int k = 0; k < m; ++k)
    if (cluster.bilateral[k] && cluster.mu[k] == 0. && first[k + 1] - first[k] == 1)
    {
      links.rows_B.push_back(first[k]);
      links.condensed.push_back(k);
    }
    else
    {
      links.kept.push_back(k);
      for (unsigned int i = first[k]; i < first[k + 1]; ++i)
        links.rows_C.push_back(i);
    }
  links.valid = true;
  if (links.rows_B.empty() || links.kept.empty())
    return;
  // T = W_BB^-1 W_BC, S = W_CC - W_CB T; where the links are dependent
  // (W_BB singular), its pseudo-inverse
  if (!eliminate_rows(W, links.rows_B, links.rows_C, links.schur))
  {
    const unsigned int nB = links.rows_B.size();
    FullMatrix<double> W_BB(nB, nB);
    for (unsigned int a = 0; a < nB; ++a)
      for (unsigned int b = 0; b < nB; ++b)
        W_BB(a, b) = W(links.rows_B[a], links.rows_B[b]);
    pseudo_inverse(W_BB, links.schur.Wbb_inverse);
    complete_elimination(W, links.rows_C, links.schur);
  }
  links.first_S.assign(1, 0);
  links.mu_S.clear();
  links.bilateral_S.clear();
  for (const unsigned int k : links.kept)
  {
    links.first_S.push_back(links.first_S.back() + first[k + 1] - first[k]);
    links.mu_S.push_back(cluster.mu[k]);
    links.bilateral_S.push_back(cluster.bilateral[k]);
  }
}
} // namespace

FrictionSolverResult
solve_condensed_frictional_cluster(const FrictionalCluster &cluster,
                                   Vector<double> &r,
                                   std::vector<FrictionState> &state,
                                   const FrictionSolverControl &control,
                                   CondensedLinks *links)
{
  thread_local CondensedLinks own;
  if (links == nullptr)
  {
    own.valid = false;
    links = &own;
  }
  if (!links->valid)
    derive_links(cluster, *links);
  const std::vector<unsigned int> &rows_B = links->rows_B, &rows_C = links->rows_C;
  if (rows_B.empty() || links->kept.empty())
    return solve_frictional_cluster(cluster, r, state, control);

  const FullMatrix<double> &W = cluster.W, &X = links->schur.Wbb_inverse,
                           &T = links->schur.X;
  const Vector<double> &q = cluster.q;
  const unsigned int nB = rows_B.size(), nC = rows_C.size(), n = q.size(),
                     m = cluster.mu.size();
  // y = W_BB^-1 q_B, q_S = q_C - W_CB y
  // work vectors per size (the crane's clusters alternate between sizes,
  // and a Vector reinit() to another size allocates)
  thread_local std::vector<Vector<double>> ys, qs, rs;
  for (auto *w : {&ys, &qs, &rs})
    if (w->size() <= std::max(nB, nC))
      w->resize(std::max(nB, nC) + 1);
  Vector<double> &y = ys[nB], &q_S = qs[nC], &r_S = rs[nC];
  if (y.size() != nB)
    y.reinit(nB, true);
  for (unsigned int a = 0; a < nB; ++a)
  {
    double s = 0.;
    for (unsigned int b = 0; b < nB; ++b)
      s += X(a, b) * q[rows_B[b]];
    y[a] = s;
  }
  if (q_S.size() != nC)
    q_S.reinit(nC, true);
  for (unsigned int c = 0; c < nC; ++c)
  {
    double s = q[rows_C[c]];
    for (unsigned int a = 0; a < nB; ++a)
      s -= W(rows_C[c], rows_B[a]) * y[a];
    q_S[c] = s;
  }
  thread_local std::vector<FrictionState> state_S;
  const FrictionSolverResult result = solve_frictional_cluster(
      {links->schur.S, q_S, links->first_S, links->mu_S, links->bilateral_S},
      r_S,
      state_S,
      control);
  // a local problem of the condensed contacts without an exact solution
  // (rare: 4 of some 10^6 cluster solves on the braked crane with true
  // heights): the sweeps over the whole cluster, as without condensation
  if (!result.converged)
    return solve_frictional_cluster(cluster, r, state, control);

  // back to the whole cluster: r_C, then r_B = -(y + T r_C)
  if (r.size() != n)
    r.reinit(n);
  state.assign(m, FrictionState::open);
  for (unsigned int c = 0; c < nC; ++c)
    r[rows_C[c]] = r_S[c];
  for (unsigned int a = 0; a < nB; ++a)
  {
    double s = y[a];
    for (unsigned int c = 0; c < nC; ++c)
      s += T(a, c) * r_S[c];
    r[rows_B[a]] = -s;
    state[links->condensed[a]] =
        r[rows_B[a]] != 0. ? FrictionState::slip : FrictionState::open;
  }
  for (unsigned int i = 0; i < links->kept.size(); ++i)
    state[links->kept[i]] = state_S[i];
  return result;
}
} // namespace hati
