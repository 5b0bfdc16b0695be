// The <mesh> section of a journal: global size and per-entity settings.
#include "framework/io/journal_xml.h"

#include "framework/core/text.h"
#include "framework/io/element_size.h"

#include <algorithm>
#include <cctype>
#include <optional>
#include <map>
#include <string>
#include <utility>

namespace cooperage::io::detail {

namespace {

const std::vector<std::string> kMeshElements = {"curve", "surface", "volume", "vertex_type"};

/// Remembers the line of the first setting per key and rejects a second one.
template <class Key>
class FirstLine {
 public:
  void claim(const Element& e, const Key& key, const std::string& what) {
    auto [it, inserted] = lines_.emplace(key, e.line());
    if (!inserted)
      e.fail(what + " is already set at line " + std::to_string(it->second) +
             "; give each entity one <" + e.tag() + "> element");
  }

 private:
  std::map<Key, int> lines_;
};

// A scheme pin: "auto" or a name, checked against the registry (built-in
// and plug-in schemes) when the run starts, not here.
std::optional<std::string> scheme_name(const Element& e) {
  const auto name = e.text("scheme");
  if (!name) return std::nullopt;
  const bool valid = !name->empty() && std::all_of(name->begin(), name->end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
  });
  if (!valid)
    e.fail_at("scheme",
              "attribute \"scheme\" must be \"auto\" or a scheme name (letters, digits, "
              "'_', '-', '.'), got \"" +
                  *name + "\"");
  return name;
}

SizeSetting read_sizing(const Element& e, bool with_intervals) {
  SizeSetting s;
  s.size = e.number("size", NumberKind::Positive);
  if (with_intervals) {
    s.intervals = e.integer("intervals", 1);
    if (s.size && s.intervals) e.fail("give \"size\" or \"intervals\", not both");
    if (auto f = e.choice("firmness", {"default", "soft", "hard"})) {
      if (!s.size && !s.intervals)
        e.fail_at("firmness", "attribute \"firmness\" needs \"size\" or \"intervals\"");
      s.firmness = static_cast<Firmness>(*f);
    }
  }
  return s;
}

CurveSetting read_curve(const Element& e) {
  e.allow_attributes(
      {"id", "size", "intervals", "firmness", "bias", "ratio", "first_size", "reverse"});
  e.expect_empty();
  CurveSetting c;
  c.id = e.required_integer("id", 1);
  c.sizing = read_sizing(e, true);
  c.bias = static_cast<BiasKind>(e.choice("bias", {"none", "geometric", "dual"}).value_or(0));
  c.bias_ratio = e.number("ratio", NumberKind::Positive);
  c.bias_first_size = e.number("first_size", NumberKind::Positive);
  const auto reverse = e.boolean("reverse");
  c.reverse_bias = reverse.value_or(false);
  if (c.bias == BiasKind::None) {
    for (const char* a : {"ratio", "first_size", "reverse"})
      if (e.has(a))
        e.fail_at(a,
                  "attribute \"" + std::string(a) + "\" needs bias=\"geometric\" or bias=\"dual\"");
  } else {
    if (c.bias_ratio.has_value() == c.bias_first_size.has_value())
      e.fail("a biased curve needs exactly one of \"ratio\" and \"first_size\"");
    if (c.bias == BiasKind::Dual && reverse)
      e.fail_at("reverse", "attribute \"reverse\" has no meaning with bias=\"dual\"");
  }
  if (!c.sizing.size && !c.sizing.intervals && c.bias == BiasKind::None)
    e.fail("sets nothing; give size, intervals or bias");
  c.where = e.where();
  return c;
}

SurfaceSetting read_surface(const Element& e) {
  e.allow_attributes({"id", "size", "scheme"});
  e.expect_empty();
  SurfaceSetting s;
  s.id = e.required_integer("id", 1);
  s.sizing = read_sizing(e, false);
  if (auto name = scheme_name(e)) s.scheme = *name;
  if (!s.sizing.size && !e.has("scheme")) e.fail("sets nothing; give size or scheme");
  s.where = e.where();
  return s;
}

VolumeSetting read_volume(const Element& e) {
  e.allow_attributes({"id", "size", "scheme", "elements", "sources", "targets", "direction"});
  e.expect_empty();
  VolumeSetting v;
  v.id = e.required_integer("id", 1);
  v.sizing = read_sizing(e, false);
  if (auto name = scheme_name(e)) v.scheme = *name;
  if (const auto kind = e.choice("elements", {"hex", "wedge", "mixed"}))
    v.elements = static_cast<ElementKind>(*kind);
  if (e.has("sources")) v.sources = e.ids("sources");
  if (e.has("targets")) v.targets = e.ids("targets");
  v.direction = e.vector("direction", VectorKind::NonZero);
  if (v.scheme == "map") {
    for (const char* a : {"sources", "targets", "direction"})
      if (e.has(a))
        e.fail_at(a, "attribute \"" + std::string(a) +
                         "\" is a sweep hint; it needs scheme=\"cooper\" or \"auto\"");
    if (v.elements && *v.elements != ElementKind::Hex)
      e.fail_at("elements", "scheme=\"map\" makes hexahedra only; use elements=\"hex\"");
  }
  for (int id : v.sources)
    if (std::find(v.targets.begin(), v.targets.end(), id) != v.targets.end())
      e.fail("surface " + std::to_string(id) + " is both a source and a target");
  if (!v.sizing.size && !e.has("scheme") && !e.has("elements") && v.sources.empty() &&
      v.targets.empty() && !v.direction)
    e.fail("sets nothing; give size, scheme, elements or sweep hints");
  v.where = e.where();
  return v;
}

VertexTypeSetting read_vertex_type(const Element& e) {
  e.allow_attributes({"surface", "vertex", "type"});
  e.expect_empty();
  VertexTypeSetting t;
  t.surface = e.required_integer("surface", 1);
  t.vertex = e.required_integer("vertex", 1);
  e.required("type");
  t.type = static_cast<VertexType>(*e.choice("type", {"end", "side", "corner", "reversal"}));
  t.where = e.where();
  return t;
}

}  // namespace

