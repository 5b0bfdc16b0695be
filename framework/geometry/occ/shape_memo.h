#pragma once
// Values remembered per shape (same TShape and location) for the calling
// thread: measures a model build would otherwise take again (face_facts.cpp,
// solid_volume.cpp). Holding the shape keeps its TShape alive, so a key is
// never reused by another shape. Bounded: cleared past kMax entries.
#include <NCollection_DataMap.hxx>
#include <TopTools_ShapeMapHasher.hxx>
#include <TopoDS_Shape.hxx>

namespace cooperage::occ::detail {

template <class T, int kMax>
class ShapeMemo {
 public:
  static const T* find(const TopoDS_Shape& shape) { return known().Seek(shape); }
  static void remember(const TopoDS_Shape& shape, const T& value) {
    Map& map = known();
    if (map.Extent() >= kMax) map.Clear();
    map.Bind(shape, value);
  }

 private:
  using Map = NCollection_DataMap<TopoDS_Shape, T, TopTools_ShapeMapHasher>;
  static Map& known() {
    thread_local Map map;
    return map;
  }
};

}  // namespace cooperage::occ::detail
