// StatusMessages: short notices and errors shown in the window for a while (no UI code).
#pragma once

#include <string>
#include <vector>

namespace ewa {

class StatusMessages {
 public:
  enum class Kind { Info, Progress, Error };
  struct Message {
    Kind kind;
    std::string text;
    double expires;  // seconds on the caller's clock
  };
  static constexpr double kInfoSeconds = 6.0;
  static constexpr double kErrorSeconds = 20.0;

  // Adds a message shown until `now` + its kind's duration (errors stay longer).
  void post(Kind kind, std::string text, double now);
  // Drops expired messages; returns those left, oldest first.
  const std::vector<Message>& current(double now);
  void clear() { messages_.clear(); }

 private:
  static constexpr size_t kMaxMessages = 6;
  std::vector<Message> messages_;
};

}  // namespace ewa
