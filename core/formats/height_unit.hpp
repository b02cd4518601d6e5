// The unit of files that state none (internal to core/formats/): a plain matrix, a NumPy array, an x y z
// point list hold bare numbers. They are metres unless the caller names a unit (--unit, unit = "nm"); without
// one, heights whose Sq is implausible for metres are refused with the unit they were likely written in.
#pragma once

#include <filesystem>
#include <optional>
#include <span>
#include <string>

#include "contactbench/core/types.hpp"

namespace contactbench::formats {

// Sq outside [kLeastPlausibleSq, kGreatestPlausibleSq] m is refused without an explicit unit: no measured
// surface is rougher than a millimetre rms, and none is smoother than a picometre.
inline constexpr Real kGreatestPlausibleSq = 1e-3;
inline constexpr Real kLeastPlausibleSq = 1e-12;

// Units per metre of a unit the caller named (m, mm, um, µm, μm, nm, pm: 1, 1e3, ... 1e12, each exact);
// InputError naming the file and the accepted units for any other. Values are divided by it: 3 nm becomes
// 3 / 1e9, the double nearest to 3e-9, as the text "3e-9" reads (a product by 1e-9 would round twice).
Real given_units_per_metre(const std::filesystem::path& path, const std::string& unit);

// The rule above, for heights read as metres with no unit stated anywhere (NaN, invalid points, skipped).
// `kind` names the format in the message ("plain matrix").
void check_plausible_as_metres(const std::filesystem::path& path, std::span<const Real> heights,
                               const std::string& kind);

}  // namespace contactbench::formats
