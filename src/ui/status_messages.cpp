// StatusMessages: a bounded list of timed messages.
#include "ui/status_messages.h"

#include <algorithm>
#include <utility>

namespace ewa {

void StatusMessages::post(Kind kind, std::string text, double now) {
  const double seconds = kind == Kind::Error ? kErrorSeconds : kInfoSeconds;
  messages_.push_back({kind, std::move(text), now + seconds});
  if (messages_.size() > kMaxMessages) messages_.erase(messages_.begin());
}

const std::vector<StatusMessages::Message>& StatusMessages::current(double now) {
  messages_.erase(std::remove_if(messages_.begin(), messages_.end(),
                                 [now](const Message& m) { return m.expires <= now; }),
                  messages_.end());
  return messages_;
}

}  // namespace ewa
