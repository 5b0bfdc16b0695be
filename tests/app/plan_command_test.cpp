// `cooperage plan` prints a cooper volume's barrel tree (issue 15): the
// barrels, their caps and subcaps, the imprint operations; in text and JSON.
#include "run_command.h"
#include "temp_dir.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace cooperage {
namespace {

namespace fs = std::filesystem;
using testing::run_command;

const std::string kCli = COOPERAGE_CLI;
const std::string kSource = COOPERAGE_SOURCE_DIR;

class PlanCommand : public testing::TempDirTest {};

TEST_F(PlanCommand, PrintsTheBarrelTreeOfABlindHole) {
  fs::copy_file(kSource + "/examples/blind_hole.xml", path("blind_hole.xml"));
  const auto r = run_command(kCli + " plan " + path("blind_hole.xml"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // Two barrels along z: the tube around the hole, then the block below
  // the floor, whose upper cap is the floor and the tube's virtual cap.
  EXPECT_NE(r.out.find("cooper plan of volume 1: 2 barrels, straight along (0, 0, -1)"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("barrel 1: sides"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("lower: virtual cap into barrel 2"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("virtual cap from barrel 1"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("subtract"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("(by the sweep)"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(path("blind_hole.vtu")));  // nothing meshed
}

TEST_F(PlanCommand, JsonCarriesTheBarrelTree) {
  fs::copy_file(kSource + "/examples/blind_hole.xml", path("blind_hole.xml"));
  const auto j = run_command(kCli + " plan --json " + path("blind_hole.xml"));
  ASSERT_EQ(j.exit_code, 0) << j.err;
  std::ofstream(path("plan.json")) << j.out;
  const auto check =
      run_command(std::string(COOPERAGE_DEBIAN_PYTHON) + " -c \"import json; d=json.load(open('" +
                  path("plan.json") +
                  "')); t=d['volumes'][0]['barrel_tree']; b=t['barrels']; "
                  "print(len(b), t['direction'], b[0]['operation'], b[1]['operation'], "
                  "[p.get('virtual_from_barrel', p.get('meshed_by')) for p in b[1]['upper']], "
                  "[p.get('meshed_by') for p in b[1]['lower']])\"");
  ASSERT_EQ(check.exit_code, 0) << check.err;
  EXPECT_EQ(check.out, "2 [0, 0, -1] match subtract ['pave', 1] ['cooper']\n") << j.out;
}

}  // namespace
}  // namespace cooperage
