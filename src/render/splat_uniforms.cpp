// SplatRenderer's uniforms: the footprint, projection and lighting of the splat programs, the
// slab passes' classification, each slab's depth range, the scale of coarser slab images.
#include <algorithm>
#include <cmath>

#include "render/clip_uniforms.h"
#include "render/splat_renderer.h"

namespace ewa {

void SplatRenderer::setCommonUniforms(gl::Program& p, const Camera& camera, const Projection& proj,
                                      const RenderSettings& settings) {
  const glm::dvec3& sp = volume_->spacing();
  const FootprintParams params = footprintParams(settings, sp);
  const Lighting& light = settings.lighting;
  p.setMat4("uView", glm::mat4(camera.viewMatrix()));
  const glm::dvec3 sigma = kernelSigma(sp, settings.kernelWidth);
  p.setMat3("uCovariance", glm::mat3(cameraCovariance(camera.rotation(), sigma)));
  p.setVec3("uKernelSigma", glm::vec3(sigma));
  p.setVec3("uOrigin", glm::vec3(volume_->origin()));
  p.setVec3("uSpacing", glm::vec3(sp));
  p.setFloat("uVoxelVolume", float(sp.x * sp.y * sp.z));
  p.setFloat("uMaxSigma", float(std::max({sigma.x, sigma.y, sigma.z})));
  p.setInt("uOrthographic", proj.orthographic ? 1 : 0);
  setProjectionUniforms(p, proj, params.lowPass);
  p.setInt("uFilter", int(params.filter));
  p.setFloat("uCutoff", float(params.cutoff));
  p.setFloat("uDepthCutoff", float(frame_.reach.depthCutoff));  // the partition's reach
  const DepthProfile profile = depthProfile(settings);
  p.setVec2("uDepthProfile", glm::vec2(profile.erfReach, profile.scale));
  p.setFloat("uMinSpacing", float(params.minSpacing));
  p.setFloat("uSwanSpacing", float(params.swanSpacing));
  p.setFloat("uCullDepth", float(params.cullDepth));
  p.setFloat("uPointSizeLimit", pointSizeLimit_);
  p.setInt("uTransfer", 0);
  p.setFloat("uSurfaceTau",
             float(-std::log(1.0 - std::clamp(settings.surfaceOpacity, 0.0, 0.999999))));
  p.setInt("uShading", light.enabled ? 1 : 0);
  p.setFloat("uAmbient", float(light.ambient));
  p.setFloat("uDiffuse", float(light.diffuse));
  p.setFloat("uSpecular", float(light.specular));
  p.setFloat("uShininess", float(std::max(light.shininess, 1e-3)));
  setClipUniforms(p, settings.clip, *volume_, camera, proj);  // planes; rays again per scale
  p.setInt("uAttributes", attributesUploaded_ ? 1 : 0);
  p.setInt("uSplatTexels", int(kSplatTexelUnit));
  p.setInt("uAttributeTexels", int(kAttributeTexelUnit));
  occlusion_.setUniforms(p, kOpaqueUnit, false);  // until the frame's first pyramid
}

void SplatRenderer::setProjectionUniforms(gl::Program& p, const Projection& proj,
                                          double lowPass) const {
  p.setFloat("uFocalPixels", float(proj.focalPixels));
  p.setFloat("uPixelsPerUnit", float(proj.pixelsPerUnit));
  p.setVec2("uViewport", glm::vec2(proj.width, proj.height));
  p.setVec2("uPrincipal", glm::vec2(proj.principal));
  // The GL viewport the splats are drawn with (drawSplats): the image and a guard band.
  const float guard = float(guardBand(proj));
  p.setVec4("uViewportRect", glm::vec4(-guard, -guard, float(proj.width) + 2.0f * guard,
                                       float(proj.height) + 2.0f * guard));
  p.setFloat("uLowPass", float(lowPass));
}

void SplatRenderer::setSplatScale(double scale) {
  if (scale == frame_.splatScale) return;
  frame_.splatScale = scale;
  const Projection proj = scaledProjection(frame_.proj, scale);
  // The footprints are the picture's, low-pass filter included, sampled on coarser texels and
  // narrowed by the blur of the bilinear read-back (kBilinearReadVariance).
  const double lowPass = lowPassVariance(frame_.settings) / (scale * scale) -
                         (scale > 1.0 ? kBilinearReadVariance : 0.0);
  for (gl::Program* p : splatPrograms_.both()) {
    setProjectionUniforms(*p, proj, lowPass);
    // The clip rays of the coarser image's pixels.
    setClipUniforms(*p, frame_.settings.clip, *volume_, frame_.camera, proj);
    // The opacity pyramid is the picture's pixels: coarser images are not culled.
    occlusion_.setUniforms(*p, kOpaqueUnit, frame_.pyramidBuilt && scale == 1);
  }
}

void SplatRenderer::setSlabPassUniforms(const Projection& proj, const RenderSettings& settings) {
  const bool coarser = std::any_of(frame_.slabScales.begin(), frame_.slabScales.end(),
                                   [](double scale) { return scale > 1.0; });
  slabPass_[1] = nullptr;
  for (int scaled = coarser ? 1 : 0; scaled >= 0; --scaled) {
    gl::Program& p = slabPrograms_.select(slabPassVariant(settings, scaled == 1));
    slabPass_[scaled] = &p;
    p.setInt("uTransfer", 0);
    p.setInt("uSlabNormal", 3);
    p.setVec2("uViewport", glm::vec2(proj.width, proj.height));
    setClassifyUniforms(p, proj, settings);
    p.setInt("uNeighbourSlab", int(kNeighbourSlabUnit));
    p.setInt("uSlabBack", int(kSlabBackUnit));
    p.setInt("uNeighbourBack", int(kNeighbourBackUnit));
    p.setInt("uSlab", 1);
    p.setFloat("uSlabScale", 1.0f);
    p.setFloat("uNeighbourScale", 1.0f);
  }
}

void SplatRenderer::setClassifyUniforms(gl::Program& p, const Projection& proj,
                                        const RenderSettings& settings) {
  const Lighting& light = settings.lighting;
  p.setInt("uOrthographic", proj.orthographic ? 1 : 0);
  p.setFloat("uFocalPixels", float(proj.focalPixels));
  p.setInt("uShading", light.enabled ? 1 : 0);
  p.setFloat("uAmbient", float(light.ambient));
  p.setFloat("uDiffuse", float(light.diffuse));
  p.setFloat("uSpecular", float(light.specular));
  p.setFloat("uShininess", float(std::max(light.shininess, 1e-3)));
  p.setFloat("uPixelsPerUnit", float(proj.pixelsPerUnit));
  // Post-classified: the covered lengths end at the data's box.
  setDataBoxUniforms(p, *volume_, frame_.camera, proj);
  // Samplers of different types must not share a unit, used or not.
  p.setInt("uPairTable", int(kPairTableUnit));
  p.setInt("uPairPrefix", int(kPairPrefixUnit));
  p.setInt("uGradient", int(kGradientUnit));
}

void SplatRenderer::setSlabUniforms(const Slab& slab, bool split, bool openTails, int slabIndex) {
  for (gl::Program* p : splatPrograms_.both()) {
    p->setInt("uSlabIndex", slabIndex);
    p->setInt("uSplitDepth", split ? 1 : 0);
    p->setInt("uOpenTails", openTails ? 1 : 0);
    p->setFloat("uSlabNear", float(slab.nearDepth));
    p->setFloat("uSlabFar", float(slab.farDepth));
  }
}

int SplatRenderer::guardBand(const Projection& image) const {
  const int room = (maxViewport_ - std::max(image.width, image.height)) / 2;
  return std::clamp(int(std::ceil(0.5 * pointSizeLimit_)) + 2, 0, std::max(room, 0));
}

}  // namespace ewa
