// ISO 25178-72 / ISO 5436-2 XML surface data (.x3p), docs/formats.md "x3p": a zip archive holding main.xml
// (axes, data type, z increment and offset, matrix size, the name and MD5 of the binary point data,
// optionally a valid-points bit mask) and the little-endian binary data with x fastest.
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

#include <zip.h>
#include <pugixml.hpp>

#include "contactbench/core/formats/binary_view.hpp"
#include "contactbench/core/formats/declared_memory.hpp"
#include "contactbench/core/formats/md5.hpp"
#include "contactbench/core/formats/readers.hpp"
#include "contactbench/core/formats/text_values.hpp"

namespace contactbench::formats {

namespace {

namespace fs = std::filesystem;

constexpr std::string_view zip_magic = "PK\x03\x04";
// main.xml of a real instrument is a few kilobytes; a larger one is not an x3p (and must not exhaust memory).
constexpr zip_uint64_t max_main_xml_size = 16u << 20;

struct ZipCloser {
  void operator()(zip_t* archive) const { zip_discard(archive); }
};
struct ZipFileCloser {
  void operator()(zip_file_t* file) const { zip_fclose(file); }
};

// The whole content of one archive member, refusing a member that is larger than `limit` bytes or that
// yields fewer bytes than its directory entry promises.
std::string read_member(const fs::path& path, zip_t* archive, std::string_view name, zip_uint64_t limit) {
  const zip_int64_t index = zip_name_locate(archive, std::string(name).c_str(), 0);
  if (index < 0) throw InputError(path, 0, "the x3p archive has no member '" + std::string(name) + "'");
  zip_stat_t stat;
  zip_stat_init(&stat);
  if (zip_stat_index(archive, static_cast<zip_uint64_t>(index), 0, &stat) != 0 ||
      !(stat.valid & ZIP_STAT_SIZE))
    throw InputError(path, 0, "cannot read the size of x3p member '" + std::string(name) + "'");
  if (stat.size > limit)
    throw InputError(path, 0,
                     "x3p member '" + std::string(name) + "' is " + std::to_string(stat.size) +
                         " bytes, more than the " + std::to_string(limit) + " bytes it can hold");
  // Deflate cannot shrink data by more than about 1032:1; a member claiming more is corrupt (or a zip bomb),
  // and must be refused before its claimed size is allocated.
  if ((stat.valid & ZIP_STAT_COMP_SIZE) && stat.size > 1100 * stat.comp_size + (1u << 20))
    throw InputError(path, 0,
                     "x3p member '" + std::string(name) + "' claims " + std::to_string(stat.size) +
                         " bytes from " + std::to_string(stat.comp_size) + " compressed: corrupt archive");
  std::unique_ptr<zip_file_t, ZipFileCloser> file(
      zip_fopen_index(archive, static_cast<zip_uint64_t>(index), 0));
  if (!file)
    throw InputError(path, 0, "cannot open x3p member '" + std::string(name) + "': " + zip_strerror(archive));
  std::string content(static_cast<std::size_t>(stat.size), '\0');
  zip_uint64_t done = 0;
  while (done < stat.size) {
    const zip_int64_t got = zip_fread(file.get(), content.data() + done, stat.size - done);
    if (got <= 0)
      throw InputError(path, 0,
                       "x3p member '" + std::string(name) + "' is corrupt: it yields " +
                           std::to_string(done) + " of its " + std::to_string(stat.size) + " bytes (" +
                           zip_file_strerror(file.get()) + ")");
    done += static_cast<zip_uint64_t>(got);
  }
  return content;
}

std::optional<zip_uint64_t> member_size(zip_t* archive, std::string_view name) {
  const zip_int64_t index = zip_name_locate(archive, std::string(name).c_str(), 0);
  if (index < 0) return std::nullopt;
  zip_stat_t stat;
  zip_stat_init(&stat);
  if (zip_stat_index(archive, static_cast<zip_uint64_t>(index), 0, &stat) != 0) return std::nullopt;
  return stat.size;
}

std::string lower(std::string text) {
  for (char& c : text)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return text;
}

std::string trimmed(std::string_view text) {
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front())))
    text.remove_prefix(1);
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back())))
    text.remove_suffix(1);
  return std::string(text);
}

// A child element's text; throws naming the element path when it is missing.
std::string required_text(const fs::path& path, const pugi::xml_node& parent, const char* child,
                          const std::string& where) {
  const pugi::xml_node node = parent.child(child);
  if (!node) throw InputError(path, 0, "main.xml has no <" + where + "/" + child + ">");
  return trimmed(node.child_value());
}

Real parse_number(const fs::path& path, const std::string& text, const std::string& where) {
  Real value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
    throw InputError(path, 0, "main.xml <" + where + "> is '" + text + "', not a finite number");
  return value;
}

