// Peak resident memory of this process, for benchmark counters.
#pragma once

#include <cstddef>

namespace cooperage::bench {

/// Peak resident set size so far, in bytes (getrusage ru_maxrss).
std::size_t peak_memory_bytes();

}  // namespace cooperage::bench
