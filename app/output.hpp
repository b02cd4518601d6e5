// Where a command's text output goes: standard output, or a file written to a temporary name and renamed.
#pragma once

#include <filesystem>
#include <functional>
#include <ostream>
#include <string>

namespace contactbench {

// write(stream) to standard output when `path` is empty, else to `path` atomically (core/atomic_file.hpp:
// never over a device, a link or a folder). A failed write to standard output (a full disk, a closed pipe)
// throws Error: output is never lost with exit status 0.
void write_output(const std::string& path, const std::function<void(std::ostream&)>& write);

// Throws Error when the output `output` (named by `option`, e.g. "--out") is the input file `input` itself,
// by any name (hard links and links included): a command never overwrites what it reads.
void refuse_output_over_input(const std::filesystem::path& output, const std::filesystem::path& input,
                              const std::string& option);

// Checks an output file option before any work: not the input, not a device, link or folder (Error names the
// option and what the path is).
void check_output_file(const std::filesystem::path& output, const std::filesystem::path& input,
                       const std::string& option);

// Checks a prefix of output files (PREFIX_<suffix>) before any work: its folder must exist and be a folder,
// and the prefix itself must not name an existing device, link or folder (`--fields /dev/full` would
// otherwise create files in /dev).
void check_output_prefix(const std::filesystem::path& prefix, const std::string& option);

// A CLI11 check for options that name an output: an empty name is refused (it would silently mean the
// default), with a hint to omit the option instead.
std::string refuse_empty_output_name(const std::string& name);

// Throws Error when standard output has failed (checked once a command has written everything).
void check_standard_output();

}  // namespace contactbench
