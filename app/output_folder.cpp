#include "contactbench/app/output_folder.hpp"

#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <string>
#include <system_error>

#include "contactbench/core/error.hpp"

namespace contactbench {

namespace fs = std::filesystem;

namespace {

const std::string kPartial = ".partial.";
const std::string kRetired = ".retired.";

// ".<name>.partial.<pid>.<k>" or ".<name>.retired.<pid>.<k>" beside the folder.
fs::path sibling(const fs::path& folder, const std::string& kind) {
  static std::atomic<unsigned long> counter{0};
  return folder.parent_path() / ("." + folder.filename().string() + kind + std::to_string(::getpid()) + "." +
                                 std::to_string(counter++));
}

// Removes ".<name>.partial.<pid>.*" and ".<name>.retired.<pid>.*" left by processes that no longer exist.
void remove_stale_siblings(const fs::path& folder) {
  const fs::path parent = folder.parent_path().empty() ? fs::path(".") : folder.parent_path();
  std::error_code code;
  const std::string stem = "." + folder.filename().string();
  for (const fs::directory_entry& entry : fs::directory_iterator(parent, code)) {
    const std::string name = entry.path().filename().string();
    for (const std::string& kind : {kPartial, kRetired}) {
      if (name.rfind(stem + kind, 0) != 0) continue;
      const std::string rest = name.substr(stem.size() + kind.size());
      const pid_t pid = static_cast<pid_t>(std::strtol(rest.c_str(), nullptr, 10));
      if (pid > 0 && ::kill(pid, 0) != 0 && errno == ESRCH) fs::remove_all(entry.path(), code);
    }
  }
}

// A staging folder that removes itself unless it was committed.
class Staging {
 public:
  explicit Staging(fs::path path) : path_(std::move(path)) {
    std::error_code code;
    if (!fs::create_directory(path_, code) || code)
      throw Error(path_.parent_path().string() + ": cannot create a staging folder for the output: " +
                  (code ? code.message() : "it exists"));
  }
  ~Staging() {
    std::error_code ignored;
    if (!committed_) fs::remove_all(path_, ignored);
  }
  Staging(const Staging&) = delete;
  Staging& operator=(const Staging&) = delete;
  const fs::path& path() const { return path_; }
  void committed() { committed_ = true; }

 private:
  fs::path path_;
  bool committed_ = false;
};

}  // namespace

void check_replaceable_folder(const fs::path& folder) {
  if (folder.empty()) throw Error("the output folder name is empty");
  std::error_code code;
  const fs::file_type type = fs::symlink_status(folder, code).type();
  if (type == fs::file_type::not_found) return;
  if (type != fs::file_type::directory)
    throw Error(folder.string() + ": exists and is not a folder (" +
                (type == fs::file_type::symlink ? "a symbolic link" : "a file or device") +
                "); refusing to replace it with a run's output");
  if (fs::is_empty(folder, code) || fs::exists(folder / kRunFolderMark)) return;
  throw Error(folder.string() + ": is a folder that a run did not write (no " + kRunFolderMark +
              " in it); refusing to replace what it holds: give a new or empty folder to --out");
}

void write_folder_atomically(const fs::path& given, const std::function<void(const fs::path&)>& write) {
  const fs::path folder = given.has_filename() ? given : given.parent_path();  // "out/" -> "out"
  check_replaceable_folder(folder);
  if (!folder.parent_path().empty()) {
    std::error_code code;
    fs::create_directories(folder.parent_path(), code);
    if (code) throw Error(folder.parent_path().string() + ": cannot create the folder: " + code.message());
  }
  remove_stale_siblings(folder);

  Staging staging(sibling(folder, kPartial));
  write(staging.path());
  {
    std::ofstream mark(staging.path() / kRunFolderMark);
    mark << "Written by contactbench run; the next run into this folder replaces it as a whole.\n";
    if (!mark.flush()) throw Error(folder.string() + ": writing the output failed (disk full?)");
  }

  check_replaceable_folder(folder);  // again: it may have changed while the run worked
  if (::renameat2(AT_FDCWD, staging.path().c_str(), AT_FDCWD, folder.c_str(), RENAME_NOREPLACE) == 0) {
    staging.committed();
    return;
  }
  if (errno != EEXIST && errno != ENOTEMPTY)
    throw Error(folder.string() + ": cannot move the finished output into place: " + std::strerror(errno));
  // The folder exists (a previous run's): swap the two in one step, then remove the old contents.
  if (::renameat2(AT_FDCWD, staging.path().c_str(), AT_FDCWD, folder.c_str(), RENAME_EXCHANGE) != 0)
    throw Error(folder.string() +
                ": cannot exchange the finished output with the previous one: " + std::strerror(errno));
  const fs::path retired = sibling(folder, kRetired);
  std::error_code code;
  fs::rename(staging.path(), retired, code);  // the staging name now holds the previous run
  staging.committed();
  fs::remove_all(code ? staging.path() : retired, code);
}

}  // namespace contactbench
