// A journal's text around a <geometry> block, for the journal reader's tests.
#pragma once

#include <string>

namespace cooperage::io::testing {

inline std::string journal(const std::string& ops, const std::string& rest = "") {
  return "<cooperage version=\"1\">\n<geometry>\n" + ops + "\n</geometry>\n" + rest +
         "\n</cooperage>\n";
}

}  // namespace cooperage::io::testing
