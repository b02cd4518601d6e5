// Running the contactbench binary from a test: its exit status and what it printed, and the fixture that
// gives each test its own folder to run it in.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/wait.h>

#include "test_folder.hpp"

namespace contactbench::testing {

struct CommandResult {
  int status = -1;
  std::string out, err;
};

inline std::string slurp(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

// `contactbench <arguments>` (shell syntax) with its output captured in `folder`. `environment`: VAR=value
// assignments for the command (the shell's), or empty. `out`: where standard output goes instead of a file of
// `folder` (a device, a pipe: it is then not read back), or empty.
inline CommandResult run_contactbench(const std::string& arguments, const std::filesystem::path& folder,
                                      const std::string& environment = "", const std::string& out = "") {
  const auto stdout_file = folder / "stdout.txt", err = folder / "stderr.txt";
  const std::string target = out.empty() ? stdout_file.string() : out;
  const std::string command = environment + (environment.empty() ? "" : " ") + std::string(CB_CLI_PATH) +
                              " " + arguments + " >" + target + " 2>" + err.string() + " </dev/null";
  const int raw = std::system(command.c_str());
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, out.empty() ? slurp(stdout_file) : "", slurp(err)};
}

// A test with a folder of its own (FolderTest) where the program runs.
class CliTest : public FolderTest {
 protected:
  explicit CliTest(const std::string& prefix) : FolderTest(prefix) {}

  CommandResult run(const std::string& arguments, const std::string& environment = "") {
    return run_contactbench(arguments, folder_, environment);
  }
};

}  // namespace contactbench::testing