Index parse_size(const fs::path& path, const std::string& text, const std::string& where) {
  long long value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || value < 1 || value > (1ll << 31))
    throw InputError(path, 0, "main.xml <" + where + "> is '" + text + "', not a size from 1 to 2^31");
  return static_cast<Index>(value);
}

}  // namespace

bool looks_like_zip(std::string_view bytes) {
  return bytes.starts_with(zip_magic);
}

RawTopography read_x3p(const fs::path& path, std::string_view bytes) {
  if (!looks_like_zip(bytes))
    throw InputError(path, 0, "wrong magic: an .x3p file is a zip archive and begins with 'PK\\x03\\x04'");
  zip_error_t error;
  zip_error_init(&error);
  zip_source_t* source = zip_source_buffer_create(bytes.data(), bytes.size(), 0, &error);
  if (source == nullptr)
    throw InputError(path, 0, std::string("cannot read the zip archive: ") + zip_error_strerror(&error));
  std::unique_ptr<zip_t, ZipCloser> archive(zip_open_from_source(source, ZIP_RDONLY | ZIP_CHECKCONS, &error));
  if (!archive) {
    zip_source_free(source);
    const std::string reason = zip_error_strerror(&error);
    zip_error_fini(&error);
    throw InputError(path, 0, "not a readable zip archive (" + reason + ")");
  }

  if (zip_name_locate(archive.get(), "main.xml", 0) < 0)
    throw InputError(path, 0, "the zip archive has no main.xml, so it is not an x3p file");
  const std::string main_xml = read_member(path, archive.get(), "main.xml", max_main_xml_size);

  // Record4 names a file with the MD5 of main.xml; when it is there, it must match.
  pugi::xml_document document;
  const pugi::xml_parse_result parsed = document.load_buffer(main_xml.data(), main_xml.size());
  if (!parsed)
    throw InputError(path, 0,
                     std::string("main.xml is not well-formed XML: ") + parsed.description() + " at byte " +
                         std::to_string(parsed.offset));
  const pugi::xml_node root = document.document_element();
  const pugi::xml_node record1 = root.child("Record1");
  const pugi::xml_node record3 = root.child("Record3");
  if (!record1) throw InputError(path, 0, "main.xml has no <Record1> (axes)");
  if (!record3) throw InputError(path, 0, "main.xml has no <Record3> (matrix and data link)");

  if (const pugi::xml_node checksum_file = root.child("Record4").child("ChecksumFile")) {
    const std::string name = trimmed(checksum_file.child_value());
    if (member_size(archive.get(), name)) {
      const std::string listed = read_member(path, archive.get(), name, 4096);
      const std::string expected = lower(trimmed(listed.substr(0, std::min<std::size_t>(32, listed.size()))));
      const std::string actual = md5_hex(main_xml);
      if (expected != actual)
        throw InputError(path, 0,
                         "checksum failure: " + name + " gives MD5 " + expected +
                             " for main.xml, but main.xml has " + actual +
                             " (the archive is corrupt or was edited)");
    }
  }

  const std::string feature = required_text(path, record1, "FeatureType", "Record1");
  if (feature != "SUR")
    throw InputError(path, 0,
                     "x3p feature type '" + feature + "' is not SUR (an areal surface); only SUR is read");
  const pugi::xml_node axes = record1.child("Axes");
  const pugi::xml_node cx = axes.child("CX");
  const pugi::xml_node cy = axes.child("CY");
  const pugi::xml_node cz = axes.child("CZ");
  if (!cx || !cy || !cz) throw InputError(path, 0, "main.xml <Record1/Axes> needs CX, CY and CZ");
  for (const auto& [axis, name] : {std::pair{cx, "CX"}, std::pair{cy, "CY"}})
    if (required_text(path, axis, "AxisType", std::string("Record1/Axes/") + name) != "I")
      throw InputError(path, 0,
                       std::string("x3p axis ") + name +
                           " is not incremental (AxisType I); lists of x, y coordinates are not read");
  const Real dx = parse_number(path, required_text(path, cx, "Increment", "Record1/Axes/CX"), "CX/Increment");
  const Real dy = parse_number(path, required_text(path, cy, "Increment", "Record1/Axes/CY"), "CY/Increment");
  if (!(dx > 0) || !(dy > 0)) throw InputError(path, 0, "x3p lateral increments must be > 0");

  const std::string type = required_text(path, cz, "DataType", "Record1/Axes/CZ");
  std::size_t item_size = 0;
  if (type == "I") item_size = 2;
  if (type == "L" || type == "F") item_size = 4;
  if (type == "D") item_size = 8;
  if (item_size == 0)
    throw InputError(path, 0,
                     "unknown x3p data type '" + type +
                         "' for CZ; the standard allows I (int16), L (int32), F (float32), D (float64)");
  Real z_increment = 1;
  Real z_offset = 0;
  if (cz.child("Increment"))
    z_increment = parse_number(path, required_text(path, cz, "Increment", "Record1/Axes/CZ"),
                               "Record1/Axes/CZ/Increment");
  if (cz.child("Offset"))
    z_offset =
        parse_number(path, required_text(path, cz, "Offset", "Record1/Axes/CZ"), "Record1/Axes/CZ/Offset");
  // A zero increment would turn any data into a flat surface without a word.
  if (z_increment == 0)
    throw InputError(
        path, 0,
        "main.xml <Record1/Axes/CZ/Increment> is 0: every height would be 0; the z increment must "
        "be a finite number other than 0 (absent means 1)");

  const pugi::xml_node matrix = record3.child("MatrixDimension");
  const Index nx = parse_size(path, required_text(path, matrix, "SizeX", "Record3/MatrixDimension"), "SizeX");
  const Index ny = parse_size(path, required_text(path, matrix, "SizeY", "Record3/MatrixDimension"), "SizeY");
  const Index nz = parse_size(path, required_text(path, matrix, "SizeZ", "Record3/MatrixDimension"), "SizeZ");
  if (nz != 1)
    throw InputError(path, 0, "x3p SizeZ is " + std::to_string(nz) + "; only 1 (one layer) is read");
  const std::uint64_t count = static_cast<std::uint64_t>(nx) * static_cast<std::uint64_t>(ny);
  if (count > (std::uint64_t{1} << 32))
    throw InputError(path, 0,
                     "x3p matrix " + std::to_string(nx) + " x " + std::to_string(ny) + " is too large");

  // Before anything is inflated: the deflated data may expand about 1000-fold.
  check_declared_memory(path, nx, ny, item_size, "x3p data of type " + type);

  const pugi::xml_node link = record3.child("DataLink");
  if (!link)
    throw InputError(path, 0, "main.xml has no <Record3/DataLink>: point data inside the XML is not read");
  const std::string data_name = required_text(path, link, "PointDataLink", "Record3/DataLink");
  const std::optional<zip_uint64_t> data_size = member_size(archive.get(), data_name);
  if (!data_size)
    throw InputError(path, 0, "main.xml points to '" + data_name + "', which the archive lacks");
  if (*data_size < count * item_size)
    throw InputError(path, 0,
                     "x3p data '" + data_name + "' holds " + std::to_string(*data_size) + " bytes but " +
                         std::to_string(nx) + " x " + std::to_string(ny) + " points of type " + type +
                         " need " + std::to_string(count * item_size));
  const std::string data = read_member(path, archive.get(), data_name, count * item_size + 1024);
  if (const pugi::xml_node sum = link.child("MD5ChecksumPointData")) {
    const std::string expected = lower(trimmed(sum.child_value()));
    const std::string actual = md5_hex(data);
    if (expected != actual)
      throw InputError(path, 0,
                       "checksum failure: main.xml gives MD5 " + expected + " for '" + data_name +
                           "' but the data has " + actual);
  }

  // The valid-points mask: one bit per point in the data's order, least significant bit first, 1 = valid.
  std::string valid_bits;
  if (const pugi::xml_node valid = link.child("ValidPointsLink")) {
    const std::string valid_name = trimmed(valid.child_value());
    valid_bits = read_member(path, archive.get(), valid_name, (count + 7) / 8 + 1024);
    if (valid_bits.size() < (count + 7) / 8)
      throw InputError(path, 0,
                       "x3p valid-points mask '" + valid_name + "' has " + std::to_string(valid_bits.size()) +
                           " bytes, fewer than the " + std::to_string((count + 7) / 8) + " its points need");
    if (const pugi::xml_node sum = link.child("MD5ChecksumValidPoints")) {
      const std::string expected = lower(trimmed(sum.child_value()));
      if (expected != md5_hex(valid_bits))
        throw InputError(path, 0,
                         "checksum failure: the MD5 of the valid-points mask '" + valid_name + "' differs");
    }
  }

  Channel channel = make_channel("height", true, "m", nx, ny);
  channel.lx = dx * static_cast<Real>(nx);
  channel.ly = dy * static_cast<Real>(ny);
  allocate_values(path, channel);
  for (std::uint64_t k = 0; k < count; ++k) {
    const char* source = data.data() + k * item_size;
    Real raw = 0;
    if (type == "I") raw = BinaryView::decode<std::int16_t>(source, ByteOrder::little);
    if (type == "L") raw = BinaryView::decode<std::int32_t>(source, ByteOrder::little);
    if (type == "F") raw = BinaryView::decode<float>(source, ByteOrder::little);
    if (type == "D") raw = BinaryView::decode<double>(source, ByteOrder::little);
    // Scaling only what the file asks for keeps float64 data bit for bit.
    Real height = raw;
    if (z_increment != 1) height *= z_increment;
    if (z_offset != 0) height += z_offset;
    const bool masked =
        !valid_bits.empty() && ((static_cast<unsigned char>(valid_bits[k / 8]) >> (k % 8)) & 1u) == 0;
    channel.values[k] = masked || !std::isfinite(height) ? std::numeric_limits<Real>::quiet_NaN() : height;
  }
  RawTopography topography;
  topography.channels.push_back(std::move(channel));
  return topography;
}

