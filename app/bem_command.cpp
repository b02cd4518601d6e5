// contactbench bem: the boundary-element ground truth (Polonsky-Keer) at a list of loads, as a load-area CSV.
#include <algorithm>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "contactbench/app/cli.hpp"
#include "contactbench/app/json_writer.hpp"
#include "contactbench/app/output.hpp"
#include "contactbench/app/topography_options.hpp"
#include "contactbench/bem/contact_statistics.hpp"
#include "contactbench/bem/polonsky_keer.hpp"
#include "contactbench/core/error.hpp"
#include "contactbench/core/topography_io.hpp"

namespace contactbench {

namespace {

struct BemOptions {
  TopographyOptions topography;
  bool non_periodic = false;
  std::vector<Real> loads;
  Real modulus =
      100e9 / (1 - 0.3 * 0.3);    // the paper's material: E = 100 GPa, nu = 0.3 (docs/theory.md section 2)
  std::optional<Real> tolerance;  // default: 1e-8, or the smallest single precision accepts with --float
  Index max_iterations = 20000;
  std::optional<Real> hardness;
  bool single_precision = false;
  std::string solver{solver_name(kDefaultSolver)};
  std::string fields;  // prefix of the per-load pressure and gap files; empty: none
  int connectivity = 4;
  std::string out;
  int threads = 1;
};

constexpr Real kDefaultTolerance = 1e-8;

// The files of load k (1-based, in the order solved): <prefix>_load<k>_pressure.txt and _gap.txt.
std::string field_path(const std::string& prefix, std::size_t k, const char* what) {
  return prefix + "_load" + std::to_string(k) + "_" + what + ".txt";
}

struct Row {
  Real load;
  ContactStatistics statistics;
  ContactSolution solution;
};

void write_csv(std::ostream& out, const std::vector<Row>& rows, const BemOptions& o, const Surface& surface,
               Real tolerance) {
  out << "# contactbench bem of " << o.topography.file << ": "
      << (surface.grid().periodic ? "periodic" : "non-periodic") << " half-space, solver " << o.solver
      << ", E* = " << json_number(o.modulus) << " Pa, tolerance " << json_number(tolerance)
      << " on the relative pressure change, " << (o.single_precision ? "single" : "double") << " precision, "
      << (o.hardness ? "hardness " + json_number(*o.hardness) + " Pa (perfectly plastic cap)" : "no hardness")
      << ", spots by " << o.connectivity << "-connectivity; load = P/(E* A0)";
  if (!o.fields.empty())
    out << "; row k's fields in " << o.fields << "_load<k>_pressure.txt [Pa] and " << o.fields
        << "_load<k>_gap.txt [m]";
  out << "\n";
  out << "load,area_fraction,area_fraction_corrected,spots,mean_gap,max_pressure,separation,iterations,"
         "residual,converged,seconds"
      << (o.hardness ? ",plastic_points" : "") << "\n";
  for (const Row& r : rows) {
    out << json_number(r.load) << ',' << json_number(r.statistics.area_fraction) << ','
        << json_number(r.statistics.area_fraction_corrected) << ',' << r.statistics.spots << ','
        << json_number(r.statistics.mean_gap) << ',' << json_number(r.statistics.max_pressure) << ','
        << json_number(r.solution.separation) << ',' << r.solution.iterations << ','
        << json_number(r.solution.residual) << ',' << (r.solution.converged ? 1 : 0) << ','
        << json_number(r.solution.seconds);
    if (o.hardness) out << ',' << r.solution.plastic_points;
    out << '\n';
  }
}

void run_bem(BemOptions o) {
  if (o.topography.periodic && o.non_periodic) throw Error("--periodic and --non-periodic: give one of them");
  if (o.loads.empty()) throw Error("--loads: give at least one load P/(E* A0)");
  for (const Real load : o.loads)
    if (!(std::isfinite(load) && load >= 0))
      throw Error("--loads: every load P/(E* A0) must be finite and >= 0, got " + json_number(load));
  if (!(std::isfinite(o.modulus) && o.modulus > 0))
    throw Error("--modulus: E* must be finite and > 0 Pa, got " + json_number(o.modulus));
  if (o.hardness && !(std::isfinite(*o.hardness) && *o.hardness > 0))
    throw Error("--hardness: H must be finite and > 0 Pa, got " + json_number(*o.hardness));
  const SolverKind solver = solver_kind(o.solver, "--solver");
  const Real tolerance =
      o.tolerance.value_or(o.single_precision ? kSinglePrecisionTolerance : kDefaultTolerance);
  if (!(tolerance > 0)) throw Error("--tolerance: must be > 0, got " + json_number(tolerance));
  if (o.single_precision && tolerance < kSinglePrecisionTolerance)
    throw Error("--tolerance: single precision (--float) cannot reach a relative pressure change of " +
                json_number(tolerance) + "; give --tolerance " + json_number(kSinglePrecisionTolerance) +
                " or more, or drop --float");
  if (o.hardness)
    for (const Real load : o.loads)
      if (load * o.modulus >= *o.hardness)
        throw Error("--loads: the load " + json_number(load) + " (P/A0 = " + json_number(load * o.modulus) +
                    " Pa) is at or above --hardness " + json_number(*o.hardness) +
                    " Pa: full plastic contact, nothing to solve");
  std::sort(o.loads.begin(), o.loads.end());  // solved in increasing order, each warm-started

  Surface surface = o.topography.read();
  if (o.non_periodic) surface = surface.with_periodic(false);
  const Grid& grid = surface.grid();
  PolonskyKeer bem(surface, o.modulus,
                   {.tolerance = tolerance,
                    .max_iterations = o.max_iterations,
                    .hardness = o.hardness,
                    .single_precision = o.single_precision,
                    .solver = solver},
                   o.threads);
  Labeller labeller(
      Topology::for_surface(o.connectivity == 8 ? Connectivity::eight : Connectivity::four, grid.periodic),
      o.threads);
  const bool report_progress = grid.points() >= 512 * 512;
  std::vector<Row> rows;
  for (std::size_t k = 0; k < o.loads.size(); ++k) {
    const ContactSolution& solution = bem.solve(o.loads[k] * o.modulus);
    rows.push_back({o.loads[k], contact_statistics(solution, labeller), solution});
    if (!o.fields.empty()) {  // as each load is solved, so that a long run leaves what it has done
      write_surface(field_path(o.fields, k + 1, "pressure"), Surface(grid, solution.pressure));
      write_surface(field_path(o.fields, k + 1, "gap"), Surface(grid, solution.gap));
    }
    if (report_progress)
      std::cerr << "contactbench bem: load " << k + 1 << " of " << o.loads.size() << " (" << o.loads[k]
                << "): " << solution.iterations << " iterations, " << solution.seconds << " s\n";
  }
  write_output(o.out, [&](std::ostream& out) { write_csv(out, rows, o, surface, tolerance); });
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
  command->add_option(
      "--tolerance", options->tolerance,
      "convergence: relative change of the pressure in one iteration (default 1e-8; 1e-6, the "
      "smallest it accepts, with --float)");
  command->add_option(
      "--hardness", options->hardness,
      "H [Pa]: cap the pressure at H, perfectly plastic (points at H are plastic: the surface "
      "flows to fit the flat there, gap 0); adds the CSV column plastic_points. Every load must "
      "be below H/E*");
  command->add_flag("--float", options->single_precision,
                    "iterate in single precision: half the memory, faster on large grids; results agree with "
                    "double to float's accuracy (area to 1e-3, mean gap to 1e-4)");
  std::string known;
  for (const std::string& name : solver_names())
    known += (known.empty() ? "" : ", ") + name;
  command->add_option("--solver", options->solver,
                      "the BEM iteration: " + known + " (default " +
                          std::string(solver_name(kDefaultSolver)) +
                          "; docs/solvers.md); recorded in the CSV's header");
  command->add_option(
      "--fields", options->fields,
      "PREFIX: write the pressure [Pa] and gap [m] of the k-th load solved (k = 1, 2, ... in "
      "increasing load) to PREFIX_load<k>_pressure.txt and PREFIX_load<k>_gap.txt, in the "
      "project's surface format (lossless, with the grid; read back by stats and the library's "
      "read_topography), each written to a temporary file and renamed");
  command->add_option("--max-iterations", options->max_iterations, "iteration cap per load (default 20000)")
      ->check(CLI::PositiveNumber);
  command->add_option("--connectivity", options->connectivity, "4 or 8, for counting contact spots")
      ->check(CLI::IsMember({4, 8}));
  command->add_option("--out", options->out, "CSV file (default: standard output)");
  add_threads_option(*command, options->threads);
  command->callback([options] { run_bem(*options); });
}

}  // namespace contactbench
