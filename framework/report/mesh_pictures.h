// mesh_pictures: what the report draws of each part (usually a volume): the
// faces on the part's boundary, coloured by the scaled Jacobian of the
// element they belong to, and the part's worst elements.
#pragma once

#include <string>
#include <vector>

#include "framework/report/report_input.h"
#include "framework/report/simplify_faces.h"

namespace cooperage::report {

/// An element marked in a picture.
struct MarkedElement {
  std::string block;      ///< ElementBlock::name
  std::size_t index = 0;  ///< 0-based element index in the block
  double scaled_jacobian = 0.0;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
};

struct Picture {
  std::string part;
  /// The drawn faces; values are scaled Jacobians.
  FaceSoup surface;
  std::size_t elements = 0;          ///< elements of the part
  std::size_t boundary_faces = 0;    ///< faces before simplification
  std::vector<MarkedElement> worst;  ///< lowest scaled Jacobian first
};

/// One picture per distinct non-empty ElementBlock::part, in order of first
/// appearance. A part with volume elements shows the faces used by exactly
/// one of its elements (its skin, also around internal voids); a part of
/// surface elements shows them all. Faces are simplified (simplify_faces)
/// when all pictures together would exceed options.max_drawn_faces.
/// @param[in] input            the mesh
/// @param[in] scaled_jacobian  per block of input.blocks, one value per element
/// @param[in] options          face budget and number of marked elements
std::vector<Picture> build_pictures(const ReportInput& input,
                                    const std::vector<std::vector<double>>& scaled_jacobian,
                                    const ReportOptions& options);

}  // namespace cooperage::report
