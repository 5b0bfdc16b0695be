// Workbench::import_file: STEP, IGES and BREP, keeping the file's length
// unit, with optional shape healing. Every failure becomes a MeshingError
// naming the file; corrupt input never escapes as a kernel exception.
//
// The kernel's readers are not safe on damaged files: they dereference null
// handles (SIGSEGV) and loop at a truncated end (issue 21: 79 crashes and
// 25 hangs in 800 mutated files). Signal handlers cannot make that safe (a
// fault leaves the kernel's state half-updated, and a loop raises nothing),
// so the file is read in a forked child with a time and memory limit
// (framework/core/isolate.h). The child reads, heals, checks that the model
// can be built and is valid, and sends the shape back in OCCT's binary
// format, which round-trips exactly, with the measures it took of its faces
// and solids on the way; the parent never runs the readers.
#include "framework/core/isolate.h"
#include "framework/core/readable_file.h"
#include "framework/core/text.h"
#include "framework/geometry/occ/detail.h"
#include "framework/geometry/occ/exchange.h"
#include "framework/geometry/validate.h"

#include <BRepBndLib.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <Bnd_Box.hxx>
#include <BRepLib.hxx>
#include <BRepTools.hxx>
#include <BinTools.hxx>
#include <BRep_Builder.hxx>
#include <ShapeFix_Shape.hxx>
#include <ShapeFix_Solid.hxx>
#include <ShapeUpgrade_RemoveLocations.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Iterator.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Solid.hxx>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace cooperage::occ {
namespace {

[[noreturn]] void parse_error(const std::string& path, const std::string& why) {
  throw MeshingError(ErrorCode::ParseError, path + ": " + why);
}

TopoDS_Shape read_brep(const std::string& path) {
  // OCCT reports a wrong header on std::cout, not through the messenger:
  // check the header here so bad files fail quietly.
  std::ifstream in(path);
  std::string line;
  bool header = false;
  for (int i = 0; i < 5 && std::getline(in, line); ++i)
    header = header || line.rfind("CASCADE Topology V", 0) == 0;
  if (!header) parse_error(path, "not a BREP file (no 'CASCADE Topology' header)");
  TopoDS_Shape shape;
  BRep_Builder builder;
  if (!BRepTools::Read(shape, path.c_str(), builder) || shape.IsNull())
    parse_error(path, "not a readable BREP file");
  return shape;
}

/// `shape` with every sub-shape's placement moved into its geometry. Files
/// written from assemblies nest placements (occt_CrankArm.brep: 109, its
/// edges 23 deep on average), and the kernel composes the whole chain on
/// every query of an edge on a face: a fifth of a decomposition search's
/// time went to reference counting the chains.
TopoDS_Shape without_locations(const TopoDS_Shape& shape) {
  ShapeUpgrade_RemoveLocations remove;
  remove.SetRemoveLevel(TopAbs_COMPOUND);
  if (!remove.Remove(shape)) return shape;
  return remove.GetResult().IsNull() ? shape : remove.GetResult();
}

/// The closed shells of `shape` as solids (oriented outward), or null.
TopoDS_Shape closed_shells_as_solids(const TopoDS_Shape& shape) {
  TopoDS_Compound out;
  BRep_Builder b;
  b.MakeCompound(out);
  bool any = false;
  for (TopExp_Explorer ex(shape, TopAbs_SHELL); ex.More(); ex.Next()) {
    const TopoDS_Shell& shell = TopoDS::Shell(ex.Current());
    if (!BRep_Tool::IsClosed(shell)) continue;
    ShapeFix_Solid fix;
    const TopoDS_Solid solid = fix.SolidFromShell(shell);
    if (solid.IsNull()) continue;
    b.Add(out, solid);
    any = true;
  }
  return any ? TopoDS_Shape(out) : TopoDS_Shape();
}

/// Closed shells that are not inside solids become solids (IGES and some
/// STEP files carry shells only). Faces that close a volume only once their
/// shared edges are sewn (a surface model written as an "open shell", e.g.
/// Gmsh's cube_filet.stp) are sewn first; the rest is kept as is.
TopoDS_Shape solidify(const TopoDS_Shape& shape) {
  if (detail::contains_solid(shape)) return shape;
  if (TopoDS_Shape solids = closed_shells_as_solids(shape); !solids.IsNull()) return solids;
  Bnd_Box box;
  BRepBndLib::Add(shape, box);
  if (box.IsVoid()) return shape;
  // Gaps up to 1e-5 of the model's size are seams the writer left open.
  const double tolerance = std::max(1e-7, 1e-5 * std::sqrt(box.SquareExtent()));
  BRepBuilderAPI_Sewing sewing(tolerance);
  sewing.Add(shape);
  sewing.Perform();
  const TopoDS_Shape sewn = sewing.SewedShape();
  if (sewn.IsNull()) return shape;
  if (TopoDS_Shape solids = closed_shells_as_solids(sewn); !solids.IsNull()) return solids;
  return shape;
}

/// The measures of the shape's faces (detail::face_facts) and solids
/// (detail::solid_volume), remembered from the model built in the child, as
/// raw doubles in TopExp::MapShapes order: the parent reads the same faces
/// and solids in the same order from the binary shape, and need not measure
/// them again (bounding B-spline faces tightly is a particle swarm each).
constexpr std::size_t kDoublesPerFace = 10;

std::string measures_of(const TopoDS_Shape& shape) {
  TopTools_IndexedMapOfShape faces, solids;
  TopExp::MapShapes(shape, TopAbs_FACE, faces);
  TopExp::MapShapes(shape, TopAbs_SOLID, solids);
  std::vector<double> values;
  values.reserve(kDoublesPerFace * static_cast<std::size_t>(faces.Extent()) +
                 static_cast<std::size_t>(solids.Extent()));
  for (int i = 1; i <= faces.Extent(); ++i) {
    const detail::FaceFacts f = detail::face_facts(TopoDS::Face(faces(i)));
    values.push_back(f.area);
    for (const geom::Vec3* v : {&f.centroid, &f.box.min, &f.box.max})
      values.insert(values.end(), v->data(), v->data() + 3);
  }
  for (int i = 1; i <= solids.Extent(); ++i) values.push_back(detail::solid_volume(solids(i)));
  return std::string(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(double));
}

/// Seeds this thread's measures from the child's; ignored unless they cover
/// exactly the faces and solids read (the parent then measures them itself).
void remember_measures(const TopoDS_Shape& shape, const std::string& bytes) {
  TopTools_IndexedMapOfShape faces, solids;
  TopExp::MapShapes(shape, TopAbs_FACE, faces);
  TopExp::MapShapes(shape, TopAbs_SOLID, solids);
  const std::size_t nf = static_cast<std::size_t>(faces.Extent());
  const std::size_t ns = static_cast<std::size_t>(solids.Extent());
  std::vector<double> values(nf * kDoublesPerFace + ns);
  if (bytes.size() != values.size() * sizeof(double)) return;
  std::memcpy(values.data(), bytes.data(), bytes.size());
  for (std::size_t i = 0; i < nf; ++i) {
    const double* v = values.data() + i * kDoublesPerFace;
    detail::FaceFacts f;
    f.area = v[0];
    f.centroid = geom::Vec3(v[1], v[2], v[3]);
    f.box.min = geom::Vec3(v[4], v[5], v[6]);
    f.box.max = geom::Vec3(v[7], v[8], v[9]);
    detail::remember_face_facts(TopoDS::Face(faces(static_cast<int>(i) + 1)), f);
  }
  for (std::size_t i = 0; i < ns; ++i)
    detail::remember_solid_volume(solids(static_cast<int>(i) + 1),
                                  values[nf * kDoublesPerFace + i]);
}

/// Which reader a file needs, from its extension.
enum class CadKind { Step, Iges, Brep };

/// The child's work: read, heal, solidify; imprint and merge the file's own
/// solids when the model will be merged; build and validate the model of the
/// result as the parent will (so that a kernel fault in any of these steps
/// happens here, not in the parent); then serialise the unit and the shapes
/// (one compound: the shape, then its merged pieces, sharing what they share).
void read_in_child(const std::string& path, CadKind kind, bool heal, bool merge, std::string& out) {
  Unit unit{"MM", 1e-3};
  const TopoDS_Shape shape = detail::guarded(ErrorCode::ParseError, path, [&] {
    TopoDS_Shape s = kind == CadKind::Step   ? exchange::read(exchange::Format::Step, path, unit)
                     : kind == CadKind::Iges ? exchange::read(exchange::Format::Iges, path, unit)
                                             : read_brep(path);
    if (s.IsNull()) parse_error(path, "the file holds no shape");
    s = without_locations(s);
    BRepLib::BuildCurves3d(s);
    // Healing only a shape the kernel's checker rejects: the check costs
    // about half the fix (gmsh_Zylkopf: 0.13 s against 0.25 s), and the
    // fixer rebuilt valid shapes too (it reversed and renumbered the loop
    // edges of gmsh_1385_Laufrad_1000, so its ids differed from the file's).
    if (heal && !BRepCheck_Analyzer(s).IsValid()) {
      ShapeFix_Shape fix(s);
      fix.Perform();
      s = fix.Shape();
    }
    s = solidify(s);
    // A surface model that no sewing closes keeps its faces: they mesh in
    // 2D, and a volume mesh of it is refused with the reason (pipeline).
    if (!detail::contains_solid(s) && !TopExp_Explorer(s, TopAbs_FACE).More())
      parse_error(path, "the file holds no solids and no faces");
    return s;
  });
  TopoDS_Shape merged;
  if (merge) {
    merged = detail::guarded(ErrorCode::GeometryError, path + ": imprint and merge",
                             [&] { return detail::merge_alone(shape); });
  }
  // A MeshingError from the trial reaches the parent the same way when it
  // builds; only faults must stay here. The measures go along only from a
  // model that built (measuring the faces of one that did not could take
  // the child's whole time limit, hiding the build's own error).
  bool built = true;
  try {
    (void)detail::build_model_of({NamedShape{"part", merge ? merged : shape, {}}},
                                 BuildOptions{false}, 0.0);
  } catch (const MeshingError&) {
    built = false;
  }
  TopoDS_Compound both;
  BRep_Builder builder;
  builder.MakeCompound(both);
  builder.Add(both, shape);
  if (merge) builder.Add(both, merged);
  std::ostringstream bytes(std::ios::binary);
  BinTools::Write(both, bytes, Standard_False, Standard_False, BinTools_FormatVersion_CURRENT);
  const std::string shapes = bytes.str();
  char header[96];
  std::snprintf(header, sizeof header, "%s %.17g %zu\n", unit.occt, unit.metres, shapes.size());
  out = header + shapes + (built ? measures_of(merge ? merged : shape) : std::string());
}

/// Time and memory the child may take: generous for real files (30 s of
/// processor time plus 10 s per MB; 4 GB plus 100 times the file), bounded
/// for damaged ones. Processor time, not wall time, so that other work on a
/// busy machine cannot make a valid file look unreadable; the wall clock
/// stays as a backstop (4 times the processor time plus a minute) for a
/// child that waits without computing. COOPERAGE_CAD_TIMEOUT (seconds)
/// overrides the processor time.
IsolationLimits limits_for(const std::string& path) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  const double mb = ec ? 0.0 : static_cast<double>(size) / 1e6;
  IsolationLimits limits;
  limits.cpu_seconds = 30.0 + 10.0 * mb;
  if (const char* env = std::getenv("COOPERAGE_CAD_TIMEOUT")) {
    char* end = nullptr;
    const double s = std::strtod(env, &end);
    if (end != env && s > 0 && s < 1e6) limits.cpu_seconds = s;
  }
  limits.seconds = 4.0 * limits.cpu_seconds + 60.0;
  limits.memory_bytes = static_cast<std::size_t>(4e9 + 100.0 * mb * 1e6);
  return limits;
}

}  // namespace

