// The nested coarse start's restriction on slabs (mpi/distributed_restriction.hpp) against the serial one
// (bem/solvers/block_average.hpp, what ActiveSet::coarse_heights computes): the same bits, on fine slabs of
// odd row counts whose 2 x 2 blocks straddle two ranks, and on ranks without rows.
#include <gtest/gtest.h>

#include "contactbench/bem/solvers/block_average.hpp"
#include "contactbench/core/error.hpp"
#include "contactbench/mpi/distributed_restriction.hpp"
#include "mpi_fixtures.hpp"

namespace contactbench::mpi {
namespace {

void expect_serial_bits(Index nx, Index ny, std::uint64_t salt) {
  const Grid grid{.nx = nx, .ny = ny, .lx = 1e-4, .ly = 1e-4, .periodic = true};
  const HeightMap whole = testing::test_field(nx, ny, salt);
  const HeightMap local =
      restrict_to_coarse_slab(grid, testing::rows_of(whole, slab_of(grid, MPI_COMM_WORLD)), MPI_COMM_WORLD);
  const Slab coarse = slab_of(nx / 2, ny / 2, MPI_COMM_WORLD);
  ASSERT_EQ(local.rows(), coarse.count);
  ASSERT_EQ(local.cols(), nx / 2);
  const HeightMap gathered = gather_to_root(local, coarse, MPI_COMM_WORLD);
  if (rank_of(MPI_COMM_WORLD) != 0) return;
  const std::vector<double> serial = block_averages(whole.data(), nx, ny / 2);
  const Eigen::Map<const HeightMap> expected(serial.data(), ny / 2, nx / 2);
  EXPECT_TRUE(
      (gathered == expected).all())  // bit for bit: the same sums of the same values in the same order
      << nx << " x " << ny << ", max difference " << (gathered - expected).abs().maxCoeff();
  // And it is the average of a block (the last one, whichever rank held its rows): to a few ulp of 1.
  const double last =
      0.25 * (whole(ny - 2, nx - 2) + whole(ny - 2, nx - 1) + whole(ny - 1, nx - 2) + whole(ny - 1, nx - 1));
  EXPECT_NEAR(gathered(ny / 2 - 1, nx / 2 - 1), last, 1e-15);
}

TEST(DistributedRestriction, IsBitIdenticalToTheSerialCoarseLevel) {
  expect_serial_bits(64, 64, 1);
  // 66 rows: blocks of 33 on 2 ranks, so a 2 x 2 block straddles ranks 0 and 1; 50 rows: blocks of 17 on 3.
  expect_serial_bits(64, 66, 2);
  expect_serial_bits(32, 50, 3);
  // 4 and 2 rows: on 3 ranks some own no fine rows, or no coarse ones.
  expect_serial_bits(16, 4, 4);
  expect_serial_bits(8, 2, 5);
}

TEST(DistributedRestriction, RefusesAnOddGrid) {
  const Grid grid{.nx = 16, .ny = 9, .lx = 1e-4, .ly = 1e-4, .periodic = true};
  const HeightMap local = testing::rows_of(testing::test_field(16, 9, 6), slab_of(grid, MPI_COMM_WORLD));
  EXPECT_THROW(restrict_to_coarse_slab(grid, local, MPI_COMM_WORLD), Error);
}

}  // namespace
}  // namespace contactbench::mpi
