// IceTCompositor: IceT's context, strategy check, tile and ordered composite.
#include "dist/icet_compositor.h"

#include <IceT.h>
#include <IceTMPI.h>

#include <climits>
#include <cstring>
#include <stdexcept>
#include <utility>

namespace ewa::dist {

namespace {

const std::pair<const char*, IceTEnum> kStrategies[] = {{"reduce", ICET_STRATEGY_REDUCE},
                                                        {"sequential", ICET_STRATEGY_SEQUENTIAL},
                                                        {"direct", ICET_STRATEGY_DIRECT},
                                                        {"split", ICET_STRATEGY_SPLIT},
                                                        {"vtree", ICET_STRATEGY_VTREE}};
const std::pair<const char*, IceTEnum> kSingleImageStrategies[] = {
    {"automatic", ICET_SINGLE_IMAGE_STRATEGY_AUTOMATIC},
    {"bswap", ICET_SINGLE_IMAGE_STRATEGY_BSWAP},
    {"tree", ICET_SINGLE_IMAGE_STRATEGY_TREE},
    {"radixk", ICET_SINGLE_IMAGE_STRATEGY_RADIXK},
    {"radixkr", ICET_SINGLE_IMAGE_STRATEGY_RADIXKR},
    {"bswap-folding", ICET_SINGLE_IMAGE_STRATEGY_BSWAP_FOLDING}};

template <size_t N>
bool parseName(const std::pair<const char*, IceTEnum> (&table)[N], const std::string& name,
               int* out) {
  for (const auto& [n, value] : table)
    if (name == n) {
      *out = int(value);
      return true;
    }
  return false;
}

std::vector<float> reduce(const std::vector<float>& values, MPI_Comm comm, int root, MPI_Op op,
                          std::int64_t* bytesSent) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  if (values.size() > size_t(INT_MAX)) throw std::invalid_argument("reduce: too many values");
  if (bytesSent) *bytesSent = reductionBytesSent(values.size(), rank, root);
  std::vector<float> out(rank == root ? values.size() : 0);
  MPI_Reduce(values.data(), rank == root ? out.data() : nullptr, int(values.size()), MPI_FLOAT, op,
             root, comm);
  return out;
}

}  // namespace

bool parseIceTStrategy(const std::string& name, int* strategy) {
  return parseName(kStrategies, name, strategy);
}

bool parseIceTSingleImageStrategy(const std::string& name, int* strategy) {
  return parseName(kSingleImageStrategies, name, strategy);
}

IceTCompositor::IceTCompositor(MPI_Comm comm, int strategy, int singleImageStrategy) : comm_(comm) {
  MPI_Comm_rank(comm, &rank_);
  MPI_Comm_size(comm, &size_);
  IceTCommunicator icetComm = icetCreateMPICommunicator(comm);
  communicator_ = icetComm;
  IceTContext context = icetCreateContext(icetComm);
  context_ = context;
  icetDiagnostics(ICET_DIAG_ERRORS | ICET_DIAG_ALL_NODES);
  icetSetColorFormat(ICET_IMAGE_COLOR_RGBA_FLOAT);
  icetSetDepthFormat(ICET_IMAGE_DEPTH_NONE);
  icetCompositeMode(ICET_COMPOSITE_MODE_BLEND);
  icetEnable(ICET_ORDERED_COMPOSITE);
  icetStrategy(IceTEnum(strategy != 0 ? strategy : int(ICET_STRATEGY_REDUCE)));
  icetSingleImageStrategy(IceTEnum(
      singleImageStrategy != 0 ? singleImageStrategy : int(ICET_SINGLE_IMAGE_STRATEGY_AUTOMATIC)));
  IceTBoolean ordered = ICET_FALSE;
  icetGetBooleanv(ICET_STRATEGY_SUPPORTS_ORDERING, &ordered);
  if (!ordered) {
    const std::string name = icetGetStrategyName();
    icetDestroyContext(context);
    icetDestroyMPICommunicator(icetComm);
    context_ = communicator_ = nullptr;
    throw std::invalid_argument("IceT strategy " + name +
                                " does not keep the visibility order "
                                "(ICET_STRATEGY_SUPPORTS_ORDERING is false): use reduce, "
                                "sequential or direct");
  }
}

IceTCompositor::~IceTCompositor() {
  if (context_) icetDestroyContext(static_cast<IceTContext>(context_));
  if (communicator_) icetDestroyMPICommunicator(static_cast<IceTCommunicator>(communicator_));
}

std::vector<float> IceTCompositor::blend(const std::vector<float>& rgba, int width, int height,
                                         const std::vector<int>& order) {
  if (width < 1 || height < 1 || rgba.size() != size_t(width) * size_t(height) * 4)
    throw std::invalid_argument("IceTCompositor::blend: the picture is not width x height RGBA");
  if (order.size() != size_t(size_))
    throw std::invalid_argument("IceTCompositor::blend: the order must list every rank once");
  icetSetContext(static_cast<IceTContext>(context_));
  if (width != tileWidth_ || height != tileHeight_) {
    icetResetTiles();
    icetAddTile(0, 0, width, height, 0);
    tileWidth_ = width;
    tileHeight_ = height;
  }
  const std::vector<IceTInt> ranks(order.begin(), order.end());
  icetCompositeOrder(ranks.data());
  const IceTInt viewport[4] = {0, 0, width, height};
  const IceTDouble identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  const IceTFloat background[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  const IceTImage image =
      icetCompositeImage(rgba.data(), nullptr, viewport, identity, identity, background);
  if (icetGetError() != ICET_NO_ERROR)
    throw std::runtime_error("IceT could not composite the pictures (see its message above)");
  // icetCompositeImage resets the count when it starts, so this is the last blend's alone.
  IceTInt sent = 0;
  icetGetIntegerv(ICET_BYTES_SENT, &sent);
  lastBytesSent_ = sent;
  if (rank_ != 0) return {};
  std::vector<float> out(rgba.size());
  if (icetImageIsNull(image) || icetImageGetNumPixels(image) != IceTSizeType(width) * height)
    throw std::runtime_error("IceT returned no picture on the display rank");
  std::memcpy(out.data(), icetImageGetColorcf(image), out.size() * sizeof(float));
  return out;
}

std::int64_t reductionBytesSent(size_t count, int rank, int root) {
  return rank == root ? 0 : std::int64_t(count * sizeof(float));
}

std::vector<float> reduceSum(const std::vector<float>& values, MPI_Comm comm, int root,
                             std::int64_t* bytesSent) {
  return reduce(values, comm, root, MPI_SUM, bytesSent);
}

std::vector<float> reduceMax(const std::vector<float>& values, MPI_Comm comm, int root,
                             std::int64_t* bytesSent) {
  return reduce(values, comm, root, MPI_MAX, bytesSent);
}

}  // namespace ewa::dist
