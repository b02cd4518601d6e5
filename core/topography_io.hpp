// Reading and writing topography files (instrument exports, plain matrices, the project's own format).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "contactbench/core/formats/crop.hpp"
#include "contactbench/core/formats/raw_topography.hpp"
#include "contactbench/core/formats/row_alignment.hpp"
#include "contactbench/core/formats/surface_repair.hpp"
#include "contactbench/core/surface.hpp"

namespace contactbench {

// The file formats this project reads (docs/formats.md). Detected by content: a binary format by its magic
// bytes (or, for .plu which has none, by its header's consistency); otherwise a text format by its first
// non-blank line. A file whose extension names a binary format but whose content does not match is refused.
enum class TopographyFormat {
  x3p,             // ISO 25178-72 XML surface (zip)
  sdf,             // ISO 25178-71, ASCII or binary
  npy,             // NumPy array; sizes from the caller, like a plain matrix
  metropro,        // Zygo MetroPro .dat
  nanoscope,       // Bruker / Digital Instruments Nanoscope .di
  sensofar,        // Sensofar .plu
  digital_surf,    // Digital Surf .sur
  wyko,            // Wyko .opd
  netcdf,          // NetCDF .nc as ContactMechanics and Tamaas write it
  gwy,             // Gwyddion's native .gwy (GwyContainer of GwyDataFields); read and written
  alicona,         // Alicona Imaging .al3d
  nanosurf,        // Nanosurf .nid
  agilent_mi,      // Agilent / Keysight PicoView .mi
  project,         // "# contactbench surface v1" header, written by write_surface, lossless
  interferometer,  // "h=NY w=NX", "pixel size=... UNIT", "data unit=...", "height conversion factor (->
                   // m)=..."
  gwyddion,  // Gwyddion text export: "# Channel:", "# Width: L UNIT", "# Height: L UNIT", "# Value units:"
  plain_matrix,  // whitespace-separated heights in metres, rows along y; sizes from the caller
  xyz_points,    // lines of x y z on a regular grid, no unit; lateral sizes from the coordinates
  line_scan,  // a 1-D profile (x h text, Dektak CSV): not a surface; `stats` reads it (formats/line_scan.hpp)
};

std::string_view to_string(TopographyFormat format);
// Whether files of this format carry their lateral sizes (npy and plain matrices do not: --size is needed).
bool format_carries_sizes(TopographyFormat format);
// Whether files of this format state the unit of their heights (npy, plain matrices and point lists do not:
// their numbers are metres unless the caller names a unit, and implausible Sq is refused without one).
bool format_carries_unit(TopographyFormat format);

struct TopographyReadOptions {
  // Lateral sizes [m]. Required for a plain matrix (ly defaults to lx * ny / nx: square pixels).
  // For a file that carries its own sizes they must agree with it (1e-6 relative), else Error.
  std::optional<Real> lx;
  std::optional<Real> ly;
  // Periodicity. Default: false for instrument exports and plain matrices (measured data do not repeat),
  // the stored flag for the project's format.
  std::optional<bool> periodic;
  // Which channel of a multi-channel file: its name or its 0-based index written as digits. Default: the
  // first height channel. An unknown channel is an error listing the file's channels.
  std::optional<std::string> channel;
  // Invalid points (masks, marker values, NaN): refused by default with their count; or filled.
  FillMethod fill = FillMethod::none;
  // Levelling after reading. Default none: the heights exactly as the file stores them.
  Levelling level = Levelling::none;
  // The length unit of a file that states none (m, mm, um, nm, pm): heights (and a point list's
  // coordinates) are multiplied by it. Absent: metres, and Sq above 1 mm or below 1 pm is refused. A file
  // that states its own unit is refused with one given.
  std::optional<std::string> unit;
  // The region read (docs/formats.md "regions and levelling"), before invalid points are counted or filled.
  std::optional<CropSpec> crop;
  // Per scan line (row), after filling and before `level`.
  RowAlignment align_rows = RowAlignment::none;
  // Threads that parse the rows of a text file whose header states its size (the values do not depend on it).
  int threads = 1;
};

// A surface with what was done to get it, for reports.
struct TopographyReading {
  Surface surface;
  TopographyFormat format;
  std::string channel;                // the name of the channel read
  std::vector<std::string> channels;  // every channel of the file, in order
  Index invalid_points = 0;           // how many were filled
  FillMethod fill = FillMethod::none;
  Levelling level = Levelling::none;
  std::string unit = "m";     // the unit the file's heights were read in (given or stated), for reports
  std::string crop = "none";  // the region read: "none", or the crop and the rectangle it selected
  RowAlignment align_rows = RowAlignment::none;
};

TopographyReading read_topography_reading(const std::filesystem::path& path,
                                          const TopographyReadOptions& options = {});

// Every channel of a binary format as its reader returns it (NaN at invalid points), for inspection and
// tests; text formats are refused (they hold one channel: use read_topography).
formats::RawTopography read_topography_channels(const std::filesystem::path& path);

// Detects the format and reads the file. Heights come back in metres, exactly as stored unless options.fill
// or options.level say otherwise.
// Any defect throws InputError naming the file and the line: an empty file, a ragged row, a non-numeric
// token, NaN or Inf, a missing or non-positive size, an unknown unit, a header that disagrees with the data.
Surface read_topography(const std::filesystem::path& path, const TopographyReadOptions& options = {});

TopographyFormat detect_topography_format(const std::filesystem::path& path);

// Writes the project's format: a header with nx, ny, lx, ly, periodic, then heights in metres printed as the
// shortest decimal that reads back to the same double, so read_topography returns the surface bit for bit.
// Written to a temporary file and renamed.
void write_surface(const std::filesystem::path& path, const Surface& surface);

// A map of one quantity on a surface's grid (a solution's pressure, gap, contact set), as a field file holds
// it: the values in `unit` (no scaling), on `values.grid()`.
struct Field {
  Surface values;
  std::string quantity;  // "pressure", "gap", "contact", ...; "height" for a surface file
  std::string unit;      // "Pa", "m", "1"
};

// Writes a field in the project's format: the header adds quantity=<quantity> and says its unit (a pressure
// field unit=Pa, not metres); values printed as write_surface prints heights (lossless). read_topography
// reads a field in metres (the gap) as heights and refuses any other with the command that draws it.
void write_field(const std::filesystem::path& path, const Field& field);

// Reads a field file (or a project surface file, as quantity "height" in m). InputError naming the file and
// line for anything else.
Field read_field(const std::filesystem::path& path);

// The extensions write_topography writes, with what each holds: ".x3p (ISO 25178-72, float64), ...".
std::string writable_topography_extensions();

// Throws Error naming the path and the writable extensions when write_topography cannot write its extension:
// a name that promises another format (out.sur) must not receive text that no reader of that format opens.
void check_writable_topography(const std::filesystem::path& path);

// Writes by the path's extension: .x3p (ISO 25178-72, float64), .npy (float64), .gwy (Gwyddion) or .txt
// (the project's format); any other extension is refused (check_writable_topography). Each reads back bit for
// bit (the sizes of .x3p go through the increment lx / nx and back).
void write_topography(const std::filesystem::path& path, const Surface& surface);

}  // namespace contactbench
