// Workbench booleans (fuse, cut, common) and the webcut by a plane.
#include "framework/geometry/occ/detail.h"

#include <BRepAlgoAPI_Common.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepAlgoAPI_Splitter.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepGProp.hxx>
#include <Bnd_Box.hxx>
#include <GProp_GProps.hxx>
#include <ShapeUpgrade_UnifySameDomain.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopTools_MapOfShape.hxx>
#include <gp_Pln.hxx>

#include <cmath>
#include <set>

namespace cooperage::occ {
namespace {

enum class Op { Fuse, Cut, Common };

const char* op_name(Op op) {
  switch (op) {
    case Op::Fuse: return "fuse";
    case Op::Cut: return "cut";
    case Op::Common: return "common";
  }
  return "boolean";
}

/// A face narrower than this fraction of the shape's diagonal (twice its
/// area over its perimeter) is a sliver.
constexpr double kSliverWidth = 0.01;

/// The faces of one surface that meet along an edge, one face again. A fuse
/// unifies them all (its coplanar faces). A cut or a common unifies only
/// slivers into their neighbours: where a second hole meets a hole's wall
/// just beside the wall's own seam, the kernel leaves a strip 0.05 wide as a
/// face of its own; its short rims graded the curves round it and twisted a
/// sweep's ribs into inverted hexes (plan => mesh campaign seed 3 case 45).
/// A wall split at its seam into two wide faces stays split: unified, such
/// walls swept worse in as many campaign parts as they swept better.
TopoDS_Shape unify_same_domain(const TopoDS_Shape& shape, bool slivers_only) {
  ShapeUpgrade_UnifySameDomain unify(shape, Standard_True, Standard_True, Standard_False);
  if (slivers_only) {
    Bnd_Box box;
    BRepBndLib::Add(shape, box);
    const double diagonal = box.IsVoid() ? 0.0 : std::sqrt(box.SquareExtent());
    TopTools_MapOfShape slivers;
    for (TopExp_Explorer f(shape, TopAbs_FACE); f.More(); f.Next()) {
      GProp_GProps area, perimeter;
      BRepGProp::SurfaceProperties(f.Current(), area);
      BRepGProp::LinearProperties(f.Current(), perimeter);
      const double width =
          perimeter.Mass() > 0 ? 2.0 * std::abs(area.Mass()) / perimeter.Mass() : 0.0;
      if (width < kSliverWidth * diagonal) slivers.Add(f.Current());
    }
    TopTools_IndexedDataMapOfShapeListOfShape faces_of_edge;
    TopExp::MapShapesAndAncestors(shape, TopAbs_EDGE, TopAbs_FACE, faces_of_edge);
    TopTools_MapOfShape keep;  // every edge no sliver borders
    for (int i = 1; i <= faces_of_edge.Extent(); ++i) {
      bool beside_sliver = false;
      for (const TopoDS_Shape& f : faces_of_edge(i))
        beside_sliver = beside_sliver || slivers.Contains(f);
      if (!beside_sliver) keep.Add(faces_of_edge.FindKey(i));
    }
    unify.KeepShapes(keep);
  }
  unify.Build();
  return unify.Shape();
}

void boolean(Workbench::Impl& impl, Op op, const std::string& name,
             const std::vector<std::string>& inputs) {
  if (inputs.size() < 2)
    detail::invalid(name, std::string(op_name(op)) + " needs at least two inputs");
  std::set<std::string> seen;
  for (const auto& in : inputs) {
    impl.get(in);  // throws for unknown names
    if (!seen.insert(in).second) detail::invalid(name, "input '" + in + "' is given twice");
  }
  if (name.empty()) throw MeshingError(ErrorCode::InvalidInput, "a shape needs a non-empty name");
  if (impl.find(name) && !seen.count(name))
    detail::invalid(name, "a shape of that name already exists");

  const std::string context = "shape '" + name + "': " + op_name(op);
  const TopoDS_Shape result = detail::guarded(ErrorCode::GeometryError, context, [&] {
    TopTools_ListOfShape args, tools;
    args.Append(impl.get(inputs[0]));
    for (size_t i = 1; i < inputs.size(); ++i) tools.Append(impl.get(inputs[i]));
    auto run = [&](BRepAlgoAPI_BooleanOperation& algo) {
      algo.SetArguments(args);
      algo.SetTools(tools);
      algo.SetRunParallel(Standard_False);
      algo.Build();
      if (!algo.IsDone() || algo.HasErrors())
        throw MeshingError(ErrorCode::GeometryError, context + " failed in the kernel");
      return algo.Shape();
    };
    TopoDS_Shape s;
    if (op == Op::Fuse) {
      BRepAlgoAPI_Fuse algo;
      s = run(algo);
    } else if (op == Op::Cut) {
      BRepAlgoAPI_Cut algo;
      s = run(algo);
    } else {
      BRepAlgoAPI_Common algo;
      s = run(algo);
    }
    s = unify_same_domain(s, op != Op::Fuse);
    if (!detail::contains_solid(s))
      throw MeshingError(ErrorCode::GeometryError, context + " gives an empty result");
    return s;
  });
  for (const auto& in : inputs) impl.remove(in);
  impl.add(name, result);
}

}  // namespace

void Workbench::fuse(const std::string& name, const std::vector<std::string>& inputs) {
  boolean(*impl_, Op::Fuse, name, inputs);
}
void Workbench::cut(const std::string& name, const std::vector<std::string>& inputs) {
  boolean(*impl_, Op::Cut, name, inputs);
}
void Workbench::common(const std::string& name, const std::vector<std::string>& inputs) {
  boolean(*impl_, Op::Common, name, inputs);
}

void Workbench::webcut(const std::string& shape, const Vec3& origin, const Vec3& normal) {
  NamedShape* target = impl_->find(shape);
  if (!target) detail::invalid(shape, "no such shape");
  const gp_Dir dir = detail::checked_dir(shape, normal, "webcut normal");
  if (!origin.allFinite()) detail::invalid(shape, "webcut origin must be finite");
  target->merged.Nullify();
  target->shape = detail::guarded(ErrorCode::GeometryError, "shape '" + shape + "': webcut", [&] {
    Bnd_Box box;
    BRepBndLib::Add(target->shape, box);
    double x0, y0, z0, x1, y1, z1;
    box.Get(x0, y0, z0, x1, y1, z1);
    const Vec3 lo(x0, y0, z0), hi(x1, y1, z1);
    const double half = 2.0 * ((hi - lo).norm() + (0.5 * (lo + hi) - origin).norm()) + 1.0;
    const TopoDS_Face tool =
        BRepBuilderAPI_MakeFace(gp_Pln(detail::to_pnt(origin), dir), -half, half, -half, half)
            .Face();
    BRepAlgoAPI_Splitter splitter;
    TopTools_ListOfShape args, tools;
    args.Append(target->shape);
    tools.Append(tool);
    splitter.SetArguments(args);
    splitter.SetTools(tools);
    splitter.SetRunParallel(Standard_False);
    splitter.Build();
    if (!splitter.IsDone() || splitter.HasErrors())
      throw MeshingError(ErrorCode::GeometryError,
                         "shape '" + shape + "': webcut failed in the kernel");
    return splitter.Shape();
  });
}

}  // namespace cooperage::occ
