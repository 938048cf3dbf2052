// readVideo through libavformat/libavcodec/libswscale: decode, then YUV -> RGB24.
#include "io/video_reader.h"

#include <memory>
#include <stdexcept>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/log.h>
#include <libswscale/swscale.h>
}

#include "io/av_error.h"

namespace ewa {

namespace {

// Owns the FFmpeg objects of one decode, freed on every path.
struct Decoder {
  AVFormatContext* format = nullptr;
  AVCodecContext* codec = nullptr;
  AVFrame* frame = nullptr;
  AVPacket* packet = nullptr;
  SwsContext* scaler = nullptr;
  ~Decoder() {
    sws_freeContext(scaler);
    av_packet_free(&packet);
    av_frame_free(&frame);
    avcodec_free_context(&codec);
    avformat_close_input(&format);
  }
};

int swsColorspace(AVColorSpace space) {
  switch (space) {
    case AVCOL_SPC_BT709:
      return SWS_CS_ITU709;
    case AVCOL_SPC_BT2020_NCL:
    case AVCOL_SPC_BT2020_CL:
      return SWS_CS_BT2020;
    default:
      return SWS_CS_ITU601;
  }
}

}  // namespace

DecodedVideo readVideo(const std::string& path) {
  const auto fail = [&](const std::string& what) { return std::runtime_error(path + ": " + what); };
  av_log_set_level(AV_LOG_QUIET);  // errors come back as one line with FFmpeg's reason
  Decoder d;
  if (int e = avformat_open_input(&d.format, path.c_str(), nullptr, nullptr); e < 0)
    throw fail("cannot open video: " + avError(e));
  if (int e = avformat_find_stream_info(d.format, nullptr); e < 0)
    throw fail("cannot read stream info: " + avError(e));
  const AVCodec* codec = nullptr;
  const int index = av_find_best_stream(d.format, AVMEDIA_TYPE_VIDEO, -1, -1, &codec, 0);
  if (index < 0 || !codec) throw fail("no video stream with a decoder");
  AVStream* stream = d.format->streams[index];
  d.codec = avcodec_alloc_context3(codec);
  if (!d.codec) throw fail("out of memory");
  avcodec_parameters_to_context(d.codec, stream->codecpar);
  if (int e = avcodec_open2(d.codec, codec, nullptr); e < 0)
    throw fail("cannot open decoder: " + avError(e));
  d.frame = av_frame_alloc();
  d.packet = av_packet_alloc();
  if (!d.frame || !d.packet) throw fail("out of memory");

  DecodedVideo video;
  video.codec = codec->name;
  video.fps = av_q2d(stream->avg_frame_rate);
  const auto drain = [&]() {
    for (;;) {
      const int e = avcodec_receive_frame(d.codec, d.frame);
      if (e == AVERROR(EAGAIN) || e == AVERROR_EOF) return;
      if (e < 0) throw fail("cannot decode: " + avError(e));
      const AVFrame& f = *d.frame;
      d.scaler = sws_getCachedContext(
          d.scaler, f.width, f.height, AVPixelFormat(f.format), f.width, f.height, AV_PIX_FMT_RGB24,
          SWS_BICUBIC | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INT, nullptr, nullptr, nullptr);
      if (!d.scaler) throw fail("cannot convert the frame to RGB");
      const int* coefficients = sws_getCoefficients(swsColorspace(f.colorspace));
      sws_setColorspaceDetails(d.scaler, coefficients, f.color_range == AVCOL_RANGE_JPEG,
                               coefficients, 1, 0, 1 << 16, 1 << 16);
      Image8 img;
      img.width = f.width;
      img.height = f.height;
      img.channels = 3;
      img.pixels.resize(size_t(f.width) * f.height * 3);
      uint8_t* dst[1] = {img.pixels.data()};
      const int stride[1] = {f.width * 3};
      sws_scale(d.scaler, f.data, f.linesize, 0, f.height, dst, stride);
      video.frames.push_back(std::move(img));
      av_frame_unref(d.frame);
    }
  };
  while (av_read_frame(d.format, d.packet) >= 0) {
    if (d.packet->stream_index == index) {
      const int e = avcodec_send_packet(d.codec, d.packet);
      av_packet_unref(d.packet);
      if (e < 0) throw fail("cannot decode: " + avError(e));
      drain();
    } else {
      av_packet_unref(d.packet);
    }
  }
  avcodec_send_packet(d.codec, nullptr);
  drain();
  return video;
}

}  // namespace ewa
