// VTK XML UnstructuredGrid (.vtu) reader (format_readers.h).
// cite: "VTK File Formats", VTK User's Guide sec. 19.3 (XML formats): inline
// DataArrays are "ascii" text or "binary" base64 of a UInt32/UInt64 byte
// count (header_type) followed by the raw little/big-endian values;
// "appended" ones point (offset) into the raw <AppendedData> block after the
// XML, each as the same byte count followed by the values.
#include "framework/io/read/format_readers.h"
#include "framework/io/read/read_common.h"

#include "framework/core/error.h"
#include "framework/core/text.h"

#include <tinyxml2.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace cooperage::io::detail {
namespace {

using quality::ElementType;

[[noreturn]] void not_supported(const std::string& path, const std::string& what) {
  throw MeshingError(ErrorCode::NotSupported, path + ": " + what + " is not supported");
}

/// Size in bytes of a VTK scalar type name, 0 for an unknown one.
std::size_t type_size(const std::string& t) {
  static const std::map<std::string, std::size_t> sizes{
      {"Int8", 1},   {"UInt8", 1}, {"Int16", 2},  {"UInt16", 2},  {"Int32", 4},
      {"UInt32", 4}, {"Int64", 8}, {"UInt64", 8}, {"Float32", 4}, {"Float64", 8}};
  const auto it = sizes.find(t);
  return it == sizes.end() ? 0 : it->second;
}

/// Base64 decoding, group by group so that concatenated padded segments
/// (header and data encoded separately) decode too. False on a bad character.
bool base64_decode(const char* text, std::vector<unsigned char>& out) {
  auto value = [](char ch) -> int {
    if (ch >= 'A' && ch <= 'Z') return ch - 'A';
    if (ch >= 'a' && ch <= 'z') return ch - 'a' + 26;
    if (ch >= '0' && ch <= '9') return ch - '0' + 52;
    if (ch == '+') return 62;
    if (ch == '/') return 63;
    if (ch == '=') return -2;
    return -1;
  };
  int group[4];
  int n = 0;
  for (const char* p = text; *p; ++p) {
    if (std::isspace(static_cast<unsigned char>(*p))) continue;
    const int v = value(*p);
    if (v == -1) return false;
    group[n++] = v;
    if (n < 4) continue;
    n = 0;
    if (group[0] < 0 || group[1] < 0) return false;
    out.push_back(static_cast<unsigned char>((group[0] << 2) | (group[1] >> 4)));
    if (group[2] < 0) continue;
    out.push_back(static_cast<unsigned char>(((group[1] & 15) << 4) | (group[2] >> 2)));
    if (group[3] < 0) continue;
    out.push_back(static_cast<unsigned char>(((group[2] & 3) << 6) | group[3]));
  }
  return n == 0;
}

class VtuParser {
 public:
  /// `appended`: the raw bytes after the '_' of <AppendedData
  /// encoding="raw"> (empty when the file has none).
  VtuParser(const std::string& path, bool big_endian, std::size_t header_size,
            std::string_view appended)
      : path_(path), big_endian_(big_endian), header_size_(header_size), appended_(appended) {}

