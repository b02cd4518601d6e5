#include "contactbench/mpi/distributed_mirror.hpp"

#include <algorithm>
#include <vector>

#include "contactbench/core/error.hpp"

namespace contactbench::mpi {

namespace {

// The rows of `slab`, each mapped by `row_of`.
std::vector<Index> rows_of(const Slab& slab, Index (*row_of)(Index y, Index ny), Index ny) {
  std::vector<Index> rows;
  rows.reserve(static_cast<std::size_t>(slab.count));
  for (Index y = slab.start; y < slab.start + slab.count; ++y)
    rows.push_back(row_of(y, ny));
  return rows;
}

// The patch row an extension row repeats: the rows of the patch, then the same rows upside down.
Index patch_row_of(Index y, Index ny) {
  return y < ny ? y : 2 * ny - 1 - y;
}

Index same_row(Index y, Index) {
  return y;
}

void check_slab(const Slab& slab, const HeightMap& local, const char* what) {
  if (local.rows() != slab.count || local.cols() != slab.nx)
    throw Error(std::string("internal: mirrored boundary: ") + what + " is " + std::to_string(local.cols()) +
                " x " + std::to_string(local.rows()) + ", not this rank's slab of " +
                std::to_string(slab.nx) + " x " + std::to_string(slab.count));
}

}  // namespace

HeightMap mirrored_slab(Index nx, Index ny, const HeightMap& patch, MPI_Comm comm) {
  const int me = rank_of(comm);
  const std::vector<Slab> patch_layout = all_slabs(nx, ny, comm);
  const std::vector<Slab> extension_layout = all_slabs(2 * nx, 2 * ny, comm);
  check_slab(patch_layout[static_cast<std::size_t>(me)], patch, "the patch's slab");
  RowExchange rows(
      patch_layout, me,
      [&](int r) { return rows_of(extension_layout[static_cast<std::size_t>(r)], patch_row_of, ny); }, comm);
  rows.exchange(patch.data());
  const Slab& mine = extension_layout[static_cast<std::size_t>(me)];
  HeightMap local(mine.count, 2 * nx);
  for (Index k = 0; k < mine.count; ++k) {
    const double* row = rows.row(patch_row_of(mine.start + k, ny));
    double* out = local.data() + k * 2 * nx;
    std::copy_n(row, nx, out);                   // the record's row
    std::reverse_copy(row, row + nx, out + nx);  // and its reflection, left to right
  }
  return local;
}

PatchOfMirrored::PatchOfMirrored(Index nx, Index ny, MPI_Comm comm)
    : patch_(slab_of(nx, ny, comm)),
      extension_(slab_of(2 * nx, 2 * ny, comm)),
      rows_(
          all_slabs(2 * nx, 2 * ny, comm), rank_of(comm),
          [layout = all_slabs(nx, ny, comm), ny](int r) {
            return rows_of(layout[static_cast<std::size_t>(r)], same_row, ny);
          },
          comm) {}

HeightMap PatchOfMirrored::cut(const HeightMap& extension) {
  check_slab(extension_, extension, "a field on the extension");
  rows_.exchange(extension.data());
  HeightMap local(patch_.count, patch_.nx);
  for (Index k = 0; k < patch_.count; ++k)
    std::copy_n(rows_.row(patch_.start + k), patch_.nx, local.data() + k * patch_.nx);
  return local;
}

}  // namespace contactbench::mpi
