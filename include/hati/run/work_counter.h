#ifndef hati_run_work_counter_h
#define hati_run_work_counter_h

#include <deal.II/base/mpi.h>

namespace hati
{
/**
 * Counters shared by the ranks of a communicator, for the dynamic
 * assignment of the members of a suite: each counter lives on rank 0 in an
 * MPI window and is read and incremented atomically (MPI_Fetch_and_op,
 * passive target), so that a rank asks for its next member when it is free
 * and no rank, rank 0 included, has to stop its own member to answer. On a
 * single rank the counters are plain integers (no window).
 */
class WorkCounter
{
public:
  /** Counter 0 counts members handed out, counter 1 members done. Collective. */
  explicit WorkCounter(MPI_Comm comm);
  /** Frees the window. Collective: every rank waits for the others here. */
  ~WorkCounter();
  WorkCounter(const WorkCounter &) = delete;
  WorkCounter &operator=(const WorkCounter &) = delete;

  /** Add 1 to counter @p which (0 or 1) and return its value before. */
  unsigned int fetch_and_increment(const unsigned int which);

private:
  MPI_Comm comm;
  MPI_Win window = MPI_WIN_NULL;
  int local[2] = {0, 0};
};
} // namespace hati

#endif
