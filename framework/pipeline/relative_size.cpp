#include "framework/pipeline/relative_size.h"

#include <cmath>

#include "framework/core/error.h"
#include "framework/core/log.h"
#include "framework/core/text.h"

namespace cooperage::pipeline {

void resolve_relative_size(io::MeshSettings& settings, const geom::Model& model) {
  if (!settings.size_divisor) return;
  const double divisor = *settings.size_divisor;
  const double diagonal = model.box().diagonal();
  if (!(diagonal > 0) || !std::isfinite(diagonal)) {
    throw MeshingError(ErrorCode::InvalidInput,
                       "size D/" + number_text(divisor) +
                           ": the model has no extent, so its bounding-box diagonal D is 0");
  }
  settings.size = diagonal / divisor;
  settings.size_divisor.reset();
  log::info("size D/" + number_text(divisor) + " = " + number_text(*settings.size) +
            " (bounding-box diagonal " + number_text(diagonal) + ")");
}

}  // namespace cooperage::pipeline
