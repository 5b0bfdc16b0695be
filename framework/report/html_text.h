// Small text helpers of the HTML report: escaping, number formatting, base64.
// Internal to framework/report.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace cooperage::report::detail {

/// Text safe inside HTML elements and attribute values.
std::string html_escape(const std::string& text);

/// A JSON string literal (quotes included), safe inside a <script> element.
std::string json_string(const std::string& text);

/// printf-style formatting of one number ("%.3f", "%g").
std::string format_number(const char* format, double value);

/// Seconds for a person: "0.012 s", "3.4 s", "2 min 05 s".
std::string format_seconds(double seconds);

/// RFC 4648 base64 of raw bytes.
std::string base64(const std::uint8_t* data, std::size_t size);

/// base64 of a little-endian array of numbers (the byte order of every
/// platform Cooperage builds on and of every browser's typed arrays).
template <class T>
std::string base64_of(const std::vector<T>& values) {
  return base64(reinterpret_cast<const std::uint8_t*>(values.data()), values.size() * sizeof(T));
}

}  // namespace cooperage::report::detail
