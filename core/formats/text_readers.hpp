// The text topography formats (docs/formats.md): the project's own, an interferometer's export, Gwyddion's
// text export and a plain matrix. Each reader takes the file's non-blank lines and returns the surface,
// heights in metres; any defect throws InputError naming the file and the line.
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <string_view>

#include "contactbench/core/formats/height_rows.hpp"
#include "contactbench/core/formats/raw_topography.hpp"
#include "contactbench/core/formats/text_lines.hpp"
#include "contactbench/core/surface.hpp"
#include "contactbench/core/topography_io.hpp"

namespace contactbench::formats {

// The project format's first line, written by write_surface; a file starting with the prefix and another
// version is refused by read_project.
inline constexpr std::string_view project_magic = "# contactbench surface v1";
inline constexpr std::string_view project_prefix = "# contactbench surface";

// The project format's first two lines: the shape its header promises, its sizes (checked against the
// caller's), periodicity, quantity (empty: heights) and unit. For a reader of its rows in slabs
// (core/topography_rows.hpp) as for the whole file.
struct ProjectHeader {
  PromisedShape shape;
  Real lx = 0, ly = 0;
  bool periodic = false;
  std::string quantity;
  std::string unit;
};
ProjectHeader read_project_header(const std::filesystem::path& path, std::span<const Line> lines,
                                  const TopographyReadOptions& options);
// Refuses a project file whose field is not in metres (a pressure map, say) as a surface, naming the file.
void require_height_unit(const std::filesystem::path& path, const std::string& quantity,
                         const std::string& unit);

// The project format's heights as its one channel, "height" (its size and periodicity with it).
RawTopography read_project(const std::filesystem::path& path, std::span<const Line> lines,
                           const TopographyReadOptions& options);
// A field file of the project's format (write_field): its values as they are, with quantity and unit; a
// surface file reads as quantity "height", unit "m".
Field read_project_field(const std::filesystem::path& path, std::span<const Line> lines);
// The other text formats return their one channel, "height", heights in metres, for the channels' sizes,
// unit, invalid points (NaN and Inf), region and levelling (channels.hpp). Those with a header carry their
// sizes (checked against the caller's here, naming the header's line).
RawTopography read_interferometer(const std::filesystem::path& path, std::span<const Line> lines,
                                  const TopographyReadOptions& options);
RawTopography read_gwyddion(const std::filesystem::path& path, std::span<const Line> lines,
                            const TopographyReadOptions& options);
RawTopography read_plain_matrix(const std::filesystem::path& path, std::span<const Line> lines);
RawTopography read_xyz_points(const std::filesystem::path& path, std::span<const Line> lines);

// Whether the lines are an x y z point list: three values a line, at least four lines, and x and y each
// taking at least two values whose combinations number the lines (a grid); or a .xyz file.
bool looks_like_point_list(const std::filesystem::path& path, std::span<const Line> lines);

}  // namespace contactbench::formats
