#include "contactbench/app/distributed_stages.hpp"

#include <chrono>
#include <cstdint>
#include <exception>
#include <iostream>
#include <optional>

#include <mpi.h>

#include "contactbench/app/distributions_csv.hpp"
#include "contactbench/app/load_fields.hpp"
#include "contactbench/app/run_observer.hpp"
#include "contactbench/app/stages.hpp"
#include "contactbench/bem/solver_registry.hpp"
#include "contactbench/core/error.hpp"
#include "contactbench/core/memory_budget.hpp"
#include "contactbench/core/topography_io.hpp"
#include "contactbench/mpi/distributed_bem_solver.hpp"
#include "contactbench/mpi/distributed_contact_statistics.hpp"
#include "contactbench/mpi/distributed_sweep.hpp"
#include "contactbench/mpi/environment.hpp"
#include "contactbench/mpi/slab.hpp"

namespace contactbench {

namespace {

using Clock = std::chrono::steady_clock;

// What rank 0 asks the other ranks to do next (one broadcast int).
enum class Job : int { stop = 0, bem = 1, sweep = 2 };

const MPI_Comm kWorld = MPI_COMM_WORLD;

bool is_root() {
  return mpi::rank_of(kWorld) == 0;
}

void announce(Job job) {
  int code = static_cast<int>(job);
  MPI_Bcast(&code, 1, MPI_INT, 0, kWorld);
}

// A job's numbers, packed by rank 0 and broadcast (counts, flags and enums are small integers, exact in a
// double).
std::vector<double> broadcast(std::vector<double> values) {
  std::uint64_t size = values.size();
  MPI_Bcast(&size, 1, MPI_UINT64_T, 0, kWorld);
  values.resize(size);
  MPI_Bcast(values.data(), static_cast<int>(size), MPI_DOUBLE, 0, kWorld);
  return values;
}

void pack_grid(std::vector<double>& out, const Grid& grid) {
  out.insert(out.end(), {static_cast<double>(grid.nx), static_cast<double>(grid.ny), grid.lx, grid.ly,
                         grid.periodic ? 1.0 : 0.0});
}

// Reads the packed values in order.
class Unpacker {
 public:
  explicit Unpacker(const std::vector<double>& values) : values_(values) {}
  double number() { return values_.at(next_++); }
  void settings(BemSettings& settings) { unpack_settings(bem_settings(), values_, next_, settings); }
  Index integer() { return static_cast<Index>(number()); }
  bool flag() { return number() != 0; }
  Grid grid() {
    Grid g;
    g.nx = integer();
    g.ny = integer();
    g.lx = number();
    g.ly = number();
    g.periodic = flag();
    return g;
  }

