// Writing Gwyddion's native .gwy (the layout is in gwy.cpp): one GwyContainer holding the surface as the
// GwyDataField "/0/data" (xres, yres, xreal, yreal, zero offsets, the units "m" and the heights as doubles,
// row by row) and its title "/0/data/title". read_gwy returns the same doubles and sizes; Gwyddion opens it.
#include <bit>
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>

#include "contactbench/core/atomic_file.hpp"
#include "contactbench/core/error.hpp"
#include "contactbench/core/formats/readers.hpp"

namespace contactbench::formats {

namespace {

template <typename T>
void append_little(std::string& out, T value) {
  auto bits = std::bit_cast<std::conditional_t<sizeof(T) == 8, std::uint64_t, std::uint32_t>>(value);
  for (std::size_t byte = 0; byte < sizeof(T); ++byte, bits >>= 8)
    out += static_cast<char>(bits & 0xff);
}

void append_name(std::string& out, std::string_view name) {
  out.append(name);
  out += '\0';
}

// A serialized object: its type name, the byte size of its components, the components.
std::string object(std::string_view type, const std::string& components) {
  if (components.size() > 0xffffffffu) throw Error(".gwy: an object larger than 4 GiB cannot be written");
  std::string out;
  append_name(out, type);
  append_little(out, static_cast<std::uint32_t>(components.size()));
  return out + components;
}

void component(std::string& out, std::string_view name, char type, const std::string& value) {
  append_name(out, name);
  out += type;
  out += value;
}

std::string int32(std::int32_t value) {
  std::string out;
  append_little(out, value);
  return out;
}

std::string real(double value) {
  std::string out;
  append_little(out, value);
  return out;
}

std::string text(std::string_view value) {
  std::string out;
  append_name(out, value);
  return out;
}

std::string metres() {
  std::string unit;
  component(unit, "unitstr", 's', text("m"));
  return object("GwySIUnit", unit);
}

}  // namespace

void write_gwy(const std::filesystem::path& path, const Surface& surface) {
  const Index nx = surface.nx(), ny = surface.ny();
  if (nx > 0x7fffffff || ny > 0x7fffffff) throw Error(path.string() + ": too many points for a .gwy file");
  std::string heights;
  append_little(heights, static_cast<std::uint32_t>(nx * ny));
  heights.reserve(4 + static_cast<std::size_t>(nx * ny) * 8);
  for (Index y = 0; y < ny; ++y)
    for (Index x = 0; x < nx; ++x) {
      const double h = surface.heights()(y, x);
      // The format allows only finite doubles (Gwyddion's user guide); a Surface holds no other.
      if (!std::isfinite(h))
        throw Error(path.string() + ": a .gwy file cannot hold a height that is not finite");
      append_little(heights, h);
    }
  std::string field;
  component(field, "xres", 'i', int32(static_cast<std::int32_t>(nx)));
  component(field, "yres", 'i', int32(static_cast<std::int32_t>(ny)));
  component(field, "xreal", 'd', real(surface.grid().lx));
  component(field, "yreal", 'd', real(surface.grid().ly));
  component(field, "xoff", 'd', real(0));
  component(field, "yoff", 'd', real(0));
  component(field, "si_unit_xy", 'o', metres());
  component(field, "si_unit_z", 'o', metres());
  component(field, "data", 'D', heights);
  std::string container;
  component(container, "/0/data", 'o', object("GwyDataField", field));
  component(container, "/0/data/title", 's', text("height"));
  const std::string file = "GWYP" + object("GwyContainer", container);
  write_file_atomically(
      path, [&](std::ostream& out) { out.write(file.data(), static_cast<std::streamsize>(file.size())); });
}

}  // namespace contactbench::formats
