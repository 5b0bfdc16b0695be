// The <block>, <sideset> and <nodeset> elements of a journal: the groups a
// solver sees in the exported files (element blocks, side sets, node sets),
// after Cubit's commands of the same names. Checked here: each element's
// attributes, ids and names unique per kind, a volume or surface in one
// block only. Whether the ids exist in the model is checked when the model
// is built (pipeline/check_groups.h).
#include "framework/io/journal_xml.h"

#include "framework/core/text.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <string>

namespace cooperage::io::detail {
namespace {

// At most 32 characters (Exodus's default name length), a letter first, then
// letters, digits and '_': a name every format keeps as it is (Abaqus labels,
// Gmsh quoted names, Exodus names).
constexpr std::size_t kMaxGroupName = 32;

std::string group_name(const Element& e, const std::string& fallback) {
  const auto name = e.text("name");
  if (!name) return fallback;
  const bool ok = !name->empty() && name->size() <= kMaxGroupName &&
                  std::isalpha(static_cast<unsigned char>((*name)[0])) &&
                  std::all_of(name->begin(), name->end(), [](char c) {
                    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
                  });
  if (!ok)
    e.fail_at("name", "attribute \"name\" must be a letter, then letters, digits or '_' (at most " +
                          std::to_string(kMaxGroupName) + " characters), got \"" + clip(*name) +
                          "\"");
  return *name;
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::vector<int> optional_ids(const Element& e, const char* attribute) {
  return e.has(attribute) ? e.ids(attribute) : std::vector<int>{};
}

// Ids and names unique within one kind of group (names compared ignoring
// case: Abaqus does).
template <class Setting>
void check_unique(const Element& e, const std::vector<Setting>& others, const Setting& s,
                  const char* kind) {
  for (const Setting& o : others) {
    if (o.id == s.id)
      e.fail_at("id", std::string(kind) + " id " + std::to_string(s.id) +
                          " is already used at line " + std::to_string(o.where.line));
    if (lower(o.name) == lower(s.name))
      e.fail_at("name", std::string(kind) + " name \"" + s.name + "\" is already used at line " +
                            std::to_string(o.where.line) + " (names are compared ignoring case)");
  }
}

void read_block(const Element& e, GroupSettings& groups) {
  e.allow_attributes({"id", "name", "volumes", "surfaces"});
  e.expect_empty();
  BlockSetting b;
  b.id = e.required_integer("id", 1);
  b.name = group_name(e, "block_" + std::to_string(b.id));
  b.volumes = optional_ids(e, "volumes");
  b.surfaces = optional_ids(e, "surfaces");
  if (b.volumes.empty() == b.surfaces.empty())
    e.fail(
        "needs exactly one of \"volumes\" (a volume mesh) and \"surfaces\" (a surface mesh, "
        "--dim 2)");
  b.where = e.where();
  check_unique(e, groups.blocks, b, "block");
  // An element belongs to one block.
  for (const BlockSetting& o : groups.blocks) {
    for (int v : b.volumes)
      if (std::count(o.volumes.begin(), o.volumes.end(), v))
        e.fail_at("volumes", "volume " + std::to_string(v) + " is already in block " +
                                 std::to_string(o.id) + " at line " + std::to_string(o.where.line) +
                                 "; an element belongs to one block");
    for (int s : b.surfaces)
      if (std::count(o.surfaces.begin(), o.surfaces.end(), s))
        e.fail_at("surfaces", "surface " + std::to_string(s) + " is already in block " +
                                  std::to_string(o.id) + " at line " +
                                  std::to_string(o.where.line) +
                                  "; an element belongs to one block");
  }
  groups.blocks.push_back(std::move(b));
}

void read_sideset(const Element& e, GroupSettings& groups) {
  e.allow_attributes({"id", "name", "surfaces"});
  e.expect_empty();
  SideSetSetting s;
  s.id = e.required_integer("id", 1);
  s.name = group_name(e, "sideset_" + std::to_string(s.id));
  s.surfaces = e.ids("surfaces");
  s.where = e.where();
  check_unique(e, groups.side_sets, s, "side set");
  groups.side_sets.push_back(std::move(s));
}

void read_nodeset(const Element& e, GroupSettings& groups) {
  e.allow_attributes({"id", "name", "surfaces", "curves", "vertices"});
  e.expect_empty();
  NodeSetSetting n;
  n.id = e.required_integer("id", 1);
  n.name = group_name(e, "nodeset_" + std::to_string(n.id));
  n.surfaces = optional_ids(e, "surfaces");
  n.curves = optional_ids(e, "curves");
  n.vertices = optional_ids(e, "vertices");
  if (n.surfaces.empty() && n.curves.empty() && n.vertices.empty())
    e.fail("needs \"surfaces\", \"curves\" or \"vertices\" (or several)");
  n.where = e.where();
  check_unique(e, groups.node_sets, n, "node set");
  groups.node_sets.push_back(std::move(n));
}

}  // namespace

void read_group(const Element& e, GroupSettings& groups) {
  const std::string tag = e.name();
  if (tag == "block")
    read_block(e, groups);
  else if (tag == "sideset")
    read_sideset(e, groups);
  else
    read_nodeset(e, groups);
}

}  // namespace cooperage::io::detail
