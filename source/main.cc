#include <deal.II/base/mpi.h>

#include <hati/simulation.h>

int main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  return hati::run_command_line(argc, argv);
}
