// Gwyddion's native .gwy files, docs/formats.md "gwy": the magic "GWYP", then one serialized GwyContainer.
// A serialized object is its type name (NUL-terminated), the byte size of its components (uint32), then the
// components: a name (NUL-terminated), a type character and a value, all little-endian: b (bool, 1 byte),
// c (char), i (int32), q (int64), d (double), s (NUL-terminated string), o (an object), and the arrays C, I,
// Q, D, S, O (a uint32 count, then the items). Images are GwyDataField objects under the keys "/N/data"
// (xres, yres, xreal, yreal, the units si_unit_xy and si_unit_z as GwySIUnit objects with "unitstr", and
// "data", xres * yres doubles row by row, x fastest, y growing with the row); "/N/data/title" names a channel
// and a data field "/N/mask" marks its invalid points (values > 0.5). Facts from Gwyddion's user guide,
// "Format of Gwyddion Files".
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "contactbench/core/formats/binary_view.hpp"
#include "contactbench/core/formats/declared_memory.hpp"
#include "contactbench/core/formats/readers.hpp"
#include "contactbench/core/formats/text_values.hpp"

namespace contactbench::formats {

namespace {

namespace fs = std::filesystem;

constexpr std::string_view gwy_magic = "GWYP";
// Objects nest a few levels in real files (container, data field, unit); a fuzzed file must not recurse
// without end.
constexpr int max_depth = 16;

struct GwyObject;

// One component's value: numbers, a string, an object, or an array left in the file's bytes.
struct GwyComponent {
  char type = 0;
  std::int64_t integer = 0;
  double real = 0;
  std::string text;
  std::shared_ptr<GwyObject> object;
  std::string_view array;  // the items of a numeric array
  std::uint32_t count = 0;
};

struct GwyObject {
  std::string type;
  std::map<std::string, GwyComponent> components;  // a name given twice keeps the last
};

class GwyParser {
 public:
  explicit GwyParser(const BinaryView& view) : view_(view) {}

  // The object at `offset`; `end` bounds it (its parent's end). Returns the offset after it.
  std::uint64_t object(std::uint64_t offset, std::uint64_t end, int depth, GwyObject& out) const {
    if (depth > max_depth)
      throw InputError(view_.path(), 0,
                       "corrupt .gwy: objects nested deeper than " + std::to_string(max_depth));
    out.type = string(offset, end, "an object's type name");
    offset += out.type.size() + 1;
    const auto size = view_.read<std::uint32_t>(offset, ByteOrder::little, "the size of a " + out.type);
    offset += 4;
    if (size > end - offset)
      throw InputError(view_.path(), 0,
                       "corrupt .gwy: the " + out.type + " at byte " + std::to_string(offset - 4) +
                           " declares " + std::to_string(size) + " bytes, more than its container holds");
    const std::uint64_t object_end = offset + size;
    while (offset < object_end) {
      const std::string name = string(offset, object_end, "a component name of a " + out.type);
      offset += name.size() + 1;
      GwyComponent component;
      component.type = view_.read<char>(offset, ByteOrder::little, "the type of component " + name);
      offset = value(offset + 1, object_end, depth, name, component);
      out.components[name] = std::move(component);
    }
    return object_end;
  }

 private:
  // A NUL-terminated string starting at `offset`, before `end`.
  std::string string(std::uint64_t offset, std::uint64_t end, const std::string& what) const {
    const std::string_view rest = view_.slice(offset, end > offset ? end - offset : 0, what);
    const std::size_t nul = rest.find('\0');
    if (nul == std::string_view::npos)
      throw InputError(view_.path(), 0,
                       "corrupt .gwy: " + what + " at byte " + std::to_string(offset) +
                           " is not NUL-terminated within its object");
    return std::string(rest.substr(0, nul));
  }

