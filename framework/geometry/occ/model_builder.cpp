// Workbench::build_model: collect the solids of all shapes, imprint and merge
// them (one BOPAlgo general fuse with every solid as an argument), then number
// entities deterministically and convert them into a geom::Model.
//
// Numbering: volumes in solid order; surfaces, curves and vertices in
// first-encounter order walking volumes -> shells (outer first) -> faces ->
// wires (outer first) -> edges (in loop order) -> vertices, with maps keyed on
// the un-oriented shape (TopTools_IndexedMapOfShape).
//
// Orientation: a face is recorded as oriented in its first volume, so its
// topological normal (surface normal, flipped when REVERSED) is the natural
// normal; its wires, explored from that oriented face, run with the material
// on the left seen against that normal (OCCT's convention).
#include "framework/geometry/occ/detail.h"
#include "framework/geometry/validate.h"

#include <BRepAlgoAPI_BuilderAlgo.hxx>
#include <BRepClass3d.hxx>
#include <BRepTools.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <TopoDS_Compound.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Iterator.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Solid.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>

#include <algorithm>
#include <map>

namespace cooperage::occ {
namespace {

using detail::Piece;

}  // namespace

namespace detail {

/// Solids and free faces of the named shapes, in creation order.
void collect(const std::vector<NamedShape>& shapes, std::vector<Piece>& solids,
             std::vector<Piece>& faces) {
  for (size_t i = 0; i < shapes.size(); ++i) {
    for (TopExp_Explorer ex(shapes[i].shape, TopAbs_SOLID); ex.More(); ex.Next())
      solids.push_back({ex.Current(), static_cast<int>(i)});
    for (TopExp_Explorer ex(shapes[i].shape, TopAbs_FACE, TopAbs_SOLID); ex.More(); ex.Next())
      faces.push_back({ex.Current(), static_cast<int>(i)});
  }
}

/// Imprint + merge: one general fuse of every piece; each piece is replaced by
/// its images (a solid partly overlapping another splits into several).
void imprint_merge(std::vector<Piece>& solids, std::vector<Piece>& faces, bool touching_only) {
  if (solids.size() + faces.size() < 2) return;
  BRepAlgoAPI_BuilderAlgo algo;
  TopTools_ListOfShape args;
  for (const auto& p : solids) args.Append(p.shape);
  for (const auto& p : faces) args.Append(p.shape);
  algo.SetArguments(args);
  algo.SetRunParallel(Standard_False);
  // Pieces that only touch need no face/face intersections but where their
  // faces coincide: a decomposition's trial models fused a third faster
  // (real-cad occt_Pump_TopCover --dim 3, the same mesh). Overlapping solids
  // (an assembly as imported) would be fused wrongly.
  if (touching_only) algo.SetGlue(BOPAlgo_GlueShift);
  algo.Build();
  if (!algo.IsDone() || algo.HasErrors())
    throw MeshingError(ErrorCode::GeometryError,
                       "imprint and merge of the solids failed in the kernel");
  auto images = [&](std::vector<Piece>& pieces, TopAbs_ShapeEnum type) {
    TopTools_IndexedMapOfShape seen;
    std::vector<Piece> out;
    for (const auto& p : pieces) {
      const TopTools_ListOfShape& mod = algo.Modified(p.shape);
      if (mod.IsEmpty()) {
        if (algo.IsDeleted(p.shape)) continue;
        if (seen.Add(p.shape) > static_cast<int>(out.size())) out.push_back(p);
        continue;
      }
      for (TopTools_ListOfShape::Iterator it(mod); it.More(); it.Next()) {
        if (it.Value().ShapeType() != type) continue;
        if (seen.Add(it.Value()) > static_cast<int>(out.size()))
          out.push_back({it.Value(), p.owner});
      }
    }
    pieces.swap(out);
  };
  images(solids, TopAbs_SOLID);
  images(faces, TopAbs_FACE);
}

}  // namespace detail

namespace {

using detail::Piece;

class Numbering {
 public:
  geom::Model build(const std::vector<Piece>& solids, const std::vector<Piece>& free_faces,
                    const std::vector<std::string>& names) {
    for (size_t v = 0; v < solids.size(); ++v)
      walk_solid(TopoDS::Solid(solids[v].shape), static_cast<int>(v) + 1);
    for (const auto& f : free_faces) face_index(TopoDS::Face(f.shape));

    geom::Model model;
    for (int i = 1; i <= vertices_.Extent(); ++i) {
      geom::Vertex v;
      v.point = detail::to_vec3(BRep_Tool::Pnt(TopoDS::Vertex(vertices_(i))));
      model.add_vertex(v);
    }
    for (int i = 1; i <= edges_.Extent(); ++i) {
      const TopoDS_Edge e = TopoDS::Edge(edges_(i).Oriented(TopAbs_FORWARD));
      geom::Curve c;
      c.start_vertex = vertices_.FindIndex(TopExp::FirstVertex(e));
      c.end_vertex = vertices_.FindIndex(TopExp::LastVertex(e));
      c.geometry = detail::make_curve_geometry(e);
      c.length = c.geometry->length();
      const int id = model.add_curve(c);
      model.mutable_vertex(c.start_vertex).curves.push_back(id);
      if (c.end_vertex != c.start_vertex) model.mutable_vertex(c.end_vertex).curves.push_back(id);
    }
    for (int i = 1; i <= faces_.Extent(); ++i) {
      const TopoDS_Face& f = oriented_faces_[static_cast<size_t>(i - 1)];
      geom::Surface s;
      s.loops = loops_[static_cast<size_t>(i - 1)];
      s.volumes = face_volumes_[static_cast<size_t>(i - 1)];
      s.geometry = detail::make_surface_geometry(f);
      const detail::FaceFacts facts = detail::face_facts(f);
      s.area = facts.area;
      if (facts.area > 0) s.centroid = facts.centroid;
      s.box = facts.box;
      const int id = model.add_surface(s);
      for (const auto& loop : s.loops)
        for (const auto& use : loop.uses) {
          auto& owners = model.mutable_curve(use.curve).surfaces;
          if (std::find(owners.begin(), owners.end(), id) == owners.end()) owners.push_back(id);
        }
    }
    std::map<int, int> pieces_per_owner, seen_per_owner;
    for (const auto& p : solids) ++pieces_per_owner[p.owner];
    for (size_t v = 0; v < solids.size(); ++v) {
      geom::Volume vol;
      vol.shells = shells_[v];
      vol.volume = detail::solid_volume(solids[v].shape);
      // The union of its faces' tight boxes: what BRepBndLib::AddOptimal
      // gives for the solid, without bounding every face a second time (an
      // optimisation per face; the decomposition search builds a model for
      // every candidate cut).
      for (const auto& shell : vol.shells)
        for (const auto& use : shell) vol.box.add(model.surface(use.surface).box);
      const int owner = solids[v].owner;
      vol.name = names[static_cast<size_t>(owner)];
      if (pieces_per_owner[owner] > 1) vol.name += "." + std::to_string(++seen_per_owner[owner]);
      model.add_volume(vol);
    }
    for (const auto& v : model.vertices()) {
      auto& list = model.mutable_vertex(v.id).curves;
      std::sort(list.begin(), list.end());
    }
    for (const auto& c : model.curves()) {
      auto& list = model.mutable_curve(c.id).surfaces;
      std::sort(list.begin(), list.end());
    }
    return model;
  }

