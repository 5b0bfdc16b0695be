#include "model_report.h"

#include "json_writer.h"

#include "framework/core/text.h"
#include "framework/scheme/vertex_angles.h"

#include <cmath>
#include <optional>
#include <sstream>

namespace cooperage::app {
namespace {

/// `info` names a surface's corner sharper than this [degrees]: from here
/// on no element at it reaches the scaled Jacobian 0.2 of `--dim 2`.
constexpr double kSharpCornerDegrees = 12.0;

using geom::Sense;

std::string point(const geom::Vec3& p) {
  return "(" + number_text(p.x()) + ", " + number_text(p.y()) + ", " + number_text(p.z()) + ")";
}

std::string id_list(const std::vector<int>& ids) {
  std::string s;
  for (int id : ids) s += (s.empty() ? "" : " ") + std::to_string(id);
  return s.empty() ? "-" : s;
}

std::string loop_text(const geom::Loop& loop) {
  std::string s;
  for (const auto& use : loop.uses) {
    s += (s.empty() ? "" : " ") + std::to_string(use.curve) +
         (use.sense == Sense::Forward ? "+" : "-");
  }
  return s;
}

int inner_loop_count(const geom::Model& model) {
  int n = 0;
  for (const auto& s : model.surfaces()) n += static_cast<int>(s.loops.size()) - 1;
  return n;
}

}  // namespace

void write_model_text(const geom::Model& model, const std::string& source, std::ostream& out) {
  out << "model " << source << "\n";
  out << "  " << model.volumes().size() << " volumes, " << model.surfaces().size() << " surfaces, "
      << model.curves().size() << " curves, " << model.vertices().size()
      << " vertices; Euler-Poincare V-E+F-R = " << geom::euler_characteristic(model)
      << " (R = " << inner_loop_count(model) << " inner loops)\n";
  out << "  length unit: " << number_text(model.unit_in_metres()) << " m\n";
  const geom::BoundingBox box = model.box();
  if (!box.empty()) {
    out << "  box " << point(box.min) << " - " << point(box.max) << ", diagonal D "
        << number_text(box.diagonal()) << " (--size D/40 = " << number_text(box.diagonal() / 40)
        << ")\n";
  }

  out << "\nvolumes\n";
  for (const auto& v : model.volumes()) {
    size_t faces = 0;
    for (const auto& shell : v.shells) faces += shell.size();
    out << "  volume " << v.id;
    if (!v.name.empty()) out << " \"" << v.name << "\"";
    out << ": volume " << number_text(v.volume) << ", " << faces << " surfaces in "
        << v.shells.size() << (v.shells.size() == 1 ? " shell" : " shells") << ":";
    for (const auto& shell : v.shells) {
      for (const auto& use : shell) {
        out << " " << use.surface << (use.sense == Sense::Forward ? "+" : "-");
      }
    }
    out << "\n";
  }

  out << "\nsurfaces\n";
  for (const auto& s : model.surfaces()) {
    out << "  surface " << s.id << ": " << geom::to_string(s.geometry->type()) << ", area "
        << number_text(s.area) << ", volumes " << id_list(s.volumes);
    const auto sharpest = scheme::sharpest_corner(model, s.id);
    if (sharpest && sharpest->angle < kSharpCornerDegrees) {
      out << ", corner of " << number_text(std::round(sharpest->angle * 10) / 10)
          << " degrees at vertex " << sharpest->vertex
          << " (no element there above scaled Jacobian "
          << number_text(std::round(std::sin(sharpest->angle * M_PI / 180) * 1000) / 1000) << ")";
    }
    out << "\n";
    for (size_t i = 0; i < s.loops.size(); ++i) {
      out << "    " << (i == 0 ? "outer loop: " : "hole loop:  ") << loop_text(s.loops[i]) << "\n";
    }
  }

  out << "\ncurves\n";
  for (const auto& c : model.curves()) {
    out << "  curve " << c.id << ": " << geom::to_string(c.geometry->type()) << ", length "
        << number_text(c.length) << ", vertices " << c.start_vertex << " -> " << c.end_vertex
        << ", surfaces " << id_list(c.surfaces) << "\n";
  }

  out << "\nvertices\n";
  for (const auto& v : model.vertices()) {
    out << "  vertex " << v.id << ": " << point(v.point) << ", curves " << id_list(v.curves)
        << "\n";
  }
}

void write_model_json(const geom::Model& model, const std::string& source, std::ostream& out) {
  JsonWriter j(out);
  auto vec = [&](const geom::Vec3& p) { j.value(std::vector<double>{p.x(), p.y(), p.z()}); };
  j.begin_object();
  j.key("source");
  j.value(source);
  j.key("unit_in_metres");
  j.value(model.unit_in_metres());
  j.key("euler_characteristic");
  j.value(geom::euler_characteristic(model));

  j.key("volumes");
  j.begin_array();
  for (const auto& v : model.volumes()) {
    j.begin_object();
    j.key("id");
    j.value(v.id);
    j.key("name");
    j.value(v.name);
    j.key("volume");
    j.value(v.volume);
    j.key("shells");
    j.begin_array();
    for (const auto& shell : v.shells) {
      j.begin_array();
      for (const auto& use : shell) {
        j.begin_object();
        j.key("surface");
        j.value(use.surface);
        j.key("sense");
        j.value(use.sense == Sense::Forward ? 1 : -1);
        j.end_object();
      }
      j.end_array();
    }
    j.end_array();
    j.key("box_min");
    vec(v.box.min);
    j.key("box_max");
    vec(v.box.max);
    j.end_object();
  }
  j.end_array();

  j.key("surfaces");
  j.begin_array();
  for (const auto& s : model.surfaces()) {
    j.begin_object();
    j.key("id");
    j.value(s.id);
    j.key("type");
    j.value(geom::to_string(s.geometry->type()));
    j.key("area");
    j.value(s.area);
    j.key("volumes");
    j.value(s.volumes);
    j.key("sharpest_corner");
    if (const auto sharpest = scheme::sharpest_corner(model, s.id)) {
      j.begin_object();
      j.key("vertex");
      j.value(sharpest->vertex);
      j.key("degrees");
      j.value(sharpest->angle);
      j.end_object();
    } else {
      j.null();
    }
    j.key("box_min");
    vec(s.box.min);
    j.key("box_max");
    vec(s.box.max);
    j.key("loops");
    j.begin_array();
    for (const auto& loop : s.loops) {
      j.begin_array();
      for (const auto& use : loop.uses) {
        j.begin_object();
        j.key("curve");
        j.value(use.curve);
        j.key("sense");
        j.value(use.sense == Sense::Forward ? 1 : -1);
        j.end_object();
      }
      j.end_array();
    }
    j.end_array();
    j.end_object();
  }
  j.end_array();

  j.key("curves");
  j.begin_array();
  for (const auto& c : model.curves()) {
    j.begin_object();
    j.key("id");
    j.value(c.id);
    j.key("type");
    j.value(geom::to_string(c.geometry->type()));
    j.key("length");
    j.value(c.length);
    j.key("vertices");
    j.value(std::vector<int>{c.start_vertex, c.end_vertex});
    j.key("surfaces");
    j.value(c.surfaces);
    j.end_object();
  }
  j.end_array();

  j.key("vertices");
  j.begin_array();
  for (const auto& v : model.vertices()) {
    j.begin_object();
    j.key("id");
    j.value(v.id);
    j.key("point");
    vec(v.point);
    j.key("curves");
    j.value(v.curves);
    j.end_object();
  }
  j.end_array();
  j.end_object();
  out << "\n";
}

}  // namespace cooperage::app