MeshSettings read_mesh(const Element& mesh) {
  mesh.allow_attributes({"size", "threads", "max_elements", "volume_tolerance", "decompose",
                         "finer_retries", "elements"});
  MeshSettings m;
  // "D/40": the model's bounding-box diagonal over 40 (element_size.h).
  const std::optional<std::string> size_text = mesh.text("size");
  if (size_text && size_text->find('/') != std::string::npos) {
    const std::optional<ElementSize> size = parse_element_size(*size_text);
    if (!size || !size->of_diagonal)
      mesh.fail_at("size",
                   "attribute \"size\" must be a positive number or D/N (the model's "
                   "bounding-box diagonal over N), got \"" +
                       clip(*size_text, 40) + "\"");
    set_element_size(m, *size);
  } else {
    m.size = mesh.number("size", NumberKind::Positive);
  }
  m.threads = mesh.integer("threads", 0).value_or(0);
  if (const auto n = mesh.integer("max_elements", 1)) m.max_elements = static_cast<double>(*n);
  if (const auto t = mesh.number("volume_tolerance", NumberKind::Positive)) {
    if (*t > 100)
      mesh.fail_at("volume_tolerance",
                   "attribute \"volume_tolerance\" is in percent and at most 100, got \"" +
                       *mesh.text("volume_tolerance") + "\"");
    m.volume_tolerance = *t / 100.0;
  }
  m.decompose = static_cast<Decompose>(mesh.choice("decompose", {"auto", "off"}).value_or(0));
  m.elements =
      static_cast<ElementKind>(mesh.choice("elements", {"hex", "wedge", "mixed"}).value_or(0));
  m.finer_retries = mesh.integer("finer_retries", 0).value_or(m.finer_retries);
  if (m.finer_retries > MeshSettings::kMaxFinerRetries)
    mesh.fail_at("finer_retries", "attribute \"finer_retries\" is at most " +
                                      std::to_string(MeshSettings::kMaxFinerRetries) +
                                      " (each halves the size), got \"" +
                                      *mesh.text("finer_retries") + "\"");
  m.where = mesh.where();
  FirstLine<int> curves, surfaces, volumes;
  FirstLine<std::pair<int, int>> vertices;
  for (const Element& e : mesh.children()) {
    const std::string tag = e.name();
    if (tag == "curve") {
      m.curves.push_back(read_curve(e));
      curves.claim(e, m.curves.back().id, "curve " + std::to_string(m.curves.back().id));
    } else if (tag == "surface") {
      m.surfaces.push_back(read_surface(e));
      surfaces.claim(e, m.surfaces.back().id, "surface " + std::to_string(m.surfaces.back().id));
    } else if (tag == "volume") {
      m.volumes.push_back(read_volume(e));
      volumes.claim(e, m.volumes.back().id, "volume " + std::to_string(m.volumes.back().id));
    } else if (tag == "vertex_type") {
      const auto& t = m.vertex_types.emplace_back(read_vertex_type(e));
      vertices.claim(e, {t.surface, t.vertex},
                     "the type of vertex " + std::to_string(t.vertex) + " on surface " +
                         std::to_string(t.surface));
    } else {
      e.fail("unknown element in <mesh>" + suggestion(tag, kMeshElements, "<", ">") +
             "; allowed: " + list(kMeshElements, "<", ">"));
    }
  }
  return m;
}

}  // namespace cooperage::io::detail
