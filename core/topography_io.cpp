// The entry points for topography files: which format a file is in and which reader reads it
// (core/formats/ holds the detection, the readers, the channels and the writers).
#include "contactbench/core/topography_io.hpp"

#include <string>
#include <utility>
#include <vector>

#include "contactbench/core/bounded_read.hpp"
#include "contactbench/core/error.hpp"
#include "contactbench/core/formats/channels.hpp"
#include "contactbench/core/formats/detection.hpp"
#include "contactbench/core/formats/readers.hpp"
#include "contactbench/core/formats/text_lines.hpp"
#include "contactbench/core/formats/text_readers.hpp"

namespace contactbench {

namespace {

namespace fs = std::filesystem;

std::string read_whole_file(const fs::path& path) {
  return read_file_bounded(path, kMaxTopographyFileBytes, "topographies");
}

}  // namespace

std::string_view to_string(TopographyFormat format) {
  switch (format) {
    case TopographyFormat::x3p:
      return "x3p";
    case TopographyFormat::sdf:
      return "sdf";
    case TopographyFormat::npy:
      return "npy";
    case TopographyFormat::metropro:
      return "metropro";
    case TopographyFormat::nanoscope:
      return "nanoscope";
    case TopographyFormat::sensofar:
      return "sensofar";
    case TopographyFormat::digital_surf:
      return "digital_surf";
    case TopographyFormat::wyko:
      return "wyko";
    case TopographyFormat::netcdf:
      return "netcdf";
    case TopographyFormat::gwy:
      return "gwy";
    case TopographyFormat::alicona:
      return "alicona";
    case TopographyFormat::nanosurf:
      return "nanosurf";
    case TopographyFormat::agilent_mi:
      return "agilent_mi";
    case TopographyFormat::project:
      return "project";
    case TopographyFormat::interferometer:
      return "interferometer";
    case TopographyFormat::gwyddion:
      return "gwyddion";
    case TopographyFormat::plain_matrix:
      return "plain_matrix";
    case TopographyFormat::xyz_points:
      return "xyz_points";
    case TopographyFormat::line_scan:
      return "line_scan";
  }
  throw Error("unknown topography format " + std::to_string(static_cast<int>(format)));
}

bool format_carries_sizes(TopographyFormat format) {
  return format != TopographyFormat::npy && format != TopographyFormat::plain_matrix;
}

bool format_carries_unit(TopographyFormat format) {
  return format != TopographyFormat::npy && format != TopographyFormat::plain_matrix &&
         format != TopographyFormat::xyz_points && format != TopographyFormat::line_scan;
}

TopographyFormat detect_topography_format(const std::filesystem::path& path) {
  // The file's beginning decides most formats, so a large file is not read whole here and again by its
  // reader (a scene's checks detect its file's format twice before it is read): the binary formats' magic and
  // header checks look at their first 508 bytes only (and at whether the file has that many), and a text
  // format with a header is named by its first non-blank line. Only a file without either (a plain matrix, a
  // line scan, a point list) is read whole, for its lines.
  constexpr std::uintmax_t head_bytes = 1 << 16;
  const std::string head = read_file_head(path, kMaxTopographyFileBytes, "topographies", head_bytes);
  if (head.size() == head_bytes) {
    if (const formats::BinaryFormat* binary = formats::binary_format_of(path, head)) return binary->format;
    // Two lines in the head: the first is whole.
    const std::vector<formats::Line> lines = formats::non_blank_lines(head);
    if (lines.size() >= 2) {
      const TopographyFormat format = formats::text_format_of(path, std::span(lines).first(1));
      if (format == TopographyFormat::project || format == TopographyFormat::interferometer ||
          format == TopographyFormat::gwyddion)
        return format;
    }
  }
  const std::string content = head.size() < head_bytes ? head : read_whole_file(path);
  if (const formats::BinaryFormat* binary = formats::binary_format_of(path, content)) return binary->format;
  return formats::text_format_of(path, formats::non_blank_lines(content));
}

formats::RawTopography read_topography_channels(const std::filesystem::path& path) {
  const std::string content = read_whole_file(path);
  const formats::BinaryFormat* binary = formats::binary_format_of(path, content);
  if (binary == nullptr)
    throw InputError(path, 0, "a text topography has one channel; read it with read_topography");
  return binary->read(path, content);
}

TopographyReading read_topography_reading(const std::filesystem::path& path,
                                          const TopographyReadOptions& options) {
  const std::string content = read_whole_file(path);
  if (const formats::BinaryFormat* binary = formats::binary_format_of(path, content))
    return formats::reading_from_channels(path, binary->read(path, content), binary->format, options);

  formats::check_is_text(path, content);
  const std::vector<formats::Line> lines = formats::non_blank_lines(content);
  const TopographyFormat format = formats::text_format_of(path, lines);
  if (format == TopographyFormat::line_scan)
    throw InputError(
        path, 0,
        "is a line scan (a profile along one line), not a surface: `contactbench stats` gives its "
        "profile statistics and a scene runs the analytic theories on it, but contact areas, spots and the "
        "elastic coupling need heights over an area (a 2-D file)");
  // Every text format gives its one channel; the channels' code does units, invalid points, region and
  // levelling for all of them alike.
  const formats::RawTopography raw = [&] {
    switch (format) {
      case TopographyFormat::plain_matrix:
        return formats::read_plain_matrix(path, lines);
      case TopographyFormat::xyz_points:
        return formats::read_xyz_points(path, lines);
      case TopographyFormat::interferometer:
        return formats::read_interferometer(path, lines, options);
      case TopographyFormat::gwyddion:
        return formats::read_gwyddion(path, lines, options);
      default:
        return formats::read_project(path, lines, options);
    }
  }();
  return formats::reading_from_channels(path, raw, format, options);
}

Field read_field(const std::filesystem::path& path) {
  const std::string content = read_whole_file(path);
  formats::check_is_text(path, content);
  const std::vector<formats::Line> lines = formats::non_blank_lines(content);
  if (lines.empty() || !lines.front().text.starts_with(formats::project_prefix))
    throw InputError(path, lines.empty() ? 0 : lines.front().number,
                     "is not a field file of contactbench (first line " +
                         std::string(formats::project_magic) +
                         "); fields are written by `contactbench bem --fields` and a scene's `fields` key");
  return formats::read_project_field(path, lines);
}

Surface read_topography(const std::filesystem::path& path, const TopographyReadOptions& options) {
  return read_topography_reading(path, options).surface;
}

std::string writable_topography_extensions() {
  return ".x3p (ISO 25178-72, float64), .npy (NumPy float64), .gwy (Gwyddion, float64), .txt (the project's "
         "text format)";
}

void check_writable_topography(const std::filesystem::path& path) {
  const std::string extension = formats::lower_extension(path);
  if (extension != ".x3p" && extension != ".npy" && extension != ".gwy" && extension != ".txt")
    throw Error(
        path.string() + ": cannot write " +
        (extension.empty() ? std::string("a file without an extension") : "'" + extension + "' files") +
        "; the extension picks the format, and the writable ones are " + writable_topography_extensions());
}

void write_topography(const std::filesystem::path& path, const Surface& surface) {
  check_writable_topography(path);
  const std::string extension = formats::lower_extension(path);
  if (extension == ".x3p") return formats::write_x3p(path, surface);
  if (extension == ".npy") return formats::write_npy(path, surface);
  if (extension == ".gwy") return formats::write_gwy(path, surface);
  write_surface(path, surface);
}

}  // namespace contactbench
