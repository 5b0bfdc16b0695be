// The quality report of a run: per element block (volume x element type, or
// surface x element type for surface meshes) the scaled Jacobian and every
// metric the journal checks, and the outcome of each check.
#pragma once

#include "framework/geometry/model.h"
#include "framework/io/job.h"
#include "framework/mesh/mesh_db.h"
#include "framework/quality/metric.h"
#include "framework/quality/summary.h"

#include <map>
#include <vector>

namespace cooperage::pipeline {

struct BlockReport {
  int dim = 3;  ///< 3: a volume's block, 2: a surface's
  int id = 0;
  quality::ElementType type = quality::ElementType::Hex;
  std::size_t count = 0;
  std::vector<quality::MetricSummary> metrics;  ///< scaled_jacobian first

  const quality::MetricSummary* find(const std::string& metric) const;
};

struct CheckOutcome {
  io::QualityCheck check;
  std::size_t violations = 0;  ///< elements outside the thresholds, all blocks
  bool failed = false;         ///< violations with action Fail
};

struct QualityReport {
  std::vector<BlockReport> blocks;
  std::vector<CheckOutcome> checks;
  bool failed() const;
  std::size_t inverted() const;  ///< elements with scaled Jacobian <= 0
};

/// The CAD surface's normal at the centroid of each element: the reference
/// surface elements' scaled Jacobian, Jacobian and shape are signed against
/// (quality::EvaluateOptions::normals).
std::vector<Eigen::Vector3d> reference_normals(const mesh::MeshDB& db, const geom::Surface& surface,
                                               const std::vector<mesh::Quad>& quads);
std::vector<Eigen::Vector3d> reference_normals(const mesh::MeshDB& db, const geom::Surface& surface,
                                               const std::vector<mesh::Tri>& tris);

/// Scaled Jacobians a volume scheme already computed on the mesh's final
/// coordinates (scheme::EntityMesh::hex_scaled_jacobian), per volume id, in
/// the order of the volume's elements in the MeshDB.
struct KnownScaledJacobians {
  std::map<int, std::vector<double>> hexes, wedges;
};

/// Volume blocks when the mesh has volume elements, otherwise surface blocks
/// (scaled Jacobian signed against the surface normal). Unknown metric names
/// in checks give MeshingError(InvalidInput) naming the journal line.
/// \param[in] known  values to take instead of computing them; a block's are
///                   used only when there is one per element (the report is
///                   the same either way, bit for bit)
QualityReport assess_quality(const mesh::MeshDB& db, const geom::Model& model,
                             const std::vector<io::QualityCheck>& checks,
                             const KnownScaledJacobians* known = nullptr);

}  // namespace cooperage::pipeline
