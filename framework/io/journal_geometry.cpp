// The <geometry> section of a journal: shape operations in order, then
// <imprint_merge>. Shape names are checked in journal order: a name is
// defined once, and a boolean consumes its inputs.
#include "framework/io/journal_xml.h"

#include "framework/core/text.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <string>
#include <type_traits>
#include <variant>

namespace cooperage::io::detail {

namespace {

const std::vector<std::string> kGeometryElements = {
    "import", "brick", "cylinder", "cone",      "sphere", "torus", "prism",  "revolve",      "loft",
    "fuse",   "cut",   "common",   "translate", "rotate", "scale", "webcut", "imprint_merge"};

/// Names in journal order: where each was defined and, once a boolean used
/// it, where it was consumed.
class ShapeTable {
 public:
  void define(const Element& e, const std::string& name) {
    if (auto it = defined_.find(name); it != defined_.end())
      e.fail_at("name", "shape \"" + name + "\" is already defined at line " +
                            std::to_string(it->second) + "; names must be unique");
    defined_[name] = e.line();
  }
  void require_live(const Element& e, const char* attribute, const std::string& name) const {
    if (defined_.count(name) == 0) {
      std::vector<std::string> names;
      for (const auto& [n, line] : defined_)
        if (consumed_.count(n) == 0) names.push_back(n);
      e.fail_at(attribute, "attribute \"" + std::string(attribute) + "\" refers to shape \"" +
                               name + "\", which is not defined before this line" +
                               suggestion(name, names, "\"", "\""));
    }
    if (auto it = consumed_.find(name); it != consumed_.end())
      e.fail_at(attribute, "shape \"" + name + "\" was consumed by the boolean at line " +
                               std::to_string(it->second) + "; use that boolean's result");
  }
  void consume(const Element& e, const std::string& name) { consumed_[name] = e.line(); }

