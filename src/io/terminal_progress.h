// TerminalProgress: "label 3/36" progress lines on stderr, redrawn in place on a terminal.
#pragma once

#include <string>

namespace ewa {

class TerminalProgress {
 public:
  // `enabled` false prints nothing (scripts and tests that read stderr stay clean); by default
  // progress shows only when stderr is a terminal.
  explicit TerminalProgress(std::string label, bool enabled = isTerminal());
  ~TerminalProgress();  // ends the line if one is open
  // "label done/total detail", over the previous one.
  void update(int done, int total, const std::string& detail = "");
  // Ends the line with a closing note ("done in 3.2 s").
  void finish(const std::string& note);

  static bool isTerminal();

 private:
  std::string label_;
  bool enabled_;
  bool open_ = false;
};

}  // namespace ewa
