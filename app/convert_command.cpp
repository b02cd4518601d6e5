// contactbench convert IN OUT: any topography the project reads, written as .x3p, .npy or the project's own
// format (chosen by OUT's extension; docs/formats.md). Reading options (channel, fill, level, sizes, unit)
// are those every command shares. Before anything is read, OUT is checked: never the input itself (by any
// name), never an extension the program cannot write.
#include <iostream>
#include <string>

#include "contactbench/app/cli.hpp"
#include "contactbench/app/output.hpp"
#include "contactbench/app/topography_options.hpp"
#include "contactbench/core/topography_io.hpp"

namespace contactbench {

namespace {

struct ConvertOptions {
  TopographyOptions topography;
  std::string output;
};

void run_convert(const ConvertOptions& o) {
  check_output_file(o.output, o.topography.file, "OUT");
  check_writable_topography(o.output);
  const TopographyReading reading = o.topography.read_with_report();
  write_topography(o.output, reading.surface);
  std::cerr << "convert: " << o.topography.file << " (" << to_string(reading.format) << ", channel '"
            << reading.channel << "', " << reading.invalid_points << " invalid points filled by "
            << to_string(reading.fill) << ", crop " << reading.crop << ", rows aligned by "
            << to_string(reading.align_rows) << ", level " << to_string(reading.level) << ") -> " << o.output
            << '\n';
}

}  // namespace

void add_convert_command(CLI::App& parent) {
  auto options = std::make_shared<ConvertOptions>();
  CLI::App* command =
      parent.add_subcommand("convert", "Write a topography file of any format read (see FILE) as " +
                                           writable_topography_extensions() + ", chosen by OUT's extension.");
  options->topography.add_to(*command, "recorded in the project's format; .x3p and .npy carry no flag");
  command
      ->add_option("OUT", options->output,
                   "output file; its extension picks the format: " + writable_topography_extensions())
      ->required();
  command->callback([options] { run_convert(*options); });
}

}  // namespace contactbench
