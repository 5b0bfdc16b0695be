// `cooperage info`: a person's and a program's view of a model's topology,
// geometric types and measures.
#pragma once

#include "framework/geometry/model.h"

#include <ostream>
#include <string>

namespace cooperage::app {

/// Plain text: counts, then every volume, surface, curve and vertex.
void write_model_text(const geom::Model& model, const std::string& source, std::ostream& out);

/// The same content as one JSON object.
void write_model_json(const geom::Model& model, const std::string& source, std::ostream& out);

}  // namespace cooperage::app
