#include "framework/io/element_size.h"

#include <cctype>
#include <cmath>
#include <cstdlib>

#include "framework/io/job.h"

namespace cooperage::io {

namespace {

// A positive finite number filling [begin, end) once blanks are trimmed.
std::optional<double> positive_number(const std::string& text, size_t begin, size_t end) {
  while (begin < end && std::isspace(static_cast<unsigned char>(text[begin]))) ++begin;
  while (end > begin && std::isspace(static_cast<unsigned char>(text[end - 1]))) --end;
  if (begin == end) return std::nullopt;
  const std::string part = text.substr(begin, end - begin);
  char* stop = nullptr;
  const double value = std::strtod(part.c_str(), &stop);
  if (stop != part.c_str() + part.size()) return std::nullopt;
  if (!std::isfinite(value) || !(value > 0)) return std::nullopt;
  return value;
}

}  // namespace

std::optional<ElementSize> parse_element_size(const std::string& text) {
  size_t begin = 0;
  while (begin < text.size() && std::isspace(static_cast<unsigned char>(text[begin]))) ++begin;
  if (begin < text.size() && (text[begin] == 'D' || text[begin] == 'd')) {
    size_t slash = begin + 1;
    while (slash < text.size() && std::isspace(static_cast<unsigned char>(text[slash]))) ++slash;
    if (slash >= text.size() || text[slash] != '/') return std::nullopt;
    const auto n = positive_number(text, slash + 1, text.size());
    if (!n) return std::nullopt;
    return ElementSize{*n, true};
  }
  const auto length = positive_number(text, begin, text.size());
  if (!length) return std::nullopt;
  return ElementSize{*length, false};
}

void set_element_size(MeshSettings& settings, const ElementSize& size) {
  if (size.of_diagonal) {
    settings.size.reset();
    settings.size_divisor = size.value;
  } else {
    settings.size = size.value;
    settings.size_divisor.reset();
  }
}

}  // namespace cooperage::io
