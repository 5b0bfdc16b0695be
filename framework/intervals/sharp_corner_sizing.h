// First intervals at a face's sharp corners (issue 16, item 1; issue 15).
// Where a curved curve leaves a corner of a few degrees, its first chord
// turns away from its tangent by half the angle the curve turns over it.
// When it turns towards the corner's other curve the discrete corner is
// sharper than the CAD's, or closed or crossed: a lug's 7-degree horn met
// by an arc took a 0.24-degree corner at the element size. Both curves'
// first intervals at such a corner get a bound under which their two
// chords together close at most a quarter of the corner; an arc that opens
// the corner makes up for one that closes it (two arcs bending the same
// way: shortening one of them alone made the quads at a 10.7-degree tip
// worse, campaign seed 23 case 88). Only corners under 15 degrees, where
// the corner already bounds every element at it below 0.26.
#pragma once

#include "framework/geometry/model.h"

#include <functional>
#include <vector>

namespace cooperage::intervals {

struct SharpCornerOptions {
  double max_corner_deg = 15.0;      ///< corners at most this sharp are kept (sin 15 = 0.26)
  double min_corner_deg = 0.5;       ///< sharper: a tangent contact, left alone
  double share = 0.25;               ///< of the corner the two first chords may close
  double min_fraction = 1.0 / 64.0;  ///< the first interval >= this fraction of the size
};

/// A bound on the local size at one end of a curve.
struct EndSize {
  int curve = 0;
  bool at_start = true;  ///< the end at the curve's start vertex
  double size = 0.0;
};

/// The bounds at every sharp corner of every face, in ascending order of
/// surface, loop and use (deterministic). `size_of(curve id)` is the
/// element size of the curve, for the lower bound.
std::vector<EndSize> sharp_corner_sizes(const geom::Model& model,
                                        const std::function<double(int)>& size_of,
                                        const SharpCornerOptions& options = {});

}  // namespace cooperage::intervals
