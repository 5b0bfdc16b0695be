#include "json_writer.h"

#include <cmath>
#include <cstdio>

namespace cooperage::app {

std::string JsonWriter::escape(const std::string& s) {
  std::string r;
  r.reserve(s.size() + 2);
  for (char c : s) {
    switch (c) {
      case '"': r += "\\\""; break;
      case '\\': r += "\\\\"; break;
      case '\n': r += "\\n"; break;
      case '\t': r += "\\t"; break;
      case '\r': r += "\\r"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", c);
          r += buf;
        } else {
          r += c;
        }
    }
  }
  return r;
}

void JsonWriter::separate() {
  if (after_key_) {
    after_key_ = false;
    return;
  }
  if (!first_.empty()) {
    if (!first_.back()) out_ << ',';
    first_.back() = false;
  }
}

void JsonWriter::open(char c) {
  separate();
  out_ << c;
  first_.push_back(true);
}

void JsonWriter::close(char c) {
  first_.pop_back();
  out_ << c;
}

void JsonWriter::key(const std::string& k) {
  separate();
  out_ << '"' << escape(k) << "\":";
  after_key_ = true;
}

void JsonWriter::value(const std::string& s) {
  separate();
  out_ << '"' << escape(s) << '"';
}

void JsonWriter::value(double d) {
  separate();
  if (!std::isfinite(d)) {
    out_ << "null";
    return;
  }
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", d);
  out_ << buf;
}

void JsonWriter::null() {
  separate();
  out_ << "null";
}

void JsonWriter::value(int i) {
  separate();
  out_ << i;
}

void JsonWriter::value(bool b) {
  separate();
  out_ << (b ? "true" : "false");
}

void JsonWriter::value(const std::vector<int>& list) {
  begin_array();
  for (int i : list) value(i);
  end_array();
}

void JsonWriter::value(const std::vector<double>& list) {
  begin_array();
  for (double d : list) value(d);
  end_array();
}

}  // namespace cooperage::app
