// SolidPieces: the solids of a workbench, cut one at a time by planes,
// cylinders or cones (BRepAlgoAPI_Splitter, as the journal's webcut) and numbered into
// a model by the same steps as Workbench::build_model.
#include "framework/geometry/occ/solid_pieces.h"

#include "framework/geometry/occ/detail.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAlgoAPI_Splitter.hxx>
#include <BRepBndLib.hxx>
#include <BRep_Tool.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <Bnd_Box.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <gp_Ax3.hxx>
#include <gp_Cone.hxx>
#include <gp_Cylinder.hxx>
#include <gp_Pln.hxx>

#include <cmath>

namespace cooperage::occ {

struct SolidPieces::Impl {
  std::vector<detail::Piece> solids;
  std::vector<detail::Piece> faces;
  std::vector<std::string> names;  ///< by owner
  double unit_in_metres = 0.0;
  /// The solids and faces share faces at most, never overlap: imprinted and
  /// merged on import, or pieces of one cut (build_model may glue them).
  bool touching_only = false;
};

SolidPieces::SolidPieces() : impl_(std::make_unique<Impl>()) {}
SolidPieces::~SolidPieces() = default;
SolidPieces::SolidPieces(const SolidPieces& o) : impl_(std::make_unique<Impl>(*o.impl_)) {}
SolidPieces& SolidPieces::operator=(const SolidPieces& o) {
  if (this != &o) impl_ = std::make_unique<Impl>(*o.impl_);
  return *this;
}
SolidPieces::SolidPieces(SolidPieces&&) noexcept = default;
SolidPieces& SolidPieces::operator=(SolidPieces&&) noexcept = default;

SolidPieces SolidPieces::of(const Workbench& bench, const BuildOptions& options) {
  silence_kernel_output();
  SolidPieces out;
  detail::guarded(ErrorCode::GeometryError, "collecting the solids", [&] {
    // A lone import merged in its child: the pieces build_model took, without
    // imprinting the assembly a second time (real-cad gmsh_as1-tu-203, 19
    // solids: 1.2 s of a 7.4 s run).
    const auto& shapes = bench.impl_->shapes;
    const bool premerged =
        options.imprint_merge && shapes.size() == 1 && !shapes[0].merged.IsNull();
    if (premerged) {
      detail::collect({NamedShape{shapes[0].name, shapes[0].merged, {}}}, out.impl_->solids,
                      out.impl_->faces);
    } else {
      detail::collect(shapes, out.impl_->solids, out.impl_->faces);
      if (options.imprint_merge) detail::imprint_merge(out.impl_->solids, out.impl_->faces);
    }
    out.impl_->touching_only = options.imprint_merge;
  });
  for (const NamedShape& s : bench.impl_->shapes) out.impl_->names.push_back(s.name);
  out.impl_->unit_in_metres = bench.impl_->unit_in_metres;
  return out;
}

int SolidPieces::size() const { return static_cast<int>(impl_->solids.size()); }

namespace {

void check_index(const SolidPieces& p, int index) {
  if (index < 0 || index >= p.size())
    throw MeshingError(ErrorCode::Internal,
                       "solid index " + std::to_string(index) + " out of range");
}

// A face of the cutting surface that covers the whole box of `shape`.
TopoDS_Face tool_face(const TopoDS_Shape& shape, const CutSurface& cut) {
  Bnd_Box box;
  BRepBndLib::Add(shape, box);
  double x0, y0, z0, x1, y1, z1;
  box.Get(x0, y0, z0, x1, y1, z1);
  const Vec3 lo(x0, y0, z0), hi(x1, y1, z1);
  const Vec3 centre = 0.5 * (lo + hi);
  const Vec3 dir = cut.direction.normalized();
  // Centre the tool on the point of the surface's axis/plane nearest the box.
  const Vec3 foot = cut.kind == CutSurface::Kind::Plane
                        ? Vec3(centre - dir * dir.dot(centre - cut.origin))
                        : Vec3(cut.origin + dir * dir.dot(centre - cut.origin));
  const double half = 2.0 * ((hi - lo).norm() + (centre - foot).norm()) + 1.0;
  const gp_Ax3 frame(detail::to_pnt(foot), detail::checked_dir("cut", dir, "cut direction"));
  if (cut.kind == CutSurface::Kind::Plane) {
    return BRepBuilderAPI_MakeFace(gp_Pln(frame), -half, half, -half, half).Face();
  }
  if (!(cut.radius > 0.0) || !std::isfinite(cut.radius))
    throw MeshingError(ErrorCode::InvalidInput,
                       "a cylindrical or conical cut needs a positive radius");
  const Vec3 seam = cut.seam - dir * dir.dot(cut.seam);
  if (cut.kind == CutSurface::Kind::Cylinder) {
    const gp_Ax3 seamed =
        seam.norm() > 1e-9
            ? gp_Ax3(detail::to_pnt(foot), detail::checked_dir("cut", dir, "cut direction"),
                     detail::checked_dir("cut", seam.normalized(), "cut seam"))
            : frame;
    return BRepBuilderAPI_MakeFace(gp_Cylinder(seamed, cut.radius), 0.0, 2.0 * M_PI, -half, half)
        .Face();
  }
  if (!(cut.half_angle > 1e-6 && cut.half_angle < 0.5 * M_PI - 1e-6))
    throw MeshingError(ErrorCode::InvalidInput,
                       "a conical cut needs a half angle in (0, 90) degrees");
  // The cone's own frame at `origin` (its radius is given there); v runs
  // along the generatrix, the apex at v = -radius / sin(half_angle).
  const gp_Ax3 cone_frame =
      seam.norm() > 1e-9
          ? gp_Ax3(detail::to_pnt(cut.origin), detail::checked_dir("cut", dir, "cut direction"),
                   detail::checked_dir("cut", seam.normalized(), "cut seam"))
          : gp_Ax3(detail::to_pnt(cut.origin), detail::checked_dir("cut", dir, "cut direction"));
  const double apex = -cut.radius / std::sin(cut.half_angle);
  const double reach = 2.0 * ((hi - lo).norm() + (centre - cut.origin).norm()) + 1.0;
  const double v0 = std::max(-reach, apex * (1.0 - 1e-6));
  return BRepBuilderAPI_MakeFace(gp_Cone(cone_frame, cut.half_angle, cut.radius), 0.0, 2.0 * M_PI,
                                 v0, reach)
      .Face();
}

}  // namespace

SolidPieces SolidPieces::only(int index) const {
  check_index(*this, index);
  SolidPieces out;
  detail::Piece p = impl_->solids[static_cast<size_t>(index)];
  out.impl_->names = {impl_->names[static_cast<size_t>(p.owner)]};
  p.owner = 0;
  out.impl_->solids.push_back(p);
  out.impl_->unit_in_metres = impl_->unit_in_metres;
  out.impl_->touching_only = true;
  return out;
}

SolidPieces SolidPieces::split(int index, const CutSurface& cut) const {
  check_index(*this, index);
  silence_kernel_output();
  const detail::Piece& target = impl_->solids[static_cast<size_t>(index)];
  SolidPieces out;
  out.impl_->names = {impl_->names[static_cast<size_t>(target.owner)]};
  out.impl_->unit_in_metres = impl_->unit_in_metres;
  out.impl_->touching_only = true;  // the pieces of one solid
  detail::guarded(ErrorCode::GeometryError, "cutting solid " + std::to_string(index + 1), [&] {
    BRepAlgoAPI_Splitter splitter;
    TopTools_ListOfShape args, tools;
    args.Append(target.shape);
    tools.Append(tool_face(target.shape, cut));
    splitter.SetArguments(args);
    splitter.SetTools(tools);
    splitter.SetRunParallel(Standard_False);
    // The solid is a closed, outward one (imported or cut from one): the
    // kernel's check for an inverted solid (a point at infinity classified
    // against it, 5 % of gmsh_Kurbelwelle's refusal) cannot find one.
    splitter.SetCheckInverted(Standard_False);
    if (cut.fuzzy > 0.0) splitter.SetFuzzyValue(cut.fuzzy);
    splitter.Build();
    if (!splitter.IsDone() || splitter.HasErrors())
      throw MeshingError(ErrorCode::GeometryError,
                         "cutting solid " + std::to_string(index + 1) + " failed in the kernel");
    for (TopExp_Explorer ex(splitter.Shape(), TopAbs_SOLID); ex.More(); ex.Next())
      out.impl_->solids.push_back({ex.Current(), 0});
  });
  return out;
}

std::vector<Vec3> SolidPieces::boundary_samples(int index, int per_curve) const {
  check_index(*this, index);
  const TopoDS_Shape& solid = impl_->solids[static_cast<size_t>(index)].shape;
  std::vector<Vec3> out;
  detail::guarded(ErrorCode::GeometryError, "sampling solid " + std::to_string(index + 1), [&] {
    TopTools_IndexedMapOfShape vertices, edges;
    TopExp::MapShapes(solid, TopAbs_VERTEX, vertices);
    TopExp::MapShapes(solid, TopAbs_EDGE, edges);
    for (int i = 1; i <= vertices.Extent(); ++i)
      out.push_back(detail::to_vec3(BRep_Tool::Pnt(TopoDS::Vertex(vertices(i)))));
    for (int i = 1; i <= edges.Extent(); ++i) {
      const TopoDS_Edge edge = TopoDS::Edge(edges(i).Oriented(TopAbs_FORWARD));
      if (BRep_Tool::Degenerated(edge)) continue;  // a pole: its vertex is in
      // As the model's curve geometry evaluates it (curve_geometry.cpp).
      const BRepAdaptor_Curve c(edge);
      const double t0 = c.FirstParameter(), t1 = c.LastParameter();
      for (int k = 1; k <= per_curve; ++k)
        out.push_back(detail::to_vec3(c.Value(t0 + (t1 - t0) * k / (per_curve + 1))));
    }
  });
  return out;
}

SolidPieces SolidPieces::replace(int index, const SolidPieces& pieces) const {
  check_index(*this, index);
  SolidPieces out(*this);
  auto& solids = out.impl_->solids;
  const int owner = solids[static_cast<size_t>(index)].owner;
  solids.erase(solids.begin() + index);
  std::vector<detail::Piece> added;
  for (const detail::Piece& p : pieces.impl_->solids) added.push_back({p.shape, owner});
  solids.insert(solids.begin() + index, added.begin(), added.end());
  // The pieces of the solid they replace (or none) overlap nothing else.
  out.impl_->touching_only =
      impl_->touching_only && (pieces.impl_->solids.empty() || pieces.impl_->touching_only);
  return out;
}

geom::Model SolidPieces::build_model(bool imprint_merge, bool glue) const {
  silence_kernel_output();
  return detail::guarded(ErrorCode::GeometryError, "building the model of the pieces", [&] {
    std::vector<detail::Piece> solids = impl_->solids, faces = impl_->faces;
    if (solids.empty() && faces.empty())
      throw MeshingError(ErrorCode::InvalidInput, "no shapes to build a model from");
    if (imprint_merge) detail::imprint_merge(solids, faces, glue && impl_->touching_only);
    return detail::number_model(solids, faces, impl_->names, impl_->unit_in_metres);
  });
}

}  // namespace cooperage::occ
