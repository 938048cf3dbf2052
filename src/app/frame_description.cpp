// serializeFrame and deserializeFrame: a FrameDescription field by field, with a version tag.
#include "app/frame_description.h"

#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace ewa {

namespace {

// Bumped whenever a field is added, removed or reordered.
constexpr uint32_t kMagic = 0x45574631;  // "EWF1"
constexpr uint32_t kVersion = 1;

// A new field of these structs must be written below too: their sizes (LP64) catch one
// forgotten.
static_assert(sizeof(void*) != 8 || sizeof(RenderSettings) == 360,
              "RenderSettings changed: serialize the new field in frame_description.cpp");
static_assert(sizeof(void*) != 8 || sizeof(Camera) == 88,
              "Camera changed: serialize the new field in frame_description.cpp");

class Writer {
 public:
  template <typename T>
  void put(T value) {
    static_assert(std::is_arithmetic_v<T> || std::is_enum_v<T>, "plain values only");
    const size_t at = bytes.size();
    bytes.resize(at + sizeof value);
    std::memcpy(bytes.data() + at, &value, sizeof value);
  }
  void put(const glm::dvec3& v) {
    for (int a = 0; a < 3; ++a) put(v[a]);
  }
  std::vector<uint8_t> bytes;
};

class Reader {
 public:
  Reader(const uint8_t* data, size_t size) : data_(data), size_(size) {}
  template <typename T>
  void get(T& value) {
    static_assert(std::is_arithmetic_v<T> || std::is_enum_v<T>, "plain values only");
    if (size_ - at_ < sizeof value)
      throw std::runtime_error("a frame description cut short at byte " + std::to_string(at_));
    std::memcpy(&value, data_ + at_, sizeof value);
    at_ += sizeof value;
  }
  void get(glm::dvec3& v) {
    for (int a = 0; a < 3; ++a) get(v[a]);
  }
  // A count of elements that follow, each at least `elementBytes`: refused past the bytes left.
  size_t count(size_t elementBytes) {
    uint64_t n = 0;
    get(n);
    if (n > (size_ - at_) / elementBytes)
      throw std::runtime_error("a frame description with a count past its end");
    return size_t(n);
  }
  bool done() const { return at_ == size_; }

 private:
  const uint8_t* data_;
  size_t size_;
  size_t at_ = 0;
};

}  // namespace

std::vector<uint8_t> serializeFrame(const FrameDescription& f) {
  Writer w;
  w.put(kMagic);
  w.put(kVersion);
  w.put(f.quit);
  w.put(int32_t(f.exitStatus));
  w.put(int32_t(f.width));
  w.put(int32_t(f.height));
  const Camera& c = f.camera;
  w.put(c.position), w.put(c.focalPoint), w.put(c.viewUp), w.put(c.viewAngleDeg);
  w.put(c.orthographic);

  const RenderSettings& s = f.settings;
  w.put(s.renderer), w.put(s.filter), w.put(s.mode), w.put(s.cutoff), w.put(s.kernelWidth);
  w.put(s.lowPass), w.put(s.depthCutoff), w.put(s.slabThickness), w.put(s.background);
  w.put(s.order), w.put(s.terminationOpacity), w.put(s.occlusionCulling), w.put(s.xrayMap);
  w.put(s.xrayScale);
  const Lighting& l = s.lighting;
  w.put(l.enabled), w.put(l.ambient), w.put(l.diffuse), w.put(l.specular), w.put(l.shininess);
  const Classification& k = s.classification;
  w.put(k.gradient), w.put(k.surface), w.put(k.threshold), w.put(k.minGradient), w.put(k.mode);
  w.put(int32_t(k.postMarginSquared)), w.put(k.prefilter);
  w.put(s.slabPreintegration), w.put(int32_t(s.slabSamples)), w.put(int32_t(s.slabPasses));
  w.put(s.slabPrecision), w.put(s.postNormals), w.put(s.splatter), w.put(s.coarseSlabs);
  w.put(s.surfaceOpacity);
  const ShearWarpSettings& sw = s.shearWarp;
  w.put(sw.preintegrated), w.put(sw.lookup), w.put(sw.opacityCorrection), w.put(sw.buffers);
  w.put(sw.runLengthEncoding), w.put(sw.terminationAlpha), w.put(int32_t(sw.threads));
  w.put(int32_t(sw.tableSize)), w.put(sw.intermediateScale);
  const ClipRegion& clip = s.clip;
  w.put(clip.cropEnabled), w.put(clip.cropMin), w.put(clip.cropMax);
  w.put(uint64_t(clip.planes.size()));
  for (const ClipPlane& p : clip.planes) w.put(p.point), w.put(p.normal), w.put(p.enabled);

  w.put(f.tf.opacityUnitDistance);
  w.put(uint64_t(f.tf.opacity.size()));
  for (const OpacityPoint& p : f.tf.opacity) w.put(p.value), w.put(p.alpha);
  w.put(uint64_t(f.tf.color.size()));
  for (const ColorPoint& p : f.tf.color) w.put(p.value), w.put(p.rgb);
  return std::move(w.bytes);
}

