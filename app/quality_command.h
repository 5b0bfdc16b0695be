// `cooperage quality FILE [--json]`: the quality of an existing mesh file
// (.exo .e .g .msh .vtu, from Cooperage or other tools), block by block.
#pragma once

#include <ostream>
#include <string>

namespace cooperage::app {

/// Reads `path` with io::read_mesh_file() and prints, for every block, its
/// name, element type and count, and for every metric defined for the type
/// (quality::kAllMetrics, quality::is_defined) min / mean / max; the scaled
/// Jacobian also gets its median and the number of inverted elements
/// (value <= 0). Relative size compares with the block's mean size.
/// @param[in] path  the mesh file
/// @param[in] json  one JSON object instead of text
/// @param[out] out  where the report goes
/// @param[in] html  when not empty, also write the HTML report there
///                  (framework/report/html_report.h)
/// @return 0
/// @throws MeshingError from read_mesh_file() (missing file, parse error,
///         unsupported variant, unknown extension) and from write_report().
int run_quality(const std::string& path, bool json, std::ostream& out,
                const std::string& html = "");

}  // namespace cooperage::app
