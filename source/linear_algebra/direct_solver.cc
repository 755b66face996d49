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

DirectSolver::DirectSolver() : data(std::make_unique<Data>()) {}

DirectSolver::~DirectSolver() = default;

void DirectSolver::factorize(const SparseMatrix<double> &matrix,
                             const std::string &failure_message)
{
  const auto start = std::chrono::steady_clock::now();
  failure = failure_message;
  data->matrix.reinit(matrix, 0.);
  data->solver = std::make_unique<TrilinosWrappers::SolverDirect>(
      data->control, TrilinosWrappers::SolverDirect::AdditionalData(false, "Amesos_Klu"));
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
