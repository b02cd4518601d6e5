// Checks on a topography's lateral sizes (internal to core/formats/), shared by the text readers and the
// channels of the binary ones: a size is finite and > 0, and a size the caller gave agrees with the file's.
#pragma once

#include <filesystem>
#include <optional>
#include <string_view>

#include "contactbench/core/types.hpp"

namespace contactbench::formats {

void check_lateral_size(const std::filesystem::path& path, long line, std::string_view name, Real value);

// A size the caller gave must match the one the file carries, to 1e-6 relative (TopographyReadOptions).
void check_agrees(const std::filesystem::path& path, long line, std::string_view name, Real from_file,
                  const std::optional<Real>& given);

}  // namespace contactbench::formats
