// avError: FFmpeg's text for an error code, shared by the video writer and reader.
#pragma once

#include <string>

extern "C" {
#include <libavutil/error.h>
}

namespace ewa {

inline std::string avError(int code) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {0};
  av_strerror(code, text, sizeof text);
  return text;
}

}  // namespace ewa
