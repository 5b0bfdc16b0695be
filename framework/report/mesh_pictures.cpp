#include "framework/report/mesh_pictures.h"

#include <algorithm>
#include <numeric>

namespace cooperage::report {
namespace {

using quality::ElementType;

// Local corner lists of the faces of a volume element (Exodus/VTK order);
// -1 pads a triangle.
const std::vector<std::array<int, 4>>& element_faces(ElementType type) {
  static const std::vector<std::array<int, 4>> hex = {{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6},
                                                      {3, 0, 4, 7}, {0, 3, 2, 1}, {4, 5, 6, 7}};
  static const std::vector<std::array<int, 4>> wedge = {
      {0, 2, 1, -1}, {3, 4, 5, -1}, {0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}};
  static const std::vector<std::array<int, 4>> none;
  return type == ElementType::Hex ? hex : type == ElementType::Wedge ? wedge : none;
}

bool is_volume(ElementType type) { return type == ElementType::Hex || type == ElementType::Wedge; }

struct ElementRef {
  std::size_t block;
  std::size_t index;
};

class Part {
 public:
  Part(const ReportInput& input, std::vector<std::size_t> blocks)
      : input_(input), blocks_(std::move(blocks)) {}

  const int* nodes(const ElementRef& e) const {
    const ElementBlock& b = input_.blocks[e.block];
    return b.connectivity + e.index * static_cast<std::size_t>(b.stride);
  }
  int corner_count(const ElementRef& e) const {
    return quality::node_count(input_.blocks[e.block].type);
  }

  std::vector<ElementRef> elements(bool volume) const {
    std::vector<ElementRef> out;
    for (std::size_t b : blocks_) {
      if (is_volume(input_.blocks[b].type) != volume) continue;
      for (std::size_t i = 0; i < input_.blocks[b].count; ++i) out.push_back({b, i});
    }
    return out;
  }

  bool has_volume_elements() const {
    for (std::size_t b : blocks_) {
      if (is_volume(input_.blocks[b].type) && input_.blocks[b].count > 0) return true;
    }
    return false;
  }