 private:
  void walk_solid(const TopoDS_Solid& solid, int volume_id) {
    std::vector<TopoDS_Shell> shells;
    const TopoDS_Shell outer = BRepClass3d::OuterShell(solid);
    for (TopoDS_Iterator it(solid); it.More(); it.Next()) {
      if (it.Value().ShapeType() != TopAbs_SHELL) continue;
      if (!outer.IsNull() && it.Value().IsSame(outer))
        shells.insert(shells.begin(), TopoDS::Shell(it.Value()));
      else
        shells.push_back(TopoDS::Shell(it.Value()));
    }
    std::vector<std::vector<geom::SurfaceUse>> uses;
    for (const auto& shell : shells) {
      std::vector<geom::SurfaceUse> shell_uses;
      for (TopoDS_Iterator it(shell); it.More(); it.Next()) {
        if (it.Value().ShapeType() != TopAbs_FACE) continue;
        const TopoDS_Face f = TopoDS::Face(it.Value());
        if (f.Orientation() != TopAbs_FORWARD && f.Orientation() != TopAbs_REVERSED) continue;
        const int idx = face_index(f);
        auto& vols = face_volumes_[static_cast<size_t>(idx - 1)];
        if (std::find(vols.begin(), vols.end(), volume_id) == vols.end()) vols.push_back(volume_id);
        const bool same =
            f.Orientation() == oriented_faces_[static_cast<size_t>(idx - 1)].Orientation();
        shell_uses.push_back({idx, same ? geom::Sense::Forward : geom::Sense::Reversed});
      }
      if (!shell_uses.empty()) uses.push_back(std::move(shell_uses));
    }
    shells_.push_back(std::move(uses));
  }

