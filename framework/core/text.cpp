#include "framework/core/text.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>

namespace cooperage {
namespace {

/// Length of the UTF-8 sequence starting with byte c (1 for a stray byte).
std::size_t sequence_length(unsigned char c) {
  if (c >= 0xF0 && c < 0xF8) return 4;
  if (c >= 0xE0) return c < 0xF0 ? 3 : 1;
  if (c >= 0xC0) return 2;
  return 1;
}

}  // namespace

std::string clip(std::string_view text, std::size_t limit) {
  if (limit == 0) limit = 1;
  std::string out;
  out.reserve(std::min(text.size(), 4 * limit));
  std::size_t chars = 0;
  for (std::size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    std::size_t n = sequence_length(c);
    bool whole = i + n <= text.size();
    for (std::size_t k = 1; whole && k < n; ++k)
      whole = (static_cast<unsigned char>(text[i + k]) & 0xC0) == 0x80;
    if (!whole) n = 1;
    if (chars + 1 == limit && i + n < text.size()) {
      out += "\xE2\x80\xA6";  // U+2026 HORIZONTAL ELLIPSIS
      return out;
    }
    if (n == 1) {
      out += (c < 0x20 || c == 0x7F || c >= 0x80) ? '?' : static_cast<char>(c);
    } else {
      out.append(text.substr(i, n));
    }
    ++chars;
    i += n;
  }
  return out;
}

std::string clip_path(std::string_view path, std::size_t limit) {
  if (limit == 0) limit = 1;
  // Count characters from the end, keeping UTF-8 sequences whole.
  std::size_t chars = 0;
  std::size_t begin = path.size();
  while (begin > 0) {
    std::size_t b = begin - 1;
    while (b > 0 && (static_cast<unsigned char>(path[b]) & 0xC0) == 0x80 && begin - b < 4) --b;
    if (chars + 1 >= limit && b > 0) {
      return "\xE2\x80\xA6" + clip(path.substr(begin), limit);
    }
    ++chars;
    begin = b;
  }
  return clip(path, limit);
}

std::string point_text(double x, double y, double z) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.4g, %.4g, %.4g)", x, y, z);
  return buf;
}

std::string number_text(double value) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", value);
  return buf;
}

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

}  // namespace cooperage
