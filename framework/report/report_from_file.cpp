#include "framework/report/report_from_file.h"

namespace cooperage::report {

ReportInput report_input(const io::MeshFile& file, const std::string& title) {
  using quality::ElementType;
  const auto is_volume = [](ElementType t) {
    return t == ElementType::Hex || t == ElementType::Wedge;
  };
  bool volumes = false;
  for (const auto& b : file.blocks) volumes = volumes || is_volume(b.type);
  ReportInput in;
  in.title = title;
  in.coords = &file.coords;
  for (const auto& b : file.blocks) {
    ElementBlock e;
    e.name = "block \"" + b.name + "\"";
    e.part = volumes ? (is_volume(b.type) ? e.name : std::string()) : std::string("all surfaces");
    e.type = b.type;
    e.connectivity = b.connectivity.data();
    e.count = b.size();
    e.stride = quality::node_count(b.type);
    in.blocks.push_back(std::move(e));
  }
  for (const auto& [type, count] : file.skipped) {
    in.notes.push_back("skipped " + std::to_string(count) + " " + type + " cells");
  }
  in.notes.push_back("read " + title + ": " + std::to_string(file.coords.size()) + " nodes, " +
                     std::to_string(file.blocks.size()) + " blocks");
  return in;
}

}  // namespace cooperage::report
