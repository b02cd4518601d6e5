// The mirrored boundary on slabs (mpi/distributed_mirror.hpp) against the even extension written out here
// (the four blocks of app/mirrored_boundary.cpp's mirrored_surface): the same bits, on slabs of uneven row
// counts whose extension rows come from two or three ranks, and on ranks without rows; and the patch cut
// back out of a field on the extension's slabs.
#include <gtest/gtest.h>

#include "contactbench/core/error.hpp"
#include "contactbench/mpi/distributed_mirror.hpp"
#include "mpi_fixtures.hpp"

namespace contactbench::mpi {
namespace {

HeightMap even_extension(const HeightMap& h) {
  const Index ny = h.rows(), nx = h.cols();
  HeightMap extended(2 * ny, 2 * nx);
  extended.block(0, 0, ny, nx) = h;
  extended.block(0, nx, ny, nx) = h.rowwise().reverse();
  extended.block(ny, 0, ny, nx) = h.colwise().reverse();
  extended.block(ny, nx, ny, nx) = h.reverse();
  return extended;
}

void expect_extension_and_patch(Index nx, Index ny, std::uint64_t salt) {
  const HeightMap whole = testing::test_field(nx, ny, salt);
  const HeightMap local =
      mirrored_slab(nx, ny, testing::rows_of(whole, slab_of(nx, ny, MPI_COMM_WORLD)), MPI_COMM_WORLD);
  const Slab extension = slab_of(2 * nx, 2 * ny, MPI_COMM_WORLD);
  ASSERT_EQ(local.rows(), extension.count);
  ASSERT_EQ(local.cols(), 2 * nx);
  const HeightMap expected = even_extension(whole);
  EXPECT_TRUE((local == testing::rows_of(expected, extension)).all()) << nx << " x " << ny;

  // The patch of a field on the extension: its first nx x ny block, on the patch's slabs.
  PatchOfMirrored patch(nx, ny, MPI_COMM_WORLD);
  const HeightMap field = testing::test_field(2 * nx, 2 * ny, salt + 100);
  const HeightMap cut = patch.cut(testing::rows_of(field, extension));
  const HeightMap block = field.block(0, 0, ny, nx);
  EXPECT_TRUE((cut == testing::rows_of(block, slab_of(nx, ny, MPI_COMM_WORLD))).all()) << nx << " x " << ny;
  // Made once, cut again: the exchange is reused for every load.
  const HeightMap again = patch.cut(testing::rows_of(expected, extension));
  EXPECT_TRUE((again == testing::rows_of(whole, slab_of(nx, ny, MPI_COMM_WORLD))).all()) << nx << " x " << ny;
}

TEST(DistributedMirror, IsTheEvenExtensionBitForBitAndCutsThePatchBack) {
  expect_extension_and_patch(16, 16, 1);
  // 50 rows: patch slabs of 17/17/16 on 3 ranks, extension slabs of 34/34/32, so an extension slab takes
  // rows of two or three patch slabs, forwards and backwards.
  expect_extension_and_patch(12, 50, 2);
  expect_extension_and_patch(9, 7, 3);
  // 2 rows: on 2 or 3 ranks some own no patch rows.
  expect_extension_and_patch(4, 2, 4);
}

TEST(DistributedMirror, RefusesASlabOfAnotherSize) {
  const HeightMap wrong(1, 3);
  EXPECT_THROW(mirrored_slab(4, 8, wrong, MPI_COMM_WORLD), Error);
}

}  // namespace
}  // namespace contactbench::mpi
