// The distributed window's frame description: every field survives its bytes, and cut or
// foreign bytes are refused.
#include "app/frame_description.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace ewa {
namespace {

// Every field away from its default, so a field the serializer drops shows as a default.
FrameDescription unusualFrame() {
  FrameDescription f;
  f.quit = true;
  f.exitStatus = 3;
  f.width = 641;
  f.height = 357;
  f.camera.position = {1.5, -2.25, 9.0};
  f.camera.focalPoint = {0.125, 0.5, -3.0};
  f.camera.viewUp = {0.0, 0.0, 1.0};
  f.camera.viewAngleDeg = 41.5;
  f.camera.orthographic = true;
  RenderSettings& s = f.settings;
  s.renderer = RendererKind::ShearWarp;
  s.filter = FilterMode::Swan;
  s.mode = RenderMode::Mip;
  s.cutoff = 3.5;
  s.kernelWidth = 1.25;
  s.lowPass = 0.5;
  s.depthCutoff = 2.5;
  s.slabThickness = 0.75;
  s.background = {0.1, 0.2, 0.3};
  s.order = CompositeOrder::BackToFront;
  s.terminationOpacity = 0.9;
  s.occlusionCulling = OcclusionCulling::Off;
  s.xrayMap = XRayMap::Sum;
  s.xrayScale = 0.05;
  s.lighting = {true, 0.2, 0.6, 0.4, 12.0};
  s.classification.gradient = GradientMode::Smooth;
  s.classification.surface = SurfaceCriterion::Opacity;
  s.classification.threshold = 0.25;
  s.classification.minGradient = 0.125;
  s.classification.mode = ClassificationMode::Post;
  s.classification.postMarginSquared = 9;
  s.classification.prefilter = 0.2;
  s.slabPreintegration = false;
  s.slabSamples = 2;
  s.slabPasses = 2;
  s.slabPrecision = SlabPrecision::Float;
  s.postNormals = PostNormals::Voxel;
  s.splatter = Splatter::Cpu;
  s.coarseSlabs = false;
  s.surfaceOpacity = 0.5;
  s.shearWarp = {true, TableLookup::Bilinear, false, BufferSlices::Image, false, 0.8, 3, 64, 1.5};
  s.clip.cropEnabled = true;
  s.clip.cropMin = {-1.0, 2.0, 3.0};
  s.clip.cropMax = {10.0, 20.0, 30.0};
  s.clip.planes = {{{1.0, 2.0, 3.0}, {0.0, 1.0, 0.0}, true},
                   {{4.0, 5.0, 6.0}, {1.0, 0.0, 0.0}, false}};
  f.tf.opacityUnitDistance = 2.5;
  f.tf.opacity = {{0.0, 0.0}, {0.4, 0.7}, {1.0, 0.2}};
  f.tf.color = {{0.0, {1.0, 0.0, 0.0}}, {0.9, {0.25, 0.5, 0.75}}};
  return f;
}

TEST(FrameDescription, EveryFieldSurvivesItsBytes) {
  const FrameDescription f = unusualFrame();
  const std::vector<uint8_t> bytes = serializeFrame(f);
  const FrameDescription g = deserializeFrame(bytes.data(), bytes.size());
  EXPECT_EQ(g.quit, f.quit);
  EXPECT_EQ(g.exitStatus, f.exitStatus);
  EXPECT_EQ(g.width, f.width);
  EXPECT_EQ(g.height, f.height);
  EXPECT_EQ(g.camera.position, f.camera.position);
  EXPECT_EQ(g.camera.focalPoint, f.camera.focalPoint);
  EXPECT_EQ(g.camera.viewUp, f.camera.viewUp);
  EXPECT_EQ(g.camera.viewAngleDeg, f.camera.viewAngleDeg);
  EXPECT_EQ(g.camera.orthographic, f.camera.orthographic);
  const RenderSettings &a = g.settings, &b = f.settings;
  EXPECT_EQ(a.renderer, b.renderer);
  EXPECT_EQ(a.filter, b.filter);
  EXPECT_EQ(a.mode, b.mode);
  EXPECT_EQ(a.cutoff, b.cutoff);
  EXPECT_EQ(a.kernelWidth, b.kernelWidth);
  EXPECT_EQ(a.lowPass, b.lowPass);
  EXPECT_EQ(a.depthCutoff, b.depthCutoff);
  EXPECT_EQ(a.slabThickness, b.slabThickness);
  EXPECT_EQ(a.background, b.background);
  EXPECT_EQ(a.order, b.order);
  EXPECT_EQ(a.terminationOpacity, b.terminationOpacity);
  EXPECT_EQ(a.occlusionCulling, b.occlusionCulling);
  EXPECT_EQ(a.xrayMap, b.xrayMap);
  EXPECT_EQ(a.xrayScale, b.xrayScale);
  EXPECT_TRUE(a.lighting == b.lighting);
  // Classification's == skips the post-only fields when pre-classified: this one is post.
  EXPECT_TRUE(a.classification == b.classification);
  EXPECT_EQ(a.slabPreintegration, b.slabPreintegration);
  EXPECT_EQ(a.slabSamples, b.slabSamples);
  EXPECT_EQ(a.slabPasses, b.slabPasses);
  EXPECT_EQ(a.slabPrecision, b.slabPrecision);
  EXPECT_EQ(a.postNormals, b.postNormals);
  EXPECT_EQ(a.splatter, b.splatter);
  EXPECT_EQ(a.coarseSlabs, b.coarseSlabs);
  EXPECT_EQ(a.surfaceOpacity, b.surfaceOpacity);
  EXPECT_EQ(a.shearWarp.preintegrated, b.shearWarp.preintegrated);
  EXPECT_EQ(a.shearWarp.lookup, b.shearWarp.lookup);
  EXPECT_EQ(a.shearWarp.opacityCorrection, b.shearWarp.opacityCorrection);
  EXPECT_EQ(a.shearWarp.buffers, b.shearWarp.buffers);
  EXPECT_EQ(a.shearWarp.runLengthEncoding, b.shearWarp.runLengthEncoding);
  EXPECT_EQ(a.shearWarp.terminationAlpha, b.shearWarp.terminationAlpha);
  EXPECT_EQ(a.shearWarp.threads, b.shearWarp.threads);
  EXPECT_EQ(a.shearWarp.tableSize, b.shearWarp.tableSize);
  EXPECT_EQ(a.shearWarp.intermediateScale, b.shearWarp.intermediateScale);
  EXPECT_TRUE(a.clip == b.clip);
  ASSERT_EQ(a.clip.planes.size(), 2u);
  EXPECT_FALSE(a.clip.planes[1].enabled);
  EXPECT_TRUE(g.tf == f.tf);
  EXPECT_EQ(g.tf.opacityUnitDistance, f.tf.opacityUnitDistance);
  // And once more: the bytes of the copy are the bytes of the original.
  EXPECT_EQ(serializeFrame(g), bytes);
}

TEST(FrameDescription, CutOrForeignBytesAreRefused) {
  const std::vector<uint8_t> bytes = serializeFrame(unusualFrame());
  for (size_t cut : {size_t(0), size_t(3), size_t(40), bytes.size() - 1})
    EXPECT_THROW(deserializeFrame(bytes.data(), cut), std::runtime_error) << cut;
  std::vector<uint8_t> longer = bytes;
  longer.push_back(0);
  EXPECT_THROW(deserializeFrame(longer.data(), longer.size()), std::runtime_error);
  std::vector<uint8_t> other = bytes;
  other[4] ^= 0xff;  // the version
  EXPECT_THROW(deserializeFrame(other.data(), other.size()), std::runtime_error);
  // A default frame (no planes, an empty transfer function) round-trips too.
  const std::vector<uint8_t> plain = serializeFrame(FrameDescription{});
  EXPECT_EQ(serializeFrame(deserializeFrame(plain.data(), plain.size())), plain);
}

}  // namespace
}  // namespace ewa
