// The IGES module (libcooperage_occ_iges.so): OCCT's IGES reader and writer,
// loaded by exchange.cpp on the first IGES file. Apart from the STEP module
// (step_module.cpp) because TKIGES needs TKBool: 17,600 symbol relocations
// a STEP run would otherwise pay for. The same C interface and version.
#include "framework/geometry/occ/exchange_transfer.h"

#include <IFSelect_ReturnStatus.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESControl_Reader.hxx>
#include <IGESControl_Writer.hxx>
#include <IGESData_IGESModel.hxx>
#include <TopoDS_Shape.hxx>

using cooperage::occ::Unit;
using cooperage::occ::unit_from_name;
using namespace cooperage::occ::exchange_module;

extern "C" {

int cooperage_exchange_abi() { return cooperage::occ::kExchangeModuleAbi; }

int cooperage_exchange_read(const char* path, TopoDS_Shape* shape, Unit* unit, char* error,
                            size_t size) {
  IGESControl_Reader reader;
  if (reader.ReadFile(path) != IFSelect_RetDone)
    return fail(error, size, "not a readable IGES file");
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

int cooperage_exchange_write(const char* path, const TopoDS_Shape* shape, const char* unit_name) {
  IGESControl_Controller::Init();
  IGESControl_Writer writer(unit_name, /*modecr=*/1);  // 1: B-rep solids
  bool ok = writer.AddShape(*shape);
  writer.ComputeModel();
  ok = ok && writer.Write(path);
  return ok ? 0 : 1;
}

}  // extern "C"