  /// Index of the face, numbering it and its loops on first encounter.
  int face_index(const TopoDS_Face& f) {
    const int known = faces_.FindIndex(f);
    if (known > 0) return known;
    const int idx = faces_.Add(f);
    oriented_faces_.push_back(f);
    face_volumes_.emplace_back();
    std::vector<TopoDS_Wire> wires;
    const TopoDS_Wire outer = BRepTools::OuterWire(f);
    if (!outer.IsNull()) wires.push_back(outer);
    for (TopoDS_Iterator it(f); it.More(); it.Next()) {
      if (it.Value().ShapeType() != TopAbs_WIRE) continue;
      if (!outer.IsNull() && it.Value().IsSame(outer)) continue;
      wires.push_back(TopoDS::Wire(it.Value()));
    }
    std::vector<geom::Loop> loops;
    for (const auto& w : wires) {
      geom::Loop loop;
      for (BRepTools_WireExplorer wex(w, f); wex.More(); wex.Next()) {
        const TopoDS_Edge& e = wex.Current();
        if (BRep_Tool::Degenerated(e)) continue;
        const TopAbs_Orientation o = e.Orientation();
        if (o != TopAbs_FORWARD && o != TopAbs_REVERSED) continue;
        loop.uses.push_back(
            {edge_index(e), o == TopAbs_FORWARD ? geom::Sense::Forward : geom::Sense::Reversed});
      }
      if (!loop.uses.empty()) loops.push_back(std::move(loop));
    }
    loops_.push_back(std::move(loops));
    return idx;
  }

  int edge_index(const TopoDS_Edge& e) {
    const int known = edges_.FindIndex(e);
    if (known > 0) return known;
    const TopoDS_Edge fwd = TopoDS::Edge(e.Oriented(TopAbs_FORWARD));
    const int idx = edges_.Add(fwd);
    vertices_.Add(TopExp::FirstVertex(fwd));
    vertices_.Add(TopExp::LastVertex(fwd));
    return idx;
  }

  TopTools_IndexedMapOfShape faces_, edges_, vertices_;
  std::vector<TopoDS_Face> oriented_faces_;
  std::vector<std::vector<int>> face_volumes_;
  std::vector<std::vector<geom::Loop>> loops_;
  std::vector<std::vector<std::vector<geom::SurfaceUse>>> shells_;
};

}  // namespace

namespace detail {

geom::Model number_model(const std::vector<Piece>& solids, const std::vector<Piece>& faces,
                         const std::vector<std::string>& names, double unit_in_metres) {
  geom::Model model = Numbering().build(solids, faces, names);
  if (unit_in_metres > 0.0) model.set_unit_in_metres(unit_in_metres);
  geom::validate(model);
  return model;
}

TopoDS_Shape merge_alone(const TopoDS_Shape& shape) {
  std::vector<Piece> solids, faces;
  collect({NamedShape{"", shape, {}}}, solids, faces);
  imprint_merge(solids, faces);
  TopoDS_Compound out;
  BRep_Builder b;
  b.MakeCompound(out);
  for (const auto& p : solids) b.Add(out, p.shape);
  for (const auto& p : faces) b.Add(out, p.shape);
  return out;
}

geom::Model build_model_of(const std::vector<NamedShape>& shapes, const BuildOptions& options,
                           double unit_in_metres) {
  silence_kernel_output();
  return guarded(ErrorCode::GeometryError, "building the model", [&] {
    std::vector<Piece> solids, faces;
    // A lone import merged in its child: the same pieces, in the same order.
    const bool premerged =
        options.imprint_merge && shapes.size() == 1 && !shapes[0].merged.IsNull();
    if (premerged) {
      collect({NamedShape{shapes[0].name, shapes[0].merged, {}}}, solids, faces);
    } else {
      collect(shapes, solids, faces);
    }
    if (solids.empty() && faces.empty())
      throw MeshingError(ErrorCode::InvalidInput, "no shapes to build a model from");
    if (options.imprint_merge && !premerged) imprint_merge(solids, faces);
    std::vector<std::string> names;
    for (const NamedShape& s : shapes) names.push_back(s.name);
    return number_model(solids, faces, names, unit_in_metres);
  });
}

}  // namespace detail

geom::Model Workbench::build_model(const BuildOptions& options) const {
  return detail::build_model_of(impl_->shapes, options, impl_->unit_in_metres);
}

}  // namespace cooperage::occ
