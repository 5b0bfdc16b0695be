// Internal to the journal reader: typed, validated access to one XML element.
// Every failure throws MeshingError(InvalidInput) with a message of the form
//   job.xml:12: <brick>: attribute "size" must be three positive numbers, got "1 -2 3"
#pragma once

#include "framework/io/job.h"

#include <cstddef>
#include <initializer_list>
#include <optional>
#include <string>
#include <vector>

namespace tinyxml2 {
class XMLElement;
class XMLAttribute;
}  // namespace tinyxml2

namespace cooperage::io::detail {

/// Bounds on journal values (issue 21, 3c): numbers are 0 or normal with a
/// magnitude up to kMaxMagnitude (the kernel works to 1e-7; coordinates of
/// 1e300 hang it); positive numbers are at least kMinPositive (the kernel's
/// confusion distance); integers at most kMaxInteger (32-bit sums stay
/// exact); shape names at most kMaxNameLength characters (names are carried
/// into every export).
inline constexpr double kMaxMagnitude = 1e7;
inline constexpr double kMinPositive = 1e-7;
inline constexpr int kMaxInteger = 1000000000;
inline constexpr std::size_t kMaxNameLength = 64;

enum class NumberKind { Any, Positive, NonNegative };
enum class VectorKind { Any, NonZero, Positive };

/// One journal element: checks attributes and children, converts values.
class Element {
 public:
  Element(const tinyxml2::XMLElement* element, const std::string& file);

  const char* name() const;
  /// The element name for messages: name(), cut to 40 characters.
  std::string tag() const;
  int line() const;
  SourceLocation where() const;

  /// Fails on any attribute not in `allowed`, listing the allowed ones.
  void allow_attributes(std::initializer_list<const char*> allowed) const;
  /// Fails on child elements and on non-blank text.
  void expect_empty() const;
  /// Child elements in order (fails on non-blank text between them).
  std::vector<Element> children() const;

  bool has(const char* attribute) const;
  /// Value of a required attribute, which must not be blank.
  std::string required(const char* attribute) const;
  std::optional<std::string> text(const char* attribute) const;
  /// A shape name: a letter or '_' then letters, digits, '_', '.', '-';
  /// at most kMaxNameLength characters.
  std::string shape_name(const char* attribute) const;
  /// Two or more distinct shape names separated by blanks.
  std::vector<std::string> shape_names(const char* attribute) const;

  std::optional<double> number(const char* attribute, NumberKind kind) const;
  double required_number(const char* attribute, NumberKind kind) const;
  /// An integer >= `min`.
  std::optional<int> integer(const char* attribute, int min) const;
  int required_integer(const char* attribute, int min) const;
  /// One or more distinct positive ids separated by blanks.
  std::vector<int> ids(const char* attribute) const;
  std::optional<bool> boolean(const char* attribute) const;
  std::optional<Vec3> vector(const char* attribute, VectorKind kind) const;
  Vec3 required_vector(const char* attribute, VectorKind kind) const;
  /// "x y z, x y z, ..." with at least three points; with allow_single, a
  /// single point "x y z" is accepted too (a loft apex).
  Polygon points(const char* attribute, bool allow_single = false) const;
  /// Index of the value in `options`, or nullopt when absent.
  std::optional<int> choice(const char* attribute,
                            std::initializer_list<const char*> options) const;

  /// Throws "<file>:<line>: <name>: <message>" at the element's line.
  [[noreturn]] void fail(const std::string& message) const;
  /// Throws the same, at the line of `attribute` when it is present.
  [[noreturn]] void fail_at(const char* attribute, const std::string& message) const;

 private:
  [[noreturn]] void bad_value(const char* attribute, const std::string& expected) const;

  const tinyxml2::XMLElement* element_;
  const std::string* file_;
};

/// "file:line: " prefix.
std::string at(const std::string& file, int line);
/// Quotes `options` as a comma-separated list, each wrapped as pre + option + post.
std::string list(const std::vector<std::string>& options, const char* pre = "",
                 const char* post = "");
/// " (did you mean X?)" when `word` is close to one of `options`, else "".
std::string suggestion(const std::string& word, const std::vector<std::string>& options,
                       const char* pre = "", const char* post = "");

/// Reads the children of <geometry> into job.geometry and job.imprint_merge.
void read_geometry(const Element& geometry, Job& job);
/// Reads <mesh> and its settings.
MeshSettings read_mesh(const Element& mesh);
/// Reads one <block>, <sideset> or <nodeset> into `groups` (journal_groups.cpp).
void read_group(const Element& group, GroupSettings& groups);

}  // namespace cooperage::io::detail
