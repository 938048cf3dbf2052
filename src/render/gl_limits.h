// Limits of the current GL context that callers outside the GL layers need to check sizes, and
// whether it is a software rasterizer.
#pragma once

namespace ewa {

// The largest width and height a render target may have in the current context: the smallest
// of GL_MAX_TEXTURE_SIZE, GL_MAX_VIEWPORT_DIMS and GL_MAX_FRAMEBUFFER_WIDTH/HEIGHT.
int maxRenderTargetSize();

// GL_RENDERER names a software rasterizer (llvmpipe, softpipe): what the auto modes go by.
bool softwareRasterizer();

}  // namespace ewa
