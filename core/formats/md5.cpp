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

// The sine table as a namespace constant (not a function-local static, whose guard is tested on every block).
const std::array<std::uint32_t, 64> table = sine_table();

// Step i of round `round` (RFC 1321 section 3.4): F, G, H or I of b, c, d, and the message word it uses.
template <int round>
inline void step(std::uint32_t& a, std::uint32_t& b, std::uint32_t& c, std::uint32_t& d, std::uint32_t i,
                 const std::array<std::uint32_t, 16>& words) {
  std::uint32_t f = 0;
  std::uint32_t g = 0;
  if constexpr (round == 0) {
    f = (b & c) | (~b & d);
    g = i;
  } else if constexpr (round == 1) {
    f = (d & b) | (~d & c);
    g = (5 * i + 1) % 16;
  } else if constexpr (round == 2) {
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

// The four rounds as four loops of sixteen steps, each unrolled, so that the round's function and the word
// index are fixed at compile time: one loop of 64 steps with a branch per step hashed at about a third of
// the speed, and the checksum of an x3p's point data was a large part of reading it
// (results/bench/formats_read.md).
void process_block(const unsigned char* block, std::array<std::uint32_t, 4>& state) {
  std::array<std::uint32_t, 16> words{};
  for (std::size_t i = 0; i < 16; ++i)
    words[i] = static_cast<std::uint32_t>(block[4 * i]) |
               (static_cast<std::uint32_t>(block[4 * i + 1]) << 8) |
               (static_cast<std::uint32_t>(block[4 * i + 2]) << 16) |
               (static_cast<std::uint32_t>(block[4 * i + 3]) << 24);
  std::uint32_t a = state[0], b = state[1], c = state[2], d = state[3];
#pragma GCC unroll 16
  for (std::uint32_t i = 0; i < 16; ++i)
    step<0>(a, b, c, d, i, words);
#pragma GCC unroll 16
  for (std::uint32_t i = 16; i < 32; ++i)
    step<1>(a, b, c, d, i, words);
#pragma GCC unroll 16
  for (std::uint32_t i = 32; i < 48; ++i)
    step<2>(a, b, c, d, i, words);
#pragma GCC unroll 16
  for (std::uint32_t i = 48; i < 64; ++i)
    step<3>(a, b, c, d, i, words);
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
