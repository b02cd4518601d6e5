// Reading the values of a text topography's header (internal to core/formats/): numbers, counts, lengths with
// their unit, keys given once, and how an offending token is quoted in a message.
#pragma once

#include <charconv>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "contactbench/core/formats/text_lines.hpp"
#include "contactbench/core/types.hpp"

namespace contactbench::formats {

inline constexpr std::string_view accepted_length_units = "m, mm, um, \u00b5m, \u03bcm, nm";

// A header value and the line it came from (line 0: absent).
struct HeaderEntry {
  std::string_view value;
  long line = 0;
};

// A token as a message shows it: control bytes and bytes that are not UTF-8 as \xNN (a NUL would end the
// message, a raw binary byte garble the terminal), cut after 40 characters.
std::string quoted(std::string_view token);

// Shortest decimal that reads back to the same double.
std::string format_real(Real value);

// std::from_chars, which rejects a leading '+' that instruments and people sometimes write.
std::from_chars_result parse_real_prefix(const char* first, const char* last, Real& value);

// The whole token as a double (possibly NaN or Inf), or nothing if it is not exactly one number in range.
std::optional<Real> parse_real(std::string_view token);

// Metres per unit for m, mm, um (µm, μm) and nm; nothing for any other unit.
std::optional<Real> length_unit_in_metres(std::string_view unit);
Real length_unit_or_throw(const std::filesystem::path& path, long line, std::string_view what,
                          std::string_view unit);

// A lateral size written as "<number> <unit>" (or "<number><unit>"), in metres; finite and > 0.
Real parse_size(const std::filesystem::path& path, long line, std::string_view key, std::string_view text);

// A whole number >= 1.
Index parse_count(const std::filesystem::path& path, long line, std::string_view key, std::string_view text);

// ASCII case-insensitive equality, for header keys that tools spell with varying capitals.
bool equals_ignoring_case(std::string_view a, std::string_view b);

// Stores a key's value, refusing a key given twice.
void store_entry(const std::filesystem::path& path, const Line& line, std::string_view key,
                 std::string_view value, HeaderEntry& entry);

}  // namespace contactbench::formats
