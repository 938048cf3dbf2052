// SplatRenderer's early termination: an occlusion query on the volume's box (narrowed to the
// crop box and planes, its pixels to the rays that cross what they keep) over the marked
// (opaque) pixels, read at once or lagged under conditional rendering.
#include <algorithm>
#include <cmath>

#include "core/clip_share.h"
#include "core/kernel_reach.h"
#include "render/clip_uniforms.h"
#include "render/splat_renderer.h"

namespace ewa {

namespace {

// World to clip space for the pixel mapping of `proj`: x_pixel = principal + f u.xy / depth
// (or ppu u.xy), and clip z inside [-w, w] for depths beyond `nearClip`.
glm::mat4 clipMatrix(const Projection& proj, const glm::dmat4& view, double nearClip) {
  glm::dmat4 p(0.0);
  const double w = proj.width, h = proj.height;
  const double ox = 2.0 * proj.principal.x / w - 1.0, oy = 2.0 * proj.principal.y / h - 1.0;
  if (proj.orthographic) {
    p[0][0] = 2.0 * proj.pixelsPerUnit / w;
    p[1][1] = 2.0 * proj.pixelsPerUnit / h;
    p[3][0] = ox;
    p[3][1] = oy;
    p[3][3] = 1.0;
  } else {
    p[0][0] = 2.0 * proj.focalPixels / w;
    p[1][1] = 2.0 * proj.focalPixels / h;
    p[2][0] = -ox;
    p[2][1] = -oy;
    p[2][2] = -1.0;
    p[3][2] = -2.0 * nearClip;
    p[2][3] = -1.0;
  }
  return glm::mat4(p * view);
}

}  // namespace

bool SplatRenderer::issueOpaqueQuery(unsigned query, double nextDepth) {
  const Camera& camera = frame_.camera;
  const Projection& proj = frame_.proj;
  const glm::dvec3& sp = volume_->spacing();
  const double maxSpacing = std::max({sp.x, sp.y, sp.z});
  const KernelReach& reach = frame_.reach;
  const glm::dmat4 view = camera.viewMatrix();
  const DepthRange box = boxDepthRange(view, volume_->boundsMin(), volume_->boundsMax());
  // A box reaching the eye plane would be clipped: not a safe bound for the test.
  if (!proj.orthographic &&
      box.nearest < 2.0 * std::max(maxSpacing, reach.maxSigma) * std::sqrt(reach.cutoff))
    return false;
  const double farDepth = std::max(0.0, box.farthest);
  // Grow the box by what a kernel reaches beyond its centre at the farthest corner (reach
  // grows with depth), plus a pixel for rasterization; then narrow it to the crop box, where the
  // clip cuts every pixel's ray: pixels whose rays miss it get nothing and never turn opaque.
  // The box bounds what oblique planes keep; its fragments whose rays miss that are left out
  // too (bounds_box.frag.glsl): the planes cut every ray's share where the splat shaders cut
  // it, at the picture's pixels, so they are not grown; but a coarser slab image's texels are
  // read back bilinearly, so a pixel takes the sums of texels up to one texel (s pixels) away,
  // whose rays a plane may keep when its own is cut: there the planes move out that far. So
  // are those whose rays leave it before the slabs still to come (a kernel's share lies within
  // its reach of its slab), as a ray grazing a plane or the box's edge does: it takes little
  // opacity and then nothing more.
  const double grow = worldReach(reach, farDepth) + worldPerPixel(reach, farDepth);
  const double coarsest = frame_.slabScales.empty() ? 1.0
                                                    : *std::max_element(frame_.slabScales.begin(),
                                                                        frame_.slabScales.end());
  const double outward = coarsest > 1.0 ? (coarsest + 1.0) * worldPerPixel(reach, farDepth) : 0.0;
  const DataBox kept = keptBoxInVolumeFrame(frame_.settings.clip, *volume_, grow, outward);
  boxProgram_.setMat4("uClip", clipMatrix(proj, view, 0.5 * maxSpacing));
  boxProgram_.setVec3("uBoxMin", glm::vec3(kept.low));
  boxProgram_.setVec3("uBoxMax", glm::vec3(kept.high));
  const glm::dvec3 origin = volume_->origin(), spacing = volume_->spacing();
  setClipUniforms(boxProgram_, frame_.settings.clip, *volume_, camera, proj, outward);
  setDataBoxUniforms(boxProgram_, *volume_, camera, proj,
                     DataBox{(kept.low - origin) / spacing, (kept.high - origin) / spacing});
  boxProgram_.setFloat("uFromDepth", float(nextDepth - grow));
  glBindFramebuffer(GL_FRAMEBUFFER, targets_.slabFbo.id());
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  // One face of each pair the box's pixels see (its triangles turn alike, so culling either
  // side leaves the box's outline covered once): half the fragments.
  glEnable(GL_CULL_FACE);
  glCullFace(GL_FRONT);
  glBeginQuery(GL_SAMPLES_PASSED, query);
  glUseProgram(boxProgram_.id());
  glDrawArrays(GL_TRIANGLES, 0, 36);
  glEndQuery(GL_SAMPLES_PASSED);
  glDisable(GL_CULL_FACE);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  return true;
}

bool SplatRenderer::terminationCheck(double nextDepth) {
  const int current = frame_.nextQuery, previous = current ^ 1;
  endConditionalSlabs();  // the check's own query counts unconditionally
  const bool issued = issueOpaqueQuery(queries_[current], nextDepth);
  if (!laggedTermination_) {
    GLuint samples = 1;
    if (issued) glGetQueryObjectuiv(queries_[current], GL_QUERY_RESULT, &samples);
    return samples == 0;
  }
  bool done = false;
  if (frame_.queryIssued[previous]) {
    GLuint available = 0, samples = 1;
    glGetQueryObjectuiv(queries_[previous], GL_QUERY_RESULT_AVAILABLE, &available);
    if (available) {
      glGetQueryObjectuiv(queries_[previous], GL_QUERY_RESULT, &samples);
      frame_.queryIssued[previous] = false;
      done = samples == 0;
    }
  }
  if (frame_.queryIssued[previous] && !done) {
    // The CPU has no answer yet: until the next check the GPU draws only if the last check
    // counted an unmarked pixel. The GPU waits for that answer, a check's slabs back and so
    // all but certainly there, and never the CPU; the stencil rejects what would be hidden
    // anyway, so the picture is the same as without.
    glBeginConditionalRender(queries_[previous], GL_QUERY_WAIT);
    frame_.conditional = true;
  }
  frame_.queryIssued[current] = issued;
  frame_.nextQuery = previous;
  glFlush();  // so that the query's answer comes while the next slabs are drawn
  return done;
}

void SplatRenderer::endConditionalSlabs() {
  if (!frame_.conditional) return;
  glEndConditionalRender();
  frame_.conditional = false;
}

bool SplatRenderer::terminates() const {
  const RenderSettings& settings = frame_.settings;
  return settings.order == CompositeOrder::FrontToBack && settings.terminationOpacity < 1.0;
}

}  // namespace ewa
