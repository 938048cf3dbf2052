// ewaview-mpi entry point: mpirun -np P ewaview-mpi FILE [--output out.png] [ewaview's options];
// without --output the window opens on rank 0.
#include <mpi.h>

#include <iostream>
#include <sstream>

#include "app/options.h"
#include "dist/mpi_render.h"
#include "dist/mpi_window.h"

int main(int argc, char** argv) {
  // Serialized: the window's rank draws full-quality frames on a worker thread, which calls MPI
  // while the window's thread does not.
  int provided = MPI_THREAD_SINGLE;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_SERIALIZED, &provided);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (provided < MPI_THREAD_SERIALIZED && rank == 0)
    std::cerr << "ewaview-mpi: this MPI is not thread-serialized: the window draws full quality "
                 "on its own thread (it waits for each frame)"
              << std::endl;
  ewa::Options options;
  ewa::ParseResult parsed;
  {
    // The same command line on every rank: only rank 0 prints what the parser says.
    std::ostringstream quietOut, quietErr;
    std::streambuf* out = std::cout.rdbuf();
    std::streambuf* err = std::cerr.rdbuf();
    if (rank != 0) {
      std::cout.rdbuf(quietOut.rdbuf());
      std::cerr.rdbuf(quietErr.rdbuf());
    }
    parsed = ewa::parseCommandLine(argc, argv, &options);
    std::cout.rdbuf(out);
    std::cerr.rdbuf(err);
  }
  int status = parsed.exitCode;
  if (parsed.run) {
    if (const std::string problem = ewa::dist::distributedUsageProblem(options); !problem.empty()) {
      if (rank == 0) std::cerr << "ewaview-mpi: " << problem << std::endl;
      status = 2;
    } else if (options.output.empty()) {
      status = ewa::dist::runDistributedWindow(options, argc, argv, MPI_COMM_WORLD);
    } else {
      status = ewa::dist::renderDistributed(options, MPI_COMM_WORLD);
    }
  }
  MPI_Finalize();
  return status;
}
