// PNG chunks walked before stb_image reads a slice: it sizes buffers by what a chunk claims.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace ewa {

// What makes the PNG file in `data` unsafe for stb_image, or "": a chunk (after the 8-byte
// signature) whose length runs past the file's end. stb_image grows its image-data buffer to a
// chunk's claimed length before reading it, so a 358-byte file could ask for a gigabyte (Debian
// 12's libstb: found by fuzzing). The walk stops at IEND; a file cut short between chunks
// passes, for stb_image to refuse.
std::string pngChunksProblem(const uint8_t* data, size_t size);

}  // namespace ewa
