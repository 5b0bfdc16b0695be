// The exchange module (libcooperage_occ_exchange.so): OCCT's STEP and IGES
// readers and writers, loaded by exchange.cpp on the first STEP or IGES
// file instead of at start-up. Their toolkits (TKSTEP*, TKIGES, TKXSBase)
// are six of the process's libraries but about 30 % of its symbol
// relocations: linked into every process they cost ~35 ms of CPU before
// main (issue 20), also in runs that only build geometry from a journal.
// A C interface, versioned by cooperage_exchange_abi(), so the loader finds
// the functions by name; OCCT objects cross it by pointer (one OCCT in the
// process). Errors come back as text; kernel exceptions propagate to the
// caller's guard (detail::guarded) like any other kernel call's.
#include "framework/geometry/occ/exchange_units.h"

#include <IFSelect_ReturnStatus.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESControl_Reader.hxx>
#include <IGESControl_Writer.hxx>
#include <IGESData_IGESModel.hxx>
#include <Interface_Static.hxx>
#include <STEPControl_Reader.hxx>
#include <STEPControl_Writer.hxx>
#include <TColStd_SequenceOfAsciiString.hxx>
#include <TopoDS_Shape.hxx>
#include <XSControl_Reader.hxx>

#include <cstdio>
#include <cstring>

namespace {

using cooperage::occ::Unit;
using cooperage::occ::unit_from_name;

int fail(char* error, size_t size, const char* why) {
  std::snprintf(error, size, "%s", why);
  return 1;
}

// The read file's roots as one shape, in the file's unit (the cascade
// unit set for the transfer only, so the kernel does not convert).
int transfer(XSControl_Reader& reader, const char* kind, TopoDS_Shape* shape, const Unit& unit,
             char* error, size_t size) {
  char why[64];
  Interface_Static::SetCVal("xstep.cascade.unit", unit.occt);
  if (reader.NbRootsForTransfer() <= 0) {
    std::snprintf(why, sizeof why, "the %s file holds no shape", kind);
    Interface_Static::SetCVal("xstep.cascade.unit", "MM");
    return fail(error, size, why);
  }
  reader.TransferRoots();
  Interface_Static::SetCVal("xstep.cascade.unit", "MM");
  if (reader.NbShapes() <= 0) {
    std::snprintf(why, sizeof why, "no shape could be read from the %s file", kind);
    return fail(error, size, why);
  }
  *shape = reader.OneShape();
  return 0;
}

int read_step(const char* path, TopoDS_Shape* shape, Unit* unit, char* error, size_t size) {
  STEPControl_Reader reader;
  if (reader.ReadFile(path) != IFSelect_RetDone) return fail(error, size, "not a readable STEP file");
  TColStd_SequenceOfAsciiString lengths, angles, solid_angles;
  reader.FileUnits(lengths, angles, solid_angles);
  if (lengths.Length() > 0) unit_from_name(lengths.First().ToCString(), *unit);
  reader.SetSystemLengthUnit(unit->metres * 1000.0);
  return transfer(reader, "STEP", shape, *unit, error, size);
}

int read_iges(const char* path, TopoDS_Shape* shape, Unit* unit, char* error, size_t size) {
  IGESControl_Reader reader;
  if (reader.ReadFile(path) != IFSelect_RetDone) return fail(error, size, "not a readable IGES file");
  Handle(IGESData_IGESModel) model = reader.IGESModel();
  if (!model.IsNull()) {
    // The unit flag of the global section (IGES 5.3, sec. 2.2.4.3); the
    // cascade unit (in mm) is set to it so the transfer does not convert.
    IGESData_GlobalSection gs = model->GlobalSection();
    static const Unit by_flag[] = {{"INCH", 0.0254}, {"MM", 1e-3},     {"MM", 1e-3},
                                   {"FT", 0.3048},   {"MI", 1609.344}, {"M", 1.0},
                                   {"KM", 1e3},      {"MIL", 2.54e-5}, {"UM", 1e-6},
                                   {"CM", 1e-2},     {"UIN", 2.54e-8}};
    const int flag = gs.UnitFlag();
    bool known = false;
    if (flag == 3 && !gs.UnitName().IsNull())
      known = unit_from_name(gs.UnitName()->ToCString(), *unit);
    if (!known && flag >= 1 && flag <= 11 && flag != 3) *unit = by_flag[flag - 1];
    gs.SetCascadeUnit(unit->metres * 1000.0);
    model->SetGlobalSection(gs);
  }
  return transfer(reader, "IGES", shape, *unit, error, size);
}

}  // namespace

extern "C" {

/// The interface version; the loader refuses a module that differs.
__attribute__((visibility("default"))) int cooperage_exchange_abi() { return 1; }

/// Reads a STEP (format 0) or IGES (format 1) file into *shape, in the
/// file's length unit (*unit: in, the default; out, the file's). 0 on
/// success; otherwise the reason in `error`.
__attribute__((visibility("default"))) int cooperage_exchange_read(int format, const char* path,
                                                                   TopoDS_Shape* shape, Unit* unit,
                                                                   char* error, size_t size) {
  return format == 0 ? read_step(path, shape, unit, error, size)
                     : read_iges(path, shape, unit, error, size);
}

/// Writes *shape as STEP (format 0) or IGES (format 1) in the unit named
/// (an OCCT unit name, "MM", "INCH", ...). 0 on success.
__attribute__((visibility("default"))) int cooperage_exchange_write(int format, const char* path,
                                                                    const TopoDS_Shape* shape,
                                                                    const char* unit_name) {
  bool ok = false;
  if (format == 0) {
    STEPControl_Writer writer;
    Interface_Static::SetCVal("xstep.cascade.unit", unit_name);
    Interface_Static::SetCVal("write.step.unit", unit_name);
    ok = writer.Transfer(*shape, STEPControl_AsIs) == IFSelect_RetDone &&
         writer.Write(path) == IFSelect_RetDone;
    Interface_Static::SetCVal("xstep.cascade.unit", "MM");
    Interface_Static::SetCVal("write.step.unit", "MM");
  } else {
    IGESControl_Controller::Init();
    IGESControl_Writer writer(unit_name, /*modecr=*/1);  // 1: B-rep solids
    ok = writer.AddShape(*shape);
    writer.ComputeModel();
    ok = ok && writer.Write(path);
  }
  return ok ? 0 : 1;
}

}  // extern "C"
