// Workbench::import_file: STEP, IGES and BREP, keeping the file's length
// unit, with optional shape healing. Every failure becomes a MeshingError
// naming the file; corrupt input never escapes as a kernel exception.
#include "framework/geometry/occ/detail.h"

#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepLib.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESControl_Reader.hxx>
#include <IGESData_IGESModel.hxx>
#include <Interface_Static.hxx>
#include <STEPControl_Reader.hxx>
#include <ShapeFix_Shape.hxx>
#include <TColStd_SequenceOfAsciiString.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Shell.hxx>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>

namespace cooperage::occ {
namespace {

struct Unit {
  const char* occt;  ///< name understood by "xstep.cascade.unit"
  double metres;
};

/// Length unit from a STEP/IGES unit name ("MM", "MILLIMETRE", "INCH", ...).
bool unit_from_name(std::string name, Unit& unit) {
  std::transform(name.begin(), name.end(), name.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  static const struct { const char* names[4]; Unit unit; } table[] = {
      {{"MM", "MILLIMETRE", "MILLIMETER", nullptr}, {"MM", 1e-3}},
      {{"M", "METRE", "METER", nullptr}, {"M", 1.0}},
      {{"CM", "CENTIMETRE", "CENTIMETER", nullptr}, {"CM", 1e-2}},
      {{"KM", "KILOMETRE", "KILOMETER", nullptr}, {"KM", 1e3}},
      {{"UM", "MICROMETRE", "MICROMETER", "MICRON"}, {"UM", 1e-6}},
      {{"INCH", "IN", "INCHES", nullptr}, {"INCH", 0.0254}},
      {{"FT", "FOOT", "FEET", nullptr}, {"FT", 0.3048}},
      {{"MI", "MILE", nullptr, nullptr}, {"MI", 1609.344}},
      {{"MIL", nullptr, nullptr, nullptr}, {"MIL", 2.54e-5}},
      {{"UIN", "MICROINCH", nullptr, nullptr}, {"UIN", 2.54e-8}},
  };
  for (const auto& row : table)
    for (const char* n : row.names)
      if (n && name == n) {
        unit = row.unit;
        return true;
      }
  return false;
}

[[noreturn]] void parse_error(const std::string& path, const std::string& why) {
  throw MeshingError(ErrorCode::ParseError, path + ": " + why);
}

TopoDS_Shape read_step(const std::string& path, Unit& unit) {
  STEPControl_Reader reader;
  if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) parse_error(path, "not a readable STEP file");
  TColStd_SequenceOfAsciiString lengths, angles, solid_angles;
  reader.FileUnits(lengths, angles, solid_angles);
  if (lengths.Length() > 0) unit_from_name(lengths.First().ToCString(), unit);
  Interface_Static::SetCVal("xstep.cascade.unit", unit.occt);
  reader.SetSystemLengthUnit(unit.metres * 1000.0);
  if (reader.NbRootsForTransfer() <= 0) parse_error(path, "the STEP file holds no shape");
  reader.TransferRoots();
  Interface_Static::SetCVal("xstep.cascade.unit", "MM");
  if (reader.NbShapes() <= 0) parse_error(path, "no shape could be read from the STEP file");
  return reader.OneShape();
}

TopoDS_Shape read_iges(const std::string& path, Unit& unit) {
  IGESControl_Reader reader;
  if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) parse_error(path, "not a readable IGES file");
  Handle(IGESData_IGESModel) model = reader.IGESModel();
  if (!model.IsNull()) {
    // The unit flag of the global section (IGES 5.3, sec. 2.2.4.3); the
    // cascade unit (in mm) is set to it so the transfer does not convert.
    IGESData_GlobalSection gs = model->GlobalSection();
    static const Unit by_flag[] = {{"INCH", 0.0254}, {"MM", 1e-3},    {"MM", 1e-3},
                                   {"FT", 0.3048},   {"MI", 1609.344}, {"M", 1.0},
                                   {"KM", 1e3},      {"MIL", 2.54e-5}, {"UM", 1e-6},
                                   {"CM", 1e-2},     {"UIN", 2.54e-8}};
    const int flag = gs.UnitFlag();
    bool known = false;
    if (flag == 3 && !gs.UnitName().IsNull()) known = unit_from_name(gs.UnitName()->ToCString(), unit);
    if (!known && flag >= 1 && flag <= 11 && flag != 3) unit = by_flag[flag - 1];
    gs.SetCascadeUnit(unit.metres * 1000.0);
    model->SetGlobalSection(gs);
  }
  Interface_Static::SetCVal("xstep.cascade.unit", unit.occt);
  if (reader.NbRootsForTransfer() <= 0) parse_error(path, "the IGES file holds no shape");
  reader.TransferRoots();
  Interface_Static::SetCVal("xstep.cascade.unit", "MM");
  if (reader.NbShapes() <= 0) parse_error(path, "no shape could be read from the IGES file");
  return reader.OneShape();
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

/// Closed shells that are not inside solids become solids (IGES and some
/// STEP files carry shells only); the rest is kept as is.
TopoDS_Shape solidify(const TopoDS_Shape& shape) {
  if (detail::contains_solid(shape)) return shape;
  TopoDS_Compound out;
  BRep_Builder b;
  b.MakeCompound(out);
  bool any = false;
  for (TopExp_Explorer ex(shape, TopAbs_SHELL); ex.More(); ex.Next()) {
    const TopoDS_Shell& shell = TopoDS::Shell(ex.Current());
    if (!BRep_Tool::IsClosed(shell)) continue;
    BRepBuilderAPI_MakeSolid ms(shell);
    if (!ms.IsDone()) continue;
    b.Add(out, ms.Solid());
    any = true;
  }
  return any ? TopoDS_Shape(out) : shape;
}

}  // namespace

void Workbench::import_file(const std::string& name, const std::string& path, bool heal) {
  silence_kernel_output();
  impl_->check_new_name(name);
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec) || !std::ifstream(path).good())
    throw MeshingError(ErrorCode::FileNotFound, path + ": no such file");
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  const bool step = ext == ".step" || ext == ".stp";
  const bool iges = ext == ".iges" || ext == ".igs";
  const bool brep = ext == ".brep" || ext == ".brp";
  if (!step && !iges && !brep)
    throw MeshingError(ErrorCode::InvalidInput,
                       path + ": unknown CAD file extension '" + ext +
                           "' (expected .step, .stp, .iges, .igs or .brep)");

  Unit unit{"MM", 1e-3};
  bool has_unit = !brep;
  const TopoDS_Shape shape = detail::guarded(ErrorCode::ParseError, path, [&] {
    TopoDS_Shape s = step ? read_step(path, unit) : iges ? read_iges(path, unit) : read_brep(path);
    if (s.IsNull()) parse_error(path, "the file holds no shape");
    BRepLib::BuildCurves3d(s);
    if (heal) {
      ShapeFix_Shape fix(s);
      fix.Perform();
      s = fix.Shape();
    }
    s = solidify(s);
    if (!detail::contains_solid(s)) parse_error(path, "the file holds no solids");
    return s;
  });
  if (has_unit) {
    if (impl_->unit_in_metres > 0.0 && std::abs(impl_->unit_in_metres - unit.metres) > 1e-12)
      throw MeshingError(ErrorCode::InvalidInput,
                         path + ": its length unit differs from a file imported before");
    impl_->unit_in_metres = unit.metres;
    impl_->unit_name = unit.occt;
  }
  impl_->add(name, shape);
}

}  // namespace cooperage::occ
