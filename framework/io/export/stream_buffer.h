// StreamBuffer: what the mesh encoders write through. Numbers are formatted
// with std::to_chars (shortest text that reads back to the same double, so
// ASCII files are exact) or appended as raw bytes, into a buffer flushed to
// the stream in large blocks: std::ostream's operator<< with precision 17
// made ASCII exports formatting-bound (issue 20: 2.7 s for a 1 M-hex .vtu).
// Internal to framework/io/export.
#pragma once

#include <charconv>
#include <cstdint>
#include <cstring>
#include <ostream>
#include <string>
#include <string_view>
#include <type_traits>

namespace cooperage::io::detail {

class StreamBuffer {
 public:
  explicit StreamBuffer(std::ostream& out) : out_(out) { buf_.reserve(kFlushAt + 64); }
  ~StreamBuffer() { flush(); }
  StreamBuffer(const StreamBuffer&) = delete;
  StreamBuffer& operator=(const StreamBuffer&) = delete;

  StreamBuffer& operator<<(std::string_view s) {
    buf_.append(s.data(), s.size());
    return maybe_flush();
  }
  StreamBuffer& operator<<(char c) {
    buf_.push_back(c);
    return maybe_flush();
  }
  /// Integers and doubles as text (doubles: shortest round-trip form).
  template <class T, class = std::enable_if_t<std::is_arithmetic_v<T>>>
  StreamBuffer& operator<<(T v) {
    char tmp[32];
    const auto r = std::to_chars(tmp, tmp + sizeof tmp, v);
    buf_.append(tmp, static_cast<size_t>(r.ptr - tmp));
    return maybe_flush();
  }
  /// The bytes of v as stored (little-endian on every supported machine).
  template <class T>
  void raw(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>, "raw bytes of a plain value");
    const size_t at = buf_.size();
    buf_.resize(at + sizeof(T));
    std::memcpy(&buf_[at], &v, sizeof(T));
    maybe_flush();
  }
  void flush() {
    if (!buf_.empty()) out_.write(buf_.data(), static_cast<std::streamsize>(buf_.size()));
    buf_.clear();
  }

 private:
  static constexpr size_t kFlushAt = size_t{1} << 20;
  StreamBuffer& maybe_flush() {
    if (buf_.size() >= kFlushAt) flush();
    return *this;
  }
  std::ostream& out_;
  std::string buf_;
};

}  // namespace cooperage::io::detail
