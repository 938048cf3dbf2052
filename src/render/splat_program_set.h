// SplatProgramSet: a splat renderer's GL programs, which the renderers of one context may share.
#pragma once

#include <memory>

#include "gl/program.h"
#include "gl/shader_library.h"
#include "render/slab_pass_programs.h"
#include "render/splat_programs.h"
#include "render/tile_ewa_programs.h"

namespace ewa {

// The window's level-of-detail renderers share one set: a level compiles (and llvmpipe
// translates) no program another level has, so the full level's first refinement steps do not
// stall on them. Programs keep uniforms as their state: the renderer whose frame's uniforms they
// hold is `user`, and a renderer re-sets its own when another drew in between
// (SplatRenderer::stepFrame). One GL context only.
struct SplatProgramSet {
  explicit SplatProgramSet(const gl::ShaderLibrary& shaders);

  gl::ShaderLibrary shaders;  // its own copy: the set may outlive the renderer that made it
  SplatPrograms splat;        // the point and quad programs of a frame's variant
  SlabPassPrograms slab;      // the slab pass of a frame's variants
  gl::Program mark;
  gl::Program final;
  gl::Program box;
  // The compute splatter's (RenderSettings::splatter), made when a renderer first draws in tiles.
  std::shared_ptr<TileEwaPrograms> tiles;
  const void* user = nullptr;
};

}  // namespace ewa
