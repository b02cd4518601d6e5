// Outputs never destroy anything: a device, a link, a folder a run did not write and the input itself are
// refused before any work; a failed write to standard output is an error; a run's folder appears whole or not
// at all (app/output.hpp, app/output_folder.hpp, core/atomic_file.hpp).
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "cli_runner.hpp"
#include "contactbench/app/output_folder.hpp"
#include "contactbench/core/atomic_file.hpp"
#include "contactbench/core/error.hpp"

namespace contactbench {
namespace {

namespace fs = std::filesystem;

using testing::slurp;

class OutputSafety : public testing::CliTest {
 protected:
  OutputSafety() : CliTest("contactbench_output_") {}

  void SetUp() override {
    surface_ = folder_ / "s.txt";
    ASSERT_EQ(cli("generate --sigma 1e-6 --hurst 0.8 --qr 2e5 --size 32e-6 --grid 16 --seed 1 --out " +
                  surface_.string()),
              0)
        << err_;
  }

  // Runs the program with `arguments`; stdout goes to `out` (a file of the test's folder by default).
  int cli(const std::string& arguments, const std::string& out = "") {
    const testing::CommandResult result = testing::run_contactbench(arguments, folder_, "", out);
    err_ = result.err;
    return result.status;
  }

  fs::path surface_;
  std::string err_;
};

TEST_F(OutputSafety, ANamedPipeAndASymlinkSurviveAsOutputs) {
  const fs::path pipe = folder_ / "pipe", target = folder_ / "target.txt", link = folder_ / "link";
  ASSERT_EQ(::mkfifo(pipe.c_str(), 0600), 0);
  std::ofstream(target) << "keep me\n";
  fs::create_symlink(target, link);
  for (const fs::path& out : {pipe, link}) {
    EXPECT_NE(cli("bem " + surface_.string() + " --loads 1e-3 --out " + out.string()), 0) << out;
    EXPECT_NE(err_.find(out.string()), std::string::npos) << err_;
    EXPECT_NE(cli("sweep " + surface_.string() + " --out " + out.string()), 0) << out;
  }
  EXPECT_TRUE(fs::is_fifo(fs::symlink_status(pipe)));
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(link)));
  EXPECT_EQ(slurp(target), "keep me\n");
  // A prefix of field files that names a node is refused too (it would create files beside the node).
  EXPECT_NE(cli("bem " + surface_.string() + " --loads 1e-3 --fields " + pipe.string()), 0);
  EXPECT_NE(err_.find("--fields"), std::string::npos) << err_;
  EXPECT_FALSE(fs::exists(folder_ / "pipe_load1_pressure.txt"));
}

TEST_F(OutputSafety, TheInputIsNeverOverwritten) {
  const std::string before = slurp(surface_);
  const fs::path hard_link = folder_ / "same.txt";
  fs::create_hard_link(surface_, hard_link);
  for (const fs::path& out : {surface_, hard_link}) {
    EXPECT_NE(cli("bem " + surface_.string() + " --loads 1e-3 --out " + out.string()), 0);
    EXPECT_NE(err_.find("is the input file"), std::string::npos) << err_;
    EXPECT_NE(cli("sweep " + surface_.string() + " --out " + out.string()), 0);
  }
  EXPECT_EQ(slurp(surface_), before);
}

TEST_F(OutputSafety, AnEmptyOutputNameIsRefused) {
  EXPECT_NE(cli("bem " + surface_.string() + " --loads 1e-3 --out ''"), 0);
  EXPECT_NE(err_.find("empty"), std::string::npos) << err_;
  EXPECT_NE(cli("run scene.toml --out ''"), 0);
  EXPECT_NE(err_.find("empty"), std::string::npos) << err_;
}

TEST_F(OutputSafety, AFailedWriteToStandardOutputIsAnError) {
  ASSERT_TRUE(fs::exists("/dev/full"));  // every Linux system has it: writes fail with ENOSPC
  for (const std::string& command : {"stats " + surface_.string(), "sweep " + surface_.string(),
                                     "bem " + surface_.string() + " --loads 1e-3"}) {
    EXPECT_NE(cli(command, "/dev/full"), 0) << command;
    EXPECT_NE(err_.find("standard output"), std::string::npos) << command << ": " << err_;
  }
}

TEST_F(OutputSafety, FileWritesRefuseNodesAndLinks) {
  const fs::path pipe = folder_ / "pipe";
  ASSERT_EQ(::mkfifo(pipe.c_str(), 0600), 0);
  EXPECT_THROW(write_file_atomically(pipe, [](std::ostream& out) { out << "x"; }), Error);
  EXPECT_THROW(write_file_atomically(folder_, [](std::ostream& out) { out << "x"; }), Error);
  EXPECT_TRUE(fs::is_fifo(fs::symlink_status(pipe)));
}

// Writes a complete "run" of one file holding `text`.
void write_run(const fs::path& folder, const std::string& text) {
  write_folder_atomically(folder,
                          [&](const fs::path& staging) { std::ofstream(staging / "curves.csv") << text; });
}

TEST_F(OutputSafety, AFailureMidWriteLeavesThePreviousRunWhole) {
  const fs::path out = folder_ / "out";
  write_run(out, "first\n");
  EXPECT_THROW(write_folder_atomically(out,
                                       [](const fs::path& staging) {
                                         std::ofstream(staging / "curves.csv") << "second, half";
                                         throw Error("disk full (simulated)");
                                       }),
               Error);
  EXPECT_EQ(slurp(out / "curves.csv"), "first\n");
  // Nothing else beside it: no staging folder is left behind.
  for (const fs::directory_entry& entry : fs::directory_iterator(folder_))
    EXPECT_EQ(entry.path().filename().string().find(".out."), std::string::npos) << entry.path();
  write_run(out, "second\n");
  EXPECT_EQ(slurp(out / "curves.csv"), "second\n");
  EXPECT_TRUE(fs::exists(out / kRunFolderMark));
}

TEST_F(OutputSafety, AFolderARunDidNotWriteIsNotReplaced) {
  const fs::path mine = folder_ / "mine";
  fs::create_directories(mine);
  std::ofstream(mine / "thesis.tex") << "years of work\n";
  EXPECT_THROW(write_run(mine, "x"), Error);
  EXPECT_EQ(slurp(mine / "thesis.tex"), "years of work\n");
  EXPECT_THROW(write_run(surface_, "x"), Error);  // a file
  write_run(folder_ / "empty_is_fine", "x");
}

TEST_F(OutputSafety, StagingLeftByADeadRunIsCleanedUp) {
  // A process that no longer exists: fork one that exits at once and reap it.
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ASSERT_GT(child, 0);
  ::waitpid(child, nullptr, 0);
  const fs::path stale = folder_ / (".out.partial." + std::to_string(child) + ".0");
  fs::create_directories(stale);
  std::ofstream(stale / "curves.csv") << "half";
  write_run(folder_ / "out", "whole\n");
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_EQ(slurp(folder_ / "out" / "curves.csv"), "whole\n");
}

}  // namespace
}  // namespace contactbench
