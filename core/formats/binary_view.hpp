// Bounds-checked reading of a binary file held in memory: every read names the file and what was being read,
// and a read past the end throws InputError instead of touching memory it does not own (the readers of
// docs/formats.md are meant to survive fuzzed input).
#pragma once

#include <bit>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <string_view>
#include <type_traits>

#include "contactbench/core/error.hpp"

namespace contactbench::formats {

enum class ByteOrder { little, big };

class BinaryView {
 public:
  BinaryView(const std::filesystem::path& path, std::string_view bytes) : path_(path), bytes_(bytes) {}

  std::size_t size() const { return bytes_.size(); }
  const std::filesystem::path& path() const { return path_; }
  std::string_view bytes() const { return bytes_; }

  // Throws unless [offset, offset + count) lies inside the file; `what` says which part of the layout it is.
  void require(std::uint64_t offset, std::uint64_t count, std::string_view what) const {
    if (offset > bytes_.size() || count > bytes_.size() - offset)
      throw InputError(path_, 0,
                       "truncated or corrupt: " + std::string(what) + " needs bytes " +
                           std::to_string(offset) + " to " + std::to_string(offset + count) +
                           " but the file has " + std::to_string(bytes_.size()) + " bytes");
  }

  std::string_view slice(std::uint64_t offset, std::uint64_t count, std::string_view what) const {
    require(offset, count, what);
    return bytes_.substr(static_cast<std::size_t>(offset), static_cast<std::size_t>(count));
  }

  // A fixed-width text field without its trailing NULs and blanks.
  std::string text(std::uint64_t offset, std::uint64_t count, std::string_view what) const {
    std::string_view field = slice(offset, count, what);
    const std::size_t nul = field.find('\0');
    if (nul != std::string_view::npos) field = field.substr(0, nul);
    while (!field.empty() && (field.back() == ' ' || field.back() == '\t'))
      field.remove_suffix(1);
    return std::string(field);
  }

  template <typename T>
  T read(std::uint64_t offset, ByteOrder order, std::string_view what) const {
    static_assert(std::is_arithmetic_v<T>);
    return decode<T>(slice(offset, sizeof(T), what).data(), order);
  }

  // Decodes one value from raw bytes (the caller has checked the bounds).
  template <typename T>
  static T decode(const char* source, ByteOrder order) {
    unsigned char buffer[sizeof(T)];
    std::memcpy(buffer, source, sizeof(T));
    const bool swap = (order == ByteOrder::little) != (std::endian::native == std::endian::little);
    if (swap)
      for (std::size_t i = 0; i < sizeof(T) / 2; ++i)
        std::swap(buffer[i], buffer[sizeof(T) - 1 - i]);
    T value;
    std::memcpy(&value, buffer, sizeof(T));
    return value;
  }

 private:
  std::filesystem::path path_;
  std::string_view bytes_;
};

// Bytes of an nx x ny block of `item_size`-byte values; throws when the counts cannot be a real grid
// (non-positive, or so large that the product would overflow), before anything is allocated.
inline std::uint64_t grid_bytes(const std::filesystem::path& path, long long nx, long long ny,
                                std::uint64_t item_size, std::string_view what) {
  constexpr long long max_side = 1ll << 24;  // 16 million points a side: far beyond any instrument
  if (nx < 1 || ny < 1 || nx > max_side || ny > max_side)
    throw InputError(path, 0,
                     std::string(what) + ": grid " + std::to_string(nx) + " x " + std::to_string(ny) +
                         " is not a valid size (each side from 1 to " + std::to_string(max_side) + ")");
  return static_cast<std::uint64_t>(nx) * static_cast<std::uint64_t>(ny) * item_size;
}

}  // namespace contactbench::formats
