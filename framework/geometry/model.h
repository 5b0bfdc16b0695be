// B-rep model: topology with stable 1-based ids and evaluators, independent
// of the CAD kernel that produced it (docs/design.md; the seed brief, "Core types").
#pragma once

#include "framework/geometry/evaluators.h"
#include "framework/geometry/types.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace cooperage::geom {

struct Vertex {
  int id = 0;
  Vec3 point = Vec3::Zero();
  std::vector<int> curves;  ///< curves ending here, ascending ids
};

/// A use of a curve in a surface loop.
struct CurveUse {
  int curve = 0;
  Sense sense = Sense::Forward;  ///< Forward: walked from start to end vertex
};

/// A closed boundary loop of a surface, ordered so that the face lies on the
/// left when walking it, seen against the natural normal (outer loop
/// counter-clockwise, holes clockwise, viewed from outside).
struct Loop {
  std::vector<CurveUse> uses;
};

struct Curve {
  int id = 0;
  int start_vertex = 0;       ///< vertex at range().first
  int end_vertex = 0;         ///< vertex at range().second (== start for closed curves)
  std::vector<int> surfaces;  ///< surfaces whose loops use this curve, ascending
  std::shared_ptr<const CurveGeometry> geometry;
  double length = 0.0;
};

struct Surface {
  int id = 0;
  std::vector<Loop> loops;  ///< outer loop first
  /// The 1 or 2 volumes bounded by this surface (0 for a free surface);
  /// the natural normal points out of volumes.front().
  std::vector<int> volumes;
  std::shared_ptr<const SurfaceGeometry> geometry;
  double area = 0.0;
  /// Area centroid (off the face where it curves: on a whole cylinder's
  /// axis); it moves with the face, unlike the box's centre. Unset in
  /// models built without OCCT.
  std::optional<Vec3> centroid;
  BoundingBox box;
};

/// A use of a surface in a volume shell.
struct SurfaceUse {
  int surface = 0;
  Sense sense = Sense::Forward;  ///< Forward: natural normal points out of this volume
};

struct Volume {
  int id = 0;
  /// Closed shells, outer shell first; cavities follow.
  std::vector<std::vector<SurfaceUse>> shells;
  double volume = 0.0;
  BoundingBox box;
  std::string name;  ///< the journal or file name of the solid, if any
};

/// The model. Entities are stored by id: vertex(i) is vertices()[i - 1].
class Model {
 public:
  const std::vector<Vertex>& vertices() const { return vertices_; }
  const std::vector<Curve>& curves() const { return curves_; }
  const std::vector<Surface>& surfaces() const { return surfaces_; }
  const std::vector<Volume>& volumes() const { return volumes_; }

  /// Entity by 1-based id; throws MeshingError(InvalidInput) when out of range.
  const Vertex& vertex(int id) const;
  const Curve& curve(int id) const;
  const Surface& surface(int id) const;
  const Volume& volume(int id) const;

  /// Sense of surface s in volume v; throws if s does not bound v.
  Sense sense_in(int surface_id, int volume_id) const;
  /// Unit normal of surface s at parameters uv pointing out of volume v.
  Vec3 outward_normal(int surface_id, int volume_id, const Vec2& uv) const;
  /// All surfaces of a volume (every shell), in shell order.
  std::vector<int> surfaces_of(int volume_id) const;
  /// Bounding box of the whole model.
  BoundingBox box() const;
  /// Length unit of the source, in metres per model unit (1e-3 for mm).
  double unit_in_metres() const { return unit_in_metres_; }

  /// Builder access (used by backends and tests). Ids are assigned in order.
  int add_vertex(Vertex v);
  int add_curve(Curve c);
  int add_surface(Surface s);
  int add_volume(Volume v);
  Vertex& mutable_vertex(int id);
  Curve& mutable_curve(int id);
  Surface& mutable_surface(int id);
  Volume& mutable_volume(int id);
  void set_unit_in_metres(double u) { unit_in_metres_ = u; }

  /// Checks ids, back references, loop closure and shell senses; throws
  /// MeshingError(GeometryError) naming the first broken entity (broken
  /// topology comes from the input). geom::validate() (validate.h) adds the
  /// geometric checks.
  void validate() const;

 private:
  std::vector<Vertex> vertices_;
  std::vector<Curve> curves_;
  std::vector<Surface> surfaces_;
  std::vector<Volume> volumes_;
  double unit_in_metres_ = 1.0;
};

/// Euler-Poincare left side V - E + F - R of the model's boundary, where R
/// counts inner loops (rings). It equals 2 (S - H) for S shells of total
/// genus H: 2 for a brick or cylinder, 2 - 2n for a plate with n through holes.
int euler_characteristic(const Model& model);

}  // namespace cooperage::geom
