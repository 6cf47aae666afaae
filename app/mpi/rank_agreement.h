#pragma once
// Steps every rank takes together: each rank's outcome is shared, so that a failure on one
// rank stops all of them at the same point (no rank waits in a collective the others never
// reach) and rank 0 says once what went wrong where.
#include <mpi.h>

#include <string>
#include <vector>

namespace voxray::mpi {

// Collective. ERROR: this rank's failure (empty: it succeeded); WHERE: what this rank was
// doing it on (e.g. "slices 57-112"). True on every rank when no rank failed. Otherwise
// false on every rank, and rank 0 has written to stderr one line per distinct failure:
// "voxray-mpi: rank 2 of 2 (WHERE): ERROR", the ranks listed together where the text is
// the same.
bool allSucceeded(MPI_Comm comm, const std::string& error, const std::string& where);

// Collective: every rank's TEXT on rank 0 (in rank order); empty elsewhere.
std::vector<std::string> gatherText(MPI_Comm comm, const std::string& text);

}  // namespace voxray::mpi
