#ifndef hati_time_cd_lagrange_kernels_h
#define hati_time_cd_lagrange_kernels_h

// The row kernels of CDLagrange (source/time/cd_lagrange.cc), internal to
// it: the undamped free velocity (A2-A3), the Rayleigh-damped one (A7) and
// the one with frequency-range damping (A8), on the stiffness scaled by
// dt M^-1 in rows padded to a fixed width (ELLPACK), the width a
// compile-time constant so that the row loop is unrolled
// (bench/explicit_throughput.sh); rows wider than the widest compiled
// kernel (solids) in CSR, without padding.

#include <cstddef>
#include <type_traits>
#include <utility>

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
 * Row @p i of the operator S applied to two vectors: `sx += (S x)_i`,
 * `sy += (S y)_i`, the entries summed in row order (the damped and the
 * frequency-range kernels; inlined, so that a compile-time width unrolls
 * the loop). W > 0: rows padded to W (ELLPACK); W = 0: row i holds the
 * entries @p start[i] to @p start[i+1] (CSR, the wide rows of solids).
 */
template <unsigned int W>
inline void two_row_products(const unsigned int i,
                             const std::size_t *__restrict start,
                             const unsigned int *__restrict col,
                             const double *__restrict val,
                             const double *__restrict x,
                             const double *__restrict y,
                             double &sx,
                             double &sy)
{
  const std::size_t begin = W > 0 ? std::size_t(i) * W : start[i],
                    end = W > 0 ? begin + W : start[i + 1];
  for (std::size_t ik = begin; ik < end; ++ik)
  {
    sx += val[ik] * x[col[ik]];
    sy += val[ik] * y[col[ik]];
  }
}

/**
 * v_new = v + a - S u for the operator S (A2-A3 with S = dt M^-1 K,
 * a = dt M^-1 F_ext): W > 0, rows padded to W, a compile-time constant so
 * that the row loop is unrolled; W = 0, rows from @p start (CSR, the wide
 * rows of solids, whose lengths vary by a factor of 4 or more).
 */
template <unsigned int W>
void free_velocity_rows(const unsigned int n,
                        const std::size_t *__restrict start,
                        const unsigned int *__restrict col,
                        const double *__restrict val,
                        const double *__restrict u,
                        const double *__restrict v,
                        const double *__restrict a,
                        double *__restrict v_new)
{
  for (unsigned int i = 0; i < n; ++i)
  {
    double ku = 0.;
    if constexpr (W > 0)
      for (unsigned int k = 0; k < W; ++k)
        ku += val[std::size_t(i) * W + k] * u[col[std::size_t(i) * W + k]];
    else
      for (std::size_t e = start[i]; e < start[i + 1]; ++e)
        ku += val[e] * u[col[e]];
    v_new[i] = v[i] + a[i] - ku;
  }
}

/**
 * The damped free velocity (A7) for the operator S = dt M^-1 K (rows
 * padded to W, or from @p start with W = 0): with a = dt M^-1 F_ext,
 * `v_new = c1 v + c2 (a - S u - a1 S v)`, and the damping force of the
 * update `d_new = dt M^-1 D = a - S u - (v_new - v)`, stored in place of
 * the previous one in @p d. Returns the work of the damping force on the
 * increment dt v, `1/2 sum_i m_i v_i (d_old,i + d_new,i)` (J).
 */
template <unsigned int W>
double damped_free_velocity_rows(const unsigned int n,
                                 const std::size_t *__restrict start,
                                 const unsigned int *__restrict col,
                                 const double *__restrict val,
                                 const double *__restrict u,
                                 const double *__restrict v,
                                 const double *__restrict a,
                                 const double *__restrict m,
                                 const double c1,
                                 const double c2,
                                 const double a1,
                                 double *__restrict d,
                                 double *__restrict v_new,
                                 double *__restrict kv_out)
{
  double work = 0.;
  for (unsigned int i = 0; i < n; ++i)
  {
    double ku = 0., kv = 0.;
    two_row_products<W>(i, start, col, val, u, v, ku, kv);
    const double g = a[i] - ku;
    const double vn = c1 * v[i] + c2 * (g - a1 * kv);
    const double dn = g - (vn - v[i]);
    work += m[i] * v[i] * (d[i] + dn);
    d[i] = dn;
    v_new[i] = vn;
    if (kv_out != nullptr)
      kv_out[i] = kv;
  }
  return 0.5 * work;
}

/**
 * The free velocity with frequency-range damping (A8) for the operator
 * S = dt M^-1 K (rows padded to W, or from @p start with W = 0): with
 * a = dt M^-1 F_ext and the branches' sum @p s, `v_new = v + a - S (u + s)`;
 * the branch force of the update `d_new = S s` replaces the previous one in
 * @p d. Returns the work of the branch force on the increment dt v,
 * `1/2 sum_i m_i v_i (d_old,i + d_new,i)` (J).
 */
template <unsigned int W>
double branch_free_velocity_rows(const unsigned int n,
                                 const std::size_t *__restrict start,
                                 const unsigned int *__restrict col,
                                 const double *__restrict val,
                                 const double *__restrict u,
                                 const double *__restrict s,
                                 const double *__restrict v,
                                 const double *__restrict a,
                                 const double *__restrict m,
                                 double *__restrict d,
                                 double *__restrict v_new)
{
  double work = 0.;
  for (unsigned int i = 0; i < n; ++i)
  {
    double ku = 0., ks = 0.;
    two_row_products<W>(i, start, col, val, u, s, ku, ks);
    v_new[i] = v[i] + a[i] - ku - ks;
    work += m[i] * v[i] * (d[i] + ks);
    d[i] = ks;
  }
  return 0.5 * work;
}
} // namespace cd_lagrange_kernels
} // namespace hati

#endif
