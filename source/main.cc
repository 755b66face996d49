#include <deal.II/base/mpi.h>

#include <hati/base/blas_kernels.h>
#include <hati/base/mpi_environment.h>
#include <hati/run/simulation.h>

int main(int argc, char **argv)
{
  // OpenBLAS's kernels for this CPU (may start the program again)
  hati::select_blas_kernels(argv);
  // before MPI_Init, destroyed after MPI_Finalize: a run started without
  // mpirun gets its own Open MPI session folder (see MpiEnvironment)
  const hati::MpiEnvironment mpi_environment;
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  return hati::run_command_line(argc, argv);
}
