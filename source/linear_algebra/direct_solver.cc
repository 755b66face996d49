#include <deal.II/base/exceptions.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <hati/linear_algebra/direct_solver.h>
#include <hati/linear_algebra/low_rank_update.h>
#include <hati/linear_algebra/symmetric_mumps.h>

#include <chrono>
#include <cstdlib>
#include <new>
#include <string>

namespace hati
{
namespace
{
/**
 * The one-line message of a factorisation that ran out of memory: MUMPS's
 * INFOG(1) @p error and INFOG(2) @p detail (for -13 the size it asked for,
 * in MB if negative), the matrix size @p n.
 */
std::string
memory_failure_message(const std::size_t n, const int error, const long detail)
{
  std::string asked;
  if (error == -13 && detail != 0)
    asked = detail < 0 ? ", " + std::to_string(-detail) + " MB asked for"
                       : ", " + std::to_string(detail) + " entries asked for";
  return "the direct solver (MUMPS) ran out of memory factorising the matrix of " +
         std::to_string(n) + " DoFs (INFOG(1) = " + std::to_string(error) + asked +
         "): not a singular model, a model too large for this machine's memory; reduce "
         "its cells or their degree";
}
} // namespace

struct DirectSolver::Data
{
  TrilinosWrappers::SparseMatrix matrix;
  // quiet: the default control formats its result into deallog at every
  // solve (a string conversion per Newmark step)
  SolverControl control{100, 0., false, false};
  std::unique_ptr<TrilinosWrappers::SolverDirect> solver;
  // Epetra-compatible vectors of the solve
  LinearAlgebra::distributed::Vector<double> x, b;
  // MUMPS's L D L^T of a symmetric matrix (instead of Amesos' L U)
  std::unique_ptr<SymmetricMumps> symmetric;
  // factorize_or_update(): the matrix factorised and the update of it
  std::unique_ptr<LowRankUpdate> update;
};

std::string resolve_linear_solver(const std::string &linear_solver,
                                  const unsigned int n_dofs,
                                  const double row_length)
{
  if (linear_solver == "auto" || linear_solver == "direct")
  {
    const bool continuum = row_length >= mumps_from_row_length;
    return n_dofs >= mumps_from_n_dofs ||
                   (continuum && n_dofs >= mumps_from_n_dofs_continua)
               ? "MUMPS"
               : "KLU";
  }
  AssertThrow(linear_solver == "KLU" || linear_solver == "MUMPS" ||
                  linear_solver == "iterative",
              ExcMessage("Time integration/Newmark/Linear solver = " + linear_solver +
                         ": unknown linear solver (auto, KLU, MUMPS, direct or "
                         "iterative)."));
  return linear_solver;
}

std::string direct_solver_package(const std::string &linear_solver,
                                  const unsigned int n_dofs,
                                  const double row_length)
{
  const std::string solver = resolve_linear_solver(
      linear_solver == "iterative" ? std::string("auto") : linear_solver,
      n_dofs,
      row_length);
  return solver == "MUMPS" ? "Amesos_Mumps" : "Amesos_Klu";
}

DirectSolver::DirectSolver(const std::string &package)
    : data(std::make_unique<Data>()), amesos_package(package)
{
  AssertThrow(package == "Amesos_Klu" || package == "Amesos_Mumps",
              ExcMessage("DirectSolver: unknown Amesos package <" + package +
                         ">: Amesos_Klu or Amesos_Mumps."));
}

DirectSolver::~DirectSolver() = default;

void DirectSolver::factorize(const SparseMatrix<double> &matrix,
                             const std::string &failure_message)
{
  const auto start = std::chrono::steady_clock::now();
  failure = failure_message;
  size = matrix.m();
  data->solver.reset();
  data->symmetric.reset();
  data->update.reset();
  // MUMPS on a symmetric matrix: L D L^T called directly (SymmetricMumps)
  if (amesos_package == "Amesos_Mumps" && is_symmetric(matrix))
  {
    data->symmetric = std::make_unique<SymmetricMumps>();
    if (!data->symmetric->factorize(matrix))
    {
      const int error = data->symmetric->error();
      const long detail = data->symmetric->error_detail();
      data->symmetric.reset();
      // memory is not singularity: MUMPS's own code said
      AssertThrow(!SymmetricMumps::memory_error(error),
                  ExcMessage(memory_failure_message(matrix.m(), error, detail)));
      AssertThrow(false, ExcMessage(failure));
    }
    seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return;
  }
  data->matrix.reinit(matrix, 0.);
  data->solver = std::make_unique<TrilinosWrappers::SolverDirect>(
      data->control,
      TrilinosWrappers::SolverDirect::AdditionalData(false, amesos_package));
  try
  {
    data->solver->initialize(data->matrix);
  }
  catch (const std::bad_alloc &)
  {
    data->solver.reset();
    AssertThrow(false, ExcMessage(memory_failure_message(matrix.m(), -13, 0)));
  }
  catch (const std::exception &e)
  {
    data->solver.reset();
    // Amesos passes MUMPS's INFOG(1) on as its error number
    const std::string what = e.what();
    const auto at = what.find("error number ");
    const int error = at == std::string::npos ? 0 : std::atoi(what.c_str() + at + 13);
    AssertThrow(amesos_package != "Amesos_Mumps" || !SymmetricMumps::memory_error(error),
                ExcMessage(memory_failure_message(matrix.m(), error, 0)));
    AssertThrow(false, ExcMessage(failure));
  }
  data->x.reinit(matrix.m());
  data->b.reinit(matrix.m());
  seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

bool DirectSolver::initialized() const
{
  return data->solver != nullptr || data->symmetric != nullptr;
}

bool DirectSolver::factorize_or_update(const SparseMatrix<double> &matrix,
                                       const std::string &failure_message,
                                       const unsigned int max_rank)
{
  std::vector<unsigned int> rows;
  if (data->update && initialized() &&
      data->update->differing_rows(matrix, max_rank, rows))
  {
    failure = failure_message;
    data->update->clear();
    const bool regular =
        data->update->update(matrix,
                             rows,
                             [this](double *columns, const unsigned int n_rhs)
                             { solve_factorised(columns, n_rhs); });
    AssertThrow(regular, ExcMessage(failure));
    return false;
  }
  factorize(matrix, failure_message);
  data->update = std::make_unique<LowRankUpdate>();
  data->update->set_base(matrix);
  return true;
}

void DirectSolver::solve(Vector<double> &x, const Vector<double> &b) const
{
  Assert(initialized(), ExcMessage("DirectSolver::solve before factorize"));
  if (&x != &b)
    x = b;
  solve_many(x.begin(), 1);
}

void DirectSolver::solve_many(double *columns, const unsigned int n_rhs) const
{
  Assert(initialized(), ExcMessage("DirectSolver::solve_many before factorize"));
  solve_factorised(columns, n_rhs);
  if (data->update && data->update->active())
    for (unsigned int k = 0; k < n_rhs; ++k)
      data->update->correct(columns + std::size_t(k) * size);
}

void DirectSolver::solve_factorised(double *columns, const unsigned int n_rhs) const
{
  if (data->symmetric)
  {
    AssertThrow(data->symmetric->solve(columns, n_rhs), ExcMessage(failure));
    return;
  }
  for (unsigned int k = 0; k < n_rhs; ++k)
  {
    double *const column = columns + std::size_t(k) * size;
    std::copy(column, column + size, data->b.begin());
    try
    {
      data->solver->solve(data->x, data->b);
    }
    catch (const std::exception &)
    {
      AssertThrow(false, ExcMessage(failure));
    }
    std::copy(data->x.begin(), data->x.end(), column);
  }
}
} // namespace hati
