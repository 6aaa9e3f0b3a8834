// The MPI launch this process is part of, read from the launcher's environment
// (OpenMPI's mpirun, or a PMI/PMIx launcher such as srun) without starting MPI: the
// program starts MPI only when a run asks for PETSc (fluid/petsc_solver.hpp), but it
// must know from its first line whether it is one rank of several (SPEC §13: the
// progress, the outputs and the summary come from rank 0 only).
#pragma once

namespace fsi {

// The number of ranks the run started with; 1 without a launcher.
int launched_ranks();
// This process's rank, 0 to launched_ranks() − 1; 0 without a launcher.
int launched_rank();

}  // namespace fsi
