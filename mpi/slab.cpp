#include "contactbench/mpi/slab.hpp"

#include <climits>
#include <string>

#include <fftw3-mpi.h>

#include "contactbench/core/error.hpp"

namespace contactbench::mpi {

int rank_of(MPI_Comm comm) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  return rank;
}

int size_of(MPI_Comm comm) {
  int size = 1;
  MPI_Comm_size(comm, &size);
  return size;
}

int ranks_sharing_memory(MPI_Comm comm) {
  MPI_Comm machine = MPI_COMM_NULL;
  MPI_Comm_split_type(comm, MPI_COMM_TYPE_SHARED, rank_of(comm), MPI_INFO_NULL, &machine);
  const int size = size_of(machine);
  MPI_Comm_free(&machine);
  return size;
}

Slab slab_of(Index nx, Index ny, MPI_Comm comm) {
  if (nx < 1 || ny < 1)
    throw Error("mpi: a slab needs a grid of at least 1 x 1 points, got " + std::to_string(nx) + " x " +
                std::to_string(ny));
  ptrdiff_t local_rows = 0, local_start = 0;
  // The half spectrum's row split is the real array's (FFTW-MPI's r2c convention).
  fftw_mpi_local_size_2d(ny, nx / 2 + 1, comm, &local_rows, &local_start);
  // FFTW gives an empty rank start 0; here it starts after the last row, so that slabs stay in rank order.
  if (local_rows == 0) local_start = ny;
  return Slab{.nx = nx, .ny = ny, .start = local_start, .count = local_rows};
}

std::vector<Slab> all_slabs(Index nx, Index ny, MPI_Comm comm) {
  const Slab mine = slab_of(nx, ny, comm);
  const int ranks = size_of(comm);
  std::vector<long long> starts(static_cast<std::size_t>(ranks)), counts(static_cast<std::size_t>(ranks));
  const long long start = mine.start, count = mine.count;
  MPI_Allgather(&start, 1, MPI_LONG_LONG, starts.data(), 1, MPI_LONG_LONG, comm);
  MPI_Allgather(&count, 1, MPI_LONG_LONG, counts.data(), 1, MPI_LONG_LONG, comm);
  std::vector<Slab> slabs;
  for (int r = 0; r < ranks; ++r)
    slabs.push_back(Slab{.nx = nx, .ny = ny, .start = starts[r], .count = counts[r]});
  return slabs;
}

namespace {

// Displacements and counts, in values, of every rank's slab in the whole row-major field.
void slab_offsets(const Slab& slab, MPI_Comm comm, std::vector<int>& counts, std::vector<int>& offsets) {
  const auto slabs = all_slabs(slab.nx, slab.ny, comm);
  counts.clear();
  offsets.clear();
  for (const Slab& s : slabs) {
    if (s.start * s.nx > INT_MAX || s.points() > INT_MAX)
      throw Error("mpi: gather/scatter of more than 2^31 values per field is not supported (files only)");
    counts.push_back(static_cast<int>(s.points()));
    offsets.push_back(static_cast<int>(s.start * s.nx));
  }
}

void check_local(const HeightMap& local, const Slab& slab, const char* what, MPI_Comm comm) {
  throw_on_any_rank(local.rows() != slab.count || local.cols() != slab.nx,
                    std::string("mpi: ") + what + ": the local array is " + std::to_string(local.cols()) +
                        " x " + std::to_string(local.rows()) + " but the slab is " + std::to_string(slab.nx) +
                        " x " + std::to_string(slab.count),
                    comm);
}

}  // namespace

HeightMap gather_to_root(const HeightMap& local, const Slab& slab, MPI_Comm comm) {
  check_local(local, slab, "gather_to_root", comm);
  std::vector<int> counts, offsets;
  slab_offsets(slab, comm, counts, offsets);
  HeightMap whole;
  if (rank_of(comm) == 0) whole.resize(slab.ny, slab.nx);
  MPI_Gatherv(local.data(), static_cast<int>(slab.points()), MPI_DOUBLE, whole.data(), counts.data(),
              offsets.data(), MPI_DOUBLE, 0, comm);
  return whole;
}

HeightMap scatter_from_root(const HeightMap& whole, const Slab& slab, MPI_Comm comm) {
  throw_on_any_rank(rank_of(comm) == 0 && (whole.rows() != slab.ny || whole.cols() != slab.nx),
                    "mpi: scatter_from_root: the field on rank 0 is " + std::to_string(whole.cols()) + " x " +
                        std::to_string(whole.rows()) + " but the grid is " + std::to_string(slab.nx) + " x " +
                        std::to_string(slab.ny),
                    comm);
  std::vector<int> counts, offsets;
  slab_offsets(slab, comm, counts, offsets);
  HeightMap local(slab.count, slab.nx);
  MPI_Scatterv(whole.data(), counts.data(), offsets.data(), MPI_DOUBLE, local.data(),
               static_cast<int>(slab.points()), MPI_DOUBLE, 0, comm);
  return local;
}

void throw_on_any_rank(bool failed, const std::string& message, MPI_Comm comm) {
  const int ranks = size_of(comm);
  int first = failed ? rank_of(comm) : ranks;
  MPI_Allreduce(MPI_IN_PLACE, &first, 1, MPI_INT, MPI_MIN, comm);
  if (first == ranks) return;
  // The failing rank's message, to every rank.
  std::string text = failed && rank_of(comm) == first ? message : std::string();
  int length = static_cast<int>(text.size());
  MPI_Bcast(&length, 1, MPI_INT, first, comm);
  text.resize(static_cast<std::size_t>(length));
  MPI_Bcast(text.data(), length, MPI_CHAR, first, comm);
  throw Error(ranks > 1 ? text + " (on rank " + std::to_string(first) + ")" : text);
}

double sum_over_ranks(double value, MPI_Comm comm) {
  double total = 0;
  MPI_Allreduce(&value, &total, 1, MPI_DOUBLE, MPI_SUM, comm);
  return total;
}

}  // namespace contactbench::mpi
