// --pick: what a pixel of the headless picture shows, printed as one JSON line.
#pragma once

#include <string>

#include "app/scene.h"
#include "core/volume_pick.h"

namespace ewa {

// The pixel options.pick (column, row from the top-left) of the --resolution picture the
// options' camera makes, picked through the volume, transfer function and crop box / clipping
// planes:
// {"pixel":[x,y],"hit":true,"world":[x,y,z],"index":[i,j,k],"voxel":[i,j,k],"value":v,
//  "opacity":a,"distance":d}, or {"pixel":[x,y],"hit":false} when the pixel shows nothing.
std::string pickJson(const Volume& volume, const TransferFunction& tf, const Options& options);

}  // namespace ewa
