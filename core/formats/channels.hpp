// From the channels a binary reader returns to the surface the caller asked for (docs/formats.md "channels",
// "invalid points"): the channel chosen by name or index (else the first height channel), its sizes checked,
// its invalid points refused or filled, its heights levelled.
#pragma once

#include <filesystem>

#include "contactbench/core/formats/raw_topography.hpp"
#include "contactbench/core/topography_io.hpp"

namespace contactbench::formats {

TopographyReading reading_from_channels(const std::filesystem::path& path, RawTopography raw,
                                        TopographyFormat format, const TopographyReadOptions& options);

}  // namespace contactbench::formats
