// Interior angles at the vertices of a surface's loops and their
// classification END / SIDE / CORNER / REVERSAL (ALGORITHMS.md sec. 1;
// Whiteley et al. 1996). Shared by map and submap.
#pragma once

#include "framework/geometry/model.h"

#include <optional>
#include <string>
#include <vector>

namespace cooperage::scheme {

enum class VertexType { End = 1, Side = 0, Corner = -1, Reversal = -2 };

/// END, SIDE, CORNER, REVERSAL.
const char* to_string(VertexType type);
/// The ideal interior angle of a type, in degrees: 90, 180, 270, 360.
double ideal_angle_degrees(VertexType type);

/// The scaled Jacobian a structured mesh can reach at a vertex of interior
/// angle `degrees` classified as `type`: the angle is shared by 1, 2, 3 or 4
/// quad corners (END, SIDE, CORNER, REVERSAL), each of sine sin(angle / k).
/// 1 at the ideal angles; used as the schemes' a-priori quality score, so
/// map, submap and pave compare on one scale.
double predicted_corner_quality(double degrees, VertexType type);

/// The sharpest corner that is still an END. MeshKit stops at 45; an END
/// of 30 degrees still gives its quad a scaled Jacobian of sin 30 = 0.5,
/// and real parts have 40-degree corners (an angled clamp's flanks).
inline constexpr double kMinEndAngle = 30.0;

/// Classification by angle: END [30, 130), SIDE [130, 225), CORNER
/// [225, 315), REVERSAL >= 315 degrees (MeshKit's thresholds above END);
/// none below kMinEndAngle.
std::optional<VertexType> classify_angle(double degrees);

/// A junction of a loop: between uses[k-1] (incoming) and uses[k] (outgoing).
struct LoopCorner {
  int use_index = 0;               ///< k: the outgoing use
  int vertex = 0;                  ///< model vertex id
  double angle = 0.0;              ///< interior angle measured inside the face [degrees], (0, 360)
  std::optional<VertexType> type;  ///< classify_angle(angle)
};

/// Interior angles at every junction of loop `loop_index` of a surface, in
/// loop order (corner k sits before uses[k]). The angle is measured in the
/// tangent plane with the surface's natural normal, so 90 and 270 degrees
/// are told apart on curved faces too; where the curves leave along one
/// line, chords a little way along them tell a cusp (0) from a slit (360).
std::vector<LoopCorner> loop_corners(const geom::Model& model, int surface_id, int loop_index);

/// The sharpest corner over all loops of a surface (smallest angle), or none
/// when no loop has a junction. Where several loops pass through a vertex
/// (a hole touching the outer loop) the angle is the face's narrowest
/// opening there, 0 for a circle touching a line. No element at a corner of
/// angle a has a scaled Jacobian above sin(a): the --dim 2 fallback and
/// `info` use it.
std::optional<LoopCorner> sharpest_corner(const geom::Model& model, int surface_id);

/// Groups the uses of a single-loop surface into logical sides between END
/// corners: side s holds the use indices from END corner s up to (excluding)
/// END corner s+1. Empty when the loop has no END corner.
std::vector<std::vector<int>> sides_between_ends(const std::vector<LoopCorner>& corners,
                                                 size_t use_count);

}  // namespace cooperage::scheme
