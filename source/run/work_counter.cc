#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <hati/run/work_counter.h>

namespace hati
{
WorkCounter::WorkCounter(MPI_Comm comm) : comm(comm)
{
  if (dealii::Utilities::MPI::n_mpi_processes(comm) == 1)
    return;
  const bool root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
  int *base = nullptr;
  int error = MPI_Win_allocate(
      root ? 2 * sizeof(int) : 0, sizeof(int), MPI_INFO_NULL, comm, &base, &window);
  AssertThrowMPI(error);
  if (root)
  {
    MPI_Win_lock(MPI_LOCK_EXCLUSIVE, 0, 0, window);
    base[0] = base[1] = 0;
    MPI_Win_unlock(0, window);
  }
  error = MPI_Barrier(comm); // the counters are set before anyone reads them
  AssertThrowMPI(error);
}

WorkCounter::~WorkCounter()
{
  if (window != MPI_WIN_NULL)
    MPI_Win_free(&window);
}

unsigned int WorkCounter::fetch_and_increment(const unsigned int which)
{
  if (window == MPI_WIN_NULL)
    return local[which]++;
  const int one = 1;
  int before = 0;
  MPI_Win_lock(MPI_LOCK_SHARED, 0, 0, window);
  const int error = MPI_Fetch_and_op(&one, &before, MPI_INT, 0, which, MPI_SUM, window);
  MPI_Win_unlock(0, window);
  AssertThrowMPI(error);
  return before;
}
} // namespace hati
