// ewaview-icet-bench: IceT's ordered composite alone (IceTCompositor::blend) on P ranks, for
// picture sizes and covered fractions, its time and the bytes each rank sends.
#include <mpi.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <numeric>
#include <string>
#include <vector>

#include "dist/icet_compositor.h"

namespace {

// Rank r's picture: premultiplied half-opaque grey over a band of rows covering `coverage` of
// the picture, placed by rank (a brick's footprint covers part of the screen), transparent
// elsewhere. IceT sends runs of covered pixels only, so the band decides the bytes.
std::vector<float> picture(int r, int size, int side, double coverage) {
  std::vector<float> rgba(size_t(side) * size_t(side) * 4, 0.0f);
  const int rows = std::clamp(int(coverage * side + 0.5), 0, side);
  const int first = size > 1 ? int(int64_t(side - rows) * r / (size - 1)) : 0;
  for (int y = first; y < first + rows; ++y)
    for (int x = 0; x < side; ++x) {
      float* p = rgba.data() + (size_t(y) * size_t(side) + size_t(x)) * 4;
      p[0] = p[1] = p[2] = 0.25f;
      p[3] = 0.5f;
    }
  return rgba;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  CLI::App app{"ewaview-icet-bench: IceT's ordered composite of P ranks' float pictures"};
  std::vector<int> sides = {512, 1024, 2048};
  std::vector<double> coverages = {1.0, 0.25};
  int repeats = 5;
  app.add_option("--sizes", sides, "Square picture sides (512 1024 2048)")->delimiter(',');
  app.add_option("--coverage", coverages, "Covered fraction of each rank's picture (1,0.25)")
      ->delimiter(',');
  app.add_option("--repeats", repeats, "Timed composites each; the median is printed (5)")
      ->check(CLI::Range(1, 1000));
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int status = rank == 0 ? app.exit(e) : (e.get_exit_code() == 0 ? 0 : 2);
    MPI_Finalize();
    return status;
  }
  {  // The compositor frees its MPI communicator before MPI_Finalize.
    ewa::dist::IceTCompositor compositor(MPI_COMM_WORLD);
    std::vector<int> order(size_t(size), 0);
    std::iota(order.begin(), order.end(), 0);
    if (rank == 0)
      std::printf(
          "ranks,side,coverage,composite_ms,bytes_sent_min,bytes_sent_median,bytes_sent_max,"
          "picture_bytes\n");
    for (int side : sides)
      for (double coverage : coverages) {
        const std::vector<float> mine = picture(rank, size, side, coverage);
        compositor.blend(mine, side, side, order);  // IceT's buffers, first touched
        std::vector<double> times;
        for (int i = 0; i < repeats; ++i) {
          MPI_Barrier(MPI_COMM_WORLD);
          const auto start = std::chrono::steady_clock::now();
          compositor.blend(mine, side, side, order);
          // The composite ends when the slowest rank is done.
          double ms =
              std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                  .count();
          MPI_Allreduce(MPI_IN_PLACE, &ms, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
          times.push_back(ms);
        }
        const double sent = double(compositor.lastBytesSent());
        std::vector<double> all(size_t(size), 0.0);
        MPI_Gather(&sent, 1, MPI_DOUBLE, all.data(), 1, MPI_DOUBLE, 0, MPI_COMM_WORLD);
        if (rank == 0)
          std::printf("%d,%d,%g,%.3f,%.0f,%.0f,%.0f,%zu\n", size, side, coverage, median(times),
                      *std::min_element(all.begin(), all.end()), median(all),
                      *std::max_element(all.begin(), all.end()), mine.size() * sizeof(float));
      }
  }
  MPI_Finalize();
  return 0;
}
