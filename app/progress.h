// Progress display for long steps: a bar redrawn in place on a terminal,
// plain lines otherwise (logs, CI).
#pragma once

#include <chrono>
#include <cstddef>
#include <string>

namespace cooperage::app {

class Progress {
 public:
  /// `enabled` false prints nothing (--quiet).
  explicit Progress(bool enabled);
  ~Progress();
  void update(const std::string& stage, std::size_t done, std::size_t total);
  /// Ends the current bar line, if any.
  void finish();

 private:
  bool enabled_;
  bool terminal_;
  std::string stage_;
  bool bar_open_ = false;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace cooperage::app
