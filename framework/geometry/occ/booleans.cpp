// Workbench booleans (fuse, cut, common) and the webcut by a plane.
#include "framework/geometry/occ/detail.h"

#include <BRepAlgoAPI_Common.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepAlgoAPI_Splitter.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <Bnd_Box.hxx>
#include <ShapeUpgrade_UnifySameDomain.hxx>
#include <TopTools_ListOfShape.hxx>
#include <gp_Pln.hxx>

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
      ShapeUpgrade_UnifySameDomain unify(s, Standard_True, Standard_True, Standard_False);
      unify.Build();
      s = unify.Shape();
    } else if (op == Op::Cut) {
      BRepAlgoAPI_Cut algo;
      s = run(algo);
    } else {
      BRepAlgoAPI_Common algo;
      s = run(algo);
    }
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
