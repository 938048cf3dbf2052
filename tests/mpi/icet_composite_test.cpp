// IceT's ordered float composite (IceTCompositor) against a serial front-to-back blend of every
// rank's picture, to 2e-7, for each ordering strategy and single-image strategy; split and
// vtree refused; X-ray sums and MIP maxima by reduction; the bytes each rank sends. Run under
// mpirun; exit 0 when all hold.
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "dist/icet_compositor.h"

namespace {

int failures = 0;
int rank = 0;

void check(bool ok, const std::string& what) {
  if (ok) return;
  ++failures;
  std::fprintf(stderr, "rank %d: FAILED: %s\n", rank, what.c_str());
}

// Rank r's premultiplied picture: random colours and opacities, a quarter of the pixels
// transparent, one rank (the last) entirely transparent (a brick with nothing to draw).
std::vector<float> picture(int r, int size, int width, int height) {
  std::vector<float> rgba(size_t(width) * height * 4, 0.0f);
  if (size > 1 && r == size - 1) return rgba;
  std::mt19937 rng(1234u + unsigned(r) * 7919u);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (size_t p = 0; p < rgba.size() / 4; ++p) {
    if (unit(rng) < 0.25f) continue;
    const float a = unit(rng);
    for (int c = 0; c < 3; ++c) rgba[p * 4 + size_t(c)] = a * unit(rng);
    rgba[p * 4 + 3] = a;
  }
  return rgba;
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  const int width = 61, height = 37;  // not a power of two, IceT splits them unevenly
  std::vector<std::vector<float>> all;
  for (int r = 0; r < size; ++r) all.push_back(picture(r, size, width, height));
  // A visibility order every rank agrees on: a fixed shuffle.
  std::vector<int> order(static_cast<size_t>(size));
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), std::mt19937(99u));
  // The serial front-to-back blend: front + (1 - front alpha) * back.
  std::vector<float> serial(all[0].size(), 0.0f);
  for (int r : order)
    for (size_t p = 0; p < serial.size() / 4; ++p) {
      const float keep = 1.0f - serial[p * 4 + 3];
      for (int c = 0; c < 4; ++c)
        serial[p * 4 + size_t(c)] += keep * all[size_t(r)][p * 4 + size_t(c)];
    }

  const char* strategies[] = {"reduce", "sequential", "direct"};
  const char* singles[] = {"automatic", "bswap", "tree", "radixk"};
  for (const char* s : strategies)
    for (const char* single : singles) {
      int strategy = 0, singleImage = 0;
      ewa::dist::parseIceTStrategy(s, &strategy);
      ewa::dist::parseIceTSingleImageStrategy(single, &singleImage);
      ewa::dist::IceTCompositor compositor(MPI_COMM_WORLD, strategy, singleImage);
      // Twice: the second composite reuses the context and tile.
      for (int round = 0; round < 2; ++round) {
        const std::vector<float> blended =
            compositor.blend(all[size_t(rank)], width, height, order);
        // Bytes sent: a few of IceT's own messages on one rank; from 2 ranks on some rank sends
        // (an empty picture compresses to a header), none more than a few whole pictures (binary
        // swap and the gather to the root move about one).
        const long long sent = compositor.lastBytesSent(), picture = (long long)(all[0].size() * 4);
        long long total = 0;
        MPI_Allreduce(&sent, &total, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
        check(sent >= 0 && sent <= 4 * picture,
              std::string(s) + "/" + single + ": bytes sent " + std::to_string(sent));
        check(size == 1 ? total < 64 : total > 0,
              std::string(s) + "/" + single + ": bytes sent by all " + std::to_string(total));
        if (rank != 0) {
          check(blended.empty(), std::string(s) + "/" + single + ": a picture off the root");
          continue;
        }
        double worst = 0.0;
        for (size_t i = 0; i < serial.size(); ++i)
          worst = std::max(worst, std::abs(double(blended[i]) - double(serial[i])));
        check(blended.size() == serial.size() && worst <= 2e-7,
              std::string(s) + "/" + single + ": largest difference " + std::to_string(worst));
      }
    }

  for (const char* refused : {"split", "vtree"}) {
    int strategy = 0;
    ewa::dist::parseIceTStrategy(refused, &strategy);
    std::string message;
    try {
      ewa::dist::IceTCompositor compositor(MPI_COMM_WORLD, strategy);
    } catch (const std::invalid_argument& e) {
      message = e.what();
    }
    check(message.find("does not keep the visibility order") != std::string::npos &&
              message.find('\n') == std::string::npos,
          std::string(refused) + " not refused in one line: '" + message + "'");
  }

  // X-ray: optical depths add; MIP: the largest value, whatever the order.
  std::vector<float> mine(all[size_t(rank)].size());
  for (size_t i = 0; i < mine.size(); ++i) mine[i] = all[size_t(rank)][i] * float(rank + 1);
  std::int64_t sumBytes = -1, maxBytes = -1;
  const std::vector<float> sum = ewa::dist::reduceSum(mine, MPI_COMM_WORLD, 0, &sumBytes);
  const std::vector<float> max = ewa::dist::reduceMax(mine, MPI_COMM_WORLD, 0, &maxBytes);
  const std::int64_t handed = rank == 0 ? 0 : std::int64_t(mine.size() * sizeof(float));
  check(sumBytes == handed && maxBytes == handed,
        "reductions' bytes sent " + std::to_string(sumBytes) + ", " + std::to_string(maxBytes));
  if (rank == 0) {
    double worstSum = 0.0, worstMax = 0.0;
    for (size_t i = 0; i < mine.size(); ++i) {
      double s = 0.0;
      float m = -INFINITY;
      for (int r = 0; r < size; ++r) {
        const float v = all[size_t(r)][i] * float(r + 1);
        s += v;
        m = std::max(m, v);
      }
      worstSum = std::max(worstSum, std::abs(double(sum[i]) - s));
      worstMax = std::max(worstMax, std::abs(double(max[i]) - double(m)));
    }
    check(worstSum <= 1e-5, "X-ray sum off by " + std::to_string(worstSum));
    check(worstMax == 0.0, "MIP maximum off by " + std::to_string(worstMax));
  } else {
    check(sum.empty() && max.empty(), "reductions returned values off the root");
  }

  int total = 0;
  MPI_Allreduce(&failures, &total, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  if (rank == 0)
    std::printf("icet_composite_test: %d ranks, %s\n", size, total == 0 ? "all held" : "FAILED");
  MPI_Finalize();
  return total == 0 ? 0 : 1;
}
