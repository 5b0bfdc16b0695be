// Vertex classification for submapping (ALGORITHMS.md sec. 1; Whiteley et
// al. 1996): raw END / SIDE / CORNER / REVERSAL types from interior angles,
// and their repair to the nearest classification that obeys the loop sum
// rule (outer loop sum t = 4, each hole -4) by an exact dynamic program.
// Value types only: testable without CAD.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "framework/scheme/vertex_angles.h"

namespace cooperage::submap {

using scheme::VertexType;

/// One junction of a loop as the classifier sees it.
struct CornerInput {
  double angle = 180.0;              ///< interior angle inside the face [degrees]
  std::optional<VertexType> pinned;  ///< a hard type from the journal (kept as is)
};

struct ClassifyOptions {
  /// A repair may give a vertex a type whose ideal angle is at most this far
  /// from its measured angle [degrees]; larger changes are never made.
  double max_repair_deviation = 80.0;
};

/// The classification of one loop.
struct LoopTypes {
  bool ok = false;
  std::vector<VertexType> types;  ///< per corner, loop order (empty unless ok)
  std::vector<VertexType> raw;    ///< classify_angle() per corner (pinned types where pinned)
  int raw_sum = 0;                ///< sum of raw t
  int target_sum = 4;             ///< 4 for the outer loop, -4 for a hole
  int changed = 0;                ///< corners whose type differs from raw
  double cost = 0.0;              ///< sum w_i |t_i - t_i0| of the repair
  int bad_corner = -1;            ///< corner whose angle has no type (< kMinEndAngle), or -1
  std::string why;                ///< reason for !ok ("loop sum 3, needs 4"), no entity prefix
};

/// Integer value t of a type: END 1, SIDE 0, CORNER -1, REVERSAL -2.
inline int t_of(VertexType type) { return static_cast<int>(type); }
/// Type of an integer value t in [-2, 1].
VertexType type_of(int t);

/// Classifies a loop: raw types by classify_angle(), pinned types where given;
/// when the raw sum differs from `target_sum` the nearest valid
/// classification is found by repair_loop().
/// \param[in] corners     angles (degrees) and pins, in loop order
/// \param[in] target_sum  4 for the outer loop, -4 for a hole
LoopTypes classify_loop(const std::vector<CornerInput>& corners, int target_sum,
                        const ClassifyOptions& options = {});

/// The repair integer program, solved exactly per loop by dynamic programming
/// over the running sum:  minimise sum_i w_i(t_i) |t_i - t0_i| subject to
/// sum_i t_i = target_sum, -2 <= t_i <= 1, pinned t_i fixed, with
/// w_i(t) = |theta_i - 90 (2 - t)| (the angle deviation of the new type; a
/// change is allowed only when that deviation is <= max_repair_deviation).
/// Ties are broken by vertex order: earlier vertices keep their raw type.
/// \return the types, or nothing when no classification satisfies the sum.
std::optional<std::vector<VertexType>> repair_loop(const std::vector<double>& angles,
                                                   const std::vector<VertexType>& raw,
                                                   const std::vector<bool>& pinned, int target_sum,
                                                   const ClassifyOptions& options = {});

}  // namespace cooperage::submap
