#include "framework/decompose/part_ids.h"

#include <algorithm>
#include <cctype>
#include <set>

namespace cooperage::decompose {
namespace {

using Kind = PartIds::Kind;

struct Keyword {
  const char* word;
  Kind kind;
  bool plural;
};

// Longer words first: "surfaces" before "surface".
const Keyword kKeywords[] = {
    {"surfaces", Kind::Surface, true}, {"surface", Kind::Surface, false},
    {"sides", Kind::Surface, true},    {"side", Kind::Surface, false},
    {"caps", Kind::Surface, true},     {"cap", Kind::Surface, false},
    {"curves", Kind::Curve, true},     {"curve", Kind::Curve, false},
    {"vertices", Kind::Vertex, true},  {"vertex", Kind::Vertex, false},
    {"volume", Kind::Volume, false},
};

bool is_digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }
bool is_alpha(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; }

std::vector<geom::Vec3> curve_samples(const geom::Curve& c) {
  std::vector<geom::Vec3> out;
  if (!c.geometry) return out;
  const auto [a, b] = c.geometry->range();
  for (double f : {0.25, 0.5, 0.75}) out.push_back(c.geometry->point(a + f * (b - a)));
  return out;
}

bool inside(const geom::BoundingBox& inner, const geom::BoundingBox& outer, double tol) {
  if (inner.empty() || outer.empty()) return false;
  return (inner.min.array() >= outer.min.array() - tol).all() &&
         (inner.max.array() <= outer.max.array() + tol).all();
}

}  // namespace

PartIds::PartIds(const geom::Model& part, int volume) : part_(part) {
  std::set<int> curves, vertices;
  for (int s : part.surfaces_of(volume)) {
    surfaces_.push_back(s);
    for (const auto& loop : part.surface(s).loops) {
      for (const auto& use : loop.uses) {
        curves.insert(use.curve);
        const geom::Curve& c = part.curve(use.curve);
        vertices.insert(c.start_vertex);
        vertices.insert(c.end_vertex);
      }
    }
  }
  std::sort(surfaces_.begin(), surfaces_.end());
  curves_.assign(curves.begin(), curves.end());
  vertices_.assign(vertices.begin(), vertices.end());
  // The kernel's own precision is ~1e-7 of a part; its intersection curves
  // lie on both faces within their tolerance, larger on imported parts.
  tolerance_ = 1e-5 * std::max(part.volume(volume).box.diagonal(), 1e-9);
}

int PartIds::vertex(const geom::Model& pieces, int id) const {
  const geom::Vec3& p = pieces.vertex(id).point;
  for (int v : vertices_) {
    if ((part_.vertex(v).point - p).norm() <= tolerance_) return v;
  }
  return 0;
}

int PartIds::curve(const geom::Model& pieces, int id) const {
  const std::vector<geom::Vec3> samples = curve_samples(pieces.curve(id));
  if (samples.empty()) return 0;
  for (int c : curves_) {
    const auto& g = part_.curve(c).geometry;
    if (!g) continue;
    bool on = true;
    for (const geom::Vec3& p : samples) {
      on = on && (g->point(g->closest_parameter(p)) - p).norm() <= tolerance_;
      if (!on) break;
    }
    if (on) return c;
  }
  return 0;
}

int PartIds::surface(const geom::Model& pieces, int id) const {
  const geom::Surface& s = pieces.surface(id);
  if (!s.geometry) return 0;
  std::vector<geom::Vec3> samples;
  for (const auto& loop : s.loops) {
    for (const auto& use : loop.uses) {
      const std::vector<geom::Vec3> on_curve = curve_samples(pieces.curve(use.curve));
      if (!on_curve.empty()) samples.push_back(on_curve[1]);
    }
  }
  if (s.centroid) samples.push_back(s.geometry->project(*s.centroid).point);
  // Of the part's faces on the same surface whose box holds the piece's,
  // the tightest: two halves of a cylinder share its geometry, not a box.
  int best = 0;
  double best_size = 0.0;
  for (int candidate : surfaces_) {
    const geom::Surface& t = part_.surface(candidate);
    if (!t.geometry || t.geometry->type() != s.geometry->type()) continue;
    if (!inside(s.box, t.box, tolerance_)) continue;
    bool on = true;
    for (const geom::Vec3& p : samples) {
      on = on && t.geometry->project(p).distance <= tolerance_;
      if (!on) break;
    }
    if (!on) continue;
    const double size = t.box.diagonal();
    if (best == 0 || size < best_size) {
      best = candidate;
      best_size = size;
    }
  }
  return best;
}

