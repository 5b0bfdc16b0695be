// Internal to the OpenCASCADE backend: the shape store behind Workbench, the
// conversions between Cooperage and OCCT value types, and the guard that turns
// every kernel exception into a MeshingError. Included only by the .cpp files
// of this folder (it names OCCT types).
#pragma once

#include "framework/core/error.h"
#include "framework/geometry/occ/workbench.h"

#include <Standard_Failure.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Dir.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

#include <exception>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace cooperage::occ {

using geom::Vec2;

struct NamedShape {
  std::string name;
  TopoDS_Shape shape;
  /// Imports only: the shape's solids and free faces imprinted and merged
  /// among themselves (a compound, solids first), made in the import's child
  /// process. build_model uses it instead of imprinting again when this is
  /// the only shape; any change to `shape` clears it.
  TopoDS_Shape merged;
};

struct Workbench::Impl {
  std::vector<NamedShape> shapes;  ///< creation order
  /// Length unit of the imported files in metres (0: none imported yet).
  double unit_in_metres = 0.0;
  /// OCCT name of that unit ("MM", "INCH", ...), used when writing STEP.
  std::string unit_name = "MM";
  /// Whether build_model will imprint and merge (imports merge in their child).
  bool merge_on_import = true;
  std::function<void()> while_importing;  ///< Workbench::set_while_importing

  NamedShape* find(const std::string& name);
  const NamedShape* find(const std::string& name) const;
  /// The shape called name; throws InvalidInput naming it when unknown.
  const TopoDS_Shape& get(const std::string& name) const;
  /// Throws InvalidInput when name is empty or already used.
  void check_new_name(const std::string& name) const;
  void add(const std::string& name, const TopoDS_Shape& shape);
  void remove(const std::string& name);
};

namespace detail {

inline gp_Pnt to_pnt(const Vec3& p) { return gp_Pnt(p.x(), p.y(), p.z()); }
inline gp_Vec to_vec(const Vec3& p) { return gp_Vec(p.x(), p.y(), p.z()); }
inline Vec3 to_vec3(const gp_Pnt& p) { return Vec3(p.X(), p.Y(), p.Z()); }
inline Vec3 to_vec3(const gp_Vec& p) { return Vec3(p.X(), p.Y(), p.Z()); }
inline Vec3 to_vec3(const gp_Dir& p) { return Vec3(p.X(), p.Y(), p.Z()); }

/// A number for messages: shortest round-trip form ("-1", "0.25").
std::string num(double value);

[[noreturn]] inline void invalid(const std::string& shape, const std::string& why) {
  throw MeshingError(ErrorCode::InvalidInput, "shape '" + shape + "': " + why);
}

/// Unit direction of a non-zero vector; throws InvalidInput naming the shape.
gp_Dir checked_dir(const std::string& shape, const Vec3& v, const char* what);

/// Runs f, converting OCCT and standard exceptions into MeshingError(code)
/// prefixed by `context`; MeshingErrors pass through unchanged.
template <class F>
auto guarded(ErrorCode code, const std::string& context, F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const MeshingError&) {
    throw;
  } catch (const Standard_Failure& e) {
    const char* msg = e.GetMessageString();
    throw MeshingError(code, context + ": OpenCASCADE " + e.DynamicType()->Name() +
                                 (msg && *msg ? std::string(": ") + msg : std::string()));
  } catch (const std::exception& e) {
    throw MeshingError(code, context + ": " + e.what());
  } catch (...) {
    throw MeshingError(code, context + ": unknown kernel failure");
  }
}

/// Polygon helpers shared by the primitives (primitives.cpp) and loft.cpp.
/// Newell normal of a closed polygon: direction = normal for which the
/// polygon is counter-clockwise, length = twice the enclosed area.
Vec3 newell(const std::vector<Vec3>& pts);
/// Diagonal of the bounding box of the points.
double extent(const std::vector<Vec3>& pts);
/// Checks a polygon (>= 3 finite points, no coincident consecutive points,
/// non-zero area); returns its unit Newell normal. `what` names it in the
/// InvalidInput message ("profile", "section 2", ...).
Vec3 check_polygon(const std::string& shape, const std::vector<Vec3>& pts, const char* what);
/// Throws InvalidInput "<what> is not planar" unless every point lies in the
/// plane (origin, unit normal n), within 1e-7 * size.
void check_in_plane(const std::string& shape, const std::vector<Vec3>& pts, const Vec3& origin,
                    const Vec3& n, double size, const char* what);
