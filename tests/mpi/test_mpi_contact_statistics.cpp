// Contact statistics of a distributed solution against the serial ones (bem/contact_statistics.hpp): the
// areas and spot counts exactly, whatever the slabs, both connectivities, with and without wrap-around.
#include <gtest/gtest.h>

#include "contactbench/bem/contact_statistics.hpp"
#include "contactbench/core/generation.hpp"
#include "contactbench/core/spectrum.hpp"
#include "contactbench/mpi/distributed_bem_solver.hpp"
#include "contactbench/mpi/distributed_contact_statistics.hpp"
#include "mpi_fixtures.hpp"

namespace contactbench::mpi {
namespace {

// The mean gap is a sum in another order (1e-15 relative, 1e-12 with room); counts and areas are exact.
constexpr double kSumTolerance = 1e-12;

void expect_same_statistics(const Grid& grid, const HeightMap& pressure, const HeightMap& gap) {
  const Slab slab = slab_of(grid, MPI_COMM_WORLD);
  for (const Connectivity connectivity : {Connectivity::four, Connectivity::eight})
    for (const bool wrap : {false, true}) {
      const Topology topology{connectivity, wrap, wrap};
      const ContactStatistics d = distributed_contact_statistics(
          grid, testing::rows_of(pressure, slab), testing::rows_of(gap, slab), topology, MPI_COMM_WORLD);
      ContactSolution serial;
      serial.pressure = pressure;
      serial.gap = gap;
      serial.contact_points = (pressure > 0).count();
      Labeller labeller(topology);
      const ContactStatistics s = contact_statistics(serial, labeller);
      const std::string what =
          std::to_string(grid.nx) + " x " + std::to_string(grid.ny) + ", " + describe(topology);
      EXPECT_EQ(d.spots, s.spots) << what;
      EXPECT_EQ(d.area_fraction, s.area_fraction) << what;
      EXPECT_EQ(d.area_fraction_corrected, s.area_fraction_corrected) << what;
      EXPECT_NEAR(d.mean_gap, s.mean_gap, kSumTolerance * std::abs(s.mean_gap) + 1e-300) << what;
      EXPECT_EQ(d.max_pressure, s.max_pressure) << what;
    }
}

TEST(DistributedContactStatistics, EqualTheSerialOnesOnRandomMapsCrossingEverySlabBorder) {
  // About 40 % of the nodes in contact, in many spots that cross the slab borders and the seams.
  for (const auto& [nx, ny] : {std::pair<Index, Index>{23, 17}, {16, 2}, {9, 31}}) {
    const Grid grid{.nx = nx, .ny = ny, .lx = 1e-4, .ly = 1e-4, .periodic = true};
    const HeightMap field = testing::test_field(nx, ny, 21);
    const HeightMap pressure = (field > 1.6).select(field, 0.0);
    const HeightMap gap = (field > 1.6).select(0.0, field - 1.0);
    expect_same_statistics(grid, pressure, gap);
  }
}

TEST(DistributedContactStatistics, CountASpotThatWrapsAroundAsOne) {
  // One band along y through every slab and across the seam, and a ring of points around the x seam.
  const Grid grid{.nx = 12, .ny = 10, .lx = 1e-4, .ly = 1e-4, .periodic = true};
  HeightMap pressure = HeightMap::Zero(10, 12);
  pressure.col(4).setConstant(1.0);
  pressure(3, 0) = pressure(3, 11) = 2.0;
  expect_same_statistics(grid, pressure, HeightMap::Constant(10, 12, 1e-7));
}

TEST(DistributedContactStatistics, EqualTheSerialOnesOnASolvedContact) {
  const Surface surface = generate_surface({.nx = 48, .ny = 40, .lx = 1e-4, .ly = 1e-4, .periodic = true},
                                           {.sigma = 1e-6, .hurst = 0.7, .qr = 1e5, .qs = std::nullopt}, 6);
  BemSolverOptions options;
  options.tolerance = 1e-8;
  const Slab slab = slab_of(surface.grid(), MPI_COMM_WORLD);
  DistributedBemSolver solver(surface.grid(), testing::rows_of(surface.heights(), slab), 1e11, MPI_COMM_WORLD,
                              options);
  const DistributedContactSolution& d = solver.solve(0.03 * 1e11 * spectral_moments(surface).rms_gradient());
  // Every rank needs the whole fields for the serial reference: gathered, then broadcast (tests only).
  HeightMap pressure = gather_to_root(d.pressure, slab, MPI_COMM_WORLD);
  HeightMap gap = gather_to_root(d.gap, slab, MPI_COMM_WORLD);
  pressure.resize(surface.grid().ny, surface.grid().nx);
  gap.resize(surface.grid().ny, surface.grid().nx);
  MPI_Bcast(pressure.data(), static_cast<int>(pressure.size()), MPI_DOUBLE, 0, MPI_COMM_WORLD);
  MPI_Bcast(gap.data(), static_cast<int>(gap.size()), MPI_DOUBLE, 0, MPI_COMM_WORLD);
  EXPECT_GT((pressure > 0).count(), 20);
  expect_same_statistics(surface.grid(), pressure, gap);
}

}  // namespace
}  // namespace contactbench::mpi
