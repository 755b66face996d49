#ifndef hati_run_mpi_consensus_h
#define hati_run_mpi_consensus_h

#include <deal.II/base/mpi.h>

#include <functional>
#include <stdexcept>
#include <string>

namespace hati
{
/**
 * A one-line error that every rank of a communicator throws together
 * (agree()): the command line prints it on rank 0 only, and no rank is
 * left waiting in a collective operation for a rank that stopped.
 */
class AgreedError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/**
 * Run @p step (on every rank, or on rank 0 only if @p rank_zero_only) and
 * agree on its outcome: if it threw on any rank, every rank throws the
 * AgreedError of the lowest such rank's one-line message; otherwise every
 * rank returns. Collective (an all-gather of the messages); on one rank it
 * only runs @p step and turns its exception into an AgreedError.
 */
void agree(const MPI_Comm comm,
           const std::function<void()> &step,
           const bool rank_zero_only = false);

/**
 * Run @p steps, which contain collective operations on @p comm, so that an
 * exception thrown on one rank only cannot leave the others waiting in a
 * collective: an AgreedError is rethrown (every rank throws it); any other
 * exception on several ranks prints `hati: error: <message>` and aborts
 * every rank (MPI_Abort, exit code 1). On one rank it only runs @p steps.
 */
void without_stray_exceptions(const MPI_Comm comm, const std::function<void()> &steps);
} // namespace hati

#endif
