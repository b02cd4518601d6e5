// The distributed solver's cost (docs/mpi.md): seconds per iteration, bytes per rank and the time of
// FFTW-MPI's global transposes, with the serial solver of the same problem as the reference in the same run
// (on rank 0, the other ranks waiting). Its own timing loop, not Google Benchmark's: Google Benchmark chooses
// its iteration counts per process, which would let the ranks disagree on how many collective calls to make.
// Every solve runs a fixed number of iterations (a tolerance no solve reaches), from a cold start, and the
// median of the repetitions is reported.
//
//   mpiexec -n RANKS bench_mpi --n 2048 [--iterations 10] [--repetitions 3] [--threads 1]
//                              [--solver polonsky_keer|preconditioned_cg|active_set] [--no-serial]
// prints one Markdown table row (rank 0): ranks, threads, n, solver, s/iteration, serial s/iteration, ratio,
// transposes s/iteration, their share, MiB per rank (largest), serial MiB.
//
//   mpiexec -n RANKS bench_mpi --n 1024 --tolerance 1e-8 [--reference active_set] [--reference-threads 2] ...
// solves to the tolerance instead (the time a load costs, iterations as they come) and prints: ranks,
// threads, n, solver, iterations, s/load, the serial reference's solver, threads, iterations and s/load, the
// ratio of the two times, and the time rank 0 spent inside MPI's all-to-all exchanges during the solve (the
// global transposes, timed inside it: mpi_call_clock.hpp) and inside its reductions, each with its share.
// The reference runs on rank 0 while the others wait without spinning (quiet_barrier), so that a reference
// on 2 threads has both cores. --no-serial leaves the reference out (a grid rank 0 cannot hold whole).
//
//   mpiexec -n RANKS bench_mpi --n 4096 --solver active_set --memory [--iterations 10]
// the memory a rank holds for one cold load (docs/mpi.md "Memory a point"): for each rank, its slab's
// points, the preflight estimate (DistributedBemSolver::estimated_bytes), what the solver says it held
// (bytes()) and the resident memory the solve added (the kernel's peak, VmHWM, reset after the surface was
// generated, less the resident memory then), each also in bytes a point of the slab.
//   mpiexec -n RANKS bench_mpi --n 16384 --solver active_set --estimate
// the preflight estimate a rank alone, nothing allocated.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <fftw3-mpi.h>

#include "contactbench/bem/bem_solver.hpp"
#include "contactbench/bem/solver_registry.hpp"
#include "contactbench/core/generation.hpp"
#include "contactbench/core/spectrum.hpp"
#include "contactbench/mpi/distributed_bem_solver.hpp"
#include "contactbench/mpi/distributed_generation.hpp"
#include "contactbench/mpi/environment.hpp"
#include "mpi_call_clock.hpp"

using namespace contactbench;

namespace {

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// One global transpose of the half spectrum (ny x (nx/2 + 1) complex values), as FFTW-MPI's transposed-out
// r2c does once per direction: its median time [s].
double transpose_seconds(Index nx, Index ny, int repetitions, MPI_Comm comm) {
  const Index nxh = nx / 2 + 1;
  ptrdiff_t rows = 0, row_start = 0, columns = 0, column_start = 0;
  const ptrdiff_t values =
      fftw_mpi_local_size_2d_transposed(ny, nxh, comm, &rows, &row_start, &columns, &column_start);
  fftw_complex* data = fftw_alloc_complex(static_cast<std::size_t>(std::max<ptrdiff_t>(values, 1)));
  std::memset(static_cast<void*>(data), 0, sizeof(fftw_complex) * static_cast<std::size_t>(values));
  auto* real = reinterpret_cast<double*>(data);
  fftw_plan plan = fftw_mpi_plan_many_transpose(ny, nxh, 2, FFTW_MPI_DEFAULT_BLOCK, FFTW_MPI_DEFAULT_BLOCK,
                                                real, real, comm, FFTW_ESTIMATE);
  std::vector<double> times;
  for (int r = 0; r < repetitions; ++r) {
    MPI_Barrier(comm);
    const auto start = std::chrono::steady_clock::now();
    fftw_execute(plan);
    MPI_Barrier(comm);
    times.push_back(seconds_since(start));
  }
  fftw_destroy_plan(plan);
  fftw_free(data);
  return median(times);
}

// A line of /proc/self/status in bytes ("VmHWM", "VmRSS"), 0 when absent.
double status_bytes(const std::string& key) {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind(key + ":", 0) == 0) return 1024.0 * std::stod(line.substr(key.size() + 1));
  return 0;
}

