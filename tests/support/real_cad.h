// Where the real CAD made by other people lives (../shared/real-cad, never
// copied into the project; issue 16). Tests skip when the file is absent.
#pragma once

#include <filesystem>
#include <string>

namespace cooperage::testing {

/// ../shared/real-cad/<file> from the checkout (the main checkout sits next
/// to shared/; a git worktree one folder deeper, hence the second guess).
/// The first guess when neither exists, so a skip message names a path.
inline std::string real_cad(const std::string& file) {
  namespace fs = std::filesystem;
  const fs::path source(COOPERAGE_SOURCE_DIR);
  for (const fs::path& up : {source / "..", source / ".." / ".."}) {
    const fs::path p = (up / "shared" / "real-cad" / file).lexically_normal();
    if (fs::exists(p)) return p.string();
  }
  return (source / ".." / "shared" / "real-cad" / file).lexically_normal().string();
}

}  // namespace cooperage::testing
