#include "contactbench/app/flag_scene.hpp"

#include <filesystem>

#include "contactbench/app/scene_toml.hpp"

namespace contactbench {

toml::table surface_keys(const TopographyOptions& o) {
  toml::table surface{{"file", std::filesystem::absolute(o.file).string()}};
  if (o.periodic) surface.insert("periodic", true);  // else: the file's own periodicity
  if (o.size && o.size_y)
    surface.insert("size", toml::array{*o.size, *o.size_y});
  else if (o.size)
    surface.insert("size", *o.size);
  else if (o.size_y)
    throw Error("--size-y: give --size too (the scene's size is lx alone or [lx, ly])");
  // The reading options every command takes (docs/formats.md), passed on rather than silently dropped.
  if (o.channel) surface.insert("channel", *o.channel);
  surface.insert("fill", o.fill);
  surface.insert("level", o.level);
  surface.insert("align_rows", o.align_rows);
  if (o.unit) surface.insert("unit", *o.unit);
  if (o.crop) surface.insert("crop", *o.crop);
  return surface;
}

void rethrow_with_flags(const SceneError& error, const std::string& command, const FlagNames& flags) {
  std::vector<std::string> lines;
  std::string message = command + ": " + std::to_string(error.problems().size()) +
                        (error.problems().size() == 1 ? " problem:" : " problems:");
  for (std::string line : error.problems()) {
    // "<origin>[:line]: <key path>[...]: <reason>": the origin is the command itself.
    if (const auto at = line.find(": "); at != std::string::npos) line.erase(0, at + 2);
    for (const auto& [key, flag] : flags)
      if (line.rfind(key, 0) == 0 && (line.size() == key.size() || line[key.size()] == ':' ||
                                      line[key.size()] == '[' || line[key.size()] == '.')) {
        line = flag + " (" + key + ")" + line.substr(line.find(':', key.size()));
        break;
      }
    message.append("\n  ").append(line);
    lines.push_back(std::move(line));
  }
  throw SceneError(message, std::move(lines));
}

Scene scene_from_flags(const toml::table& document, const std::string& command, const FlagNames& flags) {
  try {
    // The origin's folder is where relative paths resolve: the working directory.
    return parse_scene_table(document, std::filesystem::current_path() / command);
  } catch (const SceneError& error) {
    rethrow_with_flags(error, command, flags);
  }
}

}  // namespace contactbench
