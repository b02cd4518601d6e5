#include "contactbench/app/distributed_stages.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <exception>
#include <functional>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>

#include <mpi.h>

#include "contactbench/app/distributions_csv.hpp"
#include "contactbench/app/load_fields.hpp"
#include "contactbench/app/mirrored_boundary.hpp"
#include "contactbench/app/run_observer.hpp"
#include "contactbench/app/stages.hpp"
#include "contactbench/bem/solver_registry.hpp"
#include "contactbench/core/error.hpp"
#include "contactbench/core/memory_budget.hpp"
#include "contactbench/core/scales.hpp"
#include "contactbench/core/topography_io.hpp"
#include "contactbench/core/topography_rows.hpp"
#include "contactbench/mpi/distributed_bem_solver.hpp"
#include "contactbench/mpi/distributed_contact_statistics.hpp"
#include "contactbench/mpi/distributed_generation.hpp"
#include "contactbench/mpi/distributed_mirror.hpp"
#include "contactbench/mpi/distributed_refinement.hpp"
#include "contactbench/mpi/distributed_sweep.hpp"
#include "contactbench/mpi/environment.hpp"
#include "contactbench/mpi/slab.hpp"

namespace contactbench {

namespace {

using Clock = std::chrono::steady_clock;

// What rank 0 asks the other ranks to do next (one broadcast int).
enum class Job : int {
  stop = 0,
  bem = 1,
  sweep = 2,
  surface = 3,
  mean_gaps = 4,
  gather_surface = 5,
  read_surface = 6,
  refine = 7
};

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

// ---- The scene's generated surface, resident on the ranks' slabs ----------------------------------------

// This rank's slab of the scene's surface (Job::surface), kept for the stages that follow: every rank holds
// its rows only, rank 0 none more (app/scene_surface.hpp).
struct ResidentSlab {
  Grid grid;
  HeightMap local;
};
std::optional<ResidentSlab>& resident_slab() {
  static std::optional<ResidentSlab> slab;
  return slab;
}

// This rank's slab of the surface the last stage that refined asked for (Job::refine), kept until the next
// refinement or the next scene's surface: the stage solves or sweeps it, and no rank holds it whole.
std::optional<ResidentSlab>& refined_slab() {
  static std::optional<ResidentSlab> slab;
  return slab;
}

// The slab a stage on `grid` solves: the scene's resident one or the last refined one (`refined`), whose
// grid it is but for the boundary the stage chose. Every rank has the same slabs' grids, so every rank
// passes or throws alike.
const HeightMap& resident_heights(const Grid& grid, bool refined) {
  const std::optional<ResidentSlab>& slab = refined ? refined_slab() : resident_slab();
  if (!slab || slab->grid.nx != grid.nx || slab->grid.ny != grid.ny || slab->grid.lx != grid.lx ||
      slab->grid.ly != grid.ly)
    throw Error(std::string("internal: a distributed stage asked for a ") +
                (refined ? "refined" : "resident") + " surface of another grid");
  return slab->local;
}

ResidentSurface keep_resident(const Grid& grid, HeightMap local);

// Each rank generates its slab of the scene's surface (mpi::generate_surface_slab: the serial surface's
// rows bit for bit), centres it on the mean plane and reduces what the preflights and theories read: the
// spectral moments and the heights' extremes. The mean is the slabs' sums added in rank order, so it may
// differ from one process's Eigen sum in the last bits (docs/mpi.md). Rank 0 passes the spec; returns the
// reductions on every rank.
ResidentSurface surface_job(const GeneratedSurfaceSpec* spec) {
  std::vector<double> packed;
  std::uint64_t seed = 0;
  if (spec) {
    pack_grid(packed,
              Grid{.nx = spec->grid, .ny = spec->grid, .lx = spec->size, .ly = spec->size, .periodic = true});
    packed.insert(packed.end(), {spec->sigma, spec->hurst, spec->qr, spec->qs ? 1.0 : 0.0,
                                 spec->qs.value_or(0.0), spec->anisotropy});
    seed = spec->seed;
  }
  const std::vector<double> values = broadcast(std::move(packed));
  MPI_Bcast(&seed, 1, MPI_UINT64_T, 0, kWorld);
  Unpacker in(values);
  const Grid grid = in.grid();
  SelfAffinePsd psd;
  psd.sigma = in.number();
  psd.hurst = in.number();
  psd.qr = in.number();
  const bool has_qs = in.flag();
  const Real qs = in.number();
  if (has_qs) psd.qs = qs;
  psd.anisotropy = in.number();
  resident_slab().reset();  // the last scene's, freed before the new one is made
  refined_slab().reset();
  validate(psd, grid);  // the serial generator's refusal, on every rank alike
  return keep_resident(grid, mpi::generate_surface_slab(grid, psd, seed, kWorld));
}

// Each rank's slab of a file's surface, read by rank 0 (its `reader`, open) a bounded buffer at a time and
// sent to the rank that owns those rows as it is read: rank 0 holds its own slab and one buffer of about
// 1 MiB (one row when a row is longer), never the whole surface. A defect found while reading (a bad row,
// missing or extra rows) stops every rank (each chunk is preceded by a broadcast saying whether it came),
// and rank 0 rethrows the reader's error. Then the slabs are kept as a generated surface's are.
ResidentSurface read_surface_job(TopographyRowReader* reader) {
  std::vector<double> packed;
  if (reader) pack_grid(packed, reader->grid());
  const std::vector<double> values = broadcast(std::move(packed));
  Unpacker in(values);
  const Grid grid = in.grid();
  resident_slab().reset();  // the last scene's, freed before the new one is made
  refined_slab().reset();
  const auto slabs = mpi::all_slabs(grid.nx, grid.ny, kWorld);
  const int me = mpi::rank_of(kWorld);
  HeightMap local(slabs[static_cast<std::size_t>(me)].count, grid.nx);
  const Index chunk_rows = std::max<Index>(1, (Index{1} << 17) / grid.nx);  // 1 MiB of heights
  std::vector<Real> buffer;
  std::exception_ptr failure;
  // Every rank takes part in each step's broadcast: whether rank 0 read it.
  const auto step_read = [&](const std::function<void()>& read) {
    int ok = 1;
    if (is_root() && !failure) try {
        read();
      } catch (...) {
        failure = std::current_exception();
      }
    if (is_root()) ok = failure ? 0 : 1;
    MPI_Bcast(&ok, 1, MPI_INT, 0, kWorld);
    if (!ok) {
      if (failure) std::rethrow_exception(failure);
      throw Error("rank 0 could not read the surface file");
    }
  };
  for (std::size_t r = 0; r < slabs.size(); ++r)
    for (Index row = 0; row < slabs[r].count; row += chunk_rows) {
      const Index rows = std::min(chunk_rows, slabs[r].count - row);
      if (r == 0) {
        step_read([&] { reader->read(rows, local.data() + row * grid.nx); });
        continue;
      }
      if (is_root()) buffer.resize(static_cast<std::size_t>(rows * grid.nx));
      step_read([&] { reader->read(rows, buffer.data()); });
      const int count = static_cast<int>(rows * grid.nx);  // at most 2^17 values (or one row)
      if (is_root())
        MPI_Send(buffer.data(), count, MPI_DOUBLE, static_cast<int>(r), 0, kWorld);
      else if (me == static_cast<int>(r))
        MPI_Recv(local.data() + row * grid.nx, count, MPI_DOUBLE, 0, 0, kWorld, MPI_STATUS_IGNORE);
    }
  step_read([&] { reader->finish(); });
  std::vector<Real>().swap(buffer);
  return keep_resident(grid, std::move(local));
}

// The slabs kept for the stages that follow, centred on the mean plane, reduced to what the preflights and
// theories read: the moments and the heights' extremes (the same on every rank).
ResidentSurface keep_resident(const Grid& grid, HeightMap local) {
  // The mean plane: each rank's sum, gathered and added in rank order (the same value on every rank).
  const double sum = local.size() ? local.sum() : 0.0;
  std::vector<double> sums(static_cast<std::size_t>(mpi::size_of(kWorld)));
  MPI_Allgather(&sum, 1, MPI_DOUBLE, sums.data(), 1, MPI_DOUBLE, kWorld);
  double total = 0;
  for (const double s : sums)
    total += s;
  local -= total / static_cast<double>(grid.points());
  ResidentSurface summary{
      .grid = grid, .moments = {}, .min_height = 0, .max_height = 0, .gather = {}, .mean_gaps = {}};
  summary.moments = mpi::distributed_spectral_moments(grid, local, kWorld);
  double extremes[2] = {local.size() ? -local.minCoeff() : -std::numeric_limits<double>::infinity(),
                        local.size() ? local.maxCoeff() : -std::numeric_limits<double>::infinity()};
  MPI_Allreduce(MPI_IN_PLACE, extremes, 2, MPI_DOUBLE, MPI_MAX, kWorld);
  summary.min_height = -extremes[0];
  summary.max_height = extremes[1];
  resident_slab() = ResidentSlab{grid, std::move(local)};
  return summary;
}

// The scene's surface Fourier-refined on the ranks' slabs (mpi/distributed_refinement.hpp: one process's
// refinement bit for bit), kept for the stage that asked. Rank 0 passes the scene's whole surface (its
// coefficients are taken there, on rank 0's threads) and the finer size; the others nothing.
void refine_job(const Surface* surface, Index nx, Index ny, int threads) {
  refined_slab().reset();  // the last stage's, freed before the new one is made
  mpi::RefinedSlab refined = mpi::refine_surface_slab(surface, nx, ny, threads, kWorld);
  refined_slab() = ResidentSlab{refined.grid, std::move(refined.local)};
}

// The resident surface gathered whole on rank 0 (a method that reads the whole heights): 8 B a point there,
// the same bits as the slabs (centred on the slabs' mean, so one process's heights to the last bit).
HeightMap gather_surface_job() {
  const ResidentSlab& slab = *resident_slab();
  return mpi::gather_to_root(slab.local, mpi::slab_of(slab.grid, kWorld), kWorld);
}

// For each level z, the mean of (z - h)+ over the resident slabs (NaN for a NaN level): each rank's sums,
// gathered to rank 0 and added in rank order. Rank 0 passes the levels; returns them on rank 0.
std::vector<Real> mean_gaps_job(const std::vector<Real>& root_levels) {
  const std::vector<double> levels = broadcast(root_levels);
  const ResidentSlab& slab = *resident_slab();
  std::vector<double> sums(levels.size(), 0.0);
  for (std::size_t k = 0; k < levels.size(); ++k)
    if (std::isfinite(levels[k]) && slab.local.size()) sums[k] = (levels[k] - slab.local).max(0.0).sum();
  const int ranks = mpi::size_of(kWorld);
  std::vector<double> all(is_root() ? levels.size() * static_cast<std::size_t>(ranks) : 0);
  MPI_Gather(sums.data(), static_cast<int>(sums.size()), MPI_DOUBLE, all.data(),
             static_cast<int>(sums.size()), MPI_DOUBLE, 0, kWorld);
  std::vector<Real> gaps;
  if (!is_root()) return gaps;
  for (std::size_t k = 0; k < levels.size(); ++k) {
    double total = 0;
    for (int r = 0; r < ranks; ++r)
      total += all[static_cast<std::size_t>(r) * levels.size() + k];
    gaps.push_back(std::isfinite(levels[k]) ? total / static_cast<double>(slab.grid.points()) : std::nan(""));
  }
  return gaps;
}

Topology topology_of(int connectivity, bool periodic) {
  return Topology::for_surface(connectivity == 8 ? Connectivity::eight : Connectivity::four, periodic);
}

// ---- The BEM job, run by every rank (rank 0 with the surface and the writer of fields) ----------------

struct BemRequest {
  Grid grid;  // the problem's: with boundary = "mirrored" the patch, which is judged
  Real estar = 0;
  BemSettings settings;  // its solve settings the distributed solver takes (app/methods/bem_settings.hpp)
  std::optional<Real> hardness;  // the interface's; active_set only (bem_refusal)
  int threads = 1;
  bool resident =
      false;  // the heights are on the slabs (Job::surface or Job::refine), not scattered from rank 0
  bool refined = false;  // with `resident`: the last refined slabs (Job::refine), not the scene's
  // Bytes of whole-surface heights rank 0 holds during the stage (the scene's and the stage's copies),
  // counted in the memory a rank held.
  double root_surface_bytes = 0;
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
    // The boundary as resolved: a setting without a default value, which pack_settings leaves to rank 0.
    packed.push_back(request.settings.mirrored.value_or(false) ? 1.0 : 0.0);
    packed.insert(packed.end(), {request.hardness ? 1.0 : 0.0, request.hardness.value_or(0.0)});
    packed.insert(packed.end(),
                  {static_cast<double>(request.threads), request.resident ? 1.0 : 0.0,
                   request.refined ? 1.0 : 0.0, request.root_surface_bytes, request.write_fields ? 1.0 : 0.0,
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
  r.settings.mirrored = in.flag();
  const bool capped = in.flag();
  const Real hardness = in.number();
  if (capped) r.hardness = hardness;
  r.threads = static_cast<int>(in.integer());
  r.resident = in.flag();
  r.refined = in.flag();
  r.root_surface_bytes = in.number();
  r.write_fields = in.flag();
  r.measured_load = in.integer();
  r.distribution_bins = in.integer();
  for (Index k = in.integer(); k > 0; --k)
    r.mean_pressures.push_back(in.number());
  for (Index k = in.integer(); k > 0; --k)
    r.connectivities.push_back(static_cast<int>(in.integer()));
  return r;
}

// A solution on the mirrored extension's slabs made the patch's (app/mirrored_boundary.hpp's patch_of on
// slabs): its pressure and gap cut to the patch's slabs; the contact and plastic points (p >= hardness, as
// the solvers count them) and the mean pressure counted there. Collective.
mpi::DistributedContactSolution on_patch(const mpi::DistributedContactSolution& mirrored,
                                         mpi::PatchOfMirrored& patch, const Grid& grid,
                                         std::optional<Real> hardness) {
  mpi::DistributedContactSolution solved{.pressure = patch.cut(mirrored.pressure),
                                         .gap = patch.cut(mirrored.gap),
                                         .mean_pressure = 0,
                                         .separation = mirrored.separation,
                                         .contact_points = 0,
                                         .plastic_points = 0,
                                         .iterations = mirrored.iterations,
                                         .change = mirrored.change,
                                         .residual = mirrored.residual,
                                         .converged = mirrored.converged};
  const double cap = hardness.value_or(std::numeric_limits<double>::infinity());
  double sums[3] = {0, 0, 0};  // contact points, plastic points, pressure
  for (Index i = 0; i < solved.pressure.size(); ++i) {
    const double p = solved.pressure.data()[i];
    sums[0] += p > 0 ? 1 : 0;
    sums[1] += p >= cap ? 1 : 0;
    sums[2] += p;
  }
  MPI_Allreduce(MPI_IN_PLACE, sums, 3, MPI_DOUBLE, MPI_SUM, kWorld);
  solved.contact_points = static_cast<Index>(sums[0]);
  solved.plastic_points = static_cast<Index>(sums[1]);
  solved.mean_pressure = sums[2] / static_cast<double>(grid.points());
  return solved;
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
  HeightMap scattered;
  if (!request.resident) scattered = mpi::scatter_from_root(heights ? *heights : HeightMap(), slab, kWorld);
  const HeightMap& local = request.resident ? resident_heights(grid, request.refined) : scattered;
  // boundary = "mirrored": the slabs solve the patch's periodic even extension, made from the patch's slabs
  // (mpi/distributed_mirror.hpp), and everything after a solve is taken on the patch, as one process does
  // (app/serial_runner.cpp): its fields cut back onto the patch's slabs, counted and labelled there.
  const bool mirrored = request.settings.mirrored.value_or(false);
  const HeightMap extension = mirrored ? mpi::mirrored_slab(grid.nx, grid.ny, local, kWorld) : HeightMap();
  std::optional<mpi::PatchOfMirrored> patch;
  if (mirrored) patch.emplace(grid.nx, grid.ny, kWorld);
  const std::uintmax_t held_bytes =
      static_cast<std::uintmax_t>(local.size() + extension.size()) * sizeof(Real);
  if (mirrored && !request.resident) HeightMap().swap(scattered);  // the extension holds them now
  BemSolverOptions options = request.settings.solver;
  options.hardness = request.hardness;  // absent: purely elastic (as app/serial_runner.cpp)
  options.warning = warning;
  mpi::DistributedBemSolver solver(mirrored ? mirrored_grid(grid) : grid, mirrored ? extension : local,
                                   request.estar, kWorld, options, request.threads);
  SolvedLoads result;
  std::exception_ptr failure;
  for (std::size_t k = 0; k < request.mean_pressures.size(); ++k) {
    int go = failure ? 0 : 1;
    MPI_Bcast(&go, 1, MPI_INT, 0, kWorld);
    if (!go) break;
    const auto start = Clock::now();
    const mpi::DistributedContactSolution& as_solved = solver.solve(request.mean_pressures[k]);
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    std::optional<mpi::DistributedContactSolution> patch_solution;
    if (patch) patch_solution = on_patch(as_solved, *patch, grid, request.hardness);
    const mpi::DistributedContactSolution& solved = patch_solution ? *patch_solution : as_solved;
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
  // solve has made them), its slab of heights, and on rank 0 the whole-surface heights and, when fields or
  // distributions are asked for, the gathered pressure and gap (8 B a point each).
  const bool gathers = request.write_fields || request.measured_load >= 0;
  unsigned long long bytes = solver.bytes() + held_bytes;
  if (is_root())
    bytes += static_cast<unsigned long long>(request.root_surface_bytes) +
             (gathers ? static_cast<unsigned long long>(grid.points()) * 2 * sizeof(Real) : 0ULL);
  MPI_Reduce(is_root() ? MPI_IN_PLACE : &bytes, &bytes, 1, MPI_UNSIGNED_LONG_LONG, MPI_MAX, 0, kWorld);
  result.bytes_per_rank = bytes;
  if (failure) std::rethrow_exception(failure);
  return result;
}

// ---- The sweep job ---------------------------------------------------------------------------------------

SweepCurve sweep_job(const Grid& root_grid, const HeightMap* heights, bool refined,
                     const SweepLevels& root_levels, const Topology& root_topology) {
  std::vector<double> packed;
  if (is_root()) {
    pack_grid(packed, root_grid);
    packed.push_back(heights ? 0.0 : 1.0);  // no heights: the slabs
    packed.push_back(refined ? 1.0 : 0.0);  // the last refined slabs, not the scene's
    packed.insert(packed.end(), {static_cast<double>(static_cast<int>(root_levels.kind)),
                                 static_cast<double>(root_levels.count),
                                 root_topology.connectivity == Connectivity::eight ? 8.0 : 4.0,
                                 root_topology.wrap_x ? 1.0 : 0.0, root_topology.wrap_y ? 1.0 : 0.0});
  }
  const std::vector<double> values = broadcast(std::move(packed));
  Unpacker in(values);
  const Grid grid = in.grid();
  const bool resident = in.flag();
  const bool refined_slabs = in.flag();
  SweepLevels levels;
  levels.kind = static_cast<SweepLevels::Kind>(static_cast<int>(in.integer()));
  levels.count = in.integer();
  Topology topology;
  topology.connectivity = in.integer() == 8 ? Connectivity::eight : Connectivity::four;
  topology.wrap_x = in.flag();
  topology.wrap_y = in.flag();
  const mpi::Slab slab = mpi::slab_of(grid, kWorld);
  HeightMap scattered;
  if (!resident) scattered = mpi::scatter_from_root(heights ? *heights : HeightMap(), slab, kWorld);
  return mpi::distributed_sweep(grid, resident ? resident_heights(grid, refined_slabs) : scattered, levels,
                                topology, kWorld);
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
          resident_slab().reset();
          refined_slab().reset();
          return;
        case Job::surface:
          surface_job(nullptr);
          break;
        case Job::gather_surface:
          gather_surface_job();
          break;
        case Job::read_surface:
          read_surface_job(nullptr);
          break;
        case Job::mean_gaps:
          mean_gaps_job({});
          break;
        case Job::bem:
          bem_job({}, nullptr, "", {}, {});
          break;
        case Job::sweep:
          sweep_job({}, nullptr, false, {}, {});
          break;
        case Job::refine:
          refine_job(nullptr, 0, 0, 1);
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
  // blocks) and what DistributedBemSolver::estimated_bytes says of it, and its slab of heights; rank 0 also
  // `root_bytes`, the whole arrays it holds (app/methods/bem_method.cpp: none for a generated surface
  // solved on its resident slabs without fields).
  std::optional<SpreadMemory> bem_memory(const BemSolverOptions& solver, const Grid& grid,
                                         std::uintmax_t root_bytes) const override {
    const mpi::Slab largest = mpi::slab_of(grid, kWorld);
    const std::uintmax_t per_rank =
        saturating_sum(mpi::DistributedBemSolver::estimated_bytes(grid, largest.points(), solver),
                       saturating_product(static_cast<std::uintmax_t>(largest.points()), sizeof(Real)));
    return SpreadMemory{
        .bytes = saturating_sum(saturating_product(per_rank, static_cast<std::uintmax_t>(ranks_here_)),
                                root_bytes),
        .how = std::to_string(ranks()) + " ranks, " + std::to_string(ranks_here_) +
               " on this machine, about " + format_bytes(per_rank) + " each" +
               (root_bytes > 0 ? " and " + format_bytes(root_bytes) +
                                     " more on rank 0, which holds the whole surface or gathered fields"
                               : std::string(", none of them the whole surface"))};
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

  std::optional<ResidentSurface> make_resident_surface(const GeneratedSurfaceSpec& spec, int) const override {
    announce(Job::surface);
    ResidentSurface surface = surface_job(&spec);
    // The whole heights, when a method reads them, are the slabs gathered (tests/mpi/test_mpi_generation.cpp:
    // the serial generator's bits on uneven slabs). Rank 0 once made them with the serial generator instead,
    // when a gathered surface's Persson mean gap was 0.8 % off on 3 ranks: the cause was Persson's sum over
    // modes of equal |q| (theories/persson_gap.cpp), not the surface.
    add_gather(surface);
    return surface;
  }

  std::optional<ResidentSurface> read_resident_surface(const FileSurfaceSpec& file,
                                                       int threads) const override {
    // Opened and its header checked here, before the other ranks are called: a file that cannot be read in
    // slabs (its format or options: core/topography_rows.hpp) is read whole by the caller, as before.
    const std::unique_ptr<TopographyRowReader> reader =
        TopographyRowReader::open(file.path, read_options(file, threads));
    if (!reader) return std::nullopt;
    announce(Job::read_surface);
    ResidentSurface surface = read_surface_job(reader.get());
    // What make_surface checks of a file's heights (core/spectrum.hpp, check_summable_heights), from the
    // slabs' extremes; the sizes were checked with the header.
    if (const Real range = surface.max_height - surface.min_height; !within_magnitudes(range))
      throw InputError(file.path, 0,
                       "spectral moments: " + magnitude_problem("the heights' range", range, "m") +
                           ": rescale the heights (e.g. to micrometres given in metres)");
    add_gather(surface);
    return surface;
  }

  SolvedLoads solve_loads(const BemStage& stage, const StageSurface& solved, Real estar,
                          const std::vector<Real>& mean_pressures, const std::set<int>& connectivities,
                          const std::string& fields, const StageContext& context) const override {
    if (const std::string refusal = bem_refusal(stage); !refusal.empty()) throw Error(refusal);
    const RunObserver quiet;
    const RunObserver& observer = context.observer ? *context.observer : quiet;
    const std::optional<std::size_t> measured = stage.distributions_solve(mean_pressures, estar);
    const Index measured_load = measured ? static_cast<Index>(*measured) : -1;
    BemRequest request{.grid = solved.grid,
                       .estar = estar,
                       .settings = stage.settings,
                       .hardness = stage.hardness,
                       .threads = context.threads,
                       .resident = solved.whole == nullptr,
                       .refined = solved.refined_slabs,
                       .root_surface_bytes = static_cast<double>(solved.root_bytes),
                       .write_fields = !fields.empty(),
                       .measured_load = measured_load,
                       .distribution_bins = stage.distributions ? stage.distributions->bins : 0,
                       .mean_pressures = mean_pressures,
                       .connectivities = {connectivities.begin(), connectivities.end()}};
    // A progress line per load as one process says it (app/serial_runner.cpp: the grid solved), from rank 0.
    const Grid shown = stage.settings.mirrored.value_or(false) ? mirrored_grid(solved.grid) : solved.grid;
    const auto start = Clock::now();
    const auto load_solved = [&](std::size_t k, const ContactSolution& solution) {
      observer.solved(bem_load_progress(stage.name(), shown.nx, shown.ny, k, mean_pressures.size(),
                                        mean_pressures[k] / estar,
                                        static_cast<long long>(solution.iterations), solution.seconds,
                                        std::chrono::duration<double>(Clock::now() - start).count()));
    };
    announce(Job::bem);
    return bem_job(
        request, solved.whole ? &solved.whole->heights() : nullptr, fields,
        [&](const std::string& text) { observer.warn(text); }, load_solved);
  }

  SweepCurve sweep(const StageSurface& surface, const SweepLevels& levels, const Topology& topology,
                   int) const override {
    announce(Job::sweep);
    return sweep_job(surface.grid, surface.whole ? &surface.whole->heights() : nullptr, surface.refined_slabs,
                     levels, topology);
  }

  bool refine_on_slabs(const Surface& surface, Index nx, Index ny, int threads) const override {
    announce(Job::refine);
    refine_job(&surface, nx, ny, threads);
    return true;
  }

 private:
  // How rank 0 reads the resident slabs whole (gathered) and their mean gaps below a level.
  static void add_gather(ResidentSurface& surface) {
    const Grid grid = surface.grid;
    surface.gather = [grid] {
      announce(Job::gather_surface);
      return Surface(grid, gather_surface_job());
    };
    surface.mean_gaps = [](const std::vector<Real>& levels) {
      announce(Job::mean_gaps);
      return mean_gaps_job(levels);
    };
  }

  int ranks_here_ = 1;
};

}  // namespace

int run_as_mpi_ranks(int& argc, char**& argv, const std::function<int(const StageRunner&)>& command) {
  mpi::Environment environment(argc, argv);
  const int ranks_here = mpi::ranks_sharing_memory(kWorld);
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
  resident_slab().reset();
  refined_slab().reset();
  return status;
}

}  // namespace contactbench