void Workbench::import_file(const std::string& name, const std::string& path, bool heal) {
  silence_kernel_output();
  impl_->check_new_name(name);
  require_readable_file(path);
  const std::string ext = lower_extension(path);
  const bool step = ext == ".step" || ext == ".stp";
  const bool iges = ext == ".iges" || ext == ".igs";
  const bool brep = ext == ".brep" || ext == ".brp";
  if (!step && !iges && !brep)
    throw MeshingError(ErrorCode::InvalidInput,
                       path + ": unknown CAD file extension '" + clip(ext, 16) +
                           "' (expected .step, .stp, .iges, .igs or .brep)");
  const CadKind kind = step ? CadKind::Step : iges ? CadKind::Iges : CadKind::Brep;

  // The STEP or IGES module is loaded by the child when this process has one
  // thread: the parent never needs it (it reads the child's binary shape),
  // and meanwhile it loads what the mesher needs (`while_importing`), ~20 ms
  // sooner done (issue 20). With other threads it is loaded here, before the
  // fork: one of them may hold the dynamic loader's lock at the fork, and the
  // child would wait for it forever.
  if (kind != CadKind::Brep && !single_threaded())
    exchange::load(kind == CadKind::Step ? exchange::Format::Step : exchange::Format::Iges);
  const IsolationLimits limits = limits_for(path);
  std::function<void()> while_reading;
  while_reading.swap(impl_->while_importing);  // once
  const IsolatedRun run = run_isolated(
      [&](std::string& out) { read_in_child(path, kind, heal, impl_->merge_on_import, out); },
      limits, while_reading);
  if (run.outcome == IsolatedRun::Outcome::Failed) throw MeshingError(run.code, run.payload);
  if (run.outcome != IsolatedRun::Outcome::Done)
    throw MeshingError(ErrorCode::ParseError,
                       path + ": the CAD kernel could not read it (" + run.describe(limits) + ")");

  // "<unit name> <metres> <shape bytes>\n", the binary shape, then the
  // measures of its faces and solids, all from our child.
  const std::size_t eol = run.payload.find('\n');
  Unit unit{"MM", 1e-3};
  char unit_name[16] = {0};
  std::size_t shape_bytes = 0;
  if (eol == std::string::npos ||
      std::sscanf(run.payload.substr(0, eol).c_str(), "%15s %lf %zu", unit_name, &unit.metres,
                  &shape_bytes) != 3 ||
      !unit_from_name(unit_name, unit) || shape_bytes > run.payload.size() - eol - 1)
    throw MeshingError(ErrorCode::Internal, path + ": the import child sent a malformed header");
  TopoDS_Shape both, shape, merged;
  detail::guarded(ErrorCode::Internal, path, [&] {
    std::istringstream bytes(run.payload.substr(eol + 1, shape_bytes), std::ios::binary);
    BinTools::Read(both, bytes);
  });
  int k = 0;
  for (TopoDS_Iterator it(both); it.More(); it.Next(), ++k) (k == 0 ? shape : merged) = it.Value();
  if (shape.IsNull())
    throw MeshingError(ErrorCode::Internal, path + ": the import child sent no shape");
  if (!brep) {
    if (impl_->unit_in_metres > 0.0 && std::abs(impl_->unit_in_metres - unit.metres) > 1e-12)
      throw MeshingError(ErrorCode::InvalidInput,
                         path + ": its length unit differs from a file imported before");
    impl_->unit_in_metres = unit.metres;
    impl_->unit_name = unit.occt;
  }
  // The measures are of the shape the child built its model from.
  remember_measures(merged.IsNull() ? shape : merged, run.payload.substr(eol + 1 + shape_bytes));
  impl_->add(name, shape);
  impl_->find(name)->merged = merged;
}

}  // namespace cooperage::occ
