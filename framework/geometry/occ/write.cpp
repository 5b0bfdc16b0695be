// Workbench::write: the named shapes to a STEP, IGES or BREP file, written to a
// temporary name and renamed so a failure never leaves a half file.
#include "framework/geometry/occ/detail.h"
#include "framework/core/text.h"
#include "framework/geometry/occ/exchange.h"

#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <TopoDS_Compound.hxx>

#include <cctype>
#include <filesystem>

namespace cooperage::occ {

void Workbench::write(const std::string& path, const std::vector<std::string>& shapes) const {
  silence_kernel_output();
  const std::string ext = lower_extension(path);
  const bool step = ext == ".step" || ext == ".stp";
  const bool iges = ext == ".iges" || ext == ".igs";
  const bool brep = ext == ".brep" || ext == ".brp";
  if (!step && !iges && !brep)
    throw MeshingError(
        ErrorCode::InvalidInput,
        path + ": cannot write '" + ext + "' files (use .step, .stp, .iges, .igs or .brep)");
  TopoDS_Compound all;
  BRep_Builder builder;
  builder.MakeCompound(all);
  if (shapes.empty()) {
    for (const auto& s : impl_->shapes) builder.Add(all, s.shape);
  } else {
    for (const auto& name : shapes) builder.Add(all, impl_->get(name));
  }
  const std::string tmp = path + ".tmp";
  detail::guarded(ErrorCode::GeometryError, path, [&] {
    bool ok = false;
    if (step || iges) {
      ok = exchange::write(step ? exchange::Format::Step : exchange::Format::Iges, tmp, all,
                           impl_->unit_name);
    } else {
      ok = BRepTools::Write(all, tmp.c_str());
    }
    std::error_code ec;
    if (!ok) {
      std::filesystem::remove(tmp, ec);
      throw MeshingError(ErrorCode::GeometryError, path + ": the kernel could not write the file");
    }
    std::filesystem::rename(tmp, path, ec);
    if (ec) {
      std::filesystem::remove(tmp, ec);
      throw MeshingError(ErrorCode::GeometryError, path + ": cannot rename the written file");
    }
    return 0;
  });
}

}  // namespace cooperage::occ
