// The command-line flags of a settings declaration (app/settings.hpp): each row with a flag becomes an
// option `--name VALUE` (typed as the row's kind) or a switch `--name`, with the row's one-line meaning as
// its help; what was given becomes keys of the command's one-method scene, read by the scene's own schema
// (same checks, same messages, each shown with its flag: app/flag_scene.hpp).
#pragma once

#include <deque>
#include <string>
#include <vector>

#include <toml++/toml.h>
#include <CLI/CLI.hpp>

#include "contactbench/app/flag_scene.hpp"
#include "contactbench/app/settings.hpp"

namespace contactbench {

class SettingFlags {
 public:
  explicit SettingFlags(std::vector<SettingSpec> specs);

  // Adds every flag to `command`, its help the row's meaning, scene key and default.
  void add_to(CLI::App& command);
  // The given values as keys of `table` (e.g. the scene's methods.bem).
  void insert_into(toml::table& table) const;
  // The given flags as a user types them (" --tolerance 1e-08 --float"), for the provenance.
  std::string command_text() const;
  // Each flag by its key path under `prefix` (e.g. "methods.bem."), for messages.
  void name_flags(const std::string& prefix, FlagNames& names) const;

 private:
  std::vector<SettingSpec> specs_;
  std::deque<std::string> texts_;  // per row, `--name VALUE` as given ("" when not)
  std::deque<bool> switched_;      // per row, a switch given
};

}  // namespace contactbench
