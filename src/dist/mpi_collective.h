// Collective error handling for the ranks: one line from one rank, then every rank stops alike.
#pragma once

#include <mpi.h>

#include <cstdint>
#include <string>

namespace ewa::dist {

// Whether any rank failed (`error` non-empty there); the lowest such rank prints its line as
// "ewaview-mpi: rank R of P: error". Collective: every rank of `comm` calls it.
bool anyFailed(const std::string& error, MPI_Comm comm);

// Whether any rank's `mine` differs from rank 0's; the lowest such rank prints `problem` as
// anyFailed does. Collective.
bool differsFromRank0(uint64_t mine, const std::string& problem, MPI_Comm comm);

// An error where the ranks cannot meet again (one may wait in a collective): one line, then
// every rank ends through MPI_Abort.
[[noreturn]] void abortAll(const std::string& error, MPI_Comm comm);

}  // namespace ewa::dist
