// The k-th largest over the ranks (mpi/distributed_selection.hpp) against std::nth_element on the union, as
// the serial active-set method's cold start takes it (ActiveSet::coarse_area_level).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "contactbench/core/error.hpp"
#include "contactbench/mpi/distributed_selection.hpp"
#include "mpi_fixtures.hpp"

namespace contactbench::mpi {
namespace {

// Every rank's values, known to all: `count` of rank r's, of both signs, with ties (rounded to 1/64) and
// rank 1 holding none when there are several ranks.
std::vector<double> values_of(int rank, Index count) {
  if (rank == 1) return {};
  const HeightMap field = testing::test_field(count, 1, static_cast<std::uint64_t>(rank) * 7919);
  std::vector<double> values;
  for (Index i = 0; i < count; ++i)
    values.push_back(std::round(64 * (field(0, i) - 1.5) * (i % 3 == 0 ? -1e3 : 1e-3)) / 64);
  values.push_back(-0.0);
  values.push_back(0.0);
  return values;
}

TEST(DistributedSelection, FindsWhatNthElementFindsInTheUnion) {
  const int ranks = size_of(MPI_COMM_WORLD), rank = rank_of(MPI_COMM_WORLD);
  const Index count = 97;
  std::vector<double> all;
  for (int r = 0; r < ranks; ++r) {
    const std::vector<double> v = values_of(r, count);
    all.insert(all.end(), v.begin(), v.end());
  }
  const std::vector<double> mine = values_of(rank, count);
  for (const std::size_t k :
       {std::size_t{1}, std::size_t{2}, all.size() / 3, all.size() / 2, all.size() - 1, all.size()}) {
    std::vector<double> sorted = all;
    std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(k - 1), sorted.end(),
                     std::greater<>());
    // Exactly equal as values (0 and -0 compare equal): the selection is of a value, not an approximation.
    EXPECT_EQ(kth_largest_over_ranks(mine, k, MPI_COMM_WORLD), sorted[k - 1]) << "k = " << k;
  }
}

TEST(DistributedSelection, RefusesAMissingRank) {
  const std::vector<double> mine = values_of(rank_of(MPI_COMM_WORLD), 5);
  EXPECT_THROW(kth_largest_over_ranks(mine, 0, MPI_COMM_WORLD), Error);
  EXPECT_THROW(kth_largest_over_ranks(mine, 1000000, MPI_COMM_WORLD), Error);
}

}  // namespace
}  // namespace contactbench::mpi
