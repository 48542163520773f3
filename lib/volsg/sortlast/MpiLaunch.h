#pragma once
// Whether this process was started by an MPI launcher, read from its environment: a plain run
// must not pay MPI's start-up (or print its warnings), so MPI_Init is called only then.

namespace volsg {

/// The world size the launcher announced (OpenMPI's OMPI_COMM_WORLD_SIZE, or PMI_SIZE /
/// PMIX_SIZE of other launchers), or 0 when none did: not started by mpirun.
int mpiLaunchSize();

} // namespace volsg