  std::uint64_t value(std::uint64_t offset, std::uint64_t end, int depth, const std::string& name,
                      GwyComponent& c) const {
    const auto need = [&](std::uint64_t bytes) {
      if (bytes > end - offset || offset > end)
        throw InputError(view_.path(), 0, "corrupt .gwy: component " + name + " runs past its object's end");
    };
    const auto item_size = [](char type) -> std::uint64_t {
      switch (type) {
        case 'C':
          return 1;
        case 'I':
          return 4;
        case 'Q':
        case 'D':
          return 8;
        default:
          return 0;
      }
    };
    switch (c.type) {
      case 'b':
      case 'c':
        need(1);
        c.integer = view_.read<std::uint8_t>(offset, ByteOrder::little, name);
        return offset + 1;
      case 'i':
        need(4);
        c.integer = view_.read<std::int32_t>(offset, ByteOrder::little, name);
        return offset + 4;
      case 'q':
        need(8);
        c.integer = view_.read<std::int64_t>(offset, ByteOrder::little, name);
        return offset + 8;
      case 'd':
        need(8);
        c.real = view_.read<double>(offset, ByteOrder::little, name);
        return offset + 8;
      case 's':
        c.text = string(offset, end, "string " + name);
        return offset + c.text.size() + 1;
      case 'o':
        c.object = std::make_shared<GwyObject>();
        return object(offset, end, depth + 1, *c.object);
      case 'C':
      case 'I':
      case 'Q':
      case 'D': {
        need(4);
        c.count = view_.read<std::uint32_t>(offset, ByteOrder::little, "the length of array " + name);
        const std::uint64_t bytes = std::uint64_t{c.count} * item_size(c.type);
        need(4 + bytes);
        c.array = view_.slice(offset + 4, bytes, "array " + name);
        return offset + 4 + bytes;
      }
      case 'S':
      case 'O': {
        need(4);
        c.count = view_.read<std::uint32_t>(offset, ByteOrder::little, "the length of array " + name);
        offset += 4;
        for (std::uint32_t k = 0; k < c.count; ++k) {
          if (c.type == 'S') {
            offset += string(offset, end, "string array " + name).size() + 1;
          } else {
            GwyObject skipped;  // arrays of objects (graphs, selections) hold no images
            offset = object(offset, end, depth + 1, skipped);
          }
        }
        return offset;
      }
      default:
        throw InputError(view_.path(), 0,
                         "corrupt .gwy: component " + name + " has the unknown type '" +
                             std::string(1, c.type) + "'; known: b c i q d s o C I Q D S O");
    }
  }