 private:
  std::map<std::string, int> defined_;
  std::map<std::string, int> consumed_;
};

/// A profile or hole: consecutive points distinct, not collinear, coplanar.
/// Returns the unit normal of its plane.
Vec3 check_planar_polygon(const Element& e, const Polygon& points) {
  geom::BoundingBox box;
  for (const auto& p : points) box.add(p);
  const double scale = box.diagonal();
  for (size_t i = 0; i < points.size(); ++i) {
    const auto& next = points[(i + 1) % points.size()];
    if ((points[i] - next).norm() <= 1e-12 * scale) {
      if (i + 1 == points.size())
        e.fail_at("points",
                  "the first and last points coincide; the polygon closes by itself, "
                  "do not repeat the first point");
      e.fail_at("points",
                "points " + std::to_string(i + 1) + " and " + std::to_string(i + 2) + " coincide");
    }
  }
  Vec3 normal = Vec3::Zero();  // Newell's method
  for (size_t i = 0; i < points.size(); ++i)
    normal += points[i].cross(points[(i + 1) % points.size()]);
  if (normal.norm() <= 1e-12 * scale * scale)
    e.fail_at("points", "the points are collinear (the polygon has no area)");
  normal.normalize();
  for (const auto& p : points)
    if (std::abs((p - points[0]).dot(normal)) > 1e-9 * scale)
      e.fail_at("points", "the points do not lie in one plane");
  return normal;
}

/// Reads <profile> or <hole>; `normal` receives the unit normal of its plane.
Polygon read_polygon(const Element& e, Vec3& normal) {
  e.allow_attributes({"points"});
  e.expect_empty();
  Polygon polygon = e.points("points");
  normal = check_planar_polygon(e, polygon);
  return polygon;
}

PrismOp read_prism(const Element& e) {
  e.allow_attributes({"name", "direction"});
  PrismOp op;
  op.name = e.shape_name("name");
  op.direction = e.required_vector("direction", VectorKind::NonZero);
  const auto children = e.children();
  if (children.empty() || std::string(children[0].name()) != "profile")
    e.fail("needs a <profile> as its first child, then zero or more <hole>");
  Vec3 normal = Vec3::UnitZ();
  geom::BoundingBox box;
  for (size_t i = 0; i < children.size(); ++i) {
    const Element& child = children[i];
    const std::string tag = child.name();
    if (tag == "profile" && i == 0) {
      op.profile = read_polygon(child, normal);
      for (const auto& p : op.profile) box.add(p);
      if (std::abs(normal.dot(op.direction.normalized())) < 1e-9)
        e.fail_at("direction", "attribute \"direction\" lies in the plane of the profile");
    } else if (tag == "hole") {
      Vec3 hole_normal;
      Polygon hole = read_polygon(child, hole_normal);
      for (const auto& p : hole)
        if (std::abs((p - op.profile[0]).dot(normal)) > 1e-9 * box.diagonal())
          child.fail_at("points", "the hole does not lie in the plane of the profile");
      op.holes.push_back(std::move(hole));
    } else {
      child.fail(tag == "profile" ? "a <prism> has exactly one <profile>, before any <hole>"
                                  : "unknown element in <prism>; allowed: <profile>, <hole>");
    }
  }
  return op;
}

RevolveOp read_revolve(const Element& e) {
  e.allow_attributes({"name", "origin", "axis", "angle"});
  RevolveOp op;
  op.name = e.shape_name("name");
  op.origin = e.vector("origin", VectorKind::Any).value_or(op.origin);
  op.axis = e.required_vector("axis", VectorKind::NonZero);
  op.angle = e.number("angle", NumberKind::Positive).value_or(op.angle);
  if (op.angle > 360) e.fail_at("angle", "attribute \"angle\" must be in (0, 360] degrees");
  const auto children = e.children();
  for (const Element& child : children)
    if (std::string(child.name()) != "profile")
      child.fail("unknown element in <revolve>; allowed: one <profile>");
  if (children.size() != 1) e.fail("needs exactly one child, <profile>");
  Vec3 normal;
  op.profile = read_polygon(children[0], normal);
  return op;
}

/// <loft name ruled> with two or more <section points>: planar polygons, or a
/// single point (an apex) as the first or last section. The geometry kernel
/// checks the rest (consecutive sections apart, matching windings).
LoftOp read_loft(const Element& e) {
  e.allow_attributes({"name", "ruled"});
  LoftOp op;
  op.name = e.shape_name("name");
  op.ruled = e.boolean("ruled").value_or(true);
  const auto children = e.children();
  for (const Element& child : children)
    if (std::string(child.name()) != "section")
      child.fail("unknown element in <loft>; allowed: <section>");
  if (children.size() < 2)
    e.fail("needs at least two <section> children, got " + std::to_string(children.size()));
  const Element* first_polygon = nullptr;  // the <section> ruled counts are compared with
  size_t polygon_size = 0;
  for (size_t i = 0; i < children.size(); ++i) {
    const Element& child = children[i];
    child.allow_attributes({"points"});
    child.expect_empty();
    Polygon section = child.points("points", /*allow_single=*/true);
    if (section.size() == 1) {
      if (i != 0 && i + 1 != children.size())
        child.fail_at("points",
                      "a single-point section (an apex) is allowed only as the first "
                      "or the last <section>");
    } else {
      check_planar_polygon(child, section);
      if (!first_polygon) {
        first_polygon = &child;
        polygon_size = section.size();
      } else if (op.ruled && section.size() != polygon_size) {
        child.fail_at("points",
                      "a ruled loft needs the same number of points in every polygon "
                      "<section> (OpenCASCADE joins the sections edge by edge and needs "
                      "compatible wires): the <section> at line " +
                          std::to_string(first_polygon->line()) + " has " +
                          std::to_string(polygon_size) + ", this one has " +
                          std::to_string(section.size()) +
                          "; use ruled=\"false\" or give them the same count");
      }
    }
    op.sections.push_back(std::move(section));
  }
  if (!first_polygon) e.fail("needs at least one polygon <section> (three or more points)");
  return op;
}

BooleanOp read_boolean(const Element& e, BooleanKind kind, ShapeTable& shapes) {
  e.allow_attributes({"name", "inputs"});
  e.expect_empty();
  BooleanOp op;
  op.kind = kind;
  op.name = e.shape_name("name");
  op.inputs = e.shape_names("inputs");
  for (const auto& input : op.inputs) shapes.require_live(e, "inputs", input);
  for (const auto& input : op.inputs) shapes.consume(e, input);
  return op;
}

GeometryOp read_op(const Element& e, const std::string& tag, ShapeTable& shapes) {
  if (tag == "import") {
    e.allow_attributes({"name", "file", "heal"});
    ImportOp op{e.shape_name("name"), e.required("file"), e.boolean("heal").value_or(true)};
    std::string lower = op.file;
    for (auto& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    bool known = false;
    for (const char* ext : {".step", ".stp", ".iges", ".igs", ".brep"}) {
      const std::string x = ext;
      known = known ||
              (lower.size() > x.size() && lower.compare(lower.size() - x.size(), x.size(), x) == 0);
    }
    if (!known)
      e.fail_at("file", "attribute \"file\" must end in .step, .stp, .iges, .igs or .brep, got \"" +
                            clip_path(op.file) + "\"");
    return op;
  }
  if (tag == "brick") {
    e.allow_attributes({"name", "origin", "size"});
    BrickOp op;
    op.name = e.shape_name("name");
    op.origin = e.vector("origin", VectorKind::Any).value_or(op.origin);
    op.size = e.required_vector("size", VectorKind::Positive);
    return op;
  }
  if (tag == "cylinder") {
    e.allow_attributes({"name", "base", "axis", "radius", "height"});
    CylinderOp op;
    op.name = e.shape_name("name");
    op.base = e.vector("base", VectorKind::Any).value_or(op.base);
    op.axis = e.vector("axis", VectorKind::NonZero).value_or(op.axis);
    op.radius = e.required_number("radius", NumberKind::Positive);
    op.height = e.required_number("height", NumberKind::Positive);
    return op;
  }
  if (tag == "cone") {
    e.allow_attributes({"name", "base", "axis", "radius1", "radius2", "height"});
    ConeOp op;
    op.name = e.shape_name("name");
    op.base = e.vector("base", VectorKind::Any).value_or(op.base);
    op.axis = e.vector("axis", VectorKind::NonZero).value_or(op.axis);
    op.radius1 = e.required_number("radius1", NumberKind::NonNegative);
    op.radius2 = e.number("radius2", NumberKind::NonNegative).value_or(0.0);
    op.height = e.required_number("height", NumberKind::Positive);
    if (op.radius1 == op.radius2)
      e.fail(op.radius1 == 0 ? "radius1 and radius2 cannot both be 0"
                             : "radius1 equals radius2; use <cylinder>");
    return op;
  }
  if (tag == "sphere") {
    e.allow_attributes({"name", "center", "radius"});
    SphereOp op;
    op.name = e.shape_name("name");
    op.center = e.vector("center", VectorKind::Any).value_or(op.center);
    op.radius = e.required_number("radius", NumberKind::Positive);
    return op;
  }
  if (tag == "torus") {
    e.allow_attributes({"name", "center", "axis", "major_radius", "minor_radius"});
    TorusOp op;
    op.name = e.shape_name("name");
    op.center = e.vector("center", VectorKind::Any).value_or(op.center);
    op.axis = e.vector("axis", VectorKind::NonZero).value_or(op.axis);
    op.major_radius = e.required_number("major_radius", NumberKind::Positive);
    op.minor_radius = e.required_number("minor_radius", NumberKind::Positive);
    if (op.minor_radius >= op.major_radius)
      e.fail(
          "minor_radius must be less than major_radius (a tube that reaches the axis "
          "intersects itself)");
    return op;
  }
  if (tag == "prism") return read_prism(e);
  if (tag == "revolve") return read_revolve(e);
  if (tag == "loft") return read_loft(e);
  if (tag == "fuse") return read_boolean(e, BooleanKind::Fuse, shapes);
  if (tag == "cut") return read_boolean(e, BooleanKind::Cut, shapes);
  if (tag == "common") return read_boolean(e, BooleanKind::Common, shapes);
  if (tag == "translate") {
    e.allow_attributes({"shape", "by"});
    TranslateOp op;
    op.shape = e.shape_name("shape");
    op.by = e.required_vector("by", VectorKind::Any);
    return op;
  }
  if (tag == "rotate") {
    e.allow_attributes({"shape", "origin", "axis", "angle"});
    RotateOp op;
    op.shape = e.shape_name("shape");
    op.origin = e.vector("origin", VectorKind::Any).value_or(op.origin);
    op.axis = e.required_vector("axis", VectorKind::NonZero);
    op.angle = e.required_number("angle", NumberKind::Any);
    return op;
  }
  if (tag == "scale") {
    e.allow_attributes({"shape", "origin", "factor"});
    ScaleOp op;
    op.shape = e.shape_name("shape");
    op.origin = e.vector("origin", VectorKind::Any).value_or(op.origin);
    op.factor = e.required_number("factor", NumberKind::Positive);
    return op;
  }
  // webcut (the caller rejects unknown tags)
  e.allow_attributes({"shape", "origin", "normal"});
  WebcutOp op;
  op.shape = e.shape_name("shape");
  op.origin = e.required_vector("origin", VectorKind::Any);
  op.normal = e.required_vector("normal", VectorKind::NonZero);
  return op;
}

}  // namespace

void read_geometry(const Element& geometry, Job& job) {
  geometry.allow_attributes({});
  const auto children = geometry.children();
  ShapeTable shapes;
  for (size_t i = 0; i < children.size(); ++i) {
    const Element& e = children[i];
    const std::string tag = e.name();
    if (std::find(kGeometryElements.begin(), kGeometryElements.end(), tag) ==
        kGeometryElements.end())
      e.fail("unknown element in <geometry>" + suggestion(tag, kGeometryElements, "<", ">") +
             "; allowed: " + list(kGeometryElements, "<", ">"));
    if (tag == "imprint_merge") {
      if (i + 1 != children.size()) e.fail("must be the last child of <geometry>");
      e.allow_attributes({"enabled"});
      e.expect_empty();
      job.imprint_merge = e.boolean("enabled").value_or(true);
      continue;
    }
    if (tag != "prism" && tag != "revolve" && tag != "loft") e.expect_empty();
    GeometryOp op = read_op(e, tag, shapes);
    std::visit(
        [&](const auto& o) {
          using T = std::decay_t<decltype(o)>;
          if constexpr (std::is_same_v<T, TranslateOp> || std::is_same_v<T, RotateOp> ||
                        std::is_same_v<T, ScaleOp> || std::is_same_v<T, WebcutOp>)
            shapes.require_live(e, "shape", o.shape);
          else
            shapes.define(e, o.name);
        },
        op);
    job.geometry.push_back({std::move(op), e.where()});
  }
  if (job.geometry.empty())
    geometry.fail("needs at least one shape (e.g. <brick>, <cylinder>, <import>)");
}

}  // namespace cooperage::io::detail
