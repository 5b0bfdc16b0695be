// Whether a model of pieces is the part they were cut from: the same skin
// (faces bounding one volume) and the same volume. A cut adds only faces
// bounding two volumes; two coinciding faces left unmerged add their area
// to the skin twice.
#pragma once

#include "framework/geometry/model.h"

namespace cooperage::decompose {

/// The area of the faces of `model` that bound exactly one volume.
double skin_area(const geom::Model& model);

/// Whether `pieces` has the skin area and the volume of `part`, each to a
/// relative 1e-9 (split faces' areas sum to the whole's to 1e-15 on the
/// real-CAD parts).
bool same_skin_and_volume(const geom::Model& pieces, const geom::Model& part);

}  // namespace cooperage::decompose
