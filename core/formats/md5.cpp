// MD5 as RFC 1321 specifies it: 64-byte blocks, four rounds of sixteen steps, little-endian words.
#include "contactbench/core/formats/md5.hpp"

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>

namespace contactbench::formats {

namespace {

// Per-step left-rotation amounts (RFC 1321 section 3.4).
constexpr std::array<std::uint32_t, 64> shifts = {7, 12, 17, 22, 7, 12, 17, 22, 7, 12, 17, 22, 7, 12, 17, 22,
                                                  5, 9,  14, 20, 5, 9,  14, 20, 5, 9,  14, 20, 5, 9,  14, 20,
                                                  4, 11, 16, 23, 4, 11, 16, 23, 4, 11, 16, 23, 4, 11, 16, 23,
                                                  6, 10, 15, 21, 6, 10, 15, 21, 6, 10, 15, 21, 6, 10, 15, 21};

// T[i] = floor(2^32 |sin(i + 1)|) (RFC 1321 section 3.4), computed once.
std::array<std::uint32_t, 64> sine_table() {
  std::array<std::uint32_t, 64> table{};
  for (std::size_t i = 0; i < table.size(); ++i)
    table[i] =
        static_cast<std::uint32_t>(std::floor(4294967296.0 * std::abs(std::sin(static_cast<double>(i + 1)))));
  return table;
}

void process_block(const unsigned char* block, std::array<std::uint32_t, 4>& state) {
  static const std::array<std::uint32_t, 64> table = sine_table();
  std::array<std::uint32_t, 16> words{};
  for (std::size_t i = 0; i < 16; ++i)
    words[i] = static_cast<std::uint32_t>(block[4 * i]) |
               (static_cast<std::uint32_t>(block[4 * i + 1]) << 8) |
               (static_cast<std::uint32_t>(block[4 * i + 2]) << 16) |
               (static_cast<std::uint32_t>(block[4 * i + 3]) << 24);
  std::uint32_t a = state[0], b = state[1], c = state[2], d = state[3];
  for (std::uint32_t i = 0; i < 64; ++i) {
    std::uint32_t f = 0;
    std::uint32_t g = 0;
    if (i < 16) {
      f = (b & c) | (~b & d);
      g = i;
    } else if (i < 32) {
      f = (d & b) | (~d & c);
      g = (5 * i + 1) % 16;
    } else if (i < 48) {
      f = b ^ c ^ d;
      g = (3 * i + 5) % 16;
    } else {
      f = c ^ (b | ~d);
      g = (7 * i) % 16;
    }
    const std::uint32_t rotated = std::rotl(a + f + table[i] + words[g], static_cast<int>(shifts[i]));
    a = d;
    d = c;
    c = b;
    b = b + rotated;
  }
  state[0] += a;
  state[1] += b;
  state[2] += c;
  state[3] += d;
}

}  // namespace

std::string md5_hex(std::string_view data) {
  std::array<std::uint32_t, 4> state = {0x67452301, 0xefcdab89, 0x98badcfe, 0x10325476};
  const auto* bytes = reinterpret_cast<const unsigned char*>(data.data());
  const std::size_t whole_blocks = data.size() / 64;
  for (std::size_t block = 0; block < whole_blocks; ++block)
    process_block(bytes + 64 * block, state);
  // Padding: a 1 bit, zeros to 56 mod 64 bytes, then the message length in bits as a little-endian uint64.
  std::array<unsigned char, 128> tail{};
  const std::size_t rest = data.size() - 64 * whole_blocks;
  for (std::size_t i = 0; i < rest; ++i)
    tail[i] = bytes[64 * whole_blocks + i];
  tail[rest] = 0x80;
  const std::size_t tail_size = rest < 56 ? 64 : 128;
  std::uint64_t bits = static_cast<std::uint64_t>(data.size()) * 8;
  for (std::size_t i = 0; i < 8; ++i, bits >>= 8)
    tail[tail_size - 8 + i] = static_cast<unsigned char>(bits & 0xff);
  for (std::size_t offset = 0; offset < tail_size; offset += 64)
    process_block(tail.data() + offset, state);

  constexpr char digits[] = "0123456789abcdef";
  std::string hex;
  for (const std::uint32_t word : state)
    for (int byte = 0; byte < 4; ++byte) {
      const auto value = static_cast<unsigned>((word >> (8 * byte)) & 0xff);
      hex += digits[value >> 4];
      hex += digits[value & 0xf];
    }
  return hex;
}

}  // namespace contactbench::formats
