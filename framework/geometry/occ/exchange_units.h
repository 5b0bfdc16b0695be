// What the exchange modules (step_module.cpp, iges_module.cpp) and their
// loader (exchange.cpp) share: the interface's version and the length units
// of STEP and IGES files.
#pragma once

#include <algorithm>
#include <cctype>
#include <string>

namespace cooperage::occ {

/// The exchange modules' interface version (cooperage_exchange_abi); the
/// loader refuses a module that reports another.
constexpr int kExchangeModuleAbi = 2;

struct Unit {
  const char* occt;  ///< name understood by "xstep.cascade.unit"
  double metres;
};

/// Length unit from a STEP/IGES unit name ("MM", "MILLIMETRE", "INCH", ...).
inline bool unit_from_name(std::string name, Unit& unit) {
  std::transform(name.begin(), name.end(), name.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  static const struct {
    const char* names[4];
    Unit unit;
  } table[] = {
      {{"MM", "MILLIMETRE", "MILLIMETER", nullptr}, {"MM", 1e-3}},
      {{"M", "METRE", "METER", nullptr}, {"M", 1.0}},
      {{"CM", "CENTIMETRE", "CENTIMETER", nullptr}, {"CM", 1e-2}},
      {{"KM", "KILOMETRE", "KILOMETER", nullptr}, {"KM", 1e3}},
      {{"UM", "MICROMETRE", "MICROMETER", "MICRON"}, {"UM", 1e-6}},
      {{"INCH", "IN", "INCHES", nullptr}, {"INCH", 0.0254}},
      {{"FT", "FOOT", "FEET", nullptr}, {"FT", 0.3048}},
      {{"MI", "MILE", nullptr, nullptr}, {"MI", 1609.344}},
      {{"MIL", nullptr, nullptr, nullptr}, {"MIL", 2.54e-5}},
      {{"UIN", "MICROINCH", nullptr, nullptr}, {"UIN", 2.54e-8}},
  };
  for (const auto& row : table)
    for (const char* n : row.names)
      if (n && name == n) {
        unit = row.unit;
        return true;
      }
  return false;
}

}  // namespace cooperage::occ
