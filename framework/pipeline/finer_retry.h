// A volume its scheme accepted and then failed on is meshed again at half
// its size (issue 16 item 4: small features adapt the size rather than
// fail). In the plan => mesh campaign such failures are mostly features
// closer than an element: half the size meshed 47 of 106, a quarter 59
// (bench/RESULTS.md, session 22). Every retry that meshes is a warning
// naming the volume, both sizes and why the first failed.
#pragma once

#include "framework/io/job.h"
#include "framework/pipeline/mesher.h"

#include <map>
#include <string>
#include <vector>

namespace cooperage::pipeline {

/// What one volume went through.
struct FinerRetry {
  double asked = 0;          ///< the size the settings gave it
  double size = 0;           ///< the size of its latest attempt
  std::string first_reason;  ///< why the attempt at `asked` failed
};

/// Halves, in `settings`, the size of every volume of `verdicts` a smaller
/// size may mesh (Verdict::finer_may_help) whose size the settings give
/// (its own, else the global one), and records it in `retries` (volume id
/// -> retry). Returns the volumes halved (none: nothing to retry).
std::vector<int> halve_failed_volumes(const std::vector<Verdict>& verdicts,
                                      io::MeshSettings& settings,
                                      std::map<int, FinerRetry>& retries);

/// A warning for every retried volume that meshed; for one that still
/// failed, its hint says which sizes were tried.
void report_finer_retries(const std::map<int, FinerRetry>& retries, MeshResult& result);

}  // namespace cooperage::pipeline
