// TerminalProgress: carriage-return progress lines on stderr.
#include "io/terminal_progress.h"

#include <unistd.h>

#include <cstdio>
#include <utility>

namespace ewa {

TerminalProgress::TerminalProgress(std::string label, bool enabled)
    : label_(std::move(label)), enabled_(enabled) {}

TerminalProgress::~TerminalProgress() {
  if (open_) std::fputc('\n', stderr);
}

bool TerminalProgress::isTerminal() {
  return ::isatty(STDERR_FILENO) == 1;
}

void TerminalProgress::update(int done, int total, const std::string& detail) {
  if (!enabled_) return;
  // \033[K clears what a longer previous line left behind.
  std::fprintf(stderr, "\r%s %d/%d %s\033[K", label_.c_str(), done, total, detail.c_str());
  std::fflush(stderr);
  open_ = true;
}

void TerminalProgress::finish(const std::string& note) {
  if (!enabled_) return;
  std::fprintf(stderr, "%s%s %s\033[K\n", open_ ? "\r" : "", label_.c_str(), note.c_str());
  std::fflush(stderr);
  open_ = false;
}

}  // namespace ewa
