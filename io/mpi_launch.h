// What the MPI launcher (mpirun) told this process before MPI starts: its rank and the
// number of processes, read from the launcher's environment (Open MPI, PMI, PMIx). A
// process started without mpirun is rank 0 of 1 and never initialises MPI for pure MPM.
#pragma once

namespace vulnus::io
{
int launcher_rank();
int launcher_size();
} // namespace vulnus::io
