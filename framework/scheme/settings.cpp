#include "framework/scheme/settings.h"

namespace cooperage::scheme {

Settings Settings::of(const io::MeshSettings& job, int dim) {
  Settings s;
  s.size = job.size.value_or(1.0);
  s.allow_fallback = dim == 2;
  s.job = &job;
  return s;
}

const Settings& Settings::none() {
  static const Settings defaults;
  return defaults;
}

const io::VolumeSetting* Settings::volume(int volume_id) const {
  if (!job) return nullptr;
  for (const io::VolumeSetting& v : job->volumes) {
    if (v.id == volume_id) return &v;
  }
  return nullptr;
}

io::ElementKind Settings::elements(int volume_id) const {
  const io::VolumeSetting* v = volume(volume_id);
  if (v && v->elements) return *v->elements;
  return job ? job->elements : io::ElementKind::Hex;
}

std::string Settings::no_scheme_applies(int volume_id) const {
  switch (elements(volume_id)) {
    case io::ElementKind::Wedge: return "no wedge scheme applies";
    case io::ElementKind::Mixed: return "no mixed scheme applies";
    case io::ElementKind::Hex: break;
  }
  return "no hex scheme applies";
}

std::vector<io::VertexTypeSetting> Settings::vertex_types() const {
  std::vector<io::VertexTypeSetting> out;
  if (job) out = job->vertex_types;
  if (planned_vertex_types)
    out.insert(out.end(), planned_vertex_types->begin(), planned_vertex_types->end());
  return out;
}

}  // namespace cooperage::scheme
