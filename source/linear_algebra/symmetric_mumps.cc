// Symmetric L D L^T factorisation with MUMPS called directly (not through
// Amesos, which only asks MUMPS for L U).

#include <hati/linear_algebra/symmetric_mumps.h>

#include <dmumps_c.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>

namespace hati
{
namespace
{
// MUMPS's 1-based control and information arrays
constexpr int mumps_icntl(const int i) { return i - 1; }

/** MUMPS job codes. */
enum MumpsJob
{
  mumps_initialise = -1,
  mumps_terminate = -2,
  mumps_solve = 3,
  mumps_analyse_and_factorise = 4
};

/** INFOG(1) of a workspace MUMPS estimated too small (-8, -9, -14, -15, -17, -20). */
bool workspace_too_small(const int error)
{
  return error == -8 || error == -9 || error == -14 || error == -15 || error == -17 ||
         error == -20;
}
} // namespace

bool SymmetricMumps::memory_error(const int error)
{
  return error == -7 || error == -13 || error == -19 || error == -11 ||
         workspace_too_small(error);
}

bool is_symmetric(const SparseMatrix<double> &matrix)
{
  if (matrix.m() != matrix.n())
    return false;
  // the largest entry of each row: an entry's mismatch is measured against
  // the scale of its row and column (entries at round-off of the diagonal,
  // 1e-9 of it, differ by more than their own magnitude's round-off)
  std::vector<double> scale(matrix.m(), 0.);
  for (unsigned int i = 0; i < matrix.m(); ++i)
    for (auto it = matrix.begin(i); it != matrix.end(i); ++it)
      scale[i] = std::max(scale[i], std::abs(it->value()));
  for (unsigned int i = 0; i < matrix.m(); ++i)
    for (auto it = matrix.begin(i); it != matrix.end(i); ++it)
    {
      const unsigned int j = it->column();
      if (j <= i)
        continue;
      // el(): zero where the pattern has no entry
      const double a = it->value(), b = matrix.el(j, i);
      if (std::abs(a - b) > symmetry_tolerance * std::max(scale[i], scale[j]))
        return false;
    }
  return true;
}

struct SymmetricMumps::Data
{
  DMUMPS_STRUC_C mumps;
  bool initialised = false;
};

SymmetricMumps::SymmetricMumps() : data(std::make_unique<Data>()) {}

SymmetricMumps::~SymmetricMumps()
{
  if (data->initialised)
  {
    data->mumps.job = mumps_terminate;
    dmumps_c(&data->mumps);
  }
}

bool SymmetricMumps::factorize(const SparseMatrix<double> &matrix)
{
  DMUMPS_STRUC_C &m = data->mumps;
  if (data->initialised)
  {
    m.job = mumps_terminate;
    dmumps_c(&m);
    data->initialised = false;
  }
  n = matrix.m();
  // the upper triangle, 1-based (MUMPS sums the entries of both triangles)
  std::vector<MUMPS_INT> rows, columns;
  std::vector<double> values;
  const std::size_t estimate = (matrix.n_nonzero_elements() + n) / 2;
  rows.reserve(estimate);
  columns.reserve(estimate);
  values.reserve(estimate);
  for (unsigned int i = 0; i < n; ++i)
    for (auto it = matrix.begin(i); it != matrix.end(i); ++it)
      if (it->column() >= i)
      {
        rows.push_back(i + 1);
        columns.push_back(it->column() + 1);
        // (is_symmetric(): the lower triangle equals it to round-off)
        values.push_back(it->value());
      }

  m = DMUMPS_STRUC_C();
  m.job = mumps_initialise;
  m.par = 1; // the host works
  m.sym = 2; // general symmetric: L D L^T with 2x2 pivots (indefinite matrices too)
  m.comm_fortran = static_cast<MUMPS_INT>(MPI_Comm_c2f(MPI_COMM_SELF));
  dmumps_c(&m);
  infog[0] = m.infog[0];
  infog[1] = m.infog[1];
  if (m.infog[0] < 0)
    return false;
  data->initialised = true;
  // quiet: no error, warning or statistics output
  m.icntl[mumps_icntl(1)] = 0;
  m.icntl[mumps_icntl(2)] = 0;
  m.icntl[mumps_icntl(3)] = 0;
  m.icntl[mumps_icntl(4)] = 0;
  m.icntl[mumps_icntl(5)] = 0;   // assembled matrix
  m.icntl[mumps_icntl(18)] = 0;  // centralised on the host
  m.icntl[mumps_icntl(14)] = 30; // workspace relaxation (%)
  m.n = n;
  m.nnz = values.size();
  m.irn = rows.data();
  m.jcn = columns.data();
  m.a = values.data();
  for (unsigned int attempt = 0; attempt < 4; ++attempt)
  {
    m.job = mumps_analyse_and_factorise;
    dmumps_c(&m);
    if (!workspace_too_small(m.infog[0]))
      break;
    m.icntl[mumps_icntl(14)] *= 2;
  }
  // the entries are not needed after the factorisation
  m.irn = nullptr;
  m.jcn = nullptr;
  m.a = nullptr;
  infog[0] = m.infog[0];
  infog[1] = m.infog[1];
  n_negative = m.infog[0] >= 0 ? m.infog[11] : 0;
  return m.infog[0] >= 0;
}

bool SymmetricMumps::solve(double *columns, const unsigned int n_rhs) const
{
  DMUMPS_STRUC_C &m = data->mumps;
  if (!data->initialised || n_rhs == 0)
    return data->initialised;
  m.icntl[mumps_icntl(20)] = 0; // dense right-hand sides
  m.icntl[mumps_icntl(21)] = 0; // centralised solution (in place of the rhs)
  m.nrhs = n_rhs;
  m.lrhs = n;
  m.rhs = columns;
  m.job = mumps_solve;
  dmumps_c(&m);
  m.rhs = nullptr;
  return m.infog[0] >= 0;
}

} // namespace hati
