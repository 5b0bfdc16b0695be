// Where a face leaves a neighbour tangentially (issue 16: a fillet or a
// dome's rim meeting a cap at 180 degrees). A hex at such a curve has one
// face on each surface, so its angle there is 180 degrees minus how far its
// rib rises off the cap's tangent plane over the first interval: the
// interval leaving the curve must be long enough to rise kTangentLiftDeg
// (scaled Jacobian about sin(lift) at that corner). Part of gathering the
// facts (the only classification step that reads CAD).
#pragma once

#include "framework/geometry/model.h"

#include <vector>

namespace cooperage::cooper {

/// Rise [degrees] the first interval of a rib leaving a tangent cap needs:
/// sin(13) = 0.225, above the 0.2 the benchmark asks of every hex.
inline constexpr double kTangentLiftDeg = 13.0;

/// One curve of `face` leaving a vertex of the tangent curve `curve`
/// shared with `other` (a rib's first curve when `face` is a side and
/// `other` a cap).
struct TangentDeparture {
  int curve = 0;   ///< the tangent curve
  int face = 0;    ///< the face that leaves
  int other = 0;   ///< the face it leaves
  int along = 0;   ///< a curve of `face` (not of `other`) at a vertex of `curve`
  int vertex = 0;  ///< that vertex
  /// Arc length along `along` from `vertex` at which its chord first rises
  /// kTangentLiftDeg off the tangent plane of `other` at the vertex; 0 when
  /// it never does within the curve's length.
  double first_size = 0;
  double length = 0;    ///< of `along`
  double max_lift = 0;  ///< largest rise of a chord along `along` [degrees]
  /// The chord bends into the volume (a convex edge rounded off: the
  /// dihedral over one interval is below 180), else out of it (a concave
  /// fillet: a re-entrant shoulder).
  bool into_volume = true;
};

/// The departures of `face` from `other` at their shared curve `curve`, one
/// per curve of `face` leaving a vertex of `curve` (seams once).
std::vector<TangentDeparture> tangent_departures(const geom::Model& model, int volume_id, int curve,
                                                 int face, int other);

}  // namespace cooperage::cooper