namespace {

// The keyword at text[i] when an id follows it ("surface 7"); else null.
const Keyword* keyword_at(const std::string& text, size_t i) {
  if (i > 0 && is_alpha(text[i - 1])) return nullptr;  // inside a word: "subsurface 3"
  for (const Keyword& k : kKeywords) {
    const size_t len = std::char_traits<char>::length(k.word);
    if (text.compare(i, len, k.word) == 0 && i + len + 1 < text.size() && text[i + len] == ' ' &&
        is_digit(text[i + len + 1]))
      return &k;
  }
  return nullptr;
}

// The ids after a keyword from text[j]: "7", and after a plural also
// "7, 8", "7 and 8", "7, 8, and 9"; each with the separator before it.
// `end` is set past the last; empty when the number is no id ("3.5",
// "3rd").
std::vector<std::pair<std::string, int>> ids_at(const std::string& text, size_t j, bool plural,
                                                size_t& end) {
  std::vector<std::pair<std::string, int>> items;
  const size_t n = text.size();
  std::string separator;
  for (;;) {
    size_t k = j;
    int id = 0;
    while (k < n && is_digit(text[k]) && id < 100000000) id = id * 10 + (text[k++] - '0');
    const bool decimal = k + 1 < n && text[k] == '.' && is_digit(text[k + 1]);
    if (k < n && (is_alpha(text[k]) || decimal)) break;
    items.emplace_back(separator, id);
    j = k;
    if (!plural) break;
    bool more = false;
    for (const char* sep : {", and ", ", ", " and "}) {
      const size_t len = std::char_traits<char>::length(sep);
      if (text.compare(j, len, sep) == 0 && j + len < n && is_digit(text[j + len])) {
        separator = sep;
        j += len;
        more = true;
        break;
      }
    }
    if (!more) break;
  }
  end = j;
  return items;
}

bool exists(const geom::Model& m, Kind kind, int id) {
  size_t count = 0;
  switch (kind) {
    case Kind::Surface: count = m.surfaces().size(); break;
    case Kind::Curve: count = m.curves().size(); break;
    case Kind::Vertex: count = m.vertices().size(); break;
    case Kind::Volume: count = m.volumes().size(); break;
  }
  return id > 0 && static_cast<size_t>(id) <= count;
}

}  // namespace

std::string PartIds::name(Kind kind, const geom::Model& pieces, int id, int piece) const {
  switch (kind) {
    case Kind::Surface: {
      // A face of two pieces is the cut between them.
      const int mine = pieces.surface(id).volumes.size() > 1 ? 0 : surface(pieces, id);
      return mine ? std::to_string(mine) : std::string("the cut face");
    }
    case Kind::Curve: {
      const int mine = curve(pieces, id);
      return mine ? std::to_string(mine) : std::string("a curve of the cut");
    }
    case Kind::Vertex: {
      const int mine = vertex(pieces, id);
      return mine ? std::to_string(mine) : std::string("a vertex of the cut");
    }
    case Kind::Volume: return id == piece ? "the piece" : "piece " + std::to_string(id);
  }
  return std::to_string(id);
}

std::string PartIds::translate(const std::string& text, const geom::Model& pieces,
                               int piece) const {
  std::string out;
  size_t i = 0;
  while (i < text.size()) {
    const Keyword* hit = keyword_at(text, i);
    size_t end = i;
    const auto items =
        hit ? ids_at(text, i + std::char_traits<char>::length(hit->word) + 1, hit->plural, end)
            : std::vector<std::pair<std::string, int>>();
    bool known = !items.empty();
    for (const auto& item : items) known = known && exists(pieces, hit->kind, item.second);
    if (!known) {  // no keyword, or no id of the pieces after it: as it was
      out.append(text, i, std::max(end, i + 1) - i);
      i = std::max(end, i + 1);
      continue;
    }
    std::vector<std::string> names;
    bool all_numbers = true;
    for (const auto& item : items) {
      names.push_back(name(hit->kind, pieces, item.second, piece));
      all_numbers = all_numbers && is_digit(names.back()[0]);
    }
    // "surface 7" stays a keyword and a number; "the cut face" replaces
    // "surface 39" whole; in a list the keyword stays before the names.
    if (hit->kind != Kind::Volume && (all_numbers || items.size() > 1))
      out += hit->word + std::string(" ");
    for (size_t k = 0; k < items.size(); ++k) out += items[k].first + names[k];
    i = end;
  }
  return out;
}

}  // namespace cooperage::decompose