 private:
  const std::vector<double>& values_;
  std::size_t next_ = 0;
};

Topology topology_of(int connectivity, bool periodic) {
  return Topology::for_surface(connectivity == 8 ? Connectivity::eight : Connectivity::four, periodic);
}

// ---- The BEM job, run by every rank (rank 0 with the surface and the writer of fields) ----------------

struct BemRequest {
  Grid grid;
  Real estar = 0;
  BemSettings settings;  // its solve settings the distributed solver takes (app/methods/bem_settings.hpp)
  std::optional<Real> hardness;  // the interface's; active_set only (bem_refusal)
  int threads = 1;
  bool write_fields = false;
  // The load whose distributions are measured (the scene's `distributions`; -1: none) and their bins.
  Index measured_load = -1;
  Index distribution_bins = 0;
  std::vector<Real> mean_pressures;
  std::vector<int> connectivities;
};

BemRequest broadcast_request(const BemRequest& request) {
  std::vector<double> packed;
  if (is_root()) {
    pack_grid(packed, request.grid);
    packed.push_back(request.estar);
    pack_settings(bem_settings(), request.settings, packed);
    packed.insert(packed.end(), {request.hardness ? 1.0 : 0.0, request.hardness.value_or(0.0)});
    packed.insert(packed.end(),
                  {static_cast<double>(request.threads), request.write_fields ? 1.0 : 0.0,
                   static_cast<double>(request.measured_load), static_cast<double>(request.distribution_bins),
                   static_cast<double>(request.mean_pressures.size())});
    packed.insert(packed.end(), request.mean_pressures.begin(), request.mean_pressures.end());
    packed.push_back(static_cast<double>(request.connectivities.size()));
    packed.insert(packed.end(), request.connectivities.begin(), request.connectivities.end());
  }
  const std::vector<double> values = broadcast(std::move(packed));
  Unpacker in(values);
  BemRequest r;
  r.grid = in.grid();
  r.estar = in.number();
  in.settings(r.settings);
  const bool capped = in.flag();
  const Real hardness = in.number();
  if (capped) r.hardness = hardness;
  r.threads = static_cast<int>(in.integer());
  r.write_fields = in.flag();
  r.measured_load = in.integer();
  r.distribution_bins = in.integer();
  for (Index k = in.integer(); k > 0; --k)
    r.mean_pressures.push_back(in.number());
  for (Index k = in.integer(); k > 0; --k)
    r.connectivities.push_back(static_cast<int>(in.integer()));
  return r;
}

// Every load on slabs. Rank 0 passes the surface's heights, the field prefix, a warning sink and what to
// tell of each load solved (a progress line); the others pass nothing and get nothing back. The only work
// rank 0 does alone between two collective calls is writing fields: a failure there is broadcast before the
// next load (every rank stops) and rethrown at the end, so no rank is ever left waiting.
SolvedLoads bem_job(const BemRequest& root_request, const HeightMap* heights, const std::string& fields,
                    const std::function<void(const std::string&)>& warning,
                    const std::function<void(std::size_t load, const ContactSolution&)>& load_solved) {
  const BemRequest request = broadcast_request(root_request);
  const Grid& grid = request.grid;
  const mpi::Slab slab = mpi::slab_of(grid, kWorld);
  const HeightMap local = mpi::scatter_from_root(heights ? *heights : HeightMap(), slab, kWorld);
  BemSolverOptions options = request.settings.solver;
  options.hardness = request.hardness;  // absent: purely elastic (as app/serial_runner.cpp)
  options.warning = warning;
  mpi::DistributedBemSolver solver(grid, local, request.estar, kWorld, options, request.threads);
  SolvedLoads result;
  std::exception_ptr failure;
  for (std::size_t k = 0; k < request.mean_pressures.size(); ++k) {
    int go = failure ? 0 : 1;
    MPI_Bcast(&go, 1, MPI_INT, 0, kWorld);
    if (!go) break;
    const auto start = Clock::now();
    const mpi::DistributedContactSolution& solved = solver.solve(request.mean_pressures[k]);
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    for (const int c : request.connectivities) {
      const ContactStatistics statistics = mpi::distributed_contact_statistics(
          grid, solved.pressure, solved.gap, topology_of(c, grid.periodic), kWorld);
      if (is_root()) result.statistics[c].push_back(statistics);
    }
    const bool measured = static_cast<Index>(k) == request.measured_load;
    if (request.write_fields || measured) {
      const HeightMap pressure = mpi::gather_to_root(solved.pressure, slab, kWorld);
      const HeightMap gap = mpi::gather_to_root(solved.gap, slab, kWorld);
      // The distributions from the gathered fields, as one process measures them (app/distributions_csv.hpp):
      // the cluster areas need every cluster labelled whole, which the slabs' statistics do not keep, and
      // rank 0's memory already counts the gathered fields (bem_memory). The histograms' sums then run in
      // one process's order, so the counts and means are one process's exactly.
      if (is_root()) try {
          if (measured) {
            std::map<int, Labeller> labellers;
            for (const int c : request.connectivities)
              labellers.emplace(c, Labeller(topology_of(c, grid.periodic), request.threads));
            result.distributions = measure_distributions(pressure, gap, grid.dx() * grid.dy(),
                                                         request.distribution_bins, labellers);
          }
          if (request.write_fields)
            write_load_fields(fields, k + 1, grid, {.pressure = &pressure, .gap = &gap}, warning);
        } catch (...) {
          failure = std::current_exception();
        }
    }
    if (is_root())
      result.solutions.push_back(ContactSolution{.pressure = {},
                                                 .gap = {},
                                                 .mean_pressure = solved.mean_pressure,
                                                 .separation = solved.separation,
                                                 .contact_points = solved.contact_points,
                                                 .iterations = solved.iterations,
                                                 .coarse_iterations = 0,
                                                 .change = solved.change,
                                                 .residual = solved.residual,
                                                 .converged = solved.converged,
                                                 .seconds = seconds,
                                                 .plastic_points = solved.plastic_points,
                                                 .plastic_overlap = {}});
    if (is_root() && load_solved) load_solved(k, result.solutions.back());
  }
  // After the loads: the most one rank held at once (active_set knows its coarse levels' peak once a cold
  // solve has made them).
  unsigned long long bytes = solver.bytes();
  MPI_Reduce(is_root() ? MPI_IN_PLACE : &bytes, &bytes, 1, MPI_UNSIGNED_LONG_LONG, MPI_MAX, 0, kWorld);
  result.bytes_per_rank = bytes;
  if (failure) std::rethrow_exception(failure);
  return result;
}

// ---- The sweep job ---------------------------------------------------------------------------------------

SweepCurve sweep_job(const Grid& root_grid, const HeightMap* heights, const SweepLevels& root_levels,
                     const Topology& root_topology) {
  std::vector<double> packed;
  if (is_root()) {
    pack_grid(packed, root_grid);
    packed.insert(packed.end(), {static_cast<double>(static_cast<int>(root_levels.kind)),
                                 static_cast<double>(root_levels.count),
                                 root_topology.connectivity == Connectivity::eight ? 8.0 : 4.0,
                                 root_topology.wrap_x ? 1.0 : 0.0, root_topology.wrap_y ? 1.0 : 0.0});
  }
  const std::vector<double> values = broadcast(std::move(packed));
  Unpacker in(values);
  const Grid grid = in.grid();
  SweepLevels levels;
  levels.kind = static_cast<SweepLevels::Kind>(static_cast<int>(in.integer()));
  levels.count = in.integer();
  Topology topology;
  topology.connectivity = in.integer() == 8 ? Connectivity::eight : Connectivity::four;
  topology.wrap_x = in.flag();
  topology.wrap_y = in.flag();
  const mpi::Slab slab = mpi::slab_of(grid, kWorld);
  const HeightMap local = mpi::scatter_from_root(heights ? *heights : HeightMap(), slab, kWorld);
  return mpi::distributed_sweep(grid, local, levels, topology, kWorld);
}

// The other ranks: each job rank 0 announces, until it says stop. A job that fails fails on every rank at
// the same collective call (the distributed classes check collectively); rank 0 reports it.
void serve() {
  for (;;) {
    int code = 0;
    MPI_Bcast(&code, 1, MPI_INT, 0, kWorld);
    try {
      switch (static_cast<Job>(code)) {
        case Job::stop:
          return;
        case Job::bem:
          bem_job({}, nullptr, "", {}, {});
          break;
        case Job::sweep:
          sweep_job({}, nullptr, {}, {});
          break;
      }
    } catch (const std::exception&) {
      // rank 0 met the same error and reports it
    }
  }
}

// Rank 0's side of the stages: each job announced to the other ranks, which serve it (serve() above).
class DistributedRunner final : public StageRunner {
 public:
  // ranks_here: the ranks on rank 0's machine (they share its memory).
  explicit DistributedRunner(int ranks_here) : ranks_here_(ranks_here) {}

