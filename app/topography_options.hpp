// The command-line options that name a topography file and what the file may not say (sizes, periodicity),
// shared by every command that reads a surface.
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
  std::string level = "none";          // none | mean | plane

  // Registers FILE, --size, --size-y, --periodic, --channel, --fill and --level on `command`;
  // `periodic_effect` completes the help of --periodic with what periodicity changes for this command.
  void add_to(CLI::App& command, const std::string& periodic_effect);
  // Reads the file with these options (Error naming the file and line on bad content).
  Surface read() const;
  // The same, with the format, channel, filled points and levelling that were applied.
  TopographyReading read_with_report() const;
};

}  // namespace contactbench
