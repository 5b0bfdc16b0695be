#include "schemes_command.h"

#include "json_writer.h"

#include <algorithm>
#include <iomanip>

namespace cooperage::app {
namespace {

struct Row {
  std::string dim;
  std::string name;
  std::string origin;
  std::string serves;  ///< surface schemes: roles; volume schemes: element kinds
};

std::vector<Row> rows(const scheme::Registry& registry) {
  std::vector<Row> out;
  for (const scheme::SurfaceScheme* s : registry.surface_schemes()) {
    out.push_back({"surface", std::string(s->name()), registry.origin(2, s->name()),
                   s->serves() == scheme::Role::None ? "free surfaces"
                                                     : "free surfaces, " + to_string(s->serves())});
  }
  for (const scheme::VolumeScheme* v : registry.volume_schemes()) {
    out.push_back({"volume", std::string(v->name()), registry.origin(3, v->name()),
                   v->makes_wedges() ? "hex, wedge and mixed elements" : "hex elements"});
  }
  return out;
}

}  // namespace

void write_schemes_text(const scheme::Registry& registry, std::ostream& out) {
  const std::vector<Row> list = rows(registry);
  size_t name_width = 4, origin_width = 6;
  for (const Row& r : list) {
    name_width = std::max(name_width, r.name.size());
    origin_width = std::max(origin_width, r.origin.size());
  }
  out << std::left << std::setw(9) << "dim" << std::setw(static_cast<int>(name_width) + 2) << "name"
      << std::setw(static_cast<int>(origin_width) + 2) << "origin"
      << "serves\n";
  for (const Row& r : list) {
    out << std::setw(9) << r.dim << std::setw(static_cast<int>(name_width) + 2) << r.name
        << std::setw(static_cast<int>(origin_width) + 2) << r.origin << r.serves << "\n";
  }
}

void write_schemes_json(const scheme::Registry& registry, std::ostream& out) {
  JsonWriter j(out);
  j.begin_array();
  for (const Row& r : rows(registry)) {
    j.begin_object();
    j.key("name");
    j.value(r.name);
    j.key("dim");
    j.value(r.dim == "volume" ? 3 : 2);
    j.key("origin");
    j.value(r.origin);
    j.key("serves");
    j.value(r.serves);
    j.end_object();
  }
  j.end_array();
  out << "\n";
}

}  // namespace cooperage::app
