#pragma once
// Values remembered per shape (same TShape and location) for the calling
// thread: measures a model build would otherwise take again (face_facts.cpp,
// solid_volume.cpp). Holding the shape keeps its TShape alive, so a key is
// never reused by another shape. Bounded: cleared past kMax entries.
#include <NCollection_DataMap.hxx>
#include <TopTools_ShapeMapHasher.hxx>
#include <TopoDS_Shape.hxx>

#include <cstddef>
#include <unordered_map>

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

/// A function's answers by their exact query, at most kMax (cleared when
/// full): for a pure function asked the same queries again (a search
/// planning every piece of every cut). Not thread-safe; keep one per thread.
template <class Key, class Value, std::size_t kMax, class Hash = std::hash<Key>>
class QueryMemo {
 public:
  template <class Compute>
  Value answer(const Key& key, Compute&& compute) {
    if (const auto it = known_.find(key); it != known_.end()) return it->second;
    if (known_.size() >= kMax) known_.clear();
    const Value value = compute();
    known_.emplace(key, value);
    return value;
  }

 private:
  std::unordered_map<Key, Value, Hash> known_;
};

}  // namespace cooperage::occ::detail
