// An element size as a person writes it: a length in the model's units
// ("2.5") or a fraction of the model's bounding-box diagonal ("D/40"), the
// way the real-CAD issues and Gmsh's -clscale speak of sizes before anyone
// has looked at a part's dimensions.
#pragma once

#include <optional>
#include <string>

namespace cooperage::io {

struct MeshSettings;

struct ElementSize {
  ElementSize() = default;
  /// A length: implicit, so that a plain number stays an element size.
  ElementSize(double length) : value(length) {}  // NOLINT(google-explicit-constructor)
  ElementSize(double v, bool diagonal) : value(v), of_diagonal(diagonal) {}

  double value = 0;          ///< the length, or N of "D/N"
  bool of_diagonal = false;  ///< "D/N": the bounding-box diagonal over N
};

/// Reads "2.5", "1e-3" or "D/40" (also "d/40", spaces around '/' allowed).
/// Returns nullopt for anything else, for a value that is not positive
/// and finite, and for trailing text.
std::optional<ElementSize> parse_element_size(const std::string& text);

/// The settings' global size becomes `size`: a length is set at once; "D/N"
/// is kept as size_divisor until the model exists (resolve_relative_size).
void set_element_size(MeshSettings& settings, const ElementSize& size);

}  // namespace cooperage::io
