// A run's output folder appears whole or not at all: the files are written into a fresh staging folder beside
// it, which then takes the folder's place in one atomic step. A reader, a second run into the same folder, a
// full disk or kill -9 can never leave files of two runs mixed, or a half-written folder under the name.
#pragma once

#include <filesystem>
#include <functional>

namespace contactbench {

// Name of the file that marks a folder as written by a run (so that it may be replaced by the next run).
inline constexpr const char* kRunFolderMark = ".contactbench-run";

// Writes `folder` as a whole: write(staging) fills a new folder `.<name>.partial.<pid>.<k>` beside it (the
// mark is added), and that folder then replaces `folder` with renameat2(RENAME_EXCHANGE) (or a plain rename
// when there is none yet); the previous contents are removed after the exchange. Refuses (Error, before
// write is called) a `folder` that is a link, a file or device, or a folder holding anything that a run
// did not write (a non-empty folder without the mark). On any failure the staging folder is removed and
// `folder` keeps what it held. Stale staging folders of runs that died (kill -9) are removed first.
void write_folder_atomically(const std::filesystem::path& folder,
                             const std::function<void(const std::filesystem::path& staging)>& write);

// The check write_folder_atomically makes first, for validating an --out before any work.
void check_replaceable_folder(const std::filesystem::path& folder);

}  // namespace contactbench
