#include "framework/core/log.h"

#include <iostream>
#include <mutex>

namespace cooperage::log {
namespace {

const char* prefix(Level level) {
  switch (level) {
    case Level::Debug: return "debug: ";
    case Level::Info: return "";
    case Level::Warning: return "warning: ";
    case Level::Error: return "error: ";
    case Level::Off: return "";
  }
  return "";
}

struct State {
  std::mutex mutex;
  Level threshold = Level::Warning;
  Sink sink = [](Level level, const std::string& line) {
    std::cerr << prefix(level) << line << '\n';
  };
};

State& state() {
  static State s;
  return s;
}

}  // namespace

void set_sink(Sink sink) {
  std::lock_guard<std::mutex> lock(state().mutex);
  state().sink = std::move(sink);
}

void set_threshold(Level level) {
  std::lock_guard<std::mutex> lock(state().mutex);
  state().threshold = level;
}

Level threshold() {
  std::lock_guard<std::mutex> lock(state().mutex);
  return state().threshold;
}

void write(Level level, const std::string& line) {
  std::lock_guard<std::mutex> lock(state().mutex);
  if (level < state().threshold || level == Level::Off || !state().sink) return;
  state().sink(level, line);
}

}  // namespace cooperage::log
