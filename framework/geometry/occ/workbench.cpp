// Workbench: the named-shape store, rigid/scale transforms and load_model.
#include "framework/geometry/occ/detail.h"

#include <BRepBuilderAPI_Transform.hxx>
#include <TopAbs_ShapeEnum.hxx>
#include <TopExp_Explorer.hxx>
#include <gp_Ax1.hxx>
#include <gp_Trsf.hxx>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <sstream>

namespace cooperage::occ {

// ---- Impl ---------------------------------------------------------------------

NamedShape* Workbench::Impl::find(const std::string& name) {
  for (auto& s : shapes)
    if (s.name == name) return &s;
  return nullptr;
}
const NamedShape* Workbench::Impl::find(const std::string& name) const {
  for (const auto& s : shapes)
    if (s.name == name) return &s;
  return nullptr;
}
const TopoDS_Shape& Workbench::Impl::get(const std::string& name) const {
  const NamedShape* s = find(name);
  if (!s) detail::invalid(name, "no such shape");
  return s->shape;
}
void Workbench::Impl::check_new_name(const std::string& name) const {
  if (name.empty()) throw MeshingError(ErrorCode::InvalidInput, "a shape needs a non-empty name");
  if (find(name)) detail::invalid(name, "a shape of that name already exists");
}
void Workbench::Impl::add(const std::string& name, const TopoDS_Shape& shape) {
  check_new_name(name);
  shapes.push_back({name, shape, {}});
}
void Workbench::Impl::remove(const std::string& name) {
  shapes.erase(std::remove_if(shapes.begin(), shapes.end(),
                              [&](const NamedShape& s) { return s.name == name; }),
               shapes.end());
}

namespace detail {

gp_Dir checked_dir(const std::string& shape, const Vec3& v, const char* what) {
  if (!v.allFinite() || v.norm() <= 1e-12)
    invalid(shape, std::string(what) + " must be a non-zero vector");
  return gp_Dir(v.x(), v.y(), v.z());
}

std::string num(double value) {
  std::ostringstream out;
  out << std::setprecision(12) << value;
  return out.str();
}

bool contains_solid(const TopoDS_Shape& shape) {
  return !shape.IsNull() && TopExp_Explorer(shape, TopAbs_SOLID).More();
}

}  // namespace detail

// ---- Workbench -----------------------------------------------------------------

Workbench::Workbench() : impl_(std::make_unique<Impl>()) { silence_kernel_output(); }
Workbench::~Workbench() = default;

std::vector<std::string> Workbench::names() const {
  std::vector<std::string> out;
  for (const auto& s : impl_->shapes) out.push_back(s.name);
  return out;
}

bool Workbench::has(const std::string& name) const { return impl_->find(name) != nullptr; }

void Workbench::set_imprint_merge(bool merge) { impl_->merge_on_import = merge; }

void Workbench::set_while_importing(std::function<void()> task) {
  impl_->while_importing = std::move(task);
}

namespace {

void apply(Workbench::Impl& impl, const std::string& name, const gp_Trsf& trsf) {
  NamedShape* s = impl.find(name);
  if (!s) detail::invalid(name, "no such shape");
  s->merged.Nullify();
  s->shape = detail::guarded(ErrorCode::GeometryError, "shape '" + name + "': transform", [&] {
    BRepBuilderAPI_Transform t(s->shape, trsf, /*copy=*/Standard_True);
    if (!t.IsDone()) detail::invalid(name, "transform failed");
    return t.Shape();
  });
}

}  // namespace

void Workbench::translate(const std::string& shape, const Vec3& by) {
  if (!by.allFinite()) detail::invalid(shape, "translation must be finite");
  gp_Trsf trsf;
  trsf.SetTranslation(detail::to_vec(by));
  apply(*impl_, shape, trsf);
}

void Workbench::rotate(const std::string& shape, const Vec3& origin, const Vec3& axis,
                       double angle_deg) {
  const gp_Dir dir = detail::checked_dir(shape, axis, "rotation axis");
  if (!std::isfinite(angle_deg) || !origin.allFinite())
    detail::invalid(shape, "rotation origin and angle must be finite");
  gp_Trsf trsf;
  trsf.SetRotation(gp_Ax1(detail::to_pnt(origin), dir), angle_deg * M_PI / 180.0);
  apply(*impl_, shape, trsf);
}

void Workbench::scale(const std::string& shape, const Vec3& origin, double factor) {
  if (!(factor > 0.0) || !std::isfinite(factor))
    detail::invalid(shape, "scale factor must be positive, got " + detail::num(factor));
  gp_Trsf trsf;
  trsf.SetScale(detail::to_pnt(origin), factor);
  apply(*impl_, shape, trsf);
}

geom::Model load_model(const std::string& path, const BuildOptions& options) {
  Workbench wb;
  std::string name = std::filesystem::path(path).stem().string();
  if (name.empty()) name = "part";
  wb.set_imprint_merge(options.imprint_merge);
  wb.import_file(name, path);
  return wb.build_model(options);
}

}  // namespace cooperage::occ
