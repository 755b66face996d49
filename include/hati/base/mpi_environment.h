#pragma once

#include <string>

namespace hati
{
/**
 * Prepares Open MPI for a run started without `mpirun`, before
 * `MPI_Init` (construct it before deal.II's `MPI_InitFinalize`, so that it
 * is destroyed after `MPI_Finalize`).
 *
 * Such a run initialises as an isolated singleton
 * (`OMPI_MCA_ess_singleton_isolated=1`: no orted daemon forked) with the
 * ob1 messaging layer and without the UCX one-sided component
 * (`OMPI_MCA_pml=ob1`, `OMPI_MCA_osc=^ucx`: UCX is not initialised, 0.2 s
 * less per start; one process talks to no other). Open MPI
 * 4 gives every singleton the same session folder
 * `/tmp/ompi.<host>.<uid>/jf.0`, which one run's `MPI_Finalize` removes
 * while another run started at the same moment creates a folder inside it:
 * `MPI_Init` then aborts ("A call to mkdir was unable to create the desired
 * directory"). This object gives each singleton its own session base, a
 * fresh folder `${TMPDIR:-/tmp}/hati-mpi-XXXXXX`
 * (`OMPI_MCA_orte_tmpdir_base`), and removes it at the end.
 *
 * Nothing is changed under a launcher (`mpirun`, `srun`: the environment
 * names a rank) or where the user already set these variables.
 */
class MpiEnvironment
{
public:
  MpiEnvironment();
  ~MpiEnvironment();

  MpiEnvironment(const MpiEnvironment &) = delete;
  MpiEnvironment &operator=(const MpiEnvironment &) = delete;

private:
  /** The private session base this object created (empty: none). */
  std::string session_base;
};
} // namespace hati
