// contactbench sweep: bearing area and contact-spot count of {h > z} at many levels (docs/theory.md section
// 3).
#include <charconv>
#include <iostream>
#include <string>

#include "contactbench/app/cli.hpp"
#include "contactbench/app/json_writer.hpp"
#include "contactbench/app/output.hpp"
#include "contactbench/app/topography_options.hpp"
#include "contactbench/core/error.hpp"
#include "contactbench/core/sweep.hpp"

namespace contactbench {

namespace {

struct SweepOptions {
  TopographyOptions topography;
  std::string levels = "exact";
  int connectivity = 4;
  std::string out;
  int threads = 1;
};

SweepLevels parse_levels(const std::string& text) {
  if (text == "exact") return SweepLevels::exact();
  if (text == "paper") return SweepLevels::paper();
  Index count = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), count);
  if (error != std::errc() || end != text.data() + text.size() || count < 1)
    throw Error("--levels: expected 'exact', 'paper' or a whole number of levels >= 1, got '" + text + "'");
  return SweepLevels::uniform(count);
}

void write_csv(std::ostream& out, const SweepCurve& curve, const std::string& file) {
  out << "# contactbench sweep of " << file << ": " << describe(curve.topology)
      << "; row j: the set {h > z}\n";
  out << "z,area_fraction,spots\n";
  for (std::size_t j = 0; j < curve.z.size(); ++j)
    out << json_number(curve.z[j]) << ',' << json_number(curve.area_fraction[j]) << ',' << curve.spots[j]
        << '\n';
}

void run_sweep(const SweepOptions& o) {
  const SweepLevels levels = parse_levels(o.levels);
  if (!o.out.empty()) check_output_file(o.out, o.topography.file, "--out");
  const Surface surface = o.topography.read().centred();
  const Topology topology = Topology::for_surface(
      o.connectivity == 8 ? Connectivity::eight : Connectivity::four, surface.grid().periodic);
  const SweepCurve curve = sweep(surface, levels, topology, o.threads);
  write_output(o.out, [&](std::ostream& out) { write_csv(out, curve, o.topography.file); });
}

}  // namespace

void add_sweep_command(CLI::App& parent) {
  auto options = std::make_shared<SweepOptions>();
  CLI::App* command = parent.add_subcommand(
      "sweep",
      "Cut a surface with planes: bearing area fraction A_c(z)/A0 and number of contact spots N(z) of "
      "{h > z}, heights measured from the mean plane, written as CSV (z, area_fraction, spots).");
  options->topography.add_to(*command, "spots wrap around in x and y");
  command->add_option("--levels", options->levels,
                      "'exact' (every distinct height, the default), K (K+1 equally spaced levels from the "
                      "highest to the lowest height) or 'paper' (500 steps of 0.002 h_max down to the mean "
                      "plane)");
  command->add_option("--connectivity", options->connectivity, "4 or 8")->check(CLI::IsMember({4, 8}));
  command->add_option("--out", options->out, "CSV file (default: standard output)")
      ->check(refuse_empty_output_name);
  add_threads_option(*command, options->threads);
  command->callback([options] { run_sweep(*options); });
}

}  // namespace contactbench