// --memory: one cold load (`options`: a few iterations) and what each rank held; rank 0 prints a row a rank.
void memory_rows(const Grid& grid, const HeightMap& local, Real modulus, Real load,
                 const BemSolverOptions& options, int threads, MPI_Comm comm) {
  const mpi::Slab slab = mpi::slab_of(grid, comm);
  const double estimate =
      static_cast<double>(mpi::DistributedBemSolver::estimated_bytes(grid, slab.points(), options));
  { std::ofstream("/proc/self/clear_refs") << "5"; }  // the peak from here (Linux >= 4.0)
  const double before = status_bytes("VmRSS");
  double held = 0;
  {
    mpi::DistributedBemSolver solver(grid, local, modulus, comm, options, threads);
    solver.solve(load);
    held = static_cast<double>(solver.bytes());
  }
  const double added = status_bytes("VmHWM") - before;
  const double points = static_cast<double>(std::max<Index>(slab.points(), 1));
  const double mine[5] = {points, estimate, held, added, before};
  std::vector<double> all(5 * static_cast<std::size_t>(mpi::size_of(comm)));
  MPI_Gather(mine, 5, MPI_DOUBLE, all.data(), 5, MPI_DOUBLE, 0, comm);
  if (mpi::rank_of(comm) != 0) return;
  const double mib = 1 << 20;
  for (int r = 0; r < mpi::size_of(comm); ++r) {
    const double* v = all.data() + 5 * r;
    std::printf(
        "| %d | %ld | %s | %d | %.0f | %.0f MiB (%.0f B) | %.0f MiB (%.0f B) | %.0f MiB (%.0f B) | %.0f MiB "
        "|\n",
        mpi::size_of(comm), static_cast<long>(grid.nx), std::string(solver_name(options.solver)).c_str(), r,
        v[0], v[1] / mib, v[1] / v[0], v[2] / mib, v[2] / v[0], v[3] / mib, v[3] / v[0], v[4] / mib);
  }
}

// A barrier that sleeps while it waits (MPI_Barrier polls, taking a core from a reference timed meanwhile).
void quiet_barrier(MPI_Comm comm) {
  MPI_Request request;
  MPI_Ibarrier(comm, &request);
  for (int done = 0; MPI_Test(&request, &done, MPI_STATUS_IGNORE), !done;)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
}

struct TimedSolves {
  double seconds = 0;  // the median over the repetitions, of one load
  Index iterations = 0;
  bench::MpiCallTimes in_mpi;  // this rank's time inside MPI calls, of the repetition with the median time
};

