// The GPU slab partition against its reference, SlabPartition on the CPU: over many views,
// projections, filters, kernel widths, slab thicknesses and cull depths, every slab has the same
// planes and the same entries (splat and first/last flags) as a set; the order within a slab may
// differ.
#include "render/gpu_slab_partition.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "core/kernel_reach.h"
#include "core/slab_partition.h"
#include "core/splat_attributes.h"
#include "gl/buffer.h"
#include "render_fixture.h"

namespace ewa::test {
namespace {

class GpuSlabPartitionTest : public RenderFixture {};

// A ball of voxels with a value ramp (surface splats where asked) and scattered voxels.
Volume testVolume(glm::dvec3 spacing) {
  std::mt19937 rng(7);
  std::vector<bool> scattered(size_t(14 * 12 * 10));
  for (size_t v = 0; v < scattered.size(); ++v) scattered[v] = rng() % 9 == 0;
  return makeVolume(14, 12, 10, spacing, [&](int i, int j, int k) {
    const double r = std::hypot(i - 6.5, j - 5.5, k - 4.5);
    return r < 4.2 || scattered[size_t(i + 14 * (j + 12 * k))];
  });
}

// Compares the GPU's partition with the CPU's; returns the number of entries compared.
size_t expectSamePartition(const ClassifiedSplats& c, const Volume& vol, const Camera& cam,
                           const RenderSettings& settings, int size, double thickness,
                           double nearCull, GpuSlabPartition& gpu, const std::string& what) {
  const Projection proj = cam.projection(size, size);
  DepthExtent extent;
  extent.reach =
      kernelReach(proj, settings.filter, settings.cutoff, vol.spacing(), settings.kernelWidth);
  extent.rotation = cam.rotation();
  extent.spacing = vol.spacing();
  extent.kernelWidth = settings.kernelWidth;
  SlabPartition cpu;
  cpu.build(c.splats, c.attributes, vol.origin(), cam.viewMatrix(), thickness, nearCull, extent);
  const size_t n = c.splats.size();
  gl::Buffer splats =
      gl::Buffer::create(GLsizeiptr(n * sizeof(PackedSplat)), c.splats.splats().data());
  gl::Buffer attributes =
      gl::Buffer::create(GLsizeiptr(n * sizeof(PackedAttributes)), c.attributes.data());
  gpu.build(splats, attributes, n, true, vol.origin(), cam.viewMatrix(), thickness, nearCull,
            extent);
  gpu.readCounts();
  EXPECT_EQ(gpu.splatCount(), cpu.splatCount()) << what;
  if (cpu.splatCount() > 0) {
    EXPECT_FLOAT_EQ(float(gpu.nearestCenter()), float(cpu.nearestCenter())) << what;
  }
  const std::vector<uint32_t> order = gpu.readOrder();
  std::vector<Slab> nonEmpty;
  for (const Slab& s : gpu.slabs())
    if (s.count > 0) nonEmpty.push_back(s);
  EXPECT_EQ(nonEmpty.size(), cpu.slabs().size()) << what;
  EXPECT_EQ(order.size(), cpu.order().size()) << what;
  size_t compared = 0;
  for (size_t b = 0; b < std::min(nonEmpty.size(), cpu.slabs().size()); ++b) {
    const Slab &g = nonEmpty[b], &r = cpu.slabs()[b];
    EXPECT_DOUBLE_EQ(g.nearDepth, r.nearDepth) << what << " slab " << b;
    EXPECT_DOUBLE_EQ(g.farDepth, r.farDepth) << what << " slab " << b;
    EXPECT_EQ(g.count, r.count) << what << " slab " << b;
    if (g.count != r.count || size_t(g.first) + g.count > order.size()) break;
    std::vector<uint32_t> a(order.begin() + g.first, order.begin() + g.first + g.count);
    std::vector<uint32_t> e(cpu.order().begin() + r.first, cpu.order().begin() + r.first + r.count);
    std::sort(a.begin(), a.end());
    std::sort(e.begin(), e.end());
    EXPECT_EQ(a, e) << what << " slab " << b;
    compared += a.size();
  }
  return compared;
}

TEST_F(GpuSlabPartitionTest, SlabListsEqualTheCpuPartitionAsSets) {
  const gl::ShaderLibrary shaders;
  GpuSlabPartition gpu(shaders);
  size_t entries = 0, cases = 0;
  for (glm::dvec3 spacing : {glm::dvec3(1.0), glm::dvec3(0.7, 1.0, 1.6)}) {
    const Volume vol = testVolume(spacing);
    const glm::dvec3 centre = 0.5 * (vol.boundsMin() + vol.boundsMax());
    for (SurfaceCriterion surface : {SurfaceCriterion::None, SurfaceCriterion::Value}) {
      Classification cl;
      cl.surface = surface;
      cl.threshold = 0.5;
      const ClassifiedSplats c = classifySplats(vol, whiteTf(0.3, 1.0), cl);
      ASSERT_GT(c.splats.size(), 100u);
      if (surface != SurfaceCriterion::None) {
        ASSERT_GT(c.surfaceCount, 10u);
      }
      for (bool ortho : {false, true})
        for (FilterMode filter : {FilterMode::Ewa, FilterMode::Swan})
          for (double angle : {0.0, 37.0, 133.0, 250.0}) {
            Camera cam;
            cam.orthographic = ortho;
            cam.focalPoint = centre;
            // Perspective from close (the near part culled) and from afar.
            const double distance = angle == 133.0 ? 6.0 : 45.0;
            cam.position = centre + glm::dvec3(0.0, 0.3, 1.0) * distance;
            cam.orbit(angle, angle / 5.0);
            RenderSettings settings;
            settings.filter = filter;
            settings.kernelWidth = angle == 250.0 ? 0.55 : 1.0;  // narrower kernels too
            for (double thickness : {0.25, 0.7, 2.0, 5.0, 1e30})
              for (double nearCull : {0.7, 30.0}) {
                const std::string what =
                    std::string(ortho ? "ortho" : "persp") + " " + filterModeName(filter) +
                    " angle " + std::to_string(angle) + " thickness " + std::to_string(thickness) +
                    " cull " + std::to_string(nearCull) +
                    (surface != SurfaceCriterion::None ? " surfaces" : "");
                entries +=
                    expectSamePartition(c, vol, cam, settings, 64, thickness, nearCull, gpu, what);
                ++cases;
                if (HasFailure()) return;  // one failing case is enough to read
              }
          }
    }
  }
  EXPECT_EQ(cases, 2u * 2u * 2u * 2u * 4u * 5u * 2u);
  EXPECT_GT(entries, 100000u);
}

// Its memory: the order list at its exact length and a few words a slab; nothing a splat
// beyond the list's entries (no per-splat extents kept between the passes).
TEST_F(GpuSlabPartitionTest, HoldsTheOrderListAndAFewWordsASlab) {
  const gl::ShaderLibrary shaders;
  GpuSlabPartition gpu(shaders);
  const Volume vol = testVolume(glm::dvec3(1.0));
  const ClassifiedSplats c = classifySplats(vol, whiteTf(0.3, 1.0), Classification{});
  Camera cam;
  cam.focalPoint = 0.5 * (vol.boundsMin() + vol.boundsMax());
  cam.position = cam.focalPoint + glm::dvec3(0.0, 0.3, 1.0) * 45.0;
  RenderSettings settings;
  expectSamePartition(c, vol, cam, settings, 64, 0.7, 0.7, gpu, "first build");
  const size_t slabs = gpu.slabs().size(), entries = gpu.readOrder().size();
  ASSERT_GT(slabs, 10u);
  ASSERT_GT(entries, c.splats.size());  // kernels reach into more than one slab
  const auto atLeast16 = [](size_t bytes) { return std::max<size_t>(bytes, 16); };
  // The range (5 words), cursors, first entries, two draw commands a slab, the order list.
  const size_t expected =
      5 * 4 + 2 * atLeast16(4 * slabs) + atLeast16(32 * slabs) + atLeast16(4 * entries);
  EXPECT_EQ(gpu.bytes(), expected) << c.splats.size() << " splats, " << entries << " entries";
}

// The frame's statistics say which partition drew it (--stats' gpu_partition): tests that hold
// two runs' pictures equal to the bit allow the GPU's varying order its rounding.
TEST_F(GpuSlabPartitionTest, StatisticsNameThePartitionThatDrewTheFrame) {
  const Volume vol = testVolume(glm::dvec3(1.0));
  SplatRenderer& r = *renderer();
  r.setVolume(vol);
  r.setTransferFunction(whiteTf(0.3, 1.0));
  Camera cam;
  cam.frame(vol.boundsMin(), vol.boundsMax(), {0.3, 0.2, 1.0}, {0, 1, 0}, 1.0);
  for (PartitionMode mode : {PartitionMode::Gpu, PartitionMode::Cpu, PartitionMode::Gpu}) {
    r.setPartition(mode);
    r.render(cam, paperSettings(), 32, 32);
    EXPECT_GT(r.stats().slabEntries, 0u);
    EXPECT_EQ(r.stats().gpuPartition, mode == PartitionMode::Gpu) << partitionModeName(mode);
  }
}

}  // namespace
}  // namespace ewa::test