  /// The values of an inline DataArray as doubles (exact for the integer
  /// types up to 2^53, far beyond any index we can store in an int).
  std::vector<double> values(const tinyxml2::XMLElement* a) const {
    const std::string name = a->Attribute("Name") ? a->Attribute("Name") : "(unnamed)";
    const std::string where =
        "DataArray \"" + clip(name, 40) + "\" (line " + std::to_string(a->GetLineNum()) + ")";
    const char* fmt_attr = a->Attribute("format");
    const std::string format = fmt_attr ? fmt_attr : "ascii";
    const char* type_attr = a->Attribute("type");
    const std::string type = type_attr ? type_attr : "";
    const std::size_t size = type_size(type);
    if (size == 0) parse_error(path_, where + ": unknown type \"" + clip(type, 40) + "\"");
    const char* text = a->GetText();
    std::vector<double> out;
    if (format == "appended") return appended_values(a, where, type, size);
    if (format == "ascii") {
      if (!text) return out;
      std::istringstream in(text);
      std::string tok;
      while (in >> tok) {
        char* end = nullptr;
        const double v = std::strtod(tok.c_str(), &end);
        if (*end != '\0') parse_error(path_, where + ": bad number \"" + clip(tok, 40) + "\"");
        out.push_back(v);
      }
      return out;
    }
    if (format != "binary")
      parse_error(path_, where + ": unknown format \"" + clip(format, 40) + "\"");
    std::vector<unsigned char> bytes;
    if (text && !base64_decode(text, bytes)) parse_error(path_, where + ": bad base64 data");
    if (bytes.size() < header_size_) parse_error(path_, where + ": binary data without a header");
    const uint64_t length = read_uint(bytes.data(), header_size_);
    if (length > bytes.size() - header_size_ || length % size != 0) {
      parse_error(path_, where + ": binary header says " + std::to_string(length) +
                             " bytes, the data has " + std::to_string(bytes.size() - header_size_));
    }
    const unsigned char* p = bytes.data() + header_size_;
    const std::size_t n = static_cast<std::size_t>(length) / size;
    out.reserve(n);
    for (std::size_t i = 0; i < n; ++i, p += size) out.push_back(decode(p, type, size));
    return out;
  }

 private:
  std::vector<double> appended_values(const tinyxml2::XMLElement* a, const std::string& where,
                                      const std::string& type, std::size_t size) const {
    const int64_t offset = a->Int64Attribute("offset", -1);
    if (offset < 0) parse_error(path_, where + ": appended data without an offset");
    const auto at = static_cast<uint64_t>(offset);
    if (at > appended_.size() || appended_.size() - at < header_size_) {
      parse_error(path_, where + ": offset " + std::to_string(offset) + " is past the " +
                             std::to_string(appended_.size()) + " bytes of appended data");
    }
    const auto* p = reinterpret_cast<const unsigned char*>(appended_.data()) + at;
    const uint64_t length = read_uint(p, header_size_);
    const uint64_t left = appended_.size() - at - header_size_;
    if (length > left || length % size != 0) {
      parse_error(path_, where + ": its byte count " + std::to_string(length) +
                             " does not fit the " + std::to_string(left) + " bytes after it");
    }
    p += header_size_;
    const std::size_t n = static_cast<std::size_t>(length) / size;
    std::vector<double> out;
    out.reserve(n);
    for (std::size_t i = 0; i < n; ++i, p += size) out.push_back(decode(p, type, size));
    return out;
  }

  uint64_t read_uint(const unsigned char* p, std::size_t size) const {
    uint64_t v = 0;
    for (std::size_t k = 0; k < size; ++k) {
      const std::size_t byte = big_endian_ ? k : size - 1 - k;
      v = (v << 8) | p[byte];
    }
    return v;
  }
  double decode(const unsigned char* p, const std::string& type, std::size_t size) const {
    const uint64_t bits = read_uint(p, size);
    if (type == "Float64") {
      double d;
      std::memcpy(&d, &bits, 8);
      return d;
    }
    if (type == "Float32") {
      const auto b32 = static_cast<uint32_t>(bits);
      float f;
      std::memcpy(&f, &b32, 4);
      return f;
    }
    if (type[0] == 'U') return static_cast<double>(bits);
    // Signed: sign-extend from `size` bytes.
    const unsigned shift = static_cast<unsigned>(64 - 8 * size);
    return static_cast<double>(static_cast<int64_t>(bits << shift) >> shift);
  }

