// Gmsh .msh reader (format_readers.h): 4.1 ASCII and binary, 2.2 ASCII.
// cite: Gmsh reference manual, sec. 10.1 "MSH file format" (4.1) and
// sec. 10.4 "Legacy formats" (2.2); node order of types 2, 3, 5, 6 equals
// Exodus II's (the Gmsh prism's first triangle is wound like the Exodus wedge's).
// Binary 4.1 keeps the section names and $PhysicalNames as text; the bodies
// of $Entities, $Nodes and $Elements are the same records as raw
// little-endian int (4 bytes), size_t (the header's data size, 8) and double.
#include "framework/io/read/format_readers.h"
#include "framework/io/read/read_common.h"

#include "framework/core/error.h"
#include "framework/core/text.h"

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

namespace cooperage::io::detail {
namespace {

using quality::ElementType;

/// Whitespace-separated tokens of a text with the line of each.
class Cursor {
 public:
  Cursor(const std::string& path, const std::string& text) : path_(path), s_(text) {}

  int line() const { return line_; }
  bool at_end() {
    skip_space();
    return pos_ >= s_.size();
  }
  [[noreturn]] void fail(const std::string& reason) const {
    parse_error(path_, "line " + std::to_string(line_) + ": " + reason);
  }

  /// The next token; a parse error at the end of the file.
  std::string_view token(const char* what) {
    skip_space();
    if (pos_ >= s_.size()) fail(std::string("unexpected end of file, expected ") + what);
    const std::size_t start = pos_;
    while (pos_ < s_.size() && !is_space(s_[pos_])) ++pos_;
    return std::string_view(s_).substr(start, pos_ - start);
  }
  int64_t integer(const char* what) {
    const std::string t(token(what));
    char* end = nullptr;
    const long long v = std::strtoll(t.c_str(), &end, 10);
    if (t.empty() || *end != '\0')
      fail(std::string("expected ") + what + ", got \"" + clip(t) + "\"");
    return v;
  }
  double real(const char* what) {
    const std::string t(token(what));
    char* end = nullptr;
    const double v = std::strtod(t.c_str(), &end);
    if (t.empty() || *end != '\0')
      fail(std::string("expected ") + what + ", got \"" + clip(t) + "\"");
    return v;
  }
  /// Counts in a header must be >= 0 and fit in the rest of the file (every
  /// item takes at least two characters), checked before anything is
  /// allocated for them.
  std::size_t count(const char* what) {
    const int64_t v = integer(what);
    if (v < 0 || static_cast<uint64_t>(v) > (s_.size() - pos_) / 2)
      fail(std::string("bad ") + what + " " + std::to_string(v) + " (more than the file holds)");
    return static_cast<std::size_t>(v);
  }
  /// The tokens of the next non-empty line.
  std::vector<std::string_view> line_tokens(const char* what) {
    skip_space();
    if (pos_ >= s_.size()) fail(std::string("unexpected end of file, expected ") + what);
    std::vector<std::string_view> out;
    while (pos_ < s_.size() && s_[pos_] != '\n') {
      while (pos_ < s_.size() && s_[pos_] != '\n' && is_space(s_[pos_])) ++pos_;
      const std::size_t start = pos_;
      while (pos_ < s_.size() && !is_space(s_[pos_])) ++pos_;
      if (pos_ > start) out.push_back(std::string_view(s_).substr(start, pos_ - start));
    }
    return out;
  }
  /// The rest of the current line, trimmed.
  std::string rest_of_line() {
    std::size_t end = s_.find('\n', pos_);
    if (end == std::string::npos) end = s_.size();
    std::string r = s_.substr(pos_, end - pos_);
    pos_ = end;
    const auto b = r.find_first_not_of(" \t\r");
    const auto e = r.find_last_not_of(" \t\r");
    return b == std::string::npos ? std::string() : r.substr(b, e - b + 1);
  }
  /// Skips to the line "$End<section>".
  void skip_section(const std::string& section) {
    const std::string end = "$End" + section;
    while (!at_end()) {
      if (token("section end") == end) return;
    }
    fail("missing " + end);
  }
  /// Binary bodies: the raw value of T at the cursor (the file's byte order
  /// was checked to be ours).
  template <class T>
  T raw(const char* what) {
    if (s_.size() - pos_ < sizeof(T)) fail(std::string("unexpected end of file, expected ") + what);
    T v;
    std::memcpy(&v, s_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return v;
  }
  /// A binary count of items of at least `item_bytes` each, checked
  /// against the rest of the file before anything is allocated for it.
  std::size_t raw_count(const char* what, std::size_t item_bytes) {
    const auto v = raw<uint64_t>(what);
    if (v > (s_.size() - pos_) / item_bytes)
      fail(std::string("bad ") + what + " " + std::to_string(v) + " (more than the file holds)");
    return static_cast<std::size_t>(v);
  }
  /// Past the end of the current line (where a binary body starts).
  void next_line() {
    while (pos_ < s_.size() && s_[pos_] != '\n') ++pos_;
    if (pos_ < s_.size()) {
      ++pos_;
      ++line_;
    }
  }

  void expect(const std::string& word) {
    const std::string_view t = token(word.c_str());
    if (t != word) fail("expected " + word + ", got \"" + clip(t) + "\"");
  }

 private:
  static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }
  void skip_space() {
    while (pos_ < s_.size() && is_space(s_[pos_])) {
      if (s_[pos_] == '\n') ++line_;
      ++pos_;
    }
  }

