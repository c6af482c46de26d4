// Issue #26, item 4: every file written in a run folder is created through the folder's own
// descriptor with no link followed (io/atomic_file.h, guard_run_folder). The checks of
// io/run_directory.h refuse links found when a run starts; these tests replace a subfolder or
// a file by a link afterwards (as mid-run) and check that nothing is written through it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "core/error.h"
#include "io/atomic_file.h"
#include "io/run_directory.h"
#include "scenes/scenario_files.h"

namespace sg {
namespace {

namespace fs = std::filesystem;

fs::path fresh(const std::string& name) {
  const fs::path d = scenes::process_temp_dir("run_folder_writes") / name;
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::string error_of(const fs::path& path) {
  try {
    write_file_atomically(path, "content");
  } catch (const Error& e) {
    return e.what();
  }
  return "(written)";
}

TEST(RunFolderWrites, ASubfolderReplacedByALinkAfterTheChecksIsRefused) {
  const fs::path root = fresh("linked-subfolder");
  const fs::path dir = prepare_run_directory(root / "out", "run", false);
  make_run_subfolder(dir, "fields");
  write_file_atomically(dir / "fields" / "000001.vtu", "first");
  EXPECT_EQ(read_text(dir / "fields" / "000001.vtu"), "first");
  // Mid-run, fields/ becomes a link to a folder outside.
  const fs::path elsewhere = root / "elsewhere";
  fs::create_directories(elsewhere);
  fs::remove_all(dir / "fields");
  fs::create_directory_symlink(elsewhere, dir / "fields");
  EXPECT_EQ(error_of(dir / "fields" / "000002.vtu"),
            "run folder entry '" + (dir / "fields").string() +
                "' is a symbolic link: refusing to write through it (remove the link)");
  EXPECT_TRUE(fs::is_empty(elsewhere));
  // A link deeper down, and a subfolder created on demand, the same way.
  fs::remove(dir / "fields");
  write_file_atomically(dir / "analysis" / "summary.json", "{}");
  EXPECT_EQ(read_text(dir / "analysis" / "summary.json"), "{}");
  fs::create_directory_symlink(elsewhere, dir / "analysis" / "deeper");
  EXPECT_NE(error_of(dir / "analysis" / "deeper" / "x.csv").find("deeper' is a symbolic link"),
            std::string::npos);
  EXPECT_TRUE(fs::is_empty(elsewhere));
}

TEST(RunFolderWrites, AFileOrTemporaryReplacedByALinkIsReplacedNotWrittenThrough) {
  const fs::path root = fresh("linked-file");
  const fs::path dir = prepare_run_directory(root / "out", "run", false);
  const fs::path outside = root / "outside.txt";
  std::ofstream(outside) << "keep";
  fs::create_symlink(outside, dir / "fields.pvd");
  fs::create_symlink(outside, dir / "series.csv.tmp");
  write_file_atomically(dir / "fields.pvd", "new");
  EXPECT_EQ(read_text(outside), "keep");
  EXPECT_FALSE(fs::is_symlink(dir / "fields.pvd"));
  EXPECT_EQ(read_text(dir / "fields.pvd"), "new");
  write_file_atomically(dir / "series.csv", "rows");
  EXPECT_EQ(read_text(outside), "keep");
  EXPECT_FALSE(fs::exists(fs::symlink_status(dir / "series.csv.tmp")));
}

TEST(RunFolderWrites, ARunFolderReplacedByALinkIsRefused) {
  const fs::path root = fresh("linked-folder");
  const fs::path dir = prepare_run_directory(root / "out", "run", false);
  const fs::path elsewhere = root / "elsewhere";
  fs::create_directories(elsewhere);
  fs::remove_all(dir);
  fs::create_directory_symlink(elsewhere, dir);
  EXPECT_NE(error_of(dir / "run.log").find("cannot open run folder '" + dir.string()),
            std::string::npos);
  EXPECT_TRUE(fs::is_empty(elsewhere));
}

TEST(RunFolderWrites, OutsideARunFolderAPathThroughALinkIsFollowedAsGiven) {
  // Files outside run folders (a picture given with -o, a campaign's table) keep the usual
  // meaning of a path: a linked folder on the way is the user's choice.
  const fs::path root = fresh("outside");
  fs::create_directories(root / "target");
  fs::create_directory_symlink(root / "target", root / "link");
  write_file_atomically(root / "link" / "picture.png", "png");
  EXPECT_EQ(read_text(root / "target" / "picture.png"), "png");
}

}  // namespace
}  // namespace sg
