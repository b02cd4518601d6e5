// NumPy .npy (docs/formats.md "npy"): the magic "\x93NUMPY", a version, a header length, a Python dict
// literal giving dtype, memory order and shape, then the raw array. Read: float32/float64, either byte order,
// C or Fortran order, two dimensions (rows along y, columns along x). Written: little-endian float64, C
// order.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "contactbench/core/atomic_file.hpp"
#include "contactbench/core/formats/binary_view.hpp"
#include "contactbench/core/formats/declared_memory.hpp"
#include "contactbench/core/formats/readers.hpp"

namespace contactbench::formats {

namespace {

constexpr std::string_view npy_magic = "\x93NUMPY";

// The value of 'key' in the header dict, as the raw text up to the next top-level comma or closing brace.
std::string_view dict_value(const BinaryView& view, std::string_view header, std::string_view key) {
  const std::string quoted_key_single = "'" + std::string(key) + "'";
  const std::string quoted_key_double = "\"" + std::string(key) + "\"";
  std::size_t at = header.find(quoted_key_single);
  std::size_t key_length = quoted_key_single.size();
  if (at == std::string_view::npos) {
    at = header.find(quoted_key_double);
    key_length = quoted_key_double.size();
  }
  if (at == std::string_view::npos)
    throw InputError(view.path(), 0, "the .npy header has no '" + std::string(key) + "' entry");
  std::size_t position = header.find(':', at + key_length);
  if (position == std::string_view::npos)
    throw InputError(view.path(), 0, "the .npy header's '" + std::string(key) + "' entry has no value");
  ++position;
  while (position < header.size() && header[position] == ' ')
    ++position;
  std::size_t end = position;
  if (end < header.size() && header[end] == '(') {
    end = header.find(')', end);
    if (end == std::string_view::npos)
      throw InputError(view.path(), 0, "the .npy header's shape tuple is not closed");
    ++end;
  } else {
    while (end < header.size() && header[end] != ',' && header[end] != '}')
      ++end;
  }
  std::string_view value = header.substr(position, end - position);
  while (!value.empty() && value.back() == ' ')
    value.remove_suffix(1);
  return value;
}

std::vector<Index> parse_shape(const BinaryView& view, std::string_view tuple) {
  if (tuple.size() < 2 || tuple.front() != '(' || tuple.back() != ')')
    throw InputError(view.path(), 0, "the .npy shape '" + std::string(tuple) + "' is not a tuple");
  std::vector<Index> shape;
  std::string_view body = tuple.substr(1, tuple.size() - 2);
  while (!body.empty()) {
    while (!body.empty() && (body.front() == ' ' || body.front() == ','))
      body.remove_prefix(1);
    if (body.empty()) break;
    long long extent = 0;
    const auto [end, error] = std::from_chars(body.data(), body.data() + body.size(), extent);
    if (error != std::errc() || extent < 0)
      throw InputError(view.path(), 0, "the .npy shape '" + std::string(tuple) + "' is not a tuple of sizes");
    shape.push_back(static_cast<Index>(extent));
    body.remove_prefix(static_cast<std::size_t>(end - body.data()));
    if (!body.empty() && body.front() != ',' && body.front() != ' ')
      throw InputError(view.path(), 0, "the .npy shape '" + std::string(tuple) + "' is not a tuple of sizes");
  }
  return shape;
}

}  // namespace

bool looks_like_npy(std::string_view bytes) {
  return bytes.starts_with(npy_magic);
}

RawTopography read_npy(const std::filesystem::path& path, std::string_view bytes) {
  const BinaryView view(path, bytes);
  if (!looks_like_npy(bytes)) throw InputError(path, 0, "wrong magic: a .npy file begins with \\x93NUMPY");
  const auto major = view.read<std::uint8_t>(6, ByteOrder::little, ".npy version");
  std::uint64_t header_length = 0;
  std::uint64_t header_start = 0;
  if (major == 1) {
    header_length = view.read<std::uint16_t>(8, ByteOrder::little, ".npy header length");
    header_start = 10;
  } else if (major == 2 || major == 3) {
    header_length = view.read<std::uint32_t>(8, ByteOrder::little, ".npy header length");
    header_start = 12;
  } else {
    throw InputError(path, 0, "unknown .npy version " + std::to_string(major) + " (known: 1, 2, 3)");
  }
  const std::string_view header = view.slice(header_start, header_length, ".npy header");

  std::string_view descr = dict_value(view, header, "descr");
  if (descr.size() >= 2 && (descr.front() == '\'' || descr.front() == '"'))
    descr = descr.substr(1, descr.size() - 2);
  ByteOrder order = ByteOrder::little;
  std::size_t item_size = 0;
  if (descr == "<f8" || descr == "=f8" || descr == ">f8") item_size = 8;
  if (descr == "<f4" || descr == "=f4" || descr == ">f4") item_size = 4;
  if (item_size == 0)
    throw InputError(path, 0,
                     "unsupported .npy data type '" + std::string(descr) +
                         "'; accepted: float64 or float32 in either byte order (<f8, >f8, <f4, >f4)");
  if (descr.front() == '>') order = ByteOrder::big;

  const std::string_view fortran = dict_value(view, header, "fortran_order");
  if (fortran != "True" && fortran != "False")
    throw InputError(path, 0,
                     "the .npy header's fortran_order is '" + std::string(fortran) + "', not True or False");
  const std::vector<Index> shape = parse_shape(view, dict_value(view, header, "shape"));
  if (shape.size() != 2)
    throw InputError(path, 0,
                     "the .npy array has " + std::to_string(shape.size()) +
                         " dimensions; a topography needs exactly 2 (rows along y, columns along x)");
  const Index ny = shape[0];
  const Index nx = shape[1];
  if (nx < 1 || ny < 1) throw InputError(path, 0, "the .npy array is empty");
  constexpr auto limit = static_cast<std::uint64_t>(std::numeric_limits<Index>::max() / 16);
  if (static_cast<std::uint64_t>(nx) > limit / static_cast<std::uint64_t>(ny))
    throw InputError(path, 0, "the .npy shape is too large to be a real array");
  const std::uint64_t count = static_cast<std::uint64_t>(nx) * static_cast<std::uint64_t>(ny);
  const std::string_view data =
      view.slice(header_start + header_length, count * item_size,
                 ".npy data (" + std::to_string(ny) + " x " + std::to_string(nx) + ")");

  Channel channel = make_channel("array", true, "m (assumed)", nx, ny);
  allocate_values(path, channel);
  const bool column_major = fortran == "True";
  for (Index row = 0; row < ny; ++row)
    for (Index column = 0; column < nx; ++column) {
      const Index stored = column_major ? column * ny + row : row * nx + column;
      const char* source = data.data() + static_cast<std::size_t>(stored) * item_size;
      channel.values[static_cast<std::size_t>(row * nx + column)] =
          item_size == 8 ? BinaryView::decode<double>(source, order)
                         : static_cast<Real>(BinaryView::decode<float>(source, order));
    }
  RawTopography topography;
  topography.channels.push_back(std::move(channel));
  return topography;
}

void write_npy(const std::filesystem::path& path, const Surface& surface) {
  const Index nx = surface.nx();
  const Index ny = surface.ny();
  std::string header = "{'descr': '<f8', 'fortran_order': False, 'shape': (" + std::to_string(ny) + ", " +
                       std::to_string(nx) + "), }";
  // Magic (6) + version (2) + length (2) + header + '\n' is padded with blanks to a multiple of 64.
  const std::size_t unpadded = 10 + header.size() + 1;
  header.append((64 - unpadded % 64) % 64, ' ');
  header += '\n';
  std::string prefix(npy_magic);
  prefix += '\x01';
  prefix += '\x00';
  prefix += static_cast<char>(header.size() & 0xff);
  prefix += static_cast<char>((header.size() >> 8) & 0xff);
  write_file_atomically(path, [&](std::ostream& out) {
    out.write(prefix.data(), static_cast<std::streamsize>(prefix.size()));
    out.write(header.data(), static_cast<std::streamsize>(header.size()));
    std::vector<char> row(static_cast<std::size_t>(nx) * 8);
    for (Index y = 0; y < ny; ++y) {
      for (Index x = 0; x < nx; ++x) {
        const double value = surface.heights()(y, x);
        unsigned char little[8];
        std::uint64_t bits = std::bit_cast<std::uint64_t>(value);
        for (int byte = 0; byte < 8; ++byte, bits >>= 8)
          little[byte] = static_cast<unsigned char>(bits & 0xff);
        std::memcpy(row.data() + x * 8, little, 8);
      }
      out.write(row.data(), static_cast<std::streamsize>(row.size()));
    }
  });
}

}  // namespace contactbench::formats
