#include "progress.h"

#include <cstdio>
#include <unistd.h>

namespace cooperage::app {

Progress::Progress(bool enabled)
    : enabled_(enabled),
      terminal_(::isatty(STDERR_FILENO) != 0),
      start_(std::chrono::steady_clock::now()) {}

Progress::~Progress() { finish(); }

void Progress::update(const std::string& stage, std::size_t done, std::size_t total) {
  if (!enabled_) return;
  const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  if (terminal_) {
    const int width = 30;
    const int filled = total ? static_cast<int>(width * done / total) : width;
    std::fprintf(stderr, "\r%-14s [%-*.*s] %zu/%zu %6.2fs", stage.c_str(), width, filled,
                 "##############################", done, total, t);
    bar_open_ = true;
    if (done == total) {
      std::fputc('\n', stderr);
      bar_open_ = false;
    }
    std::fflush(stderr);
  } else if (stage != stage_) {
    std::fprintf(stderr, "cooperage: %s (%zu items) at %.2fs\n", stage.c_str(), total, t);
  }
  stage_ = stage;
}

void Progress::finish() {
  if (bar_open_) std::fputc('\n', stderr);
  bar_open_ = false;
}

}  // namespace cooperage::app
