// Uses an installed Cooperage the way a user would: builds a 2 x 3 x 4 brick
// through the installed geometry API, writes it as STEP, meshes it with the
// one-call API at size 1 and checks what follows from the geometry: 24 hexes
// of volume 1, 3 x 4 x 5 nodes, 2 (2x3 + 3x4 + 2x4) = 52 boundary quads.
#include <cooperage/cooperage.h>
#include <framework/geometry/occ/workbench.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>

namespace {

bool check(bool ok, const char* what) {
  if (!ok) std::cout << "consumer FAILED: " << what << '\n';
  return ok;
}

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path dir = argc > 1 ? argv[1] : std::filesystem::temp_directory_path();
  const std::string step = (dir / "brick.step").string();
  {
    cooperage::occ::Workbench bench;
    bench.brick("b", {0, 0, 0}, {2, 3, 4});
    bench.write(step);
  }
  try {
    const cooperage::Result r = cooperage::mesh_file(step, 1.0);
    const auto* sj =
        r.quality.blocks.empty() ? nullptr : r.quality.blocks.front().find("scaled_jacobian");
    bool ok = check(r.model.volumes().size() == 1, "one volume");
    ok = check(std::abs(r.model.volume(1).volume - 24.0) < 1e-9, "volume 24") && ok;
    ok = check(r.mesh.hex_count() == 24, "24 hexes") && ok;
    ok = check(r.mesh.node_count() == 60, "60 nodes") && ok;
    ok = check(r.mesh.quad_count() == 52, "52 boundary quads") && ok;
    ok = check(sj && std::abs(sj->min - 1.0) < 1e-9, "scaled Jacobian 1") && ok;
    ok = check(r.plan.volumes.at(1).scheme == "map", "volume map chosen") && ok;
    if (!ok) return 1;
  } catch (const cooperage::MeshingError& e) {
    std::cout << "consumer FAILED: " << e.what() << '\n';
    return 1;
  }
  try {  // bad input is an exception naming the file, not a crash
    cooperage::mesh_file((dir / "missing.step").string(), 1.0);
    std::cout << "consumer FAILED: no error for a missing file\n";
    return 1;
  } catch (const cooperage::MeshingError& e) {
    if (std::string(e.what()).find("missing.step") == std::string::npos) {
      std::cout << "consumer FAILED: the error does not name the file: " << e.what() << '\n';
      return 1;
    }
  }
  std::cout << "consumer ok\n";
  return 0;
}
