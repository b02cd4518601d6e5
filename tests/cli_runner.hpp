// Running the contactbench binary from a test: its exit status and what it printed.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/wait.h>

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

// `contactbench <arguments>` (shell syntax) with its output captured in `folder`.
inline CommandResult run_contactbench(const std::string& arguments, const std::filesystem::path& folder) {
  const auto out = folder / "stdout.txt", err = folder / "stderr.txt";
  const std::string command =
      std::string(CB_CLI_PATH) + " " + arguments + " >" + out.string() + " 2>" + err.string() + " </dev/null";
  const int raw = std::system(command.c_str());
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(out), slurp(err)};
}

}  // namespace contactbench::testing
