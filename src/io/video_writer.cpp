// VideoWriter through libavformat/libavcodec/libswscale: RGB -> YUV 4:2:0 -> H.264 or VP9.
#include "io/video_writer.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <stdexcept>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/log.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include "io/atomic_file.h"
#include "io/av_error.h"

namespace ewa {

namespace {

struct Codec {
  const char* muxer;
  const char* encoder;
};

Codec codecFor(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& ch : ext) ch = char(std::tolower(static_cast<unsigned char>(ch)));
  if (ext == ".mp4") return {"mp4", "libx264"};
  if (ext == ".webm") return {"webm", "libvpx-vp9"};
  throw std::runtime_error(path + ": not a video name (use .mp4 or .webm)");
}

}  // namespace

struct VideoWriter::State {
  std::string path, temp;
  int fps = 30;
  const AVCodec* codec = nullptr;
  AVFormatContext* format = nullptr;
  AVCodecContext* encoder = nullptr;
  AVStream* stream = nullptr;
  AVFrame* frame = nullptr;
  AVPacket* packet = nullptr;
  SwsContext* scaler = nullptr;
  int64_t next = 0;  // pts of the next frame, in 1/fps
  bool finished = false;

  std::runtime_error fail(const std::string& what) const {
    return std::runtime_error(path + ": " + what);
  }

  ~State() {
    sws_freeContext(scaler);
    av_packet_free(&packet);
    av_frame_free(&frame);
    avcodec_free_context(&encoder);
    if (format) {
      if (format->pb) avio_closep(&format->pb);
      avformat_free_context(format);
    }
    if (!finished && !temp.empty()) ::unlink(temp.c_str());
  }

  void openEncoder(int width, int height) {
    encoder = avcodec_alloc_context3(codec);
    if (!encoder) throw fail("cannot allocate the encoder");
    encoder->width = width;
    encoder->height = height;
    encoder->pix_fmt = AV_PIX_FMT_YUV420P;
    encoder->time_base = AVRational{1, fps};
    encoder->framerate = AVRational{fps, 1};
    encoder->gop_size = std::max(1, fps);
    encoder->color_range = AVCOL_RANGE_MPEG;
    encoder->colorspace = AVCOL_SPC_BT709;
    encoder->color_primaries = AVCOL_PRI_BT709;
    encoder->color_trc = AVCOL_TRC_BT709;
    if (format->oformat->flags & AVFMT_GLOBALHEADER) encoder->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    // Near-transparent quality: turntables are short and sharp edges matter more than size.
    if (std::string(codec->name) == "libx264") {
      av_opt_set(encoder->priv_data, "crf", "16", 0);
      av_opt_set(encoder->priv_data, "preset", "medium", 0);
    } else {
      av_opt_set(encoder->priv_data, "crf", "20", 0);
      av_opt_set_int(encoder, "b", 0, 0);  // constant quality
      av_opt_set(encoder->priv_data, "deadline", "good", 0);
      av_opt_set(encoder->priv_data, "cpu-used", "4", 0);
      av_opt_set(encoder->priv_data, "row-mt", "1", 0);
    }
    if (int e = avcodec_open2(encoder, codec, nullptr); e < 0)
      throw fail(std::string("cannot open encoder ") + codec->name + ": " + avError(e));
    stream = avformat_new_stream(format, nullptr);
    if (!stream) throw fail("cannot add a video stream");
    stream->time_base = encoder->time_base;
    stream->avg_frame_rate = encoder->framerate;
    if (int e = avcodec_parameters_from_context(stream->codecpar, encoder); e < 0)
      throw fail("cannot set stream parameters: " + avError(e));
    if (int e = avformat_write_header(format, nullptr); e < 0)
      throw fail("cannot write the header: " + avError(e));
    frame = av_frame_alloc();
    packet = av_packet_alloc();
    if (!frame || !packet) throw fail("out of memory");
    frame->format = encoder->pix_fmt;
    frame->width = width;
    frame->height = height;
    if (int e = av_frame_get_buffer(frame, 0); e < 0)
      throw fail("cannot allocate a frame: " + avError(e));
  }

  // Sends `f` (nullptr: flush) and writes every packet the encoder returns.
  void encode(AVFrame* f) {
    if (int e = avcodec_send_frame(encoder, f); e < 0) throw fail("cannot encode: " + avError(e));
    for (;;) {
      const int e = avcodec_receive_packet(encoder, packet);
      if (e == AVERROR(EAGAIN) || e == AVERROR_EOF) return;
      if (e < 0) throw fail("cannot encode: " + avError(e));
      av_packet_rescale_ts(packet, encoder->time_base, stream->time_base);
      packet->stream_index = stream->index;
      const int w = av_interleaved_write_frame(format, packet);
      av_packet_unref(packet);
      if (w < 0) throw fail("cannot write: " + avError(w));
    }
  }
};