/// Closed polygonal wire through the points (straight edges).
TopoDS_Wire polygon_wire(const std::vector<Vec3>& pts);
/// Throws GeometryError unless s is non-null and passes BRepCheck_Analyzer.
void check_valid(const std::string& shape, const TopoDS_Shape& s);

/// Workbench::build_model over any list of named shapes (model_builder.cpp):
/// collect, imprint and merge when asked, number, validate (geom::validate).
geom::Model build_model_of(const std::vector<NamedShape>& shapes, const BuildOptions& options,
                           double unit_in_metres);

/// The solids and free faces of one shape imprinted and merged among
/// themselves, as build_model_of would (a compound, solids then faces, in
/// the order build_model_of numbers them).
TopoDS_Shape merge_alone(const TopoDS_Shape& shape);

/// True when the shape holds at least one sub-shape of the given type.
bool contains_solid(const TopoDS_Shape& shape);

/// A solid or free face of the named shapes, with the index of its shape.
struct Piece {
  TopoDS_Shape shape;  ///< a solid, or a free face
  int owner = 0;       ///< index into the named shapes
};

/// A face's area and tight bounding box (tight_face_box), computed once per
/// face and thread (face_facts.cpp).
struct FaceFacts {
  double area = 0.0;
  geom::Vec3 centroid = geom::Vec3::Zero();
  geom::BoundingBox box;
};
FaceFacts face_facts(const TopoDS_Face& face);
/// A face's tight bounding box, no tolerance added (face_box.cpp): on
/// planes, cylinders, cones, spheres, tori and B-splines from its edges and
/// the surface's own extreme points; else BRepBndLib::AddOptimal's.
geom::BoundingBox tight_face_box(const TopoDS_Face& face);
/// Remembers facts computed elsewhere (the import child's) for this thread's
/// later face_facts calls: the parent then does not bound every face again.
void remember_face_facts(const TopoDS_Face& face, const FaceFacts& facts);

/// A solid's volume, computed once per solid and thread (solid_volume.cpp);
/// remember_solid_volume seeds it as remember_face_facts does.
double solid_volume(const TopoDS_Shape& solid);
void remember_solid_volume(const TopoDS_Shape& solid, double volume);

/// Solids and free faces of the named shapes, in creation order
/// (model_builder.cpp).
void collect(const std::vector<NamedShape>& shapes, std::vector<Piece>& solids,
             std::vector<Piece>& faces);
/// Imprint + merge: one general fuse of every piece; each piece is replaced by
/// its images (a solid partly overlapping another splits into several).
/// `touching_only`: the pieces are known to share faces at most, never to
/// overlap (pieces of cuts of merged solids), so the fuse may glue them
/// (OCCT's BOPAlgo_GlueShift: faces that do not coincide are not
/// intersected).
void imprint_merge(std::vector<Piece>& solids, std::vector<Piece>& faces,
                   bool touching_only = false);
/// The model of the pieces: volumes in solid order, names from
/// names[owner] (".k" appended when an owner has several solids); validated.
geom::Model number_model(const std::vector<Piece>& solids, const std::vector<Piece>& faces,
                         const std::vector<std::string>& names, double unit_in_metres);

/// Evaluator factories (curve_geometry.cpp, surface_geometry.cpp).
std::shared_ptr<const geom::CurveGeometry> make_curve_geometry(const TopoDS_Edge& edge);
/// `face` oriented as in the surface's first volume: its topological normal
/// is the natural normal.
std::shared_ptr<const geom::SurfaceGeometry> make_surface_geometry(const TopoDS_Face& face);

}  // namespace detail
}  // namespace cooperage::occ
