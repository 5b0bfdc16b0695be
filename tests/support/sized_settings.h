// Mesh settings of one element size for tests (tests only).
#pragma once

#include "framework/io/job.h"

namespace cooperage::testing {

/// The scheme at this size, not a retry at a finer one.
inline io::MeshSettings sized(double size) {
  io::MeshSettings s;
  s.size = size;
  s.finer_retries = 0;
  return s;
}

}  // namespace cooperage::testing