  int ranks() const override { return mpi::size_of(kWorld); }

  // Every rank on this machine holds at most rank 0's slab (FFTW's split gives the first ranks the full
  // blocks) and what DistributedBemSolver::estimated_bytes says of it; rank 0 also the whole surface: its
  // heights as read and centred, and with fields the gathered pressure and gap (8 B a point each).
  std::optional<SpreadMemory> bem_memory(const BemSolverOptions& solver, const Grid& grid) const override {
    const mpi::Slab largest = mpi::slab_of(grid, kWorld);
    const std::uintmax_t per_rank =
        mpi::DistributedBemSolver::estimated_bytes(grid, largest.points(), solver);
    const std::uintmax_t root_extra = saturating_product(static_cast<std::uintmax_t>(grid.points()), 32);
    return SpreadMemory{
        .bytes = saturating_sum(saturating_product(per_rank, static_cast<std::uintmax_t>(ranks_here_)),
                                root_extra),
        .how = std::to_string(ranks()) + " ranks, " + std::to_string(ranks_here_) +
               " on this machine, about " + format_bytes(per_rank) + " each and " + format_bytes(root_extra) +
               " more on rank 0, which holds the whole surface"};
  }

  std::string bem_refusal(const BemStage& stage) const override {
    // What the distributed solver lacks: the interface's effects, and the settings the declaration says
    // (app/methods/bem_settings.cpp) it does not take.
    std::vector<std::string> missing;
    // A hardness: the capped active-set method is distributed, not the PK solvers' search of the flat's
    // height (their impose_load).
    if (stage.hardness && stage.settings.solver.solver != SolverKind::active_set)
      missing.push_back("a hardness (interface.hardness) with solver " +
                        std::string(solver_name(stage.settings.solver.solver)) + " (active_set takes it)");
    if (stage.adhesion) missing.push_back("adhesion (interface.adhesion)");
    // A load path is a list of loads, each warm-started from the last as one process does; with a hardness
    // the surface keeps its plastic flow from one load to the next (BemSolver::keep_plastic_deformation),
    // new heights the slabs' solver has no way to take yet.
    if (!stage.load_path.empty() && stage.hardness)
      missing.push_back(
          "a load path with a hardness (loads.path = \"as listed\" with interface.hardness: "
          "the plastic flow kept along the path)");
    if (stage.stiffness) missing.push_back("the contact stiffness (compare = [\"stiffness\"])");
    if (stage.approach_retract)
      missing.push_back("the approach-retract path (approach_retract = { from, to, steps })");
    for (const std::string& setting :
         undistributed_settings(bem_settings(), stage.settings, default_settings(bem_settings())))
      missing.push_back(setting);
    if (missing.empty()) return "";
    std::string text = "the BEM stage has no distributed version with ";
    for (std::size_t k = 0; k < missing.size(); ++k)
      text += (k == 0 ? "" : k + 1 == missing.size() ? " and " : ", ") + missing[k];
    return text + ": run it as one process, or without " + (missing.size() > 1 ? "these" : "it") +
           " (docs/mpi.md)";
  }

