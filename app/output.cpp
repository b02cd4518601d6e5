#include "contactbench/app/output.hpp"

#include <iostream>
#include <system_error>

#include "contactbench/core/atomic_file.hpp"
#include "contactbench/core/error.hpp"

namespace contactbench {

void check_standard_output() {
  std::cout.flush();
  if (!std::cout) throw Error("standard output: writing failed (disk full, or the reader went away)");
}

void write_output(const std::string& path, const std::function<void(std::ostream&)>& write) {
  if (path.empty()) {
    write(std::cout);
    check_standard_output();
  } else {
    write_file_atomically(path, write);
  }
}

void refuse_output_over_input(const std::filesystem::path& output, const std::filesystem::path& input,
                              const std::string& option) {
  std::error_code code;
  if (std::filesystem::equivalent(output, input, code) && !code)
    throw Error(option + " " + output.string() + ": is the input file " + input.string() +
                "; refusing to overwrite what the command reads");
}

void check_output_file(const std::filesystem::path& output, const std::filesystem::path& input,
                       const std::string& option) {
  if (!input.empty()) refuse_output_over_input(output, input, option);
  try {
    check_replaceable_file(output);
  } catch (const Error& e) {
    throw Error(option + " " + e.what());
  }
}

void check_output_prefix(const std::filesystem::path& prefix, const std::string& option) {
  std::error_code code;
  const auto type = std::filesystem::symlink_status(prefix, code).type();
  if (type != std::filesystem::file_type::not_found && type != std::filesystem::file_type::regular)
    throw Error(option + " " + prefix.string() +
                ": names an existing device, link or folder; give a prefix such as out/fields (files "
                "out/fields_load1_pressure.txt, ...)");
  const std::filesystem::path folder = prefix.has_parent_path() ? prefix.parent_path() : ".";
  if (!std::filesystem::is_directory(folder, code))
    throw Error(option + " " + prefix.string() + ": the folder " + folder.string() + " does not exist");
}

std::string refuse_empty_output_name(const std::string& name) {
  return name.empty() ? "an empty name; omit the option for its default" : "";
}

}  // namespace contactbench
