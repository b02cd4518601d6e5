// A scene read from TOML (app/scene.hpp; its pieces: app/section.hpp, app/problems.hpp, app/scene_text.hpp):
// the entry point for a document already parsed or built by a command from its flags, and the largest grid.
#pragma once

#include <filesystem>

#include <toml++/toml.h>

#include "contactbench/app/scene.hpp"
#include "contactbench/core/types.hpp"

namespace contactbench {

// Points a side of any grid a scene may ask for: 65536^2 doubles are already 32 GiB.
inline constexpr Index kMaxPointsASide = 65536;

// parse_scene (app/scene.hpp) of a document already parsed, or built by a command from its flags.
Scene parse_scene_table(const toml::table& document, const std::filesystem::path& origin);

}  // namespace contactbench