  const BinaryView& view_;
};

const GwyComponent& component(const fs::path& path, const GwyObject& object, const std::string& key,
                              char type, const std::string& where) {
  const auto found = object.components.find(key);
  if (found == object.components.end()) throw InputError(path, 0, where + " has no component '" + key + "'");
  if (found->second.type != type)
    throw InputError(path, 0,
                     where + " component '" + key + "' has type '" + std::string(1, found->second.type) +
                         "', expected '" + std::string(1, type) + "'");
  return found->second;
}

// The unit string of a GwySIUnit component ("m", "V", ...); empty when absent.
std::string unit_of(const GwyObject& field, const std::string& key) {
  const auto found = field.components.find(key);
  if (found == field.components.end() || !found->second.object) return "";
  const auto unit = found->second.object->components.find("unitstr");
  return unit == found->second.object->components.end() ? "" : unit->second.text;
}

struct Field {
  Index nx = 0, ny = 0;
  Real lx = 0, ly = 0;
  std::string xy_unit, z_unit;
  std::string_view data;
};

Field field_of(const fs::path& path, const GwyObject& object, const std::string& key) {
  if (object.type != "GwyDataField")
    throw InputError(path, 0, "'" + key + "' is a " + object.type + ", not a GwyDataField");
  const std::string where = "the GwyDataField '" + key + "'";
  Field f;
  f.nx = component(path, object, "xres", 'i', where).integer;
  f.ny = component(path, object, "yres", 'i', where).integer;
  grid_bytes(path, f.nx, f.ny, 8, where);
  f.lx = component(path, object, "xreal", 'd', where).real;
  f.ly = component(path, object, "yreal", 'd', where).real;
  for (const auto& [name, size] : {std::pair{"xreal", f.lx}, std::pair{"yreal", f.ly}})
    if (!(std::isfinite(size) && size > 0))
      throw InputError(path, 0, where + " " + name + " = " + format_real(size) + " is not a finite size > 0");
  const GwyComponent& data = component(path, object, "data", 'D', where);
  if (data.count != static_cast<std::uint64_t>(f.nx) * static_cast<std::uint64_t>(f.ny))
    throw InputError(path, 0,
                     where + " holds " + std::to_string(data.count) +
                         " values for xres x yres = " + std::to_string(f.nx) + " x " + std::to_string(f.ny));
  f.data = data.array;
  f.xy_unit = unit_of(object, "si_unit_xy");
  f.z_unit = unit_of(object, "si_unit_z");
  return f;
}

}  // namespace

bool looks_like_gwy(std::string_view bytes) {
  return bytes.starts_with(gwy_magic) || bytes.starts_with("GWYO");
}

RawTopography read_gwy(const fs::path& path, std::string_view bytes) {
  const BinaryView view(path, bytes);
  if (bytes.starts_with("GWYO"))
    throw InputError(path, 0,
                     "is a .gwy file of the old format (magic GWYO), not read: resave it with Gwyddion 2");
  if (!bytes.starts_with(gwy_magic))
    throw InputError(path, 0, "wrong magic for a Gwyddion .gwy file: expected 'GWYP'");
  GwyObject container;
  GwyParser(view).object(gwy_magic.size(), bytes.size(), 0, container);
  if (container.type != "GwyContainer")
    throw InputError(path, 0, "the .gwy file holds a " + container.type + ", not a GwyContainer");

  RawTopography topography;
  // Keys "/N/data" in the order of N (std::map orders "/10/data" before "/2/data": sort by the number).
  std::vector<std::pair<long long, std::string>> images;
  for (const auto& [key, value] : container.components) {
    if (!key.starts_with("/") || !key.ends_with("/data") || value.type != 'o') continue;
    const std::string number = key.substr(1, key.size() - 6);
    if (number.empty() || number.size() > 9 || number.find_first_not_of("0123456789") != std::string::npos)
      continue;
    images.emplace_back(std::stoll(number), key);
  }
  std::sort(images.begin(), images.end());
  if (images.empty())
    throw InputError(path, 0, "the .gwy file holds no image (no GwyDataField under /N/data)");
  for (const auto& [number, key] : images) {
    const Field f = field_of(path, *container.components.at(key).object, key);
    const std::string prefix = "/" + std::to_string(number);
    const auto title = container.components.find(prefix + "/data/title");
    const std::string name = title != container.components.end() && title->second.type == 's'
                                 ? title->second.text
                                 : "channel " + std::to_string(number);
    // Gwyddion stores base SI units ("m"); a length with a prefix is scaled, anything else is not a height.
    const std::optional<Real> z_metres = length_unit_in_metres(f.z_unit);
    Channel channel = make_channel(name, z_metres.has_value(), f.z_unit, f.nx, f.ny);
    const std::optional<Real> xy_metres = length_unit_in_metres(f.xy_unit);
    if (xy_metres) {
      channel.lx = f.lx * *xy_metres;
      channel.ly = f.ly * *xy_metres;
    }
    if (z_metres) {
      if (!xy_metres)
        throw InputError(path, 0,
                         "channel '" + name + "': its lateral unit si_unit_xy is '" + f.xy_unit +
                             "', not a length (accepted: " + std::string(accepted_length_units) + ")");
      allocate_values(path, channel);
      for (std::size_t k = 0; k < channel.values.size(); ++k) {
        const double value = BinaryView::decode<double>(f.data.data() + 8 * k, ByteOrder::little);
        // Scaling only a unit other than metres keeps the doubles bit for bit.
        channel.values[k] = *z_metres == 1 ? value : value * *z_metres;
      }
      const auto mask = container.components.find(prefix + "/mask");
      if (mask != container.components.end() && mask->second.type == 'o') {
        const Field m = field_of(path, *mask->second.object, prefix + "/mask");
        if (m.nx != f.nx || m.ny != f.ny)
          throw InputError(path, 0, "the mask of channel '" + name + "' is not the size of its image");
        for (std::size_t k = 0; k < channel.values.size(); ++k)
          if (BinaryView::decode<double>(m.data.data() + 8 * k, ByteOrder::little) > 0.5)
            channel.values[k] = std::numeric_limits<Real>::quiet_NaN();
      }
    }
    topography.channels.push_back(std::move(channel));
  }
  return topography;
}

}  // namespace contactbench::formats