  std::string path_;
  bool big_endian_;
  std::size_t header_size_;
  std::string_view appended_;
};

/// Splits a .vtu file into its XML (closed after the cut) and the raw bytes
/// of <AppendedData encoding="raw">, which are not XML text.
struct SplitVtu {
  std::string xml;
  std::string_view appended;
};

SplitVtu split_appended(const std::string& path, const std::string& text) {
  const std::size_t tag = text.find("<AppendedData");
  if (tag == std::string::npos) return {text, {}};
  const std::size_t tag_end = text.find('>', tag);
  if (tag_end == std::string::npos) parse_error(path, "<AppendedData> is not closed");
  const std::string attributes = text.substr(tag, tag_end - tag);
  if (attributes.find("encoding=\"raw\"") == std::string::npos) {
    not_supported(path, "appended data that is not raw (" + attributes.substr(0, 60) + ">)");
  }
  const std::size_t underscore = text.find('_', tag_end);
  if (underscore == std::string::npos) parse_error(path, "<AppendedData> without its '_' marker");
  // The closing tags after the data are not needed: the XML ends here.
  return {text.substr(0, tag) + "</VTKFile>\n", std::string_view(text).substr(underscore + 1)};
}

const tinyxml2::XMLElement* array_named(const tinyxml2::XMLElement* parent, const char* name) {
  if (!parent) return nullptr;
  for (auto* a = parent->FirstChildElement("DataArray"); a;
       a = a->NextSiblingElement("DataArray")) {
    const char* n = a->Attribute("Name");
    if (n && std::strcmp(n, name) == 0) return a;
  }
  return nullptr;
}

std::optional<ElementType> vtk_type(int t) {
  switch (t) {
    case 5: return ElementType::Tri;
    case 9: return ElementType::Quad;
    case 12: return ElementType::Hex;
    case 13: return ElementType::Wedge;
    default: return std::nullopt;
  }
}

std::string skipped_name(int t) {
  switch (t) {
    case 1: return "vertex";
    case 3: return "line";
    case 10: return "tetra";
    case 14: return "pyramid";
    default: return "vtk type " + std::to_string(t);
  }
}

int as_index(const std::string& path, double v, const char* what) {
  if (!(v >= 0 && v <= 2147483647.0) || v != static_cast<double>(static_cast<int64_t>(v))) {
    parse_error(path, std::string("bad ") + what + " value " + std::to_string(v));
  }
  return static_cast<int>(v);
}

void read_piece(const std::string& path, const VtuParser& parser, const tinyxml2::XMLElement* piece,
                MeshFile& out, BlockCollector& blocks) {
  const std::string where = "Piece (line " + std::to_string(piece->GetLineNum()) + ")";
  const auto base = static_cast<int>(out.coords.size());
  const auto* points_el = piece->FirstChildElement("Points");
  const auto* points = points_el ? points_el->FirstChildElement("DataArray") : nullptr;
  if (!points) parse_error(path, where + ": no Points DataArray");
  const int comps = points->IntAttribute("NumberOfComponents", 1);
  if (comps < 1 || comps > 3)
    parse_error(path, where + ": Points with " + std::to_string(comps) + " components");
  const std::vector<double> xyz = parser.values(points);
  if (xyz.size() % static_cast<std::size_t>(comps) != 0)
    parse_error(path, where + ": Points count is not a multiple of the components");
  const std::size_t n_points = xyz.size() / static_cast<std::size_t>(comps);
  const int64_t declared = piece->Int64Attribute("NumberOfPoints", static_cast<int64_t>(n_points));
  if (declared != static_cast<int64_t>(n_points)) {
    parse_error(path, where + ": NumberOfPoints is " + std::to_string(declared) + ", Points has " +
                          std::to_string(n_points));
  }
  for (std::size_t i = 0; i < n_points; ++i) {
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    for (int k = 0; k < comps; ++k)
      x[k] = xyz[i * static_cast<std::size_t>(comps) + static_cast<std::size_t>(k)];
    out.coords.push_back(x);
  }

  const auto* cells = piece->FirstChildElement("Cells");
  const auto* conn_el = array_named(cells, "connectivity");
  const auto* offs_el = array_named(cells, "offsets");
  const auto* types_el = array_named(cells, "types");
  const int64_t n_declared = piece->Int64Attribute("NumberOfCells", 0);
  if (!conn_el || !offs_el || !types_el) {
    if (n_declared == 0) return;
    parse_error(path, where + ": Cells needs connectivity, offsets and types DataArrays");
  }
  const std::vector<double> conn = parser.values(conn_el);
  const std::vector<double> offsets = parser.values(offs_el);
  const std::vector<double> types = parser.values(types_el);
  if (offsets.size() != types.size() || static_cast<int64_t>(types.size()) != n_declared) {
    parse_error(path, where + ": NumberOfCells " + std::to_string(n_declared) + ", " +
                          std::to_string(offsets.size()) + " offsets, " +
                          std::to_string(types.size()) + " types");
  }
  std::vector<double> block_id;
  if (const auto* b = array_named(piece->FirstChildElement("CellData"), "block_id")) {
    block_id = parser.values(b);
    if (block_id.size() != types.size())
      parse_error(path, where + ": block_id has the wrong length");
  }
  std::size_t begin = 0;
  for (std::size_t c = 0; c < types.size(); ++c) {
    const auto end = static_cast<std::size_t>(as_index(path, offsets[c], "offsets"));
    if (end < begin || end > conn.size())
      parse_error(path, where + ": offsets out of range at cell " + std::to_string(c));
    const int vtype = as_index(path, types[c], "types");
    const auto type = vtk_type(vtype);
    if (!type) {
      ++out.skipped[skipped_name(vtype)];
      begin = end;
      continue;
    }
    const int n = quality::node_count(*type);
    if (end - begin != static_cast<std::size_t>(n)) {
      parse_error(path, where + ": cell " + std::to_string(c) + " of VTK type " +
                            std::to_string(vtype) + " has " + std::to_string(end - begin) +
                            " nodes");
    }
    int nodes[8];
    for (int k = 0; k < n; ++k) {
      const int v = as_index(path, conn[begin + static_cast<std::size_t>(k)], "connectivity");
      if (static_cast<std::size_t>(v) >= n_points)
        parse_error(path, where + ": cell " + std::to_string(c) + " uses point " +
                              std::to_string(v) + " of " + std::to_string(n_points));
      nodes[k] = base + v;
    }
    if (*type == ElementType::Wedge) {
      int vtk[6];
      std::copy(nodes, nodes + 6, vtk);
      for (int k = 0; k < 6; ++k) nodes[k] = vtk[kVtkWedgeToExodus[k]];
    }
    std::string key, name;
    if (!block_id.empty()) {
      key = std::to_string(static_cast<int64_t>(block_id[c]));
      name = "block " + key;
    } else {
      name = key = std::string(quality::to_string(*type));
    }
    blocks.add(key, name, *type, nodes);
    begin = end;
  }
}

}  // namespace

