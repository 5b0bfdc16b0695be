// Fuzz target: the journal reader (framework/io/journal_reader.h) on any
// bytes. A bad journal must end in MeshingError, never in a crash, a hang,
// a sanitizer report or an error message that echoes kilobytes of input.
#include "framework/core/error.h"
#include "framework/io/journal_reader.h"

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    (void)cooperage::io::parse_journal(text, "fuzz.xml", "/nonexistent");
  } catch (const cooperage::MeshingError& e) {
    // Errors echo at most kEchoLimit characters of user text, so a message
    // stays a line, whatever the input (issue 21 item 4).
    if (std::strlen(e.what()) > 1000) std::abort();
  }
  return 0;
}
