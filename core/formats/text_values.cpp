#include "contactbench/core/formats/text_values.hpp"

#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <system_error>

#include "contactbench/core/error.hpp"
#include "contactbench/core/formats/text_tokens.hpp"

namespace contactbench::formats {

namespace {

namespace fs = std::filesystem;

// Offending tokens are quoted in messages; a binary file must not produce a megabyte-long message.
constexpr std::size_t max_quoted_length = 40;

}  // namespace

std::string quoted(std::string_view token) {
  const bool cut = token.size() > max_quoted_length;
  if (cut) token = token.substr(0, max_quoted_length);
  std::string text = "'";
  for (std::size_t i = 0; i < token.size(); ++i) {
    const auto byte = static_cast<unsigned char>(token[i]);
    // A UTF-8 sequence: its lead byte says how many continuation bytes (10xxxxxx) follow.
    const std::size_t length = byte >= 0xf0 && byte < 0xf8 ? 4 : byte >= 0xe0 ? 3 : byte >= 0xc2 ? 2 : 1;
    bool sequence = byte >= 0xc2 && byte < 0xf8 && i + length <= token.size();
    for (std::size_t k = 1; sequence && k < length; ++k)
      sequence = (static_cast<unsigned char>(token[i + k]) & 0xc0) == 0x80;
    if (sequence) {
      text.append(token.substr(i, length));
      i += length - 1;
    } else if (byte < 0x20 || byte >= 0x7f) {
      char escaped[5];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", byte);
      text += escaped;
    } else {
      text += static_cast<char>(byte);
    }
  }
  return text + (cut ? "...'" : "'");
}

std::string format_real(Real value) {
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return std::string(buffer.data(), result.ptr);
}

std::from_chars_result parse_real_prefix(const char* first, const char* last, Real& value) {
  if (last - first > 1 && *first == '+' &&
      (std::isdigit(static_cast<unsigned char>(first[1])) || first[1] == '.'))
    ++first;
  return std::from_chars(first, last, value);
}

std::optional<Real> parse_real(std::string_view token) {
  Real value = 0;
  const char* last = token.data() + token.size();
  const auto [end, error] = parse_real_prefix(token.data(), last, value);
  if (error != std::errc() || end != last) return std::nullopt;
  return value;
}

std::optional<Real> length_unit_in_metres(std::string_view unit) {
  if (unit == "m") return 1.0;
  if (unit == "mm") return 1e-3;
  if (unit == "um" || unit == "\u00b5m" || unit == "\u03bcm") return 1e-6;
  if (unit == "nm") return 1e-9;
  return std::nullopt;
}

Real length_unit_or_throw(const fs::path& path, long line, std::string_view what, std::string_view unit) {
  const std::optional<Real> metres = length_unit_in_metres(unit);
  if (!metres)
    throw InputError(path, line,
                     "unknown unit " + quoted(unit) + " for " + std::string(what) +
                         "; accepted length units: " + std::string(accepted_length_units));
  return *metres;
}

Real parse_size(const fs::path& path, long line, std::string_view key, std::string_view text) {
  Real value = 0;
  const char* last = text.data() + text.size();
  const auto [end, error] = parse_real_prefix(text.data(), last, value);
  if (error != std::errc() || end == text.data())
    throw InputError(path, line, std::string(key) + " needs a number and a length unit, got " + quoted(text));
  const std::string_view unit = trim(std::string_view(end, static_cast<std::size_t>(last - end)), is_blank);
  if (unit.empty())
    throw InputError(path, line,
                     std::string(key) + " " + quoted(text) +
                         " has no unit; accepted length units: " + std::string(accepted_length_units));
  const Real metres = value * length_unit_or_throw(path, line, key, unit);
  if (!(std::isfinite(metres) && metres > 0))
    throw InputError(path, line, std::string(key) + " must be a finite size > 0, got " + quoted(text));
  return metres;
}

Index parse_count(const fs::path& path, long line, std::string_view key, std::string_view text) {
  long long count = 0;
  const char* last = text.data() + text.size();
  const auto [end, error] = std::from_chars(text.data(), last, count);
  if (error != std::errc() || end != last || count < 1)
    throw InputError(path, line, std::string(key) + " must be a whole number >= 1, got " + quoted(text));
  return static_cast<Index>(count);
}

bool equals_ignoring_case(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const auto lower = [](char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; };
    if (lower(a[i]) != lower(b[i])) return false;
  }
  return true;
}

void store_entry(const fs::path& path, const Line& line, std::string_view key, std::string_view value,
                 HeaderEntry& entry) {
  if (entry.line != 0)
    throw InputError(
        path, line.number,
        "header key " + quoted(key) + " given twice (first on line " + std::to_string(entry.line) + ")");
  entry = {value, line.number};
}

}  // namespace contactbench::formats
