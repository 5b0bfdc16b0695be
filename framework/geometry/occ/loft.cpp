// Workbench::loft: a solid through planar polygon sections (and optionally an
// apex point at either end), built by OCCT's ThruSections in the loft module
// (loft_module.cpp). The sections are validated here so that OCCT only sees
// input it can loft.
#include "framework/geometry/occ/detail.h"
#include "framework/core/lazy_module.h"

#include <Eigen/Geometry>

#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepLib.hxx>
#include <TopAbs_ShapeEnum.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Solid.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>

#include <dlfcn.h>

#include <cmath>
#include <mutex>
#include <vector>

namespace cooperage::occ {
namespace {

using detail::invalid;

std::string section_name(size_t i) { return "section " + std::to_string(i + 1); }

/// A validated polygon section: unit normal and a point of its plane.
struct Plane {
  Vec3 origin = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();
};

/// Validates `sections` (see Workbench::loft); returns the plane of every
/// polygon section (unused entries for point sections).
std::vector<Plane> check_sections(const std::string& shape,
                                  const std::vector<std::vector<Vec3>>& sections, bool ruled) {
  if (sections.size() < 2)
    invalid(shape, "a loft needs at least 2 sections, got " + std::to_string(sections.size()));
  const size_t last = sections.size() - 1;
  geom::BoundingBox box;
  size_t polygons = 0;
  for (size_t i = 0; i < sections.size(); ++i) {
    const auto& s = sections[i];
    const std::string what = section_name(i);
    if (s.empty()) invalid(shape, what + " is empty");
    if (s.size() == 1) {
      if (!s[0].allFinite()) invalid(shape, what + " has a non-finite point");
      if (i != 0 && i != last)
        invalid(shape, what +
                           " is a single point; a point section (an apex) is allowed only "
                           "as the first or the last section");
    } else if (s.size() == 2) {
      invalid(shape, what +
                         " has 2 points; a section is a single point (an apex) or a polygon "
                         "of at least 3 points");
    } else {
      ++polygons;
    }
    for (const auto& p : s) box.add(p);
  }
  if (polygons == 0) invalid(shape, "a loft needs at least one polygon section");

  std::vector<Plane> planes(sections.size());
  for (size_t i = 0; i < sections.size(); ++i) {
    const auto& s = sections[i];
    if (s.size() < 3) continue;
    const std::string what = section_name(i);
    planes[i].normal = detail::check_polygon(shape, s, what.c_str());
    planes[i].origin = s.front();
    detail::check_in_plane(shape, s, s.front(), planes[i].normal, detail::extent(s), what.c_str());
  }

  // Consecutive sections must span a volume: an apex off the plane of its
  // neighbour, two polygons not in one plane.
  const double tol = 1e-9 * box.diagonal();
  for (size_t i = 0; i + 1 < sections.size(); ++i) {
    const size_t poly = sections[i].size() >= 3 ? i : i + 1;
    const size_t other = poly == i ? i + 1 : i;
    bool off_plane = false;
    for (const auto& p : sections[other])
      off_plane = off_plane || std::abs((p - planes[poly].origin).dot(planes[poly].normal)) > tol;
    if (!off_plane)
      invalid(shape, section_name(i) + " and " + section_name(i + 1) +
                         " lie in one plane; consecutive sections must be apart");
  }

  if (ruled) {
    size_t first = 0;
    while (sections[first].size() < 3) ++first;
    for (size_t i = first + 1; i < sections.size(); ++i) {
      if (sections[i].size() < 3) continue;
      if (sections[i].size() != sections[first].size())
        invalid(shape,
                "a ruled loft needs the same number of points in every polygon section "
                "(OpenCASCADE joins the sections edge by edge and needs compatible "
                "wires): " +
                    section_name(first) + " has " + std::to_string(sections[first].size()) + ", " +
                    section_name(i) + " has " + std::to_string(sections[i].size()) +
                    "; use ruled=\"false\" or give both the same count");
      // Point j joins point j of the next polygon: the windings must agree.
      if (planes[i].normal.dot(planes[first].normal) < 0.0)
        invalid(shape, section_name(i) + " winds the opposite way to " + section_name(first) +
                           "; list the points of every section in the same rotational order");
      first = i;
    }
  }
  return planes;
}

// OCCT's ThruSections from the loft module (loft_module.cpp), opened on the
// first loft.
using ThruSectionsFn = int (*)(const TopoDS_Shape*, size_t, int, TopoDS_Shape*);
ThruSectionsFn thru_sections() {
  static ThruSectionsFn fn = nullptr;
  static std::once_flag once;
  std::call_once(once, [] {
    void* handle = open_module("libcooperage_occ_loft.so", "cooperage_loft_abi", /*abi=*/1);
    fn = reinterpret_cast<ThruSectionsFn>(dlsym(handle, "cooperage_loft_thru_sections"));
    if (fn == nullptr)
      throw MeshingError(ErrorCode::Internal, "libcooperage_occ_loft.so lacks its loft function");
  });
  return fn;
}

}  // namespace

void Workbench::loft(const std::string& name, const std::vector<std::vector<Vec3>>& sections,
                     bool ruled) {
  impl_->check_new_name(name);
  check_sections(name, sections, ruled);
  impl_->add(name, detail::guarded(ErrorCode::GeometryError, "shape '" + name + "'", [&] {
               // A ruled loft keeps the user's pairing of points (validated above); a
               // smooth one lets OCCT make differently shaped sections compatible.
               std::vector<TopoDS_Shape> profiles;
               for (const auto& s : sections) {
                 if (s.size() == 1)
                   profiles.push_back(
                       BRepBuilderAPI_MakeVertex(detail::to_pnt(s.front())).Vertex());
                 else
                   profiles.push_back(detail::polygon_wire(s));
               }
               TopoDS_Shape shape;
               if (thru_sections()(profiles.data(), profiles.size(), ruled ? 1 : 0, &shape) != 0)
                 invalid(name, "OpenCASCADE could not loft the sections");
               TopExp_Explorer solids(shape, TopAbs_SOLID);
               if (!solids.More()) invalid(name, "the loft did not produce a solid");
               TopoDS_Solid solid = TopoDS::Solid(solids.Current());
               // Outward face normals whatever the order and winding of the sections.
               BRepLib::OrientClosedSolid(solid);
               detail::check_valid(name, solid);
               return TopoDS_Shape(solid);
             }));
}

}  // namespace cooperage::occ
