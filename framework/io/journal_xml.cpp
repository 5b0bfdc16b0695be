#include "framework/io/journal_xml.h"

#include "framework/core/error.h"
#include "framework/core/text.h"

#include <tinyxml2.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <set>

namespace cooperage::io::detail {

namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

std::string trim(const std::string& s) {
  size_t b = 0, e = s.size();
  while (b < e && is_blank(s[b])) ++b;
  while (e > b && is_blank(s[e - 1])) --e;
  return s.substr(b, e - b);
}

std::vector<std::string> split_blanks(const std::string& s) {
  std::vector<std::string> words;
  std::string word;
  for (char c : s) {
    if (is_blank(c)) {
      if (!word.empty()) words.push_back(word);
      word.clear();
    } else {
      word += c;
    }
  }
  if (!word.empty()) words.push_back(word);
  return words;
}

/// A finite decimal number, as the XSD's Number pattern: optional sign,
/// digits with an optional point, optional exponent. No inf, nan or hex.
std::optional<double> to_number(const std::string& word) {
  if (word.empty()) return std::nullopt;
  const char* first = word.data();
  const char* last = word.data() + word.size();
  const char* digits = first;
  if (*first == '+')
    digits = ++first;  // from_chars takes no '+'
  else if (*first == '-')
    digits = first + 1;
  if (digits == last || !(std::isdigit(static_cast<unsigned char>(*digits)) || *digits == '.'))
    return std::nullopt;  // rejects "inf", "nan", "+-1"
  double value = 0;
  auto [ptr, ec] = std::from_chars(first, last, value, std::chars_format::general);
  if (ec != std::errc() || ptr != last || !std::isfinite(value)) return std::nullopt;
  // Normal range only: no denormals (4.9e-324 passed as "positive"), nothing
  // the kernel cannot place (a cylinder at 1e300 hung the boolean).
  if (value != 0 && (!std::isnormal(value) || std::abs(value) > kMaxMagnitude)) return std::nullopt;
  return value;
}

std::optional<int> to_integer(const std::string& word) {
  if (word.empty() ||
      !std::all_of(word.begin(), word.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return std::nullopt;
  int value = 0;
  auto [ptr, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (ec != std::errc() || ptr != word.data() + word.size()) return std::nullopt;
  return value;
}

bool valid_name(const std::string& s) {
  if (s.empty() || s.size() > kMaxNameLength) return false;
  auto alpha = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; };
  if (!alpha(s[0])) return false;
  return std::all_of(s.begin(), s.end(), [&](char c) {
    return alpha(c) || (c >= '0' && c <= '9') || c == '.' || c == '-';
  });
}

size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

const char* kNumberWords[] = {"a number between -1e7 and 1e7",
                              "a positive number between 1e-7 and 1e7",
                              "a non-negative number up to 1e7"};

}  // namespace

std::string at(const std::string& file, int line) {
  return clip_path(file) + ":" + std::to_string(line) + ": ";
}

std::string list(const std::vector<std::string>& options, const char* pre, const char* post) {
  std::string out;
  for (const auto& option : options) {
    if (!out.empty()) out += ", ";
    out += pre + option + post;
  }
  return out;
}

std::string suggestion(const std::string& word, const std::vector<std::string>& options,
                       const char* pre, const char* post) {
  const std::string* best = nullptr;
  size_t best_distance = 3;  // suggest only close matches
  for (const auto& option : options) {
    const size_t d = edit_distance(word, option);
    if (d < best_distance && d < word.size()) {  // not a complete rewrite ("c" -> "b")
      best_distance = d;
      best = &option;
    }
  }
  return best ? " (did you mean " + std::string(pre) + *best + post + "?)" : std::string();
}

Element::Element(const tinyxml2::XMLElement* element, const std::string& file)
    : element_(element), file_(&file) {}

const char* Element::name() const { return element_->Name(); }
std::string Element::tag() const { return clip(element_->Name(), 40); }
int Element::line() const { return element_->GetLineNum(); }

SourceLocation Element::where() const { return {*file_, line(), tag()}; }

void Element::fail(const std::string& message) const {
  throw MeshingError(ErrorCode::InvalidInput, at(*file_, line()) + "<" + tag() + ">: " + message);
}

void Element::fail_at(const char* attribute, const std::string& message) const {
  int where_line = line();
  for (auto* a = element_->FirstAttribute(); a; a = a->Next())
    if (std::strcmp(a->Name(), attribute) == 0) where_line = a->GetLineNum();
  throw MeshingError(ErrorCode::InvalidInput,
                     at(*file_, where_line) + "<" + tag() + ">: " + message);
}

void Element::bad_value(const char* attribute, const std::string& expected) const {
  fail_at(attribute, "attribute \"" + std::string(attribute) + "\" must be " + expected +
                         ", got \"" + clip(element_->Attribute(attribute)) + "\"");
}

void Element::allow_attributes(std::initializer_list<const char*> allowed) const {
  const std::vector<std::string> names(allowed.begin(), allowed.end());
  for (auto* a = element_->FirstAttribute(); a; a = a->Next()) {
    if (std::find(names.begin(), names.end(), a->Name()) != names.end()) continue;
    const std::string allowed_text = names.empty() ? "none" : list(names);
    fail_at(a->Name(), "unknown attribute \"" + clip(a->Name(), 40) + "\"" +
                           suggestion(a->Name(), names, "\"", "\"") + "; allowed: " + allowed_text);
  }
}

void Element::expect_empty() const {
  for (auto* node = element_->FirstChild(); node; node = node->NextSibling()) {
    if (auto* child = node->ToElement())
      throw MeshingError(ErrorCode::InvalidInput, at(*file_, child->GetLineNum()) + "<" + tag() +
                                                      ">: takes no child elements, got <" +
                                                      clip(child->Name(), 40) + ">");
    if (auto* text = node->ToText(); text && !trim(text->Value()).empty())
      throw MeshingError(ErrorCode::InvalidInput, at(*file_, text->GetLineNum()) + "<" + tag() +
                                                      ">: takes no text, got \"" +
                                                      clip(trim(text->Value())) + "\"");
  }
}

std::vector<Element> Element::children() const {
  std::vector<Element> out;
  for (auto* node = element_->FirstChild(); node; node = node->NextSibling()) {
    if (auto* child = node->ToElement()) {
      out.emplace_back(child, *file_);
    } else if (auto* text = node->ToText(); text && !trim(text->Value()).empty()) {
      throw MeshingError(ErrorCode::InvalidInput, at(*file_, text->GetLineNum()) + "<" + tag() +
                                                      ">: unexpected text \"" +
                                                      clip(trim(text->Value())) + "\"");
    }
  }
  return out;
}

bool Element::has(const char* attribute) const { return element_->Attribute(attribute) != nullptr; }

std::optional<std::string> Element::text(const char* attribute) const {
  const char* value = element_->Attribute(attribute);
  if (!value) return std::nullopt;
  return std::string(value);
}

std::string Element::required(const char* attribute) const {
  const char* value = element_->Attribute(attribute);
  if (!value) fail("missing required attribute \"" + std::string(attribute) + "\"");
  if (trim(value).empty()) bad_value(attribute, "non-empty");
  return value;
}

std::string Element::shape_name(const char* attribute) const {
  const std::string value = required(attribute);
  if (!valid_name(value))
    bad_value(attribute,
              "a name of at most 64 characters (a letter or '_', then letters, "
              "digits, '_', '.', '-')");
  return value;
}

std::vector<std::string> Element::shape_names(const char* attribute) const {
  const auto words = split_blanks(required(attribute));
  const std::string expected = "two or more distinct shape names separated by blanks";
  if (words.size() < 2) bad_value(attribute, expected);
  std::set<std::string> seen;
  for (const auto& word : words)
    if (!valid_name(word) || !seen.insert(word).second) bad_value(attribute, expected);
  return words;
}

std::optional<double> Element::number(const char* attribute, NumberKind kind) const {
  const auto value_text = text(attribute);
  if (!value_text) return std::nullopt;
  const auto value = to_number(trim(*value_text));
  const bool ok = value && (kind == NumberKind::Any ||
                            (kind == NumberKind::Positive && *value >= kMinPositive) ||
                            (kind == NumberKind::NonNegative && *value >= 0));
  if (!ok) bad_value(attribute, kNumberWords[static_cast<int>(kind)]);
  return value;
}

double Element::required_number(const char* attribute, NumberKind kind) const {
  required(attribute);
  return *number(attribute, kind);
}

std::optional<int> Element::integer(const char* attribute, int min) const {
  const auto value_text = text(attribute);
  if (!value_text) return std::nullopt;
  const auto value = to_integer(trim(*value_text));
  if (!value || *value < min || *value > kMaxInteger)
    bad_value(attribute, min == 1   ? std::string("a positive integer up to 1e9")
                         : min == 0 ? std::string("a non-negative integer up to 1e9")
                                    : "an integer >= " + std::to_string(min) + " up to 1e9");
  return value;
}

int Element::required_integer(const char* attribute, int min) const {
  required(attribute);
  return *integer(attribute, min);
}

std::vector<int> Element::ids(const char* attribute) const {
  const auto words = split_blanks(required(attribute));
  const std::string expected = "one or more distinct positive ids separated by blanks";
  std::vector<int> out;
  for (const auto& word : words) {
    const auto value = to_integer(word);
    if (!value || *value < 1 || std::find(out.begin(), out.end(), *value) != out.end())
      bad_value(attribute, expected);
    out.push_back(*value);
  }
  if (out.empty()) bad_value(attribute, expected);
  return out;
}

std::optional<bool> Element::boolean(const char* attribute) const {
  const auto value = text(attribute);
  if (!value) return std::nullopt;
  if (*value == "true") return true;
  if (*value == "false") return false;
  bad_value(attribute, "\"true\" or \"false\"");
}

namespace {
std::optional<Vec3> to_vector(const std::string& s) {
  const auto words = split_blanks(s);
  if (words.size() != 3) return std::nullopt;
  Vec3 v;
  for (int i = 0; i < 3; ++i) {
    const auto x = to_number(words[i]);
    if (!x) return std::nullopt;
    v[i] = *x;
  }
  return v;
}
}  // namespace

std::optional<Vec3> Element::vector(const char* attribute, VectorKind kind) const {
  const auto value_text = text(attribute);
  if (!value_text) return std::nullopt;
  const auto v = to_vector(*value_text);
  switch (kind) {
    case VectorKind::Any:
      if (!v) bad_value(attribute, "three numbers \"x y z\"");
      break;
    case VectorKind::NonZero:
      if (!v || v->norm() == 0) bad_value(attribute, "a nonzero vector of three numbers \"x y z\"");
      break;
    case VectorKind::Positive:
      if (!v || v->minCoeff() < kMinPositive)
        bad_value(attribute, "three positive numbers between 1e-7 and 1e7");
      break;
  }
  return v;
}

Vec3 Element::required_vector(const char* attribute, VectorKind kind) const {
  required(attribute);
  return *vector(attribute, kind);
}

Polygon Element::points(const char* attribute, bool allow_single) const {
  const std::string value = required(attribute);
  const std::string expected = std::string(allow_single ? "one point \"x y z\" or " : "") +
                               "three or more points \"x y z, x y z, x y z, ...\"";
  Polygon out;
  size_t begin = 0;
  while (true) {
    const size_t comma = value.find(',', begin);
    const auto point = to_vector(
        value.substr(begin, comma == std::string::npos ? std::string::npos : comma - begin));
    if (!point) bad_value(attribute, expected);
    out.push_back(*point);
    if (comma == std::string::npos) break;
    begin = comma + 1;
  }
  if (out.size() < 3 && !(allow_single && out.size() == 1)) bad_value(attribute, expected);
  return out;
}

std::optional<int> Element::choice(const char* attribute,
                                   std::initializer_list<const char*> options) const {
  const auto value = text(attribute);
  if (!value) return std::nullopt;
  int index = 0;
  for (const char* option : options) {
    if (*value == option) return index;
    ++index;
  }
  std::string expected = "one of ";
  const std::vector<std::string> names(options.begin(), options.end());
  expected += list(names, "\"", "\"");
  bad_value(attribute, expected);
}

}  // namespace cooperage::io::detail
