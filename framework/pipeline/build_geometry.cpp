#include "framework/pipeline/build_geometry.h"

#include "framework/core/error.h"
#include "framework/core/text.h"
#include "framework/geometry/occ/workbench.h"
#include "framework/intervals/solve.h"
#include "framework/io/export/write_mesh.h"
#include "framework/io/journal_reader.h"

#include <filesystem>
#include <type_traits>
#include <vector>

namespace cooperage::pipeline {
namespace {

// Applies one operation; the caller adds the journal location to errors.
void apply(occ::Workbench& bench, const io::GeometryOp& op, const std::string& base_dir) {
  std::visit(
      [&](const auto& o) {
        using T = std::decay_t<decltype(o)>;
        if constexpr (std::is_same_v<T, io::ImportOp>) {
          bench.import_file(o.name, resolve_path(base_dir, o.file), o.heal);
        } else if constexpr (std::is_same_v<T, io::BrickOp>) {
          bench.brick(o.name, o.origin, o.size);
        } else if constexpr (std::is_same_v<T, io::CylinderOp>) {
          bench.cylinder(o.name, o.base, o.axis, o.radius, o.height);
        } else if constexpr (std::is_same_v<T, io::ConeOp>) {
          bench.cone(o.name, o.base, o.axis, o.radius1, o.radius2, o.height);
        } else if constexpr (std::is_same_v<T, io::SphereOp>) {
          bench.sphere(o.name, o.center, o.radius);
        } else if constexpr (std::is_same_v<T, io::TorusOp>) {
          bench.torus(o.name, o.center, o.axis, o.major_radius, o.minor_radius);
        } else if constexpr (std::is_same_v<T, io::PrismOp>) {
          bench.prism(o.name, o.profile, o.holes, o.direction);
        } else if constexpr (std::is_same_v<T, io::RevolveOp>) {
          bench.revolve(o.name, o.profile, o.origin, o.axis, o.angle);
        } else if constexpr (std::is_same_v<T, io::LoftOp>) {
          bench.loft(o.name, o.sections, o.ruled);
        } else if constexpr (std::is_same_v<T, io::BooleanOp>) {
          switch (o.kind) {
            case io::BooleanKind::Fuse: bench.fuse(o.name, o.inputs); break;
            case io::BooleanKind::Cut: bench.cut(o.name, o.inputs); break;
            case io::BooleanKind::Common: bench.common(o.name, o.inputs); break;
          }
        } else if constexpr (std::is_same_v<T, io::TranslateOp>) {
          bench.translate(o.shape, o.by);
        } else if constexpr (std::is_same_v<T, io::RotateOp>) {
          bench.rotate(o.shape, o.origin, o.axis, o.angle);
        } else if constexpr (std::is_same_v<T, io::ScaleOp>) {
          bench.scale(o.shape, o.origin, o.factor);
        } else if constexpr (std::is_same_v<T, io::WebcutOp>) {
          bench.webcut(o.shape, o.origin, o.normal);
        }
      },
      op);
}

}  // namespace

std::string where_prefix(const io::SourceLocation& where) {
  if (where.line <= 0) return {};
  return clip_path(where.file) + ":" + std::to_string(where.line) + ": <" + where.element + ">: ";
}

std::string resolve_path(const std::string& base_dir, const std::string& path) {
  const std::filesystem::path p(path);
  if (p.is_absolute() || base_dir.empty()) return path;
  return (std::filesystem::path(base_dir) / p).lexically_normal().string();
}

geom::Model build_geometry(const io::Job& job) {
  occ::Workbench bench;
  bench.set_imprint_merge(job.imprint_merge);
  run_geometry(job, bench);
  occ::BuildOptions options;
  options.imprint_merge = job.imprint_merge;
  return bench.build_model(options);
}

void run_geometry(const io::Job& job, occ::Workbench& bench, bool will_mesh) {
  if (job.geometry.empty()) {
    throw MeshingError(ErrorCode::InvalidInput,
                       (job.file.empty() ? std::string("job") : clip_path(job.file)) +
                           ": the journal defines no geometry");
  }
  // The interval solver's and the export's libraries load while the first
  // import's child reads its file (the CBC module and the Exodus II library:
  // ~10 and ~20 ms of dynamic linking, otherwise paid on the way). In this
  // thread, after the fork: a child must not inherit a thread in the middle
  // of dlopen.
  std::vector<std::string> exports;
  for (const io::ExportSetting& e : job.exports)
    exports.push_back(resolve_path(job.base_dir, e.file));
  if (will_mesh || !exports.empty()) {
    bench.set_while_importing([exports, will_mesh] {
      if (will_mesh) intervals::preload_solver();
      for (const std::string& path : exports) io::prepare_export(path);
    });
  }
  for (const io::GeometryStep& step : job.geometry) {
    try {
      apply(bench, step.op, job.base_dir);
    } catch (const MeshingError& e) {
      throw MeshingError(e.code(), e.entity(), where_prefix(step.where) + e.message(), e.hint());
    }
  }
}

geom::Model load_any(const std::string& path, bool imprint_merge) {
  if (lower_extension(path) == ".xml") {
    io::Job job = io::read_journal(path);
    if (!imprint_merge) job.imprint_merge = false;
    return build_geometry(job);
  }
  occ::BuildOptions options;
  options.imprint_merge = imprint_merge;
  return occ::load_model(path, options);
}

}  // namespace cooperage::pipeline
