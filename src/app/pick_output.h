// --pick: what a pixel of the headless picture shows, printed as one JSON line.
#pragma once

#include <string>

#include "app/scene.h"
#include "core/volume_pick.h"

namespace ewa {

// The pick rule the render mode asks for: MIP picks the brightest point, the others the median
// depth of what the pixel shows.
PickRule pickRuleFor(RenderMode mode);

// The pixel (column, row from the top-left) of the --resolution picture the options' camera
// makes, picked through the scene's volume, transfer function and crop box / clipping planes:
// {"pixel":[x,y],"hit":true,"world":[x,y,z],"index":[i,j,k],"voxel":[i,j,k],"value":v,
//  "opacity":a,"distance":d}, or {"pixel":[x,y],"hit":false} when the pixel shows nothing.
std::string pickJson(const Scene& scene, const Options& options);

}  // namespace ewa
