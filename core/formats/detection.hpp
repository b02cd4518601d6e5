// Which format a topography file is in (docs/formats.md): a binary format by its magic bytes (or, for .plu
// which has none, by its header's consistency), else by an extension naming one; otherwise a text format by
// its first non-blank line.
#pragma once

#include <array>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

#include "contactbench/core/formats/raw_topography.hpp"
#include "contactbench/core/formats/text_lines.hpp"
#include "contactbench/core/topography_io.hpp"

namespace contactbench::formats {

// The binary formats: how each is recognised and read (docs/formats.md).
struct BinaryFormat {
  TopographyFormat format;
  std::array<std::string_view, 3> extensions;  // lower case, with the dot; "" for unused slots
  bool (*detect)(std::string_view bytes);
  formats::RawTopography (*read)(const std::filesystem::path& path, std::string_view bytes);
};

// The binary format of these bytes: by content first; else by an extension that names one (its reader then
// refuses the file with what is wrong); else none (a text format).
const BinaryFormat* binary_format_of(const std::filesystem::path& path, std::string_view bytes);

// The text format of these lines, by the first one; an empty file is refused.
TopographyFormat text_format_of(const std::filesystem::path& path, std::span<const Line> lines);

// The path's extension in lower case, with the dot.
std::string lower_extension(const std::filesystem::path& path);

}  // namespace contactbench::formats
