// contactbench convert IN OUT: any topography the project reads, written as .x3p, .npy or the project's own
// format (chosen by OUT's extension; docs/formats.md). Reading options (channel, fill, level, sizes) are
// those every command shares.
#include <iostream>
#include <string>

#include "contactbench/app/cli.hpp"
#include "contactbench/app/topography_options.hpp"
#include "contactbench/core/topography_io.hpp"

namespace contactbench {

namespace {

struct ConvertOptions {
  TopographyOptions topography;
  std::string output;
};

void run_convert(const ConvertOptions& o) {
  const TopographyReading reading = o.topography.read_with_report();
  write_topography(o.output, reading.surface);
  std::cerr << "convert: " << o.topography.file << " (" << to_string(reading.format) << ", channel '"
            << reading.channel << "', " << reading.invalid_points << " invalid points filled by "
            << to_string(reading.fill) << ", level " << to_string(reading.level) << ") -> " << o.output
            << '\n';
}

}  // namespace

void add_convert_command(CLI::App& parent) {
  auto options = std::make_shared<ConvertOptions>();
  CLI::App* command = parent.add_subcommand(
      "convert",
      "Write a topography as .x3p (ISO 25178-72, float64), .npy (float64) or, for any other "
      "extension, the project's text format.");
  options->topography.add_to(*command, "recorded in the project's format; .x3p and .npy carry no flag");
  command->add_option("OUT", options->output, "output file; its extension picks the format")->required();
  command->callback([options] { run_convert(*options); });
}

}  // namespace contactbench
