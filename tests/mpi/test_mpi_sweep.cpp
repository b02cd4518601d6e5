// The distributed sweep against the serial one (core/sweep.hpp): every level's area and spot count exactly.
#include <gtest/gtest.h>

#include "contactbench/core/error.hpp"
#include "contactbench/core/generation.hpp"
#include "contactbench/core/sweep.hpp"
#include "contactbench/mpi/distributed_sweep.hpp"
#include "mpi_fixtures.hpp"

namespace contactbench::mpi {
namespace {

void expect_same_curve(const Surface& surface, const SweepLevels& levels) {
  const Grid& grid = surface.grid();
  const Slab slab = slab_of(grid, MPI_COMM_WORLD);
  for (const Connectivity connectivity : {Connectivity::four, Connectivity::eight})
    for (const bool wrap : {false, true}) {
      const Topology topology{connectivity, wrap, wrap};
      const SweepCurve d = distributed_sweep(grid, testing::rows_of(surface.heights(), slab), levels,
                                             topology, MPI_COMM_WORLD);
      const SweepCurve s = sweep(surface, levels, topology);
      // Every distinct height: the curve lives on rank 0 only (as many rows as the field has heights).
      if (levels.kind == SweepLevels::Kind::exact && rank_of(MPI_COMM_WORLD) != 0) {
        EXPECT_TRUE(d.z.empty());
        continue;
      }
      const std::string what =
          std::to_string(grid.nx) + " x " + std::to_string(grid.ny) + ", " + describe(topology);
      ASSERT_EQ(d.z.size(), s.z.size()) << what;
      // Uniform levels come from the extremes and exact ones are the heights, exactly as serial; the paper's
      // end at the mean, a sum over the ranks that may differ from the serial mean in the last bits (1e-15 of
      // the height range, 1e-12 with room).
      const Real range = s.z.front() - s.z.back();
      for (std::size_t k = 0; k < s.z.size(); ++k) {
        if (levels.kind != SweepLevels::Kind::paper) {
          EXPECT_EQ(d.z[k], s.z[k]) << what << ", level " << k;
        } else {
          EXPECT_NEAR(d.z[k], s.z[k], 1e-12 * range) << what << ", level " << k;
        }
      }
      EXPECT_EQ(d.points, s.points) << what;
      EXPECT_EQ(d.spots, s.spots) << what;
      EXPECT_EQ(d.area_fraction, s.area_fraction) << what;
    }
}

TEST(DistributedSweep, EqualsTheSerialSweepAtEveryLevel) {
  const SelfAffinePsd psd{.sigma = 1e-6, .hurst = 0.6, .qr = 1e5, .qs = std::nullopt};
  expect_same_curve(generate_surface({.nx = 40, .ny = 37, .lx = 1e-4, .ly = 1e-4, .periodic = true}, psd, 3),
                    SweepLevels::uniform(60));
  expect_same_curve(generate_surface({.nx = 33, .ny = 64, .lx = 1e-4, .ly = 2e-4, .periodic = true}, psd, 9),
                    SweepLevels::paper(50));
}

TEST(DistributedSweep, JoinsSpotsAcrossSlabsOfOneRow) {
  // 3 rows on up to 3 ranks: every slab is a single row, which is both its first and its last.
  const Surface surface(Grid{.nx = 20, .ny = 3, .lx = 1e-4, .ly = 1e-5, .periodic = true},
                        testing::test_field(20, 3, 5));
  expect_same_curve(surface, SweepLevels::uniform(25));
}

TEST(DistributedSweep, EqualsTheSerialSweepAtEveryDistinctHeight) {
  // Every height's row exactly: distinct heights (a generated surface), heights shared within and across
  // slabs (a field rounded to 12 values, so that many levels hold points of several slabs at once), and
  // single-row slabs.
  const SelfAffinePsd psd{.sigma = 1e-6, .hurst = 0.6, .qr = 1e5, .qs = std::nullopt};
  expect_same_curve(generate_surface({.nx = 40, .ny = 37, .lx = 1e-4, .ly = 1e-4, .periodic = true}, psd, 3),
                    SweepLevels::exact());
  const HeightMap rounded = (testing::test_field(31, 29, 7) * 12).floor();
  expect_same_curve(Surface(Grid{.nx = 31, .ny = 29, .lx = 1e-4, .ly = 1e-4, .periodic = true}, rounded),
                    SweepLevels::exact());
  expect_same_curve(Surface(Grid{.nx = 20, .ny = 3, .lx = 1e-4, .ly = 1e-5, .periodic = true},
                            testing::test_field(20, 3, 5)),
                    SweepLevels::exact());
}

}  // namespace
}  // namespace contactbench::mpi