// --tolerance: each solve to the tolerance, the distributed one against the serial `reference` on
// `reference_threads` threads (rank 0); prints one row.
void per_load_row(const Grid& grid, const HeightMap& local, const Surface* surface, Real modulus, Real load,
                  const BemSolverOptions& options, int threads, SolverKind reference, int reference_threads,
                  int repetitions, MPI_Comm comm) {
  const int rank = mpi::rank_of(comm);
  TimedSolves distributed, serial;
  std::vector<double> times;
  std::vector<bench::MpiCallTimes> in_mpi;
  for (int r = 0; r < repetitions; ++r) {
    mpi::DistributedBemSolver solver(grid, local, modulus, comm, options, threads);
    MPI_Barrier(comm);
    bench::reset_mpi_call_times();
    const auto start = std::chrono::steady_clock::now();
    distributed.iterations = solver.solve(load).iterations;
    in_mpi.push_back(bench::mpi_call_times());
    MPI_Barrier(comm);
    times.push_back(seconds_since(start));
  }
  distributed.seconds = median(times);
  const auto median_repetition = std::find(times.begin(), times.end(), distributed.seconds) - times.begin();
  distributed.in_mpi = in_mpi[static_cast<std::size_t>(median_repetition)];
  char in_mpi_columns[96];
  std::snprintf(
      in_mpi_columns, sizeof in_mpi_columns, "%.3g | %.0f %% | %.3g | %.0f %%",
      distributed.in_mpi.exchange_seconds, 100 * distributed.in_mpi.exchange_seconds / distributed.seconds,
      distributed.in_mpi.reduction_seconds, 100 * distributed.in_mpi.reduction_seconds / distributed.seconds);
  if (rank == 0 && !surface) {
    std::printf("| %d | %d | %ld | %s | %ld | %.3g | - | - | - | - | - | %s |\n", mpi::size_of(comm), threads,
                static_cast<long>(grid.nx), std::string(solver_name(options.solver)).c_str(),
                static_cast<long>(distributed.iterations), distributed.seconds, in_mpi_columns);
  } else if (rank == 0) {
    BemSolverOptions reference_options = options;
    reference_options.solver = reference;
    times.clear();
    for (int r = 0; r < repetitions; ++r) {
      BemSolver solver(*surface, modulus, reference_options, reference_threads);
      const auto start = std::chrono::steady_clock::now();
      serial.iterations = solver.solve(load).iterations;
      times.push_back(seconds_since(start));
    }
    serial.seconds = median(times);
    std::printf("| %d | %d | %ld | %s | %ld | %.3g | %s | %d | %ld | %.3g | %.3g | %s |\n",
                mpi::size_of(comm), threads, static_cast<long>(grid.nx),
                std::string(solver_name(options.solver)).c_str(), static_cast<long>(distributed.iterations),
                distributed.seconds, std::string(solver_name(reference)).c_str(), reference_threads,
                static_cast<long>(serial.iterations), serial.seconds, distributed.seconds / serial.seconds,
                in_mpi_columns);
  }
  quiet_barrier(comm);
}

}  // namespace

