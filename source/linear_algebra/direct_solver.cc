#include <deal.II/base/exceptions.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <hati/linear_algebra/direct_solver.h>

#include <chrono>

namespace hati
{
struct DirectSolver::Data
{
  TrilinosWrappers::SparseMatrix matrix;
  // quiet: the default control formats its result into deallog at every
  // solve (a string conversion per Newmark step)
  SolverControl control{100, 0., false, false};
  std::unique_ptr<TrilinosWrappers::SolverDirect> solver;
  // Epetra-compatible vectors of the solve
  LinearAlgebra::distributed::Vector<double> x, b;
};

std::string resolve_linear_solver(const std::string &linear_solver,
                                  const unsigned int n_dofs)
{
  if (linear_solver == "auto" || linear_solver == "direct")
    return n_dofs < mumps_from_n_dofs ? "KLU" : "MUMPS";
  AssertThrow(linear_solver == "KLU" || linear_solver == "MUMPS" ||
                  linear_solver == "iterative",
              ExcMessage("Time integration/Newmark/Linear solver = " + linear_solver +
                         ": unknown linear solver (auto, KLU, MUMPS, direct or "
                         "iterative)."));
  return linear_solver;
}

std::string direct_solver_package(const std::string &linear_solver,
                                  const unsigned int n_dofs)
{
  const std::string solver = resolve_linear_solver(
      linear_solver == "iterative" ? std::string("auto") : linear_solver, n_dofs);
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
  data->matrix.reinit(matrix, 0.);
  data->solver = std::make_unique<TrilinosWrappers::SolverDirect>(
      data->control,
      TrilinosWrappers::SolverDirect::AdditionalData(false, amesos_package));
  try
  {
    data->solver->initialize(data->matrix);
  }
  catch (const std::exception &)
  {
    data->solver.reset();
    AssertThrow(false, ExcMessage(failure));
  }
  data->x.reinit(matrix.m());
  data->b.reinit(matrix.m());
  seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

bool DirectSolver::initialized() const { return data->solver != nullptr; }

void DirectSolver::solve(Vector<double> &x, const Vector<double> &b) const
{
  Assert(initialized(), ExcMessage("DirectSolver::solve before factorize"));
  std::copy(b.begin(), b.end(), data->b.begin());
  try
  {
    data->solver->solve(data->x, data->b);
  }
  catch (const std::exception &)
  {
    AssertThrow(false, ExcMessage(failure));
  }
  std::copy(data->x.begin(), data->x.end(), x.begin());
}
} // namespace hati
