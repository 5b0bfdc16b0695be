// The loft module (libcooperage_occ_loft.so): OCCT's ThruSections, loaded by
// loft.cpp on the first <loft> instead of at start-up. Its toolkit,
// TKOffset, brings TKFillet and TKBool with it: ~14,000 symbol relocations,
// ~12 ms of every process's start (issue 20), for a primitive few journals
// use. A C interface, versioned by cooperage_loft_abi(); kernel exceptions
// propagate to the caller's guard (detail::guarded).
#include <BRepOffsetAPI_ThruSections.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Shape.hxx>

#include <cstddef>

extern "C" {

__attribute__((visibility("default"))) int cooperage_loft_abi() { return 1; }

/// A solid through `count` sections in order, each a closed wire or a
/// vertex (an apex at either end). `ruled` joins the sections by ruled
/// faces, keeping the wires' pairing of edges; otherwise OCCT makes the
/// sections compatible and fits smooth faces. 0 and *out set on success.
__attribute__((visibility("default"))) int cooperage_loft_thru_sections(
    const TopoDS_Shape* sections, size_t count, int ruled, TopoDS_Shape* out) {
  BRepOffsetAPI_ThruSections maker(Standard_True, ruled ? Standard_True : Standard_False);
  maker.CheckCompatibility(ruled ? Standard_False : Standard_True);
  for (size_t i = 0; i < count; ++i) {
    if (sections[i].ShapeType() == TopAbs_VERTEX)
      maker.AddVertex(TopoDS::Vertex(sections[i]));
    else
      maker.AddWire(TopoDS::Wire(sections[i]));
  }
  maker.Build();
  if (!maker.IsDone()) return 1;
  *out = maker.Shape();
  return 0;
}

}  // extern "C"
