// nodeLocalRank: the ranks sharing a node, from MPI_Comm_split_type.
#include "dist/mpi_local_rank.h"

namespace ewa::dist {

int nodeLocalRank(MPI_Comm comm, int* nodeRanks) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  // Keyed by the rank in `comm`, so local ranks follow global order on each node (and any
  // launcher's placement, --map-by included, gives the same answer).
  MPI_Comm node = MPI_COMM_NULL;
  MPI_Comm_split_type(comm, MPI_COMM_TYPE_SHARED, rank, MPI_INFO_NULL, &node);
  int local = 0, count = 1;
  MPI_Comm_rank(node, &local);
  MPI_Comm_size(node, &count);
  MPI_Comm_free(&node);
  if (nodeRanks) *nodeRanks = count;
  return local;
}

}  // namespace ewa::dist
