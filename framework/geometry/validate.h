// validate(): is a B-rep fit for meshing? (issue 21 items 1 and 3b). A
// damaged or hand-edited file can hold topology that holds together while the
// geometry does not (a brick vertex moved off its edges was meshed at 44 %
// less volume than the CAD): every model is checked before any scheme sees it.
#pragma once

#include "framework/geometry/model.h"

namespace cooperage::geom {

/// Checks, in this order, and throws MeshingError(GeometryError) naming the
/// first defect and where it is:
///  - topology: ids, back references, closed loops (Model::validate());
///  - finite numbers: vertex points, curve lengths, surface areas, volumes;
///  - non-empty entities: curves longer than zero, surfaces with a loop and
///    an area, volumes with a volume;
///  - geometry agrees with topology: every curve starts and ends at its
///    vertices, and its middle lies on every surface it bounds, within
///    1e-3 of the model's size (a gap no element size can see);
///  - closed shells: in every shell of a volume, each curve bounds exactly
///    two surface uses, once in each direction.
/// The numbers in messages are in model units.
void validate(const Model& model);

/// The gap allowed between a curve and its vertices or surfaces, in model
/// units: 1e-3 of the model's bounding-box diagonal.
double validation_tolerance(const Model& model);

}  // namespace cooperage::geom
