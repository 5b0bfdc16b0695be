// A tiny streaming JSON writer for the command line's --json output.
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace cooperage::app {

class JsonWriter {
 public:
  explicit JsonWriter(std::ostream& out) : out_(out) {}

  void begin_object() { open('{'); }
  void end_object() { close('}'); }
  void begin_array() { open('['); }
  void end_array() { close(']'); }
  /// Starts a member of the current object; the next value belongs to it.
  void key(const std::string& k);
  void value(const std::string& s);
  void value(const char* s) { value(std::string(s)); }
  void value(double d);
  void value(int i);
  void value(bool b);
  void value(const std::vector<int>& list);
  void value(const std::vector<double>& list);
  void null();

  static std::string escape(const std::string& s);

 private:
  void open(char c);
  void close(char c);
  void separate();

  std::ostream& out_;
  std::vector<bool> first_;  // per open container: no member written yet
  bool after_key_ = false;
};

}  // namespace cooperage::app
