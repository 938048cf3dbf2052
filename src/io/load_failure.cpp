// One-line LoadError messages: sanitizing and quoting text taken from untrusted files.
#include "io/load_failure.h"

namespace ewa {

std::string oneLine(std::string_view text) {
  std::string out(text);
  for (char& c : out) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20 || u == 0x7f) c = ' ';
  }
  return out;
}

std::string quoteText(std::string_view text, size_t maxChars) {
  if (text.size() > maxChars) return "'" + oneLine(text.substr(0, maxChars)) + "...'";
  return "'" + oneLine(text) + "'";
}

void failLoad(const std::string& path, const std::string& problem) {
  throw LoadError(oneLine(path + ": " + problem));
}

void checkChannel(const std::string& path, int64_t channel, int64_t channels) {
  if (channel >= 0 && channel < channels) return;
  failLoad(path, "--channel " + std::to_string(channel) + " is out of range (" +
                     std::to_string(channels) + " channel" + (channels == 1 ? "" : "s") + ")");
}

void checkFrame(const std::string& path, int64_t frame, int64_t frames, const std::string& holder,
                const std::string& noun, const std::string& after) {
  if (frame >= 0 && frame < frames) return;
  failLoad(path, "--frame " + std::to_string(frame) + " is out of range (" + holder + " " +
                     std::to_string(frames) + " " + noun + (frames == 1 ? "" : "s") + after + ")");
}

}  // namespace ewa
