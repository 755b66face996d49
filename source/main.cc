#include <deal.II/base/mpi.h>

#include <hati/simulation.h>

#include <cstdlib>

int main(int argc, char **argv)
{
  // Open MPI: a run started without mpirun initialises as an isolated
  // singleton instead of forking an orted daemon (0.2 s less per start, no
  // daemon to race with other runs started at the same time); mpirun and a
  // value set by the user are not affected.
  setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  return hati::run_command_line(argc, argv);
}
