// Journal meshing settings checked against the model they apply to: ids
// that exist, and combinations that cannot work (wedge/mixed elements from a
// volume map).
#pragma once

#include "framework/geometry/model.h"
#include "framework/io/job.h"
#include "framework/scheme/registry.h"

namespace cooperage::pipeline {

/// Throws MeshingError naming the journal line: InvalidInput for an id the
/// model does not have, or for elements="wedge" / "mixed" with scheme="map".
void check_settings(const geom::Model& model, const io::MeshSettings& settings);

/// Wedges and mixed elements are a sweep's, so a surface mesh (`dim` 2)
/// of settings that ask for them would silently be quads: throws
/// MeshingError(InvalidInput) saying so.
void check_elements_for_dim(const io::MeshSettings& settings, int dim);

/// The journal's <block>, <sideset> and <nodeset> (or groups built in code,
/// cooperage::Options::groups) are well formed (ids and names unique per
/// kind, names of a letter then letters, digits, '_', at most 32
/// characters, an entity in one block, no empty group) and their ids exist
/// in the model. Throws MeshingError(InvalidInput) naming the journal line.
void check_groups(const geom::Model& model, const io::GroupSettings& groups);

/// Every scheme pin (surface and volume scheme="...") names a scheme of its
/// dimension in the registry (built in or from a plug-in). Throws
/// MeshingError(InvalidInput) naming the journal line, the closest
/// registered name if one is close, and every registered name.
void check_scheme_names(const io::MeshSettings& settings, const scheme::Registry& registry);

}  // namespace cooperage::pipeline
