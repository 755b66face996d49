#ifndef hati_time_cd_lagrange_kernels_h
#define hati_time_cd_lagrange_kernels_h

// The row kernels of CDLagrange (source/time/cd_lagrange.cc), internal to
// it: the undamped free velocity (A2-A3), the Rayleigh-damped one (A7) and
// the one with frequency-range damping (A8), on the stiffness scaled by
// dt M^-1 in groups of rows padded to one width each (sliced ELLPACK), the
// width a compile-time constant so that the row loop is unrolled
// (bench/explicit_throughput.sh); rows wider than the widest compiled
// kernel (solids) in CSR, without padding.

#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

namespace hati
{
namespace cd_lagrange_kernels
{
/**
 * Padded row widths with a compiled kernel (the row loop unrolled,
 * bench/explicit_throughput.sh); wider rows use the kernel whose width is
 * known at run time only (W = 0).
 */
using KernelWidths =
    std::integer_sequence<unsigned int, 2, 3, 4, 6, 8, 12, 16, 24, 32, 48, 64, 81, 96>;

/** The padded width of rows of at most @p w entries. */
template <unsigned int... W>
unsigned int padded_width(const unsigned int w, std::integer_sequence<unsigned int, W...>)
{
  if (w == 0)
    return 0;
  for (const unsigned int k : {W...})
    if (w <= k)
      return k;
  return w;
}

/** Whether @p w is one of the compiled widths. */
template <unsigned int... W>
bool has_compiled_width(const unsigned int w, std::integer_sequence<unsigned int, W...>)
{
  return ((w == W) || ...);
}

/**
 * `kernel(std::integral_constant<unsigned int, W>())` with the compiled
 * width W equal to @p width, or with W = 0 (the width known at run time
 * only: wider rows, or no stiffness); returns what the kernel returns.
 */
template <typename Kernel, unsigned int... W>
double with_kernel_width(const unsigned int width,
                         const Kernel &kernel,
                         std::integer_sequence<unsigned int, W...>)
{
  double result = 0.;
  const bool compiled =
      ((width == W &&
        ((result = kernel(std::integral_constant<unsigned int, W>())), true)) ||
       ...);
  return compiled ? result : kernel(std::integral_constant<unsigned int, 0>());
}

/**
 * The rows of the operator S = dt M^-1 K that share one padded width
 * (sliced ELLPACK): a frame's rows hold 2 to 9 nonzero entries, and one
 * width for all of them padded most rows to twice or three times their
 * length (issue #28). Each group runs the kernel of its width.
 */
struct RowGroup
{
  /** The padded width (a compiled one), or 0: CSR rows from `start`. */
  unsigned int width = 0;
  /** The group's rows (DoF indices), ascending. */
  std::vector<unsigned int> rows;
  /** CSR (width 0): the entries of the group's row r are start[r] .. start[r + 1]. */
  std::vector<std::size_t> start;
  /** Columns and values, row r at r * width (padding: value 0, column the row). */
  std::vector<unsigned int> column;
  std::vector<double> value;
};

/**
 * For every row r of the group @p g, with its DoF i: `row(i, (S x)_i,
 * (S y)_i)`, the entries summed in row order (the damped and the
 * frequency-range kernels; inlined, so that a compile-time width unrolls
 * the loop). W > 0: rows padded to W (ELLPACK); W = 0: CSR.
 */
template <unsigned int W, typename Row>
inline void for_each_two_row_products(const RowGroup &g,
                                      const double *__restrict x,
                                      const double *__restrict y,
                                      const Row &row)
{
  const std::size_t n = g.rows.size();
  const unsigned int *__restrict rows = g.rows.data();
  const std::size_t *__restrict start = g.start.data();
  const unsigned int *__restrict col = g.column.data();
  const double *__restrict val = g.value.data();
  for (std::size_t r = 0; r < n; ++r)
  {
    const std::size_t begin = W > 0 ? r * W : start[r],
                      end = W > 0 ? begin + W : start[r + 1];
    double sx = 0., sy = 0.;
    for (std::size_t ik = begin; ik < end; ++ik)
    {
      sx += val[ik] * x[col[ik]];
      sy += val[ik] * y[col[ik]];
    }
    row(rows[r], sx, sy);
  }
}

/**
 * v_new = v + a - S u on the rows of the group @p g (A2-A3 with
 * S = dt M^-1 K, a = dt M^-1 F_ext): W > 0, rows padded to W, a
 * compile-time constant so that the row loop is unrolled; W = 0, CSR rows
 * (the wide rows of solids, whose lengths vary by a factor of 4 or more,
 * and the empty rows of fixed DoFs).
 */
template <unsigned int W>
void free_velocity_rows(const RowGroup &g,
                        const double *__restrict u,
                        const double *__restrict v,
                        const double *__restrict a,
                        double *__restrict v_new)
{
  const std::size_t n = g.rows.size();
  const unsigned int *__restrict rows = g.rows.data();
  const std::size_t *__restrict start = g.start.data();
  const unsigned int *__restrict col = g.column.data();
  const double *__restrict val = g.value.data();
  for (std::size_t r = 0; r < n; ++r)
  {
    double ku = 0.;
    if constexpr (W > 0)
      for (unsigned int k = 0; k < W; ++k)
        ku += val[r * W + k] * u[col[r * W + k]];
    else
      for (std::size_t e = start[r]; e < start[r + 1]; ++e)
        ku += val[e] * u[col[e]];
    const unsigned int i = rows[r];
    v_new[i] = v[i] + a[i] - ku;
  }
}

/**
 * The damped free velocity (A7) on the rows of the group @p g (S = dt M^-1
 * K, rows padded to W, or CSR with W = 0): with a = dt M^-1 F_ext,
 * `v_new = c1 v + c2 (a - S u - a1 S v)`, and the damping force of the
 * update `d_new = dt M^-1 D = a - S u - (v_new - v)`, stored in place of
 * the previous one in @p d. @p work receives each row's work of the
 * damping force on the increment dt v, `m_i v_i (d_old,i + d_new,i)` (J,
 * twice; summed in row order by the caller).
 */
template <unsigned int W>
void damped_free_velocity_rows(const RowGroup &g,
                               const double *__restrict u,
                               const double *__restrict v,
                               const double *__restrict a,
                               const double *__restrict m,
                               const double c1,
                               const double c2,
                               const double a1,
                               double *__restrict d,
                               double *__restrict v_new,
                               double *__restrict kv_out,
                               double *__restrict work)
{
  for_each_two_row_products<W>(g,
                               u,
                               v,
                               [&](const unsigned int i, const double ku, const double kv)
                               {
                                 const double gi = a[i] - ku;
                                 const double vn = c1 * v[i] + c2 * (gi - a1 * kv);
                                 const double dn = gi - (vn - v[i]);
                                 work[i] = m[i] * v[i] * (d[i] + dn);
                                 d[i] = dn;
                                 v_new[i] = vn;
                                 if (kv_out != nullptr)
                                   kv_out[i] = kv;
                               });
}

/**
 * The free velocity with frequency-range damping (A8) on the rows of the
 * group @p g (S = dt M^-1 K, rows padded to W, or CSR with W = 0): with
 * a = dt M^-1 F_ext and the branches' sum @p s, `v_new = v + a - S (u + s)`;
 * the branch force of the update `d_new = S s` replaces the previous one in
 * @p d. @p work receives each row's work of the branch force on the
 * increment dt v, `m_i v_i (d_old,i + d_new,i)` (J, twice; summed in row
 * order by the caller).
 */
template <unsigned int W>
void branch_free_velocity_rows(const RowGroup &g,
                               const double *__restrict u,
                               const double *__restrict s,
                               const double *__restrict v,
                               const double *__restrict a,
                               const double *__restrict m,
                               double *__restrict d,
                               double *__restrict v_new,
                               double *__restrict work)
{
  for_each_two_row_products<W>(g,
                               u,
                               s,
                               [&](const unsigned int i, const double ku, const double ks)
                               {
                                 v_new[i] = v[i] + a[i] - ku - ks;
                                 work[i] = m[i] * v[i] * (d[i] + ks);
                                 d[i] = ks;
                               });
}
} // namespace cd_lagrange_kernels
} // namespace hati

#endif
