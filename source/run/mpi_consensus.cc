#include <deal.II/base/mpi.h>

#include <hati/output/run_directory.h>
#include <hati/run/mpi_consensus.h>

#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>

#include <iostream>
#include <vector>

namespace hati
{
void agree(const MPI_Comm comm,
           const std::function<void()> &step,
           const bool rank_zero_only)
{
  const unsigned int rank = dealii::Utilities::MPI::this_mpi_process(comm);
  std::string message;
  bool failed = false;
  if (!rank_zero_only || rank == 0)
    try
    {
      step();
    }
    catch (const AgreedError &e)
    {
      failed = true;
      message = e.what();
    }
    catch (const std::exception &e)
    {
      failed = true;
      message = one_line_message(e);
    }
  if (dealii::Utilities::MPI::n_mpi_processes(comm) == 1)
  {
    if (failed)
      throw AgreedError(message);
    return;
  }
  // (failed, message) of every rank; an empty message is still a failure
  const auto all =
      dealii::Utilities::MPI::all_gather(comm, std::make_pair(failed, message));
  for (const auto &[rank_failed, rank_message] : all)
    if (rank_failed)
      throw AgreedError(rank_message);
}

void without_stray_exceptions(const MPI_Comm comm, const std::function<void()> &steps)
{
  if (dealii::Utilities::MPI::n_mpi_processes(comm) == 1)
  {
    steps();
    return;
  }
  std::string message;
  try
  {
    steps();
    return;
  }
  catch (const AgreedError &)
  {
    throw;
  }
  catch (const std::exception &e)
  {
    message = one_line_message(e);
  }
  catch (...)
  {
    message = "an unknown exception";
  }
  // the other ranks may be waiting in a collective operation for this one
  std::cerr << "hati: error: " << message << " (rank "
            << dealii::Utilities::MPI::this_mpi_process(comm)
            << "; the other ranks are stopped)" << std::endl;
  MPI_Abort(comm, 1);
}
} // namespace hati
