// Dihedral angle between an end cap and an attached side face (Blacker 1996,
// sec. 3: a cooperable volume has at least two caps whose dihedral angles
// with the attached side faces are below pi).
#pragma once

#include "framework/geometry/model.h"

namespace cooperage::cooper {

/// Interior dihedral angle inside volume `volume_id` between surfaces `cap`
/// and `side` along their shared curve `curve`, in degrees (0, 360): 90 at a
/// brick edge, 270 at a re-entrant edge. The largest of three samples along
/// the curve (at 1/4, 1/2 and 3/4 of its parameter range).
/// Directions: d_f = N_f x t_f is the direction into face f from the curve
/// (N_f its natural normal, t_f the tangent along f's loop use); the angle
/// between d_cap and d_side is the dihedral when d_side points against the
/// cap's outward normal (convex edge), else its complement to 360.
double cap_dihedral_degrees(const geom::Model& model, int volume_id, int cap, int side, int curve);

}  // namespace cooperage::cooper
