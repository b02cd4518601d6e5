// The command-line front ends (contactbench bem, sweep) over the scene pipeline: their flags become the keys
// of a one-method scene, read by the same schema (same validation, defaults and messages, with each key path
// shown as the flag that set it).
#pragma once

#include <map>
#include <string>

#include <toml++/toml.h>

#include "contactbench/app/scene.hpp"
#include "contactbench/app/topography_options.hpp"

namespace contactbench {

// [surface] of the file the options name: file, size (x, or [x, y]), periodic.
toml::table surface_keys(const TopographyOptions& options);

// Key path -> flag (e.g. "methods.bem.tolerance" -> "--tolerance").
using FlagNames = std::map<std::string, std::string>;

// parse_scene of `document` for `command` (e.g. "contactbench bem"); a SceneError's key paths are named by
// their flags. Relative file paths resolve against the working directory.
Scene scene_from_flags(const toml::table& document, const std::string& command, const FlagNames& flags);

// The same renaming for a SceneError raised later (a preflight).
[[noreturn]] void rethrow_with_flags(const SceneError& error, const std::string& command,
                                     const FlagNames& flags);

}  // namespace contactbench
