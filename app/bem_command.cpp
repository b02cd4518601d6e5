// contactbench bem: the boundary-element ground truth (Polonsky-Keer) at a list of loads, as a load-area CSV.
#include <algorithm>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "app/cli.hpp"
#include "app/json_writer.hpp"
#include "app/output.hpp"
#include "app/topography_options.hpp"
#include "bem/contact_statistics.hpp"
#include "bem/polonsky_keer.hpp"
#include "core/error.hpp"

namespace contactbench {

namespace {

struct BemOptions {
  TopographyOptions topography;
  bool non_periodic = false;
  std::vector<Real> loads;
  Real modulus =
      100e9 / (1 - 0.3 * 0.3);  // the paper's material: E = 100 GPa, nu = 0.3 (THEORY.md section 2)
  Real tolerance = 1e-8;
  Index max_iterations = 20000;
  int connectivity = 4;
  std::string out;
  int threads = 1;
};

struct Row {
  Real load;
  ContactStatistics statistics;
  ContactSolution solution;
};

void write_csv(std::ostream& out, const std::vector<Row>& rows, const BemOptions& o, const Surface& surface) {
  out << "# contactbench bem of " << o.topography.file << ": "
      << (surface.grid().periodic ? "periodic" : "non-periodic")
      << " half-space, E* = " << json_number(o.modulus) << " Pa, tolerance " << json_number(o.tolerance)
      << " on the relative pressure change, spots by " << o.connectivity
      << "-connectivity; load = P/(E* A0)\n";
  out << "load,area_fraction,area_fraction_corrected,spots,mean_gap,max_pressure,separation,iterations,"
         "residual,"
         "converged,seconds\n";
  for (const Row& r : rows)
    out << json_number(r.load) << ',' << json_number(r.statistics.area_fraction) << ','
        << json_number(r.statistics.area_fraction_corrected) << ',' << r.statistics.spots << ','
        << json_number(r.statistics.mean_gap) << ',' << json_number(r.statistics.max_pressure) << ','
        << json_number(r.solution.separation) << ',' << r.solution.iterations << ','
        << json_number(r.solution.residual) << ',' << (r.solution.converged ? 1 : 0) << ','
        << json_number(r.solution.seconds) << '\n';
}

void run_bem(BemOptions o) {
  if (o.topography.periodic && o.non_periodic) throw Error("--periodic and --non-periodic: give one of them");
  if (o.loads.empty()) throw Error("--loads: give at least one load P/(E* A0)");
  for (const Real load : o.loads)
    if (!(std::isfinite(load) && load >= 0))
      throw Error("--loads: every load P/(E* A0) must be finite and >= 0, got " + json_number(load));
  if (!(std::isfinite(o.modulus) && o.modulus > 0))
    throw Error("--modulus: E* must be finite and > 0 Pa, got " + json_number(o.modulus));
  std::sort(o.loads.begin(), o.loads.end());  // solved in increasing order, each warm-started

  Surface surface = o.topography.read();
  if (o.non_periodic) surface = surface.with_periodic(false);
  const Grid& grid = surface.grid();
  PolonskyKeer solver(surface, o.modulus, {.tolerance = o.tolerance, .max_iterations = o.max_iterations},
                      o.threads);
  Labeller labeller(
      Topology::for_surface(o.connectivity == 8 ? Connectivity::eight : Connectivity::four, grid.periodic),
      o.threads);
  const bool report_progress = grid.points() >= 512 * 512;
  std::vector<Row> rows;
  for (std::size_t k = 0; k < o.loads.size(); ++k) {
    const ContactSolution& solution = solver.solve(o.loads[k] * o.modulus);
    rows.push_back({o.loads[k], contact_statistics(solution, labeller), solution});
    if (report_progress)
      std::cerr << "contactbench bem: load " << k + 1 << " of " << o.loads.size() << " (" << o.loads[k]
                << "): " << solution.iterations << " iterations, " << solution.seconds << " s\n";
  }
  write_output(o.out, [&](std::ostream& out) { write_csv(out, rows, o, surface); });
}

}  // namespace

void add_bem_command(CLI::App& parent) {
  auto options = std::make_shared<BemOptions>();
  CLI::App* command = parent.add_subcommand(
      "bem",
      "Solve the contact of the surface with a rigid flat by the boundary-element method (Polonsky-Keer) at "
      "each load, in increasing order, and write the load-area curve as CSV.");
  options->topography.add_to(*command, "the Fourier half-space; the default is the file's own periodicity");
  command->add_flag("--non-periodic", options->non_periodic,
                    "treat the surface as non-periodic (zero-padded half-space with Love's kernel)");
  command->add_option("--loads", options->loads, "loads P/(E* A0), comma-separated")
      ->required()
      ->delimiter(',');
  command->add_option("--modulus", options->modulus, "E* [Pa] (default: E = 100 GPa, nu = 0.3: 109.9 GPa)");
  command->add_option("--tolerance", options->tolerance,
                      "convergence: relative change of the pressure in one iteration (default 1e-8)");
  command->add_option("--max-iterations", options->max_iterations, "iteration cap per load (default 20000)")
      ->check(CLI::PositiveNumber);
  command->add_option("--connectivity", options->connectivity, "4 or 8, for counting contact spots")
      ->check(CLI::IsMember({4, 8}));
  command->add_option("--out", options->out, "CSV file (default: standard output)");
  add_threads_option(*command, options->threads);
  command->callback([options] { run_bem(*options); });
}

}  // namespace contactbench
