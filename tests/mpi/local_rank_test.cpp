// nodeLocalRank under mpirun on one node: every rank's local rank is its rank, in MPI_COMM_WORLD
// and in a communicator split by parity; exit 0 when all hold.
#include <mpi.h>

#include <cstdio>

#include "dist/mpi_local_rank.h"

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0, size = 1, failures = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  int nodeRanks = 0;
  const int local = ewa::dist::nodeLocalRank(MPI_COMM_WORLD, &nodeRanks);
  // mpirun on one machine puts every rank on one node.
  if (local != rank || nodeRanks != size) {
    std::fprintf(stderr, "rank %d: FAILED: local rank %d of %d on the node\n", rank, local,
                 nodeRanks);
    ++failures;
  }
  MPI_Comm half = MPI_COMM_NULL;
  MPI_Comm_split(MPI_COMM_WORLD, rank % 2, rank, &half);
  int halfRank = 0, halfSize = 0, halfNodeRanks = 0;
  MPI_Comm_rank(half, &halfRank);
  MPI_Comm_size(half, &halfSize);
  const int halfLocal = ewa::dist::nodeLocalRank(half, &halfNodeRanks);
  if (halfLocal != halfRank || halfNodeRanks != halfSize) {
    std::fprintf(stderr, "rank %d: FAILED: local rank %d of %d in its half (rank %d of %d)\n", rank,
                 halfLocal, halfNodeRanks, halfRank, halfSize);
    ++failures;
  }
  MPI_Comm_free(&half);
  int total = 0;
  MPI_Allreduce(&failures, &total, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  if (rank == 0)
    std::printf("local_rank_test: %d ranks, %s\n", size, total == 0 ? "all held" : "FAILED");
  MPI_Finalize();
  return total == 0 ? 0 : 1;
}