void write_x3p(const fs::path& path, const Surface& surface) {
  const Index nx = surface.nx();
  const Index ny = surface.ny();
  std::string data(static_cast<std::size_t>(nx * ny) * 8, '\0');
  for (Index y = 0; y < ny; ++y)
    for (Index x = 0; x < nx; ++x) {
      std::uint64_t bits = std::bit_cast<std::uint64_t>(surface.heights()(y, x));
      for (std::size_t byte = 0; byte < 8; ++byte, bits >>= 8)
        data[static_cast<std::size_t>(y * nx + x) * 8 + byte] = static_cast<char>(bits & 0xff);
    }
  const std::string data_name = "bindata/data.bin";
  const std::string main_xml =
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<p:ISO5436_2 xmlns:p=\"http://www.opengps.eu/2008/ISO5436_2\">\n"
      "  <Record1>\n    <Revision>ISO5436 - 2000</Revision>\n    <FeatureType>SUR</FeatureType>\n    <Axes>\n"
      "      <CX><AxisType>I</AxisType><DataType>D</DataType><Increment>" +
      format_real(surface.grid().dx()) +
      "</Increment><Offset>0</Offset></CX>\n"
      "      <CY><AxisType>I</AxisType><DataType>D</DataType><Increment>" +
      format_real(surface.grid().dy()) +
      "</Increment><Offset>0</Offset></CY>\n"
      "      <CZ><AxisType>A</AxisType><DataType>D</DataType></CZ>\n    </Axes>\n  </Record1>\n"
      "  <Record2>\n    <Date>1970-01-01T00:00:00</Date>\n    "
      "<Instrument><Manufacturer>contactbench</Manufacturer>"
      "<Model>contactbench</Model><Serial>not available</Serial><Version>1</Version></Instrument>\n"
      "    <CalibrationDate>1970-01-01T00:00:00</CalibrationDate>\n"
      "    "
      "<ProbingSystem><Type>Software</Type><Identification>contactbench</Identification></ProbingSystem>\n"
      "    <Comment>heights in metres</Comment>\n  </Record2>\n"
      "  <Record3>\n    <MatrixDimension><SizeX>" +
      std::to_string(nx) + "</SizeX><SizeY>" + std::to_string(ny) +
      "</SizeY><SizeZ>1</SizeZ></MatrixDimension>\n    <DataLink><PointDataLink>" + data_name +
      "</PointDataLink><MD5ChecksumPointData>" + md5_hex(data) +
      "</MD5ChecksumPointData></DataLink>\n  </Record3>\n"
      "  <Record4><ChecksumFile>md5checksum.hex</ChecksumFile></Record4>\n</p:ISO5436_2>\n";
  const std::string checksum = md5_hex(main_xml) + " *main.xml\n";

  // libzip writes the archive itself; a temporary beside the target and a rename keep the target whole.
  fs::path temporary = path;
  temporary += ".partial";
  int code = 0;
  std::unique_ptr<zip_t, ZipCloser> archive(zip_open(temporary.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &code));
  if (!archive) throw Error(path.string() + ": cannot create the x3p archive");
  const auto add = [&](const std::string& name, const std::string& content) {
    zip_source_t* source = zip_source_buffer(archive.get(), content.data(), content.size(), 0);
    if (source == nullptr || zip_file_add(archive.get(), name.c_str(), source, ZIP_FL_OVERWRITE) < 0) {
      if (source != nullptr) zip_source_free(source);
      throw Error(path.string() + ": cannot add " + name +
                  " to the x3p archive: " + zip_strerror(archive.get()));
    }
  };
  add("main.xml", main_xml);
  add(data_name, data);
  add("md5checksum.hex", checksum);
  if (zip_close(archive.get()) != 0) {
    const std::string reason = zip_strerror(archive.get());
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw Error(path.string() + ": writing the x3p archive failed: " + reason);
  }
  archive.release();  // zip_close freed it
  std::error_code renamed;
  fs::rename(temporary, path, renamed);
  if (renamed) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw Error(path.string() + ": cannot move the written archive into place: " + renamed.message());
  }
}

}  // namespace contactbench::formats
