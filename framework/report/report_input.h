// ReportInput: everything the HTML report shows, as plain data the callers
// fill (report_from_run.h for a meshing run, report_from_file.h for a mesh
// file). The report computes the per-element quality itself, so any mesh
// given as coordinates and connectivity can be reported.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "framework/quality/metric.h"

namespace cooperage::report {

/// The elements of one type of one block, viewed in place (not copied): the
/// caller keeps the connectivity alive while the report is rendered.
struct ElementBlock {
  std::string name;    ///< "volume 2 (boss)", "block \"hex_1\""
  std::string part;    ///< the picture the block is drawn in; "" draws it nowhere
  std::string scheme;  ///< the scheme that meshed it; "" when unknown
  quality::ElementType type = quality::ElementType::Hex;
  const int* connectivity = nullptr;  ///< count * stride 0-based node indices
  std::size_t count = 0;
  int stride = 8;  ///< >= quality::node_count(type); element e starts at e * stride
  /// Reference normals, one per element (tris and quads only), so the scaled
  /// Jacobian is signed against the surface as in the run's quality report;
  /// empty: each element's own normal.
  std::vector<Eigen::Vector3d> normals;
  std::optional<double> seconds;  ///< time spent meshing the entity
};

/// One line of the plan: an entity, its scheme and why.
struct PlanRow {
  std::string entity;  ///< "volume 2", "surface 12"
  std::string scheme;
  std::string reason;
  /// The planner's further notes, one line each (every scheme's verdict,
  /// a cooper volume's barrels, ...), shown verbatim.
  std::vector<std::string> details;
};

struct StageTime {
  std::string stage;  ///< "geometry", "plan", "surfaces", ...
  double seconds = 0.0;
};

struct ReportInput {
  std::string title;  ///< what was meshed or read: "part.step", "q.exo"
  const std::vector<Eigen::Vector3d>* coords = nullptr;  ///< node coordinates
  std::vector<ElementBlock> blocks;
  /// Optional, one flag per node: false for nodes known to be inside a
  /// volume (never on a part's boundary), which speeds up finding the
  /// boundary faces of big meshes. Empty: every node may be on it.
  std::vector<bool> maybe_boundary;
  std::vector<PlanRow> plan;
  std::vector<StageTime> stages;
  std::vector<std::string> warnings;  ///< one sentence each, entity first
  std::vector<std::string> notes;     ///< checks, files written, skipped cells
};

/// Limits that keep the file small for big meshes.
struct ReportOptions {
  /// Faces drawn over all pictures; a part with more boundary faces than its
  /// share is simplified by vertex clustering (and the report says so).
  std::size_t max_drawn_faces = 30000;
  std::size_t worst_marked = 5;  ///< worst elements marked per picture
};

}  // namespace cooperage::report
