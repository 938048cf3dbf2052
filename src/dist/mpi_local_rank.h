// The rank's place among the ranks on its own node, which picks its GPU where a node has several.
#pragma once

#include <mpi.h>

namespace ewa::dist {

// This rank's index among the ranks of `comm` that share its node (MPI_Comm_split_type with
// MPI_COMM_TYPE_SHARED, ordered by their rank in `comm`): 0 to that count - 1. Collective over
// `comm`. `nodeRanks`, when given, gets how many ranks of `comm` share the node.
int nodeLocalRank(MPI_Comm comm, int* nodeRanks = nullptr);

}  // namespace ewa::dist