  const std::string& path_;
  const std::string& s_;
  std::size_t pos_ = 0;
  int line_ = 1;
};

int64_t to_int(Cursor& c, std::string_view t) {
  const std::string s(t);
  char* end = nullptr;
  const long long v = std::strtoll(s.c_str(), &end, 10);
  if (s.empty() || *end != '\0') c.fail("expected an integer, got \"" + clip(s) + "\"");
  return v;
}

std::optional<ElementType> gmsh_type(int64_t t) {
  switch (t) {
    case 2: return ElementType::Tri;
    case 3: return ElementType::Quad;
    case 5: return ElementType::Hex;
    case 6: return ElementType::Wedge;
    default: return std::nullopt;
  }
}

std::string skipped_name(int64_t t) {
  switch (t) {
    case 1: return "line";
    case 4: return "tetra";
    case 7: return "pyramid";
    case 15: return "vertex";
    default: return "gmsh type " + std::to_string(t);
  }
}

int element_dim(ElementType t) { return t == ElementType::Hex || t == ElementType::Wedge ? 3 : 2; }

struct MshState {
  MeshFile out;
  std::unordered_map<int64_t, int> node_index;           // node tag -> 0-based index
  std::map<std::pair<int, int64_t>, std::string> names;  // (dim, physical tag) -> name
  std::map<std::pair<int, int64_t>, int64_t> physical;   // (dim, entity) -> first physical tag
  BlockCollector blocks;
  bool have_nodes = false;
};

void read_physical_names(Cursor& c, MshState& st) {
  const std::size_t n = c.count("number of physical names");
  for (std::size_t i = 0; i < n; ++i) {
    const int dim = static_cast<int>(c.integer("physical dimension"));
    const int64_t tag = c.integer("physical tag");
    std::string name = c.rest_of_line();
    if (name.size() >= 2 && name.front() == '"' && name.back() == '"') {
      name = name.substr(1, name.size() - 2);
    }
    st.names[{dim, tag}] = name;
  }
  c.expect("$EndPhysicalNames");
}

void read_entities_41(Cursor& c, MshState& st) {
  std::size_t counts[4];
  for (auto& n : counts) n = c.count("number of entities");
  for (int dim = 0; dim < 4; ++dim) {
    for (std::size_t i = 0; i < counts[dim]; ++i) {
      const int64_t tag = c.integer("entity tag");
      for (int k = 0; k < (dim == 0 ? 3 : 6); ++k) c.real("bounding box coordinate");
      const std::size_t n_phys = c.count("number of physical tags");
      for (std::size_t k = 0; k < n_phys; ++k) {
        const int64_t p = c.integer("physical tag");
        if (k == 0) st.physical[{dim, tag}] = p;
      }
      if (dim > 0) {
        const std::size_t n_bound = c.count("number of bounding entities");
        for (std::size_t k = 0; k < n_bound; ++k) c.integer("bounding entity tag");
      }
    }
  }
  c.expect("$EndEntities");
}

void add_node(Cursor& c, MshState& st, int64_t tag, const Eigen::Vector3d& x) {
  if (!st.node_index.emplace(tag, static_cast<int>(st.out.coords.size())).second) {
    c.fail("node " + std::to_string(tag) + " is defined twice");
  }
  st.out.coords.push_back(x);
}

void read_nodes_41(Cursor& c, MshState& st) {
  const std::size_t blocks = c.count("number of node blocks");
  c.count("number of nodes");
  c.integer("minimum node tag");
  c.integer("maximum node tag");
  for (std::size_t b = 0; b < blocks; ++b) {
    c.integer("entity dimension");
    c.integer("entity tag");
    const bool parametric = c.integer("parametric flag") != 0;
    const std::size_t n = c.count("number of nodes in block");
    std::vector<int64_t> tags(n);
    for (auto& t : tags) t = c.integer("node tag");
    for (int64_t t : tags) {
      Eigen::Vector3d x;
      for (int k = 0; k < 3; ++k) x[k] = c.real("node coordinate");
      if (parametric) c.rest_of_line();  // u, v, w on the same line
      add_node(c, st, t, x);
    }
  }
  c.expect("$EndNodes");
  st.have_nodes = true;
}

void read_nodes_22(Cursor& c, MshState& st) {
  const std::size_t n = c.count("number of nodes");
  for (std::size_t i = 0; i < n; ++i) {
    const int64_t tag = c.integer("node tag");
    Eigen::Vector3d x;
    for (int k = 0; k < 3; ++k) x[k] = c.real("node coordinate");
    add_node(c, st, tag, x);
  }
  c.expect("$EndNodes");
  st.have_nodes = true;
}

/// Appends one element given its node-tag tokens.
void add_element(Cursor& c, MshState& st, ElementType type, const std::string& key,
                 const std::string& name, const std::vector<std::string_view>& tokens,
                 std::size_t first) {
  const int n = quality::node_count(type);
  if (tokens.size() != first + static_cast<std::size_t>(n)) {
    c.fail("element has " + std::to_string(tokens.size() - std::min(first, tokens.size())) +
           " nodes, expected " + std::to_string(n));
  }
  int nodes[8];
  for (int k = 0; k < n; ++k) {
    const int64_t tag = to_int(c, tokens[first + static_cast<std::size_t>(k)]);
    const auto it = st.node_index.find(tag);
    if (it == st.node_index.end()) c.fail("element uses undefined node " + std::to_string(tag));
    nodes[k] = it->second;
  }
  st.blocks.add(key, name, type, nodes);
}

std::string block_name(const MshState& st, int dim, int64_t entity, std::optional<int64_t> phys) {
  if (phys) {
    const auto it = st.names.find({dim, *phys});
    if (it != st.names.end()) return it->second;
  }
  return std::to_string(dim) + ":" + std::to_string(entity);
}

void read_elements_41(Cursor& c, MshState& st) {
  if (!st.have_nodes) c.fail("$Elements before $Nodes");
  const std::size_t blocks = c.count("number of element blocks");
  c.count("number of elements");
  c.integer("minimum element tag");
  c.integer("maximum element tag");
  for (std::size_t b = 0; b < blocks; ++b) {
    const int dim = static_cast<int>(c.integer("entity dimension"));
    const int64_t entity = c.integer("entity tag");
    const int64_t gtype = c.integer("element type");
    const std::size_t n = c.count("number of elements in block");
    const auto type = gmsh_type(gtype);
    std::string key, name;
    if (type) {
      key = std::to_string(dim) + ":" + std::to_string(entity);
      const auto it = st.physical.find({dim, entity});
      name =
          block_name(st, dim, entity,
                     it == st.physical.end() ? std::nullopt : std::optional<int64_t>(it->second));
    }
    for (std::size_t e = 0; e < n; ++e) {
      const auto tokens = c.line_tokens("element");
      if (type) add_element(c, st, *type, key, name, tokens, 1);
    }
    if (!type && n > 0) st.out.skipped[skipped_name(gtype)] += n;
  }
  c.expect("$EndElements");
}

void read_elements_22(Cursor& c, MshState& st) {
  if (!st.have_nodes) c.fail("$Elements before $Nodes");
  const std::size_t n = c.count("number of elements");
  for (std::size_t e = 0; e < n; ++e) {
    const auto tokens = c.line_tokens("element");
    if (tokens.size() < 3) c.fail("element line is too short");
    const int64_t gtype = to_int(c, tokens[1]);
    const auto n_tags = static_cast<std::size_t>(to_int(c, tokens[2]));
    if (tokens.size() < 3 + n_tags) c.fail("element line is too short");
    const auto type = gmsh_type(gtype);
    if (!type) {
      ++st.out.skipped[skipped_name(gtype)];
      continue;
    }
    const int dim = element_dim(*type);
    const int64_t phys = n_tags > 0 ? to_int(c, tokens[3]) : 0;
    const int64_t entity = n_tags > 1 ? to_int(c, tokens[4]) : phys;
    const std::string key = std::to_string(dim) + ":" + std::to_string(entity);
    const std::string name =
        block_name(st, dim, entity, phys != 0 ? std::optional<int64_t>(phys) : std::nullopt);
    add_element(c, st, *type, key, name, tokens, 3 + n_tags);
  }
  c.expect("$EndElements");
}

// ---- binary 4.1 --------------------------------------------------------

/// Nodes of the Gmsh element types we skip (binary records have no line end
/// to skip to): 0 for a type not listed.
int skipped_node_count(int64_t t) {
  switch (t) {
    case 15: return 1;   // point
    case 1: return 2;    // line
    case 8: return 3;    // line3
    case 4: return 4;    // tetra
    case 7: return 5;    // pyramid
    case 9: return 6;    // triangle6
    case 16: return 8;   // quad8
    case 10: return 9;   // quad9
    case 11: return 10;  // tetra10
    default: return 0;
  }
}

void read_entities_41_binary(Cursor& c, MshState& st) {
  std::size_t counts[4];
  for (auto& n : counts) n = c.raw_count("number of entities", 4);
  for (int dim = 0; dim < 4; ++dim) {
    for (std::size_t i = 0; i < counts[dim]; ++i) {
      const int64_t tag = c.raw<int32_t>("entity tag");
      for (int k = 0; k < (dim == 0 ? 3 : 6); ++k) c.raw<double>("bounding box coordinate");
      const std::size_t n_phys = c.raw_count("number of physical tags", 4);
      for (std::size_t k = 0; k < n_phys; ++k) {
        const int64_t p = c.raw<int32_t>("physical tag");
        if (k == 0) st.physical[{dim, tag}] = p;
      }
      if (dim > 0) {
        const std::size_t n_bound = c.raw_count("number of bounding entities", 4);
        for (std::size_t k = 0; k < n_bound; ++k) c.raw<int32_t>("bounding entity tag");
      }
    }
  }
  c.expect("$EndEntities");
}

void read_nodes_41_binary(Cursor& c, MshState& st) {
  const std::size_t blocks = c.raw_count("number of node blocks", 20);
  c.raw<uint64_t>("number of nodes");
  c.raw<uint64_t>("minimum node tag");
  c.raw<uint64_t>("maximum node tag");
  for (std::size_t b = 0; b < blocks; ++b) {
    c.raw<int32_t>("entity dimension");
    c.raw<int32_t>("entity tag");
    const bool parametric = c.raw<int32_t>("parametric flag") != 0;
    if (parametric) c.fail("parametric node coordinates in a binary .msh are not supported");
    const std::size_t n = c.raw_count("number of nodes in block", 32);
    std::vector<int64_t> tags(n);
    for (auto& t : tags) t = static_cast<int64_t>(c.raw<uint64_t>("node tag"));
    for (int64_t t : tags) {
      Eigen::Vector3d x;
      for (int k = 0; k < 3; ++k) x[k] = c.raw<double>("node coordinate");
      add_node(c, st, t, x);
    }
  }
  c.expect("$EndNodes");
  st.have_nodes = true;
}

void read_elements_41_binary(Cursor& c, MshState& st) {
  if (!st.have_nodes) c.fail("$Elements before $Nodes");
  const std::size_t blocks = c.raw_count("number of element blocks", 20);
  c.raw<uint64_t>("number of elements");
  c.raw<uint64_t>("minimum element tag");
  c.raw<uint64_t>("maximum element tag");
  for (std::size_t b = 0; b < blocks; ++b) {
    const int dim = c.raw<int32_t>("entity dimension");
    const int64_t entity = c.raw<int32_t>("entity tag");
    const int64_t gtype = c.raw<int32_t>("element type");
    const auto type = gmsh_type(gtype);
    const int other = skipped_node_count(gtype);
    if (!type && other == 0)
      c.fail("element type " + std::to_string(gtype) +
             " in a binary .msh (its node count is unknown here)");
    const auto per = static_cast<std::size_t>(type ? quality::node_count(*type) : other);
    const std::size_t n = c.raw_count("number of elements in block", 8 * (1 + per));
    if (!type) {  // skipped, as in ASCII files
      for (std::size_t k = 0; k < n * (1 + per); ++k) c.raw<uint64_t>("element data");
      if (n > 0) st.out.skipped[skipped_name(gtype)] += n;
      continue;
    }
    const std::string key = std::to_string(dim) + ":" + std::to_string(entity);
    const auto it = st.physical.find({dim, entity});
    const std::string name =
        block_name(st, dim, entity,
                   it == st.physical.end() ? std::nullopt : std::optional<int64_t>(it->second));
    for (std::size_t e = 0; e < n; ++e) {
      c.raw<uint64_t>("element tag");
      int nodes[8];
      for (std::size_t k = 0; k < per; ++k) {
        const auto tag = static_cast<int64_t>(c.raw<uint64_t>("node tag"));
        const auto found = st.node_index.find(tag);
        if (found == st.node_index.end())
          c.fail("element uses undefined node " + std::to_string(tag));
        nodes[k] = found->second;
      }
      st.blocks.add(key, name, *type, nodes);
    }
  }
  c.expect("$EndElements");
}

}  // namespace

MeshFile read_msh(const std::string& path) {
  const std::string text = read_text(path);
  Cursor c(path, text);
  MshState st;
  bool legacy = false;
  bool binary = false;
  bool have_format = false;
  while (!c.at_end()) {
    const std::string section(c.token("a section"));
    if (section.empty() || section[0] != '$')
      c.fail("expected a section, got \"" + clip(section) + "\"");
    const std::string name = section.substr(1);
    if (name == "MeshFormat") {
      const std::string version(c.token("the format version"));
      const int64_t file_type = c.integer("the file type");
      const int64_t data_size = c.integer("the data size");
      binary = file_type != 0;
      if (binary) {
        if (version != "4.1") {
          throw MeshingError(ErrorCode::NotSupported, path + ": binary .msh " + clip(version, 16) +
                                                          " is not supported (use 4.1)");
        }
        if (data_size != 8)
          c.fail("binary data size " + std::to_string(data_size) + " (8 expected)");
        c.next_line();
        if (c.raw<int32_t>("the byte order mark") != 1) {
          throw MeshingError(ErrorCode::NotSupported,
                             path + ": a binary .msh of the other byte order is not supported");
        }
      }
      if (version == "4.1")
        legacy = false;
      else if (version.rfind("2.", 0) == 0)
        legacy = true;
      else {
        throw MeshingError(ErrorCode::NotSupported, path + ": .msh version " + clip(version, 16) +
                                                        " is not supported (use 4.1 or 2.2 ASCII)");
      }
      c.expect("$EndMeshFormat");
      have_format = true;
      continue;
    }
    if (!have_format) c.fail("the file does not start with $MeshFormat");
    if (name == "PhysicalNames")
      read_physical_names(c, st);
    else if (binary && (name == "Entities" || name == "Nodes" || name == "Elements")) {
      c.next_line();
      if (name == "Entities")
        read_entities_41_binary(c, st);
      else if (name == "Nodes")
        read_nodes_41_binary(c, st);
      else
        read_elements_41_binary(c, st);
    } else if (name == "Entities" && !legacy)
      read_entities_41(c, st);
    else if (name == "Nodes")
      legacy ? read_nodes_22(c, st) : read_nodes_41(c, st);
    else if (name == "Elements")
      legacy ? read_elements_22(c, st) : read_elements_41(c, st);
    else
      c.skip_section(name);
  }
  if (!have_format) parse_error(path, "no $MeshFormat section (not a Gmsh .msh file)");
  st.out.blocks = st.blocks.take();
  return std::move(st.out);
}

}  // namespace cooperage::io::detail