MeshFile read_vtu(const std::string& path) {
  const std::string text = read_text(path);
  const SplitVtu split = split_appended(path, text);
  tinyxml2::XMLDocument doc;
  if (doc.Parse(split.xml.data(), split.xml.size()) != tinyxml2::XML_SUCCESS) {
    // tinyxml2's ErrorStr() quotes the offending text whole (a damaged
    // declaration ran past 1,000 characters under libFuzzer): clipped.
    parse_error(path, std::string("XML error: ") +
                          clip(doc.ErrorStr() ? doc.ErrorStr() : "unknown") + " (line " +
                          std::to_string(doc.ErrorLineNum()) + ")");
  }
  const auto* root = doc.RootElement();
  if (!root || std::strcmp(root->Name(), "VTKFile") != 0) parse_error(path, "no VTKFile element");
  const char* type = root->Attribute("type");
  if (!type || std::strcmp(type, "UnstructuredGrid") != 0) {
    parse_error(path, std::string("VTKFile type is \"") + clip(type ? type : "", 40) +
                          "\", expected \"UnstructuredGrid\"");
  }
  if (root->Attribute("compressor")) {
    not_supported(path, std::string("compressed data (compressor=\"") +
                            clip(root->Attribute("compressor"), 40) + "\")");
  }
  const char* order = root->Attribute("byte_order");
  const bool big = order && std::strcmp(order, "BigEndian") == 0;
  const char* header = root->Attribute("header_type");
  const std::string header_type = header ? header : "UInt32";
  if (header_type != "UInt32" && header_type != "UInt64") {
    parse_error(path, "header_type \"" + clip(header_type, 40) + "\" is not UInt32 or UInt64");
  }
  const VtuParser parser(path, big, type_size(header_type), split.appended);
  const auto* grid = root->FirstChildElement("UnstructuredGrid");
  if (!grid) parse_error(path, "no UnstructuredGrid element");
  MeshFile out;
  BlockCollector blocks;
  for (auto* piece = grid->FirstChildElement("Piece"); piece;
       piece = piece->NextSiblingElement("Piece")) {
    read_piece(path, parser, piece, out, blocks);
  }
  out.blocks = blocks.take();
  return out;
}

}  // namespace cooperage::io::detail