  SolvedLoads solve_loads(const BemStage& stage, const Surface& solved, Real estar,
                          const std::vector<Real>& mean_pressures, const std::set<int>& connectivities,
                          const std::string& fields, const StageContext& context) const override {
    if (const std::string refusal = bem_refusal(stage); !refusal.empty()) throw Error(refusal);
    const RunObserver quiet;
    const RunObserver& observer = context.observer ? *context.observer : quiet;
    const std::optional<std::size_t> measured = stage.distributions_solve(mean_pressures, estar);
    const Index measured_load = measured ? static_cast<Index>(*measured) : -1;
    BemRequest request{.grid = solved.grid(),
                       .estar = estar,
                       .settings = stage.settings,
                       .hardness = stage.hardness,
                       .threads = context.threads,
                       .write_fields = !fields.empty(),
                       .measured_load = measured_load,
                       .distribution_bins = stage.distributions ? stage.distributions->bins : 0,
                       .mean_pressures = mean_pressures,
                       .connectivities = {connectivities.begin(), connectivities.end()}};
    // A progress line per load as one process says it (app/serial_runner.cpp), from rank 0.
    const auto start = Clock::now();
    const auto load_solved = [&](std::size_t k, const ContactSolution& solution) {
      observer.solved(bem_load_progress(stage.name(), solved.grid().nx, solved.grid().ny, k,
                                        mean_pressures.size(), mean_pressures[k] / estar,
                                        static_cast<long long>(solution.iterations), solution.seconds,
                                        std::chrono::duration<double>(Clock::now() - start).count()));
    };
    announce(Job::bem);
    return bem_job(
        request, &solved.heights(), fields, [&](const std::string& text) { observer.warn(text); },
        load_solved);
  }

  SweepCurve sweep(const Surface& surface, const SweepLevels& levels, const Topology& topology,
                   int) const override {
    announce(Job::sweep);
    return sweep_job(surface.grid(), &surface.heights(), levels, topology);
  }

 private:
  int ranks_here_ = 1;
};

// The ranks that share this rank's machine (its memory). Collective.
int ranks_on_this_machine() {
  MPI_Comm machine = MPI_COMM_NULL;
  MPI_Comm_split_type(kWorld, MPI_COMM_TYPE_SHARED, mpi::rank_of(kWorld), MPI_INFO_NULL, &machine);
  const int size = mpi::size_of(machine);
  MPI_Comm_free(&machine);
  return size;
}

}  // namespace

int run_as_mpi_ranks(int& argc, char**& argv, const std::function<int(const StageRunner&)>& command) {
  mpi::Environment environment(argc, argv);
  const int ranks_here = ranks_on_this_machine();
  if (!is_root()) {
    serve();
    return 0;
  }
  const DistributedRunner runner(ranks_here);
  int status = 1;
  try {
    status = command(runner);
  } catch (const std::exception& e) {
    std::cerr << "contactbench: error: " << e.what() << '\n';
  }
  announce(Job::stop);
  return status;
}

}  // namespace contactbench
