// Which scheme meshes each volume and surface, and why (the selector's output).
#pragma once

#include <map>
#include <string>
#include <vector>

namespace cooperage::pipeline {

struct PlanEntry {
  std::string scheme;  ///< registered scheme name
  std::string reason;  ///< "pinned in the journal", "role from volume 2 (map)", ...
  /// The planner's further notes for a person, one line each: every
  /// scheme's verdict, a volume scheme's structure (shown by reports).
  std::vector<std::string> details;
};

struct SchemePlan {
  std::map<int, PlanEntry> volumes;   ///< volume id -> volume scheme
  std::map<int, PlanEntry> surfaces;  ///< surface id -> surface scheme
};

}  // namespace cooperage::pipeline
