// The STEP module (libcooperage_occ_step.so): OCCT's STEP reader and writer,
// loaded by exchange.cpp on the first STEP file instead of at start-up.
// Their toolkits (TKSTEP*, TKXSBase) are a fifth of a STEP run's symbol
// relocations: linked into every process they cost ~30 ms of CPU before
// main (issue 20), also in runs that only build geometry from a journal.
// IGES has a module of its own (iges_module.cpp): TKIGES and the TKBool it
// needs are another 17,600 relocations no STEP run uses. The C interface
// both define is declared in exchange_transfer.h.
#include "framework/geometry/occ/exchange_transfer.h"

#include <IFSelect_ReturnStatus.hxx>
#include <Interface_Static.hxx>
#include <STEPControl_Reader.hxx>
#include <STEPControl_Writer.hxx>
#include <TColStd_SequenceOfAsciiString.hxx>
#include <TopoDS_Shape.hxx>

using cooperage::occ::Unit;
using cooperage::occ::unit_from_name;
using namespace cooperage::occ::exchange_module;

extern "C" {

int cooperage_exchange_abi() { return cooperage::occ::kExchangeModuleAbi; }

int cooperage_exchange_read(const char* path, TopoDS_Shape* shape, Unit* unit, char* error,
                            size_t size) {
  STEPControl_Reader reader;
  if (reader.ReadFile(path) != IFSelect_RetDone)
    return fail(error, size, "not a readable STEP file");
  TColStd_SequenceOfAsciiString lengths, angles, solid_angles;
  reader.FileUnits(lengths, angles, solid_angles);
  if (lengths.Length() > 0) unit_from_name(lengths.First().ToCString(), *unit);
  reader.SetSystemLengthUnit(unit->metres * 1000.0);
  return transfer(reader, "STEP", shape, *unit, error, size);
}

int cooperage_exchange_write(const char* path, const TopoDS_Shape* shape, const char* unit_name) {
  STEPControl_Writer writer;
  Interface_Static::SetCVal("xstep.cascade.unit", unit_name);
  Interface_Static::SetCVal("write.step.unit", unit_name);
  const bool ok = writer.Transfer(*shape, STEPControl_AsIs) == IFSelect_RetDone &&
                  writer.Write(path) == IFSelect_RetDone;
  Interface_Static::SetCVal("xstep.cascade.unit", "MM");
  Interface_Static::SetCVal("write.step.unit", "MM");
  return ok ? 0 : 1;
}

}  // extern "C"