FrameDescription deserializeFrame(const uint8_t* bytes, size_t size) {
  Reader r(bytes, size);
  uint32_t magic = 0, version = 0;
  r.get(magic);
  r.get(version);
  if (magic != kMagic || version != kVersion)
    throw std::runtime_error("not a frame description of this ewaview-mpi (version " +
                             std::to_string(version) + ")");
  FrameDescription f;
  int32_t i = 0;
  r.get(f.quit);
  r.get(i), f.exitStatus = i;
  r.get(i), f.width = i;
  r.get(i), f.height = i;
  Camera& c = f.camera;
  r.get(c.position), r.get(c.focalPoint), r.get(c.viewUp), r.get(c.viewAngleDeg);
  r.get(c.orthographic);

  RenderSettings& s = f.settings;
  r.get(s.renderer), r.get(s.filter), r.get(s.mode), r.get(s.cutoff), r.get(s.kernelWidth);
  r.get(s.lowPass), r.get(s.depthCutoff), r.get(s.slabThickness), r.get(s.background);
  r.get(s.order), r.get(s.terminationOpacity), r.get(s.occlusionCulling), r.get(s.xrayMap);
  r.get(s.xrayScale);
  Lighting& l = s.lighting;
  r.get(l.enabled), r.get(l.ambient), r.get(l.diffuse), r.get(l.specular), r.get(l.shininess);
  Classification& k = s.classification;
  r.get(k.gradient), r.get(k.surface), r.get(k.threshold), r.get(k.minGradient), r.get(k.mode);
  r.get(i), k.postMarginSquared = i;
  r.get(k.prefilter);
  r.get(s.slabPreintegration);
  r.get(i), s.slabSamples = i;
  r.get(i), s.slabPasses = i;
  r.get(s.slabPrecision), r.get(s.postNormals), r.get(s.splatter), r.get(s.coarseSlabs);
  r.get(s.surfaceOpacity);
  ShearWarpSettings& sw = s.shearWarp;
  r.get(sw.preintegrated), r.get(sw.lookup), r.get(sw.opacityCorrection), r.get(sw.buffers);
  r.get(sw.runLengthEncoding), r.get(sw.terminationAlpha);
  r.get(i), sw.threads = i;
  r.get(i), sw.tableSize = i;
  r.get(sw.intermediateScale);
  ClipRegion& clip = s.clip;
  r.get(clip.cropEnabled), r.get(clip.cropMin), r.get(clip.cropMax);
  clip.planes.resize(r.count(6 * sizeof(double) + sizeof(bool)));
  for (ClipPlane& p : clip.planes) r.get(p.point), r.get(p.normal), r.get(p.enabled);

  r.get(f.tf.opacityUnitDistance);
  f.tf.opacity.resize(r.count(2 * sizeof(double)));
  for (OpacityPoint& p : f.tf.opacity) r.get(p.value), r.get(p.alpha);
  f.tf.color.resize(r.count(4 * sizeof(double)));
  for (ColorPoint& p : f.tf.color) r.get(p.value), r.get(p.rgb);
  if (!r.done()) throw std::runtime_error("a frame description with bytes left over");
  return f;
}

}  // namespace ewa
