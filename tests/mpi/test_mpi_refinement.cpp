// Fourier refinement on slabs against the serial refinement (mpi/distributed_refinement.hpp,
// core/generation.hpp refine).
#include <gtest/gtest.h>

#include "contactbench/core/error.hpp"
#include "contactbench/core/generation.hpp"
#include "contactbench/mpi/distributed_refinement.hpp"
#include "mpi_fixtures.hpp"

namespace contactbench::mpi {
namespace {

// Every rank makes the same coarse surface (the serial generator); rank 0 passes it. The refined slabs,
// gathered on rank 0, must be the serial refinement's bits: the distributed path is only worth having if a
// scene's answers do not depend on the number of ranks.
void expect_bit_identical(const Grid& grid, std::uint64_t seed, Index nx, Index ny) {
  const Surface coarse =
      generate_surface(grid, {.sigma = 1e-6, .hurst = 0.7, .qr = 1e5, .qs = std::nullopt}, seed);
  const bool root = rank_of(MPI_COMM_WORLD) == 0;
  const RefinedSlab refined =
      refine_surface_slab(root ? &coarse : nullptr, root ? nx : 0, root ? ny : 0, 1, MPI_COMM_WORLD);
  const HeightMap& local = refined.local;
  EXPECT_EQ(refined.grid.nx, nx);  // on every rank, though only rank 0 passed the sizes
  EXPECT_EQ(refined.grid.ny, ny);
  EXPECT_EQ(refined.grid.lx, grid.lx);
  EXPECT_EQ(refined.grid.ly, grid.ly);
  EXPECT_TRUE(refined.grid.periodic);
  const Slab slab = slab_of(nx, ny, MPI_COMM_WORLD);
  ASSERT_EQ(local.rows(), slab.count);
  ASSERT_EQ(local.cols(), nx);
  const HeightMap whole = gather_to_root(local, slab, MPI_COMM_WORLD);
  if (root) {
    const Surface serial = refine(coarse, nx, ny, 1);
    EXPECT_TRUE((whole == serial.heights()).all())  // bit for bit, not approximately
        << grid.nx << " x " << grid.ny << " to " << nx << " x " << ny << ", max difference "
        << (whole - serial.heights()).abs().maxCoeff();
  }
}

TEST(DistributedRefinement, IsBitIdenticalToTheSerialRefinement) {
  // Both Nyquist modes split (even sizes, finer in both directions); 33 coarse columns of 65 finer ones.
  expect_bit_identical({.nx = 64, .ny = 64, .lx = 1e-4, .ly = 1e-4, .periodic = true}, 1, 128, 128);
  // Finer in y only: the Nyquist column stays one mode, the Nyquist row splits.
  expect_bit_identical({.nx = 48, .ny = 40, .lx = 1e-4, .ly = 8e-5, .periodic = true}, 2, 48, 96);
  // Odd coarse ny (no Nyquist row), sizes no multiple of the ranks or of the 16-column chunks.
  expect_bit_identical({.nx = 50, .ny = 37, .lx = 2e-4, .ly = 1e-4, .periodic = true}, 3, 130, 67);
  // 5 rows refined to 11: some ranks own no row; 13 coarse columns of 26, one chunk and a part.
  expect_bit_identical({.nx = 24, .ny = 5, .lx = 1e-4, .ly = 2e-5, .periodic = true}, 4, 50, 11);
  // The same size: a copy through the spectrum (round-off of a transform pair, as the serial one).
  expect_bit_identical({.nx = 32, .ny = 32, .lx = 1e-4, .ly = 1e-4, .periodic = true}, 5, 32, 32);
}

// What the serial refinement refuses, refused on every rank (no rank left waiting in a collective call).
TEST(DistributedRefinement, RefusesWhatTheSerialRefinementRefusesOnEveryRank) {
  const Surface coarse = generate_surface({.nx = 32, .ny = 32, .lx = 1e-4, .ly = 1e-4, .periodic = true},
                                          {.sigma = 1e-6, .hurst = 0.7, .qr = 1e5, .qs = std::nullopt}, 6);
  const bool root = rank_of(MPI_COMM_WORLD) == 0;
  EXPECT_THROW(refine_surface_slab(root ? &coarse : nullptr, 16, 64, 1, MPI_COMM_WORLD), Error);
  const Surface open = coarse.with_periodic(false);
  EXPECT_THROW(refine_surface_slab(root ? &open : nullptr, 64, 64, 1, MPI_COMM_WORLD), Error);
  EXPECT_THROW(refine_surface_slab(nullptr, 64, 64, 1, MPI_COMM_WORLD), Error);  // rank 0 without a surface
}

}  // namespace
}  // namespace contactbench::mpi