 private:
  const ReportInput& input_;
  std::vector<std::size_t> blocks_;
};

// Faces of `elements` used by exactly one of them. A face is shared when
// another element incident to its lowest node has all its corners.
std::vector<std::pair<ElementRef, std::array<int, 4>>> skin(
    const ReportInput& input, const Part& part, const std::vector<ElementRef>& elements) {
  // Elements around each node; only nodes that may be on the boundary are
  // looked up, so only they are indexed.
  const auto& mask = input.maybe_boundary;
  const auto indexed = [&](int v) { return mask.empty() || mask[static_cast<std::size_t>(v)]; };
  const std::size_t node_count = input.coords->size();
  std::vector<std::size_t> start(node_count + 1, 0);
  for (const ElementRef& e : elements) {
    const int* n = part.nodes(e);
    for (int k = 0; k < part.corner_count(e); ++k) {
      if (indexed(n[k])) ++start[static_cast<std::size_t>(n[k]) + 1];
    }
  }
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<std::size_t> incident(start.back());
  std::vector<std::size_t> fill(start.begin(), start.end() - 1);
  for (std::size_t i = 0; i < elements.size(); ++i) {
    const int* n = part.nodes(elements[i]);
    for (int k = 0; k < part.corner_count(elements[i]); ++k) {
      if (indexed(n[k])) incident[fill[static_cast<std::size_t>(n[k])]++] = i;
    }
  }
  std::vector<std::pair<ElementRef, std::array<int, 4>>> out;
  for (std::size_t i = 0; i < elements.size(); ++i) {
    const ElementRef& e = elements[i];
    const int* n = part.nodes(e);
    for (const auto& local : element_faces(input.blocks[e.block].type)) {
      std::array<int, 4> face{};
      const int corners = local[3] < 0 ? 3 : 4;
      bool inside = false;
      for (int k = 0; k < 4; ++k) {
        face[k] = k < corners ? n[local[k]] : -1;
        if (k < corners && !indexed(face[k])) inside = true;
      }
      if (inside) continue;
      const int lowest = *std::min_element(face.begin(), face.begin() + corners);
      bool shared = false;
      for (std::size_t j = start[lowest]; j < start[lowest + 1] && !shared; ++j) {
        const std::size_t other = incident[j];
        if (other == i) continue;
        const int* m = part.nodes(elements[other]);
        const int mc = part.corner_count(elements[other]);
        shared = std::all_of(face.begin(), face.begin() + corners,
                             [&](int v) { return std::find(m, m + mc, v) != m + mc; });
      }
      if (!shared) out.push_back({e, face});
    }
  }
  return out;
}

Eigen::Vector3d centroid(const ReportInput& input, const Part& part, const ElementRef& e) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  const int* n = part.nodes(e);
  const int corners = part.corner_count(e);
  for (int k = 0; k < corners; ++k) c += (*input.coords)[static_cast<std::size_t>(n[k])];
  return c / corners;
}

Picture picture_of(const ReportInput& input, const std::string& name,
                   const std::vector<std::size_t>& blocks,
                   const std::vector<std::vector<double>>& sj, std::size_t worst_marked) {
  const Part part(input, blocks);
  const bool volume = part.has_volume_elements();
  const std::vector<ElementRef> elements = part.elements(volume);
  Picture pic;
  pic.part = name;
  pic.elements = elements.size();

  std::vector<std::pair<ElementRef, std::array<int, 4>>> faces;
  if (volume) {
    faces = skin(input, part, elements);
  } else {
    for (const ElementRef& e : elements) {
      const int* n = part.nodes(e);
      const int c = part.corner_count(e);
      faces.push_back({e, {n[0], n[1], n[2], c == 4 ? n[3] : -1}});
    }
  }
  pic.boundary_faces = faces.size();
  std::vector<int> local(input.coords->size(), -1);
  for (const auto& [e, face] : faces) {
    std::array<int, 4> f = face;
    for (int& v : f) {
      if (v < 0) continue;
      int& l = local[static_cast<std::size_t>(v)];
      if (l < 0) {
        l = static_cast<int>(pic.surface.points.size());
        pic.surface.points.push_back((*input.coords)[static_cast<std::size_t>(v)]);
      }
      v = l;
    }
    pic.surface.faces.push_back(f);
    pic.surface.values.push_back(sj[e.block][e.index]);
  }

  // The worst elements, interior ones included (lowest value, then order).
  std::vector<std::size_t> order(elements.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  const auto value = [&](std::size_t i) { return sj[elements[i].block][elements[i].index]; };
  const std::size_t k = std::min(worst_marked, order.size());
  std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(k), order.end(),
                    [&](std::size_t a, std::size_t b) {
                      return value(a) < value(b) || (value(a) == value(b) && a < b);
                    });
  for (std::size_t i = 0; i < k; ++i) {
    const ElementRef& e = elements[order[i]];
    pic.worst.push_back(
        {input.blocks[e.block].name, e.index, value(order[i]), centroid(input, part, e)});
  }
  return pic;
}

}  // namespace

std::vector<Picture> build_pictures(const ReportInput& input,
                                    const std::vector<std::vector<double>>& scaled_jacobian,
                                    const ReportOptions& options) {
  std::vector<std::string> names;
  std::vector<std::vector<std::size_t>> members;
  for (std::size_t b = 0; b < input.blocks.size(); ++b) {
    const std::string& part = input.blocks[b].part;
    if (part.empty() || input.blocks[b].count == 0) continue;
    const auto it = std::find(names.begin(), names.end(), part);
    if (it == names.end()) {
      names.push_back(part);
      members.push_back({b});
    } else {
      members[static_cast<std::size_t>(it - names.begin())].push_back(b);
    }
  }
  std::vector<Picture> pictures;
  std::size_t total = 0;
  for (std::size_t p = 0; p < names.size(); ++p) {
    pictures.push_back(
        picture_of(input, names[p], members[p], scaled_jacobian, options.worst_marked));
    total += pictures.back().boundary_faces;
  }
  if (total > options.max_drawn_faces) {
    // Each part keeps its share of the budget (at least a coarse outline).
    for (Picture& pic : pictures) {
      const double share = static_cast<double>(pic.boundary_faces) / static_cast<double>(total);
      const auto budget = std::max<std::size_t>(
          200, static_cast<std::size_t>(share * static_cast<double>(options.max_drawn_faces)));
      pic.surface = simplify_faces(pic.surface, budget);
    }
  }
  return pictures;
}

}  // namespace cooperage::report