int main(int argc, char** argv) {
  mpi::Environment environment(argc, argv);
  Index n = 1024;
  int iterations = 10, repetitions = 3, threads = 1;
  bool serial = true, memory = false, estimate = false, periodic = true;
  SolverKind solver = SolverKind::polonsky_keer;
  double tolerance = 0;  // 0: a fixed number of iterations
  SolverKind reference = SolverKind::active_set;
  int reference_threads = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&] { return i + 1 < argc ? std::string(argv[++i]) : std::string(); };
    if (arg == "--n")
      n = std::stol(value());
    else if (arg == "--iterations")
      iterations = std::stoi(value());
    else if (arg == "--repetitions")
      repetitions = std::stoi(value());
    else if (arg == "--threads")
      threads = std::stoi(value());
    else if (arg == "--solver")
      solver = solver_kind(value(), "--solver");
    else if (arg == "--no-serial")
      serial = false;
    else if (arg == "--non-periodic")
      periodic = false;
    else if (arg == "--memory")
      memory = true;
    else if (arg == "--estimate")
      estimate = true;
    else if (arg == "--tolerance")
      tolerance = std::stod(value());
    else if (arg == "--reference")
      reference = solver_kind(value(), "--reference");
    else if (arg == "--reference-threads")
      reference_threads = std::stoi(value());
    else {
      std::fprintf(stderr, "bench_mpi: unknown argument %s (see bench/bench_mpi.cpp)\n", arg.c_str());
      return 2;
    }
  }
  const MPI_Comm comm = MPI_COMM_WORLD;
  const int rank = mpi::rank_of(comm), ranks = mpi::size_of(comm);
  // Surface A's spectrum (docs/theory.md section 2) on n x n points over 200 um, periodic (or solved as a
  // non-periodic patch: --non-periodic).
  const Grid grid{.nx = n, .ny = n, .lx = 200e-6, .ly = 200e-6, .periodic = periodic};
  const SelfAffinePsd psd{.sigma = 0.5e-6, .hurst = 0.5, .qr = 3.14e4, .qs = std::nullopt};
  if (estimate) {
    BemSolverOptions options;
    options.solver = solver;
    const Index points = mpi::slab_of(grid, comm).points();
    const double bytes =
        static_cast<double>(mpi::DistributedBemSolver::estimated_bytes(grid, points, options));
    if (rank == 0)
      std::printf(
          "%d ranks, %ld^2, %s: rank 0's slab %ld points, preflight estimate %.2f GiB a rank (%.1f B a "
          "point)\n",
          ranks, static_cast<long>(n), std::string(solver_name(solver)).c_str(), static_cast<long>(points),
          bytes / (1 << 30), bytes / static_cast<double>(points));
    return 0;
  }
  const HeightMap local = mpi::generate_surface_slab(grid, psd, 1, comm);
  const Real modulus = 1.1e11;
  const Real load = 0.02 * modulus * mpi::distributed_spectral_moments(grid, local, comm).rms_gradient();
  BemSolverOptions options;
  options.solver = solver;
  options.tolerance = 1e-300;  // never reached: every solve runs `iterations` iterations
  options.max_iterations = iterations;
  if (memory) {
    memory_rows(grid, local, modulus, load, options, threads, comm);
    return 0;
  }
  if (tolerance > 0) {
    options.tolerance = tolerance;
    options.max_iterations = BemSolverOptions{}.max_iterations;
    std::optional<Surface> surface;  // rank 0's, for the reference
    if (rank == 0 && serial) surface = generate_surface(grid, psd, 1, reference_threads);
    per_load_row(grid, local, surface ? &*surface : nullptr, modulus, load, options, threads, reference,
                 reference_threads, repetitions, comm);
    return 0;
  }

  std::vector<double> times;
  std::size_t bytes = 0;
  for (int r = 0; r < repetitions; ++r) {
    mpi::DistributedBemSolver distributed(grid, local, modulus, comm, options, threads);
    MPI_Barrier(comm);
    const auto start = std::chrono::steady_clock::now();
    const auto& solution = distributed.solve(load);
    MPI_Barrier(comm);
    times.push_back(seconds_since(start) / static_cast<double>(solution.iterations));
    bytes = std::max(bytes, distributed.bytes());
  }
  unsigned long long largest = bytes;
  MPI_Allreduce(MPI_IN_PLACE, &largest, 1, MPI_UNSIGNED_LONG_LONG, MPI_MAX, comm);
  // Transposes an iteration: two applications of G (plain) or three (with the filter), each two transforms.
  const int transforms = 2 * (solver == SolverKind::preconditioned_cg ? 3 : 2);
  const double transposes = transforms * transpose_seconds(n, n, std::max(repetitions, 5), comm);

  double serial_time = 0, serial_mib = 0;
  if (serial && rank == 0) {
    const Surface surface = generate_surface(grid, psd, 1, threads);
    std::vector<double> serial_times;
    for (int r = 0; r < repetitions; ++r) {
      BemSolver reference(surface, modulus, options, threads);
      const auto start = std::chrono::steady_clock::now();
      const auto& solution = reference.solve(load);
      serial_times.push_back(seconds_since(start) / static_cast<double>(solution.iterations));
    }
    serial_time = median(serial_times);
    // The serial solver's arrays: heights, gap, direction, two pressures (+ the filtered residual), 8 B each,
    // and its transform's work (about 8 B per point): an estimate, for comparison only.
    serial_mib = static_cast<double>(grid.points()) * 8 * (solver == SolverKind::preconditioned_cg ? 7 : 6) /
                 (1 << 20);
  }
  MPI_Barrier(comm);
  if (rank == 0) {
    const double t = median(times);
    auto number = [&](double value) {
      char text[32];
      std::snprintf(text, sizeof text, "%.3g", value);
      return serial ? std::string(text) : std::string("-");
    };
    std::printf("| %d | %d | %ld | %s | %.3g | %s | %s | %.3g | %.0f %% | %.0f | %s |\n", ranks, threads,
                static_cast<long>(n), std::string(solver_name(solver)).c_str(), t,
                number(serial_time).c_str(), number(t / serial_time).c_str(), transposes,
                100 * transposes / t, static_cast<double>(largest) / (1 << 20), number(serial_mib).c_str());
  }
  return 0;
}
