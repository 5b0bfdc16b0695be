// Nothing left behind, nothing overwritten by surprise (issue 21 item 3):
// targets checked before any work, exports of a run all or nothing,
// temporary files created exclusively under unpredictable names, bounded
// names in the files.
#include "framework/io/export/write_mesh.h"

#include "framework/core/error.h"
#include "framework/io/export/export_common.h"

#include "export_fixtures.h"
#include "export_test_util.h"

#include <gtest/gtest.h>

#include <dirent.h>
#include <sys/stat.h>
#include <unistd.h>

#include <set>

namespace cooperage::test {
namespace {

std::vector<std::string> entries(const std::string& dir) {
  std::vector<std::string> names;
  if (DIR* d = opendir(dir.c_str())) {
    while (dirent* e = readdir(d)) {
      const std::string n = e->d_name;
      if (n != "." && n != "..") names.push_back(n);
    }
    closedir(d);
  }
  std::sort(names.begin(), names.end());
  return names;
}

std::string target_error(const std::string& path) {
  try {
    io::check_export_target(path);
  } catch (const MeshingError& e) {
    return e.what();
  }
  return "";
}

TEST(ExportSafety, TargetsAreCheckedBeforeAnyWork) {
  const std::string dir = scratch_dir();
  EXPECT_EQ(target_error(dir + "/out.exo"), "");
  EXPECT_NE(target_error(dir + "/missing/out.exo").find("does not exist"), std::string::npos);
  ::mkdir((dir + "/sub.vtu").c_str(), 0700);
  EXPECT_NE(target_error(dir + "/sub.vtu").find("is a directory"), std::string::npos);
  { std::ofstream(dir + "/file") << "x"; }
  EXPECT_NE(target_error(dir + "/file/out.msh").find("is not a directory"), std::string::npos);
  EXPECT_NE(target_error(dir + "/out.txt").find("no mesh file extension"), std::string::npos);
  EXPECT_NE(target_error("/proc/out.exo").find("cannot create files"), std::string::npos);
  EXPECT_NE(target_error(dir + "/" + std::string(300, 'a') + ".exo").find("name is too long"),
            std::string::npos);
  EXPECT_EQ(entries(dir), (std::vector<std::string>{"file", "sub.vtu"})) << "the probe is removed";
}

TEST(ExportSafety, ABatchThatFailsLeavesNothingAndKeepsOldFiles) {
  const TestMesh good = one_block();
  TestMesh bad = one_block();
  bad.db.mutable_volume(1).hexes[0][0] = static_cast<int>(bad.db.node_count());
  const std::string dir = scratch_dir();
  { std::ofstream(dir + "/b.msh") << "old"; }
  {
    io::ExportBatch batch;
    batch.stage(dir + "/a.exo", good.db, good.model);
    EXPECT_THROW(batch.stage(dir + "/b.msh", bad.db, bad.model), MeshingError);
  }
  EXPECT_EQ(entries(dir), std::vector<std::string>{"b.msh"});
  EXPECT_EQ(read_all(dir + "/b.msh"), "old");
  {
    io::ExportBatch batch;  // staged but never committed: nothing appears
    batch.stage(dir + "/c.vtu", good.db, good.model);
  }
  EXPECT_EQ(entries(dir), std::vector<std::string>{"b.msh"});
}

TEST(ExportSafety, ABatchCommitsEveryFileAtOnce) {
  const TestMesh t = two_blocks();
  const std::string dir = scratch_dir();
  io::ExportBatch batch;
  for (const char* name : {"/m.exo", "/m.msh", "/m.vtu", "/m.inp"})
    batch.stage(dir + name, t.db, t.model);
  EXPECT_EQ(entries(dir).size(), 4u);  // four private directories, no target yet
  for (const auto& e : entries(dir)) EXPECT_EQ(e.rfind(".cooperage-", 0), 0u) << e;
  const auto written = batch.commit();
  EXPECT_EQ(written.size(), 4u);
  EXPECT_EQ(entries(dir), (std::vector<std::string>{"m.exo", "m.inp", "m.msh", "m.vtu"}));
  EXPECT_EQ(read_all(dir + "/m.exo").substr(0, 3), "CDF");
}

TEST(ExportSafety, AnExistingFileIsReplacedOnlyAtTheCommit) {
  // replace_file removes the old file just before the rename (ext4 would
  // otherwise flush the new one inside rename): until then it is intact.
  const TestMesh t = one_block();
  const std::string dir = scratch_dir();
  { std::ofstream(dir + "/m.vtu") << "old"; }
  io::ExportBatch batch;
  batch.stage(dir + "/m.vtu", t.db, t.model);
  EXPECT_EQ(read_all(dir + "/m.vtu"), "old");
  batch.commit();
  EXPECT_EQ(read_all(dir + "/m.vtu").substr(0, 5), "<?xml");
  EXPECT_EQ(entries(dir), std::vector<std::string>{"m.vtu"});
  // The same through the text writers' own temporary file.
  { std::ofstream(dir + "/m.msh") << "old"; }
  io::write_mesh(dir + "/m.msh", t.db, t.model);
  EXPECT_EQ(read_all(dir + "/m.msh").substr(0, 11), "$MeshFormat");
}

TEST(ExportSafety, ARenameThatFailsUndoesTheBatch) {
  const TestMesh t = one_block();
  const std::string dir = scratch_dir();
  io::ExportBatch batch;
  batch.stage(dir + "/first.vtu", t.db, t.model);
  batch.stage(dir + "/second.vtu", t.db, t.model);
  ::mkdir((dir + "/second.vtu").c_str(), 0700);  // appears after the check
  { std::ofstream(dir + "/second.vtu/keep") << "x"; }
  EXPECT_THROW(batch.commit(), MeshingError);
  EXPECT_EQ(entries(dir), std::vector<std::string>{"second.vtu"});
}

TEST(ExportSafety, TemporaryNamesAreUnpredictable) {
  std::set<std::string> names;
  for (int i = 0; i < 100; ++i) names.insert(io::detail::temp_path_for("/tmp/out.exo"));
  EXPECT_EQ(names.size(), 100u);
  for (const auto& n : names) {
    EXPECT_EQ(n.rfind("/tmp/.out.exo.", 0), 0u) << n;
    EXPECT_EQ(n.size(), std::string("/tmp/.out.exo.").size() + 16 + 4) << n;
  }
  // A long target name does not make the temporary name long (a 245-character
  // .exo name once overflowed a buffer in libexodus's error path).
  EXPECT_LT(io::detail::temp_path_for("/d/" + std::string(250, 'x') + ".exo").size(), 60u);
}

TEST(ExportSafety, ALinkAtTheTargetIsReplacedNotFollowed) {
  const TestMesh t = one_block();
  const std::string dir = scratch_dir();
  { std::ofstream(dir + "/victim") << "precious"; }
  ASSERT_EQ(::symlink((dir + "/victim").c_str(), (dir + "/out.vtu").c_str()), 0);
  for (const char* name : {"/out.vtu"}) {
    io::ExportBatch batch;
    batch.stage(dir + name, t.db, t.model);
    batch.commit();
  }
  EXPECT_EQ(read_all(dir + "/victim"), "precious");
  struct stat st {};
  ASSERT_EQ(::lstat((dir + "/out.vtu").c_str(), &st), 0);
  EXPECT_TRUE(S_ISREG(st.st_mode));
  // Direct writes too: the text writers create their file exclusively.
  ASSERT_EQ(::symlink((dir + "/victim").c_str(), (dir + "/direct.msh").c_str()), 0);
  io::write_mesh(dir + "/direct.msh", t.db, t.model);
  EXPECT_EQ(read_all(dir + "/victim"), "precious");
}

TEST(ExportSafety, VolumeLabelsAreBounded) {
  TestMesh t = one_block();
  t.model.mutable_volume(1).name = std::string(100000, 'n');
  EXPECT_EQ(io::detail::volume_label(t.model, 1), std::string(io::detail::kMaxLabelLength, 'n'));
  const std::string dir = scratch_dir();
  io::write_mesh(dir + "/big_name.exo", t.db, t.model);
  EXPECT_LT(read_all(dir + "/big_name.exo").size(), 100000u);
}

}  // namespace
}  // namespace cooperage::test
