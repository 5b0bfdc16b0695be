// Keeps OpenCASCADE quiet: the STEP/IGES readers report statistics and
// warnings through the default messenger, whose console printer writes to
// stdout. Cooperage's logger decides what a person sees (STYLE rule 4).
// Only console printers are removed; a printer the application attaches on
// purpose stays.
#include "framework/geometry/occ/workbench.h"

#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>

#include <mutex>

namespace cooperage::occ {

void silence_kernel_output() {
  static std::mutex mutex;
  const std::lock_guard<std::mutex> lock(mutex);
  const Handle(Message_Messenger)& messenger = Message::DefaultMessenger();
  if (!messenger.IsNull()) messenger->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
}

}  // namespace cooperage::occ
