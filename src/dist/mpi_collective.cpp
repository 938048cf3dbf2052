// anyFailed and abortAll: the ranks' one-line errors.
#include "dist/mpi_collective.h"

#include <climits>
#include <cstdlib>
#include <iostream>

#include "app/one_line.h"

namespace ewa::dist {

bool anyFailed(const std::string& error, MPI_Comm comm) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  const int mine = error.empty() ? INT_MAX : rank;
  int first = INT_MAX;
  MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, comm);
  if (first == INT_MAX) return false;
  if (rank == first)
    std::cerr << "ewaview-mpi: rank " << rank << " of " << size << ": " << oneLine(error)
              << std::endl;
  return true;
}

bool differsFromRank0(uint64_t mine, const std::string& problem, MPI_Comm comm) {
  uint64_t first = mine;
  MPI_Bcast(&first, 1, MPI_UINT64_T, 0, comm);
  return anyFailed(mine == first ? "" : problem, comm);
}

void abortAll(const std::string& error, MPI_Comm comm) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  std::cerr << "ewaview-mpi: rank " << rank << " of " << size << ": " << oneLine(error)
            << std::endl;
  MPI_Abort(comm, 1);
  std::abort();  // MPI_Abort does not return
}

}  // namespace ewa::dist
