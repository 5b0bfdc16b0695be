// Builds a brick through the installed API and checks its topology.
#include <framework/geometry/occ/workbench.h>

#include <cmath>
#include <iostream>

int main() {
  cooperage::occ::Workbench bench;
  bench.brick("b", {0, 0, 0}, {2, 3, 4});
  const cooperage::geom::Model model = bench.build_model();
  const bool ok = model.volumes().size() == 1 && model.surfaces().size() == 6 &&
                  model.curves().size() == 12 && model.vertices().size() == 8 &&
                  std::abs(model.volume(1).volume - 24.0) < 1e-9;
  std::cout << (ok ? "consumer ok" : "consumer FAILED") << '\n';
  return ok ? 0 : 1;
}
