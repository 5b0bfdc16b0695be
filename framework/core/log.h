// A minimal levelled logger. Algorithms log through it; the application
// decides where lines go (STYLE rule 4: no std::cout inside algorithms).
#pragma once

#include <functional>
#include <string>

namespace cooperage::log {

enum class Level { Debug = 0, Info = 1, Warning = 2, Error = 3, Off = 4 };

/// Receives every line at or above the threshold. Default: stderr, Warning.
using Sink = std::function<void(Level, const std::string&)>;

void set_sink(Sink sink);
void set_threshold(Level level);
Level threshold();

void write(Level level, const std::string& line);
inline void debug(const std::string& line) { write(Level::Debug, line); }
inline void info(const std::string& line) { write(Level::Info, line); }
inline void warning(const std::string& line) { write(Level::Warning, line); }
inline void error(const std::string& line) { write(Level::Error, line); }

}  // namespace cooperage::log
