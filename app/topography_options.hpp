// The command-line options that name a topography file and what the file may not say (sizes, periodicity,
// the unit), shared by every command that reads a surface.
#pragma once

#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "contactbench/core/surface.hpp"
#include "contactbench/core/topography_io.hpp"

namespace contactbench {

struct TopographyOptions {
  std::string file;
  std::optional<Real> size;    // lateral size along x [m]
  std::optional<Real> size_y;  // lateral size along y [m]
  bool periodic = false;
  std::optional<std::string> channel;  // name or 0-based index (docs/formats.md)
  std::string fill = "none";           // none | harmonic | mean
  std::string level = "none";          // none | mean | plane | quadratic
  std::optional<std::string> unit;     // height unit of a file that states none (m, mm, um, nm, pm)
  std::optional<std::string> crop;     // measured | px:X0,Y0,NX,NY | m:X0,Y0,LX,LY
  std::string align_rows = "none";     // none | mean | median | linear

  // Registers FILE, --size, --size-y, --periodic, --channel, --fill, --level, --unit, --crop and
  // --align-rows on `command`;
  // `periodic_effect` completes the help of --periodic with what periodicity changes for this command.
  void add_to(CLI::App& command, const std::string& periodic_effect);
  // Reads the file with these options (Error naming the file and line on bad content).
  Surface read() const;
  // The same, with the format, channel, filled points and levelling that were applied.
  TopographyReading read_with_report() const;
};

// Every format FILE may be in, for help texts: "x3p (ISO 25178-72), sdf (ISO 25178-71), ...".
std::string readable_formats_help();

}  // namespace contactbench