VideoWriter::VideoWriter(const std::string& path, int fps) : state_(std::make_unique<State>()) {
  State& s = *state_;
  s.path = path;
  const Codec c = codecFor(path);
  if (fps < 1 || fps > 1000) throw s.fail("frame rate must be 1 to 1000 frames per second");
  s.fps = fps;
  // FFmpeg logs to stderr (encoder banners, its own error lines); ewaview reports errors itself,
  // in one line with the reason FFmpeg returns.
  av_log_set_level(AV_LOG_QUIET);
  s.codec = avcodec_find_encoder_by_name(c.encoder);
  if (!s.codec)
    throw s.fail(std::string("this FFmpeg has no ") + c.encoder +
                 " encoder (install one that has)");
  namespace fs = std::filesystem;
  const fs::path target(path);
  std::error_code ec;
  if (fs::is_directory(target, ec)) throw s.fail("is a folder");
  if (!target.parent_path().empty()) {
    fs::create_directories(target.parent_path(), ec);
    if (!fs::is_directory(target.parent_path(), ec)) throw s.fail("cannot create its folder");
  }
  if (int e = avformat_alloc_output_context2(&s.format, nullptr, c.muxer, nullptr); e < 0)
    throw s.fail("cannot set up the " + std::string(c.muxer) + " muxer: " + avError(e));
  // A unique temporary name beside the target, renamed into place by finish().
  s.temp = createTemporaryBeside(path);
  if (int e = avio_open(&s.format->pb, s.temp.c_str(), AVIO_FLAG_WRITE); e < 0)
    throw s.fail("cannot write: " + avError(e));
}

VideoWriter::~VideoWriter() = default;

int VideoWriter::width() const {
  return state_->encoder ? state_->encoder->width : 0;
}
int VideoWriter::height() const {
  return state_->encoder ? state_->encoder->height : 0;
}

void VideoWriter::add(const Image8& image) {
  State& s = *state_;
  if (s.finished) throw s.fail("video already finished");
  if (image.width < 1 || image.height < 1 || (image.channels != 3 && image.channels != 4) ||
      image.pixels.size() != size_t(image.width) * image.height * image.channels)
    throw s.fail("frame has inconsistent size");
  if (!s.encoder) {
    const int w = image.width & ~1, h = image.height & ~1;
    if (w < 2 || h < 2) throw s.fail("video needs frames of at least 2x2 pixels");
    s.openEncoder(w, h);
  }
  // The first frame's odd row/column is cropped (source size rounded down); other sizes scale.
  const bool sameSize =
      (image.width & ~1) == s.encoder->width && (image.height & ~1) == s.encoder->height;
  const int srcW = sameSize ? s.encoder->width : image.width;
  const int srcH = sameSize ? s.encoder->height : image.height;
  const AVPixelFormat srcFormat = image.channels == 4 ? AV_PIX_FMT_RGBA : AV_PIX_FMT_RGB24;
  s.scaler = sws_getCachedContext(
      s.scaler, srcW, srcH, srcFormat, s.encoder->width, s.encoder->height, AV_PIX_FMT_YUV420P,
      SWS_BICUBIC | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INP, nullptr, nullptr, nullptr);
  if (!s.scaler) throw s.fail("cannot convert the frame to YUV");
  // Full-range RGB in, limited-range BT.709 out (what the stream's colour tags say).
  const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
  sws_setColorspaceDetails(s.scaler, bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16);
  if (int e = av_frame_make_writable(s.frame); e < 0) throw s.fail("frame: " + avError(e));
  const uint8_t* src[1] = {image.pixels.data()};
  const int stride[1] = {image.width * image.channels};
  sws_scale(s.scaler, src, stride, 0, srcH, s.frame->data, s.frame->linesize);
  s.frame->pts = s.next++;
  s.encode(s.frame);
}

void VideoWriter::finish() {
  State& s = *state_;
  if (s.finished) return;
  if (!s.encoder) throw s.fail("no frames to write");
  s.encode(nullptr);
  if (int e = av_write_trailer(s.format); e < 0) throw s.fail("cannot finish: " + avError(e));
  if (int e = avio_closep(&s.format->pb); e < 0) throw s.fail("cannot write: " + avError(e));
  std::error_code ec;
  std::filesystem::rename(s.temp, s.path, ec);
  if (ec) throw s.fail("cannot write: " + ec.message());
  s.finished = true;
}

}  // namespace ewa
