// Nanosurf .nid (EZD), docs/formats.md "nid": an INI-style text header of [Section] and key=value lines,
// ended by "#!", then the data sets' binary blocks in the order the [DataSet] section lists them (GroupCount
// groups, each "GrG-Count" slots, the slots in use named "GrG-ChC=<section>"). Each data set's section gives
// Points (nx), Lines (ny), Frame ("Scan forward"), Dim0Range and Dim1Range (the sizes, Dim0Unit and
// Dim1Unit), Dim2Name, Dim2Unit and Dim2Range, and SaveBits (32), SaveSign (Signed), SaveOrder (Intel:
// little-endian); height = raw * Dim2Range / 2^32. Lines are kept in the file's order. Facts from
// SurfaceTopography's EZD.py, checked against nid-1.nid.
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "contactbench/core/formats/binary_view.hpp"
#include "contactbench/core/formats/declared_memory.hpp"
#include "contactbench/core/formats/readers.hpp"
#include "contactbench/core/formats/text_tokens.hpp"
#include "contactbench/core/formats/text_values.hpp"

namespace contactbench::formats {

namespace {

namespace fs = std::filesystem;

using Section = std::map<std::string, std::string>;

std::map<std::string, Section> sections_of(std::string_view header) {
  std::map<std::string, Section> sections;
  Section* current = nullptr;
  std::size_t start = 0;
  while (start < header.size()) {
    std::size_t end = header.find('\n', start);
    if (end == std::string_view::npos) end = header.size();
    const std::string_view line = trim(header.substr(start, end - start), is_space);
    start = end + 1;
    if (line.size() > 2 && line.front() == '[' && line.back() == ']') {
      current = &sections[std::string(line.substr(1, line.size() - 2))];
    } else if (const std::size_t equals = line.find('='); current && equals != std::string_view::npos) {
      (*current)[std::string(trim(line.substr(0, equals), is_space))] =
          std::string(trim(line.substr(equals + 1), is_space));
    }
  }
  return sections;
}

const std::string& entry(const fs::path& path, const std::map<std::string, Section>& sections,
                         const std::string& section, const std::string& key) {
  const auto s = sections.find(section);
  if (s == sections.end()) throw InputError(path, 0, "the .nid header has no section [" + section + "]");
  const auto k = s->second.find(key);
  if (k == s->second.end()) throw InputError(path, 0, "the .nid section [" + section + "] has no " + key);
  return k->second;
}

Real number(const fs::path& path, const std::map<std::string, Section>& sections, const std::string& section,
            const std::string& key) {
  const std::string& text = entry(path, sections, section, key);
  const std::optional<Real> value = parse_real(text);
  if (!value || !std::isfinite(*value))
    throw InputError(
        path, 0,
        "the .nid [" + section + "] " + key + " is " + formats::quoted(text) + ", not a finite number");
  return *value;
}

long long count(const fs::path& path, const std::map<std::string, Section>& sections,
                const std::string& section, const std::string& key) {
  const Real value = number(path, sections, section, key);
  if (value < 0 || value > 1e9 || value != std::floor(value))
    throw InputError(path, 0, "the .nid [" + section + "] " + key + " is not a count");
  return static_cast<long long>(value);
}

}  // namespace

bool looks_like_nanosurf(std::string_view bytes) {
  return bytes.starts_with("[DataSet]");
}

RawTopography read_nanosurf(const fs::path& path, std::string_view bytes) {
  const BinaryView view(path, bytes);
  if (!looks_like_nanosurf(bytes))
    throw InputError(path, 0, "wrong magic for a Nanosurf .nid file: expected [DataSet]");
  const std::size_t end = bytes.find("#!");
  if (end == std::string_view::npos)
    throw InputError(path, 0, "truncated or corrupt: the .nid header does not end with '#!'");
  const std::map<std::string, Section> sections = sections_of(bytes.substr(0, end));
  std::uint64_t offset = end + 2;

  RawTopography topography;
  // A real file has a few groups of a few dozen slots; a corrupt count must not loop for minutes.
  constexpr long long max_slots = 4096;
  const long long groups = count(path, sections, "DataSet", "GroupCount");
  if (groups > max_slots)
    throw InputError(path, 0, "corrupt .nid: GroupCount " + std::to_string(groups) + " is absurd");
  for (long long g = 0; g < groups; ++g) {
    const std::string group = "Gr" + std::to_string(g);
    const long long slots = count(path, sections, "DataSet", group + "-Count");
    if (slots > max_slots)
      throw InputError(path, 0, "corrupt .nid: " + group + "-Count " + std::to_string(slots) + " is absurd");
    for (long long c = 0; c < slots; ++c) {
      const auto& dataset = sections.at("DataSet");
      const auto slot = dataset.find(group + "-Ch" + std::to_string(c));
      if (slot == dataset.end()) continue;
      const std::string& name = slot->second;
      const long long nx = count(path, sections, name, "Points"), ny = count(path, sections, name, "Lines");
      const std::uint64_t bytes_needed = grid_bytes(path, nx, ny, 4, "the .nid data set " + name);
      if (entry(path, sections, name, "SaveBits") != "32" ||
          entry(path, sections, name, "SaveSign") != "Signed" ||
          entry(path, sections, name, "SaveOrder") != "Intel")
        throw InputError(path, 0,
                         "the .nid data set " + name +
                             " is not stored as signed 32-bit little-endian integers "
                             "(SaveBits=32, SaveSign=Signed, SaveOrder=Intel), the only layout read");
      const std::string_view data = view.slice(offset, bytes_needed, "the .nid data set " + name);
      offset += bytes_needed;
      const std::string unit = entry(path, sections, name, "Dim2Unit");
      const std::string frame = entry(path, sections, name, "Frame");
      Channel channel = make_channel(entry(path, sections, name, "Dim2Name") + " (" + frame + ")",
                                     unit == "m", unit, nx, ny);
      if (entry(path, sections, name, "Dim0Unit") == "m" && entry(path, sections, name, "Dim1Unit") == "m") {
        channel.lx = number(path, sections, name, "Dim0Range");
        channel.ly = number(path, sections, name, "Dim1Range");
      }
      if (channel.is_height) {
        const Real range = number(path, sections, name, "Dim2Range");
        if (range == 0)
          throw InputError(path, 0, "the .nid [" + name + "] Dim2Range is 0: every height would be 0");
        allocate_values(path, channel);
        for (std::size_t k = 0; k < channel.values.size(); ++k)
          channel.values[k] =
              static_cast<Real>(BinaryView::decode<std::int32_t>(data.data() + 4 * k, ByteOrder::little)) *
              range / 4294967296.0;
      }
      topography.channels.push_back(std::move(channel));
    }
  }
  if (topography.channels.empty()) throw InputError(path, 0, "the .nid file lists no data set");
  return topography;
}

}  // namespace contactbench::formats
