// The distributed layout, gather/scatter and half-space operators against the serial ones
// (bem/half_space.hpp).
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "contactbench/bem/fourier_preconditioner.hpp"
#include "contactbench/bem/half_space.hpp"
#include "contactbench/core/error.hpp"
#include "contactbench/mpi/distributed_half_space.hpp"
#include "contactbench/mpi/exchange_storage.hpp"
#include "mpi_fixtures.hpp"

namespace contactbench::mpi {
namespace {

using testing::relative_difference;
using testing::rows_of;
using testing::test_field;

// The distributed and serial operators do the same transforms in a different order of operations (FFTW-MPI
// splits the 2D transform into 1D passes around a global transpose; the serial engine uses its own chunked
// passes): each output is the same sum rounded differently, a few ulp times log2(n) per transform, ~1e-15
// relative here; 1e-12 leaves a wide margin and still catches any misplaced row or mode (errors of O(1)).
constexpr double kOperatorTolerance = 1e-12;
constexpr Real kOperatorModulus = 1.1e11;

TEST(Slabs, CoverEveryRowOnceInRankOrder) {
  for (Index ny : {1, 2, 5, 64, 97}) {
    const auto slabs = all_slabs(7, ny, MPI_COMM_WORLD);
    Index next = 0;
    for (const Slab& s : slabs) {
      EXPECT_EQ(s.start, next) << ny;
      EXPECT_GE(s.count, 0);
      next += s.count;
    }
    EXPECT_EQ(next, ny);
    EXPECT_EQ(slab_of(7, ny, MPI_COMM_WORLD).start,
              slabs[static_cast<std::size_t>(rank_of(MPI_COMM_WORLD))].start);
  }
}

TEST(Slabs, ScatterThenGatherGivesBackTheFieldExactly) {
  const Index nx = 13, ny = 29;
  const HeightMap whole = test_field(nx, ny, 3);
  const Slab slab = slab_of(nx, ny, MPI_COMM_WORLD);
  const HeightMap local =
      scatter_from_root(rank_of(MPI_COMM_WORLD) == 0 ? whole : HeightMap(), slab, MPI_COMM_WORLD);
  EXPECT_TRUE((local == rows_of(whole, slab)).all());
  const HeightMap back = gather_to_root(local, slab, MPI_COMM_WORLD);
  if (rank_of(MPI_COMM_WORLD) == 0) {
    EXPECT_TRUE((back == whole).all());
  } else {
    EXPECT_EQ(back.size(), 0);
  }
}

TEST(Slabs, RefuseASlabOfTheWrongShape) {
  const Slab slab = slab_of(8, 8, MPI_COMM_WORLD);
  EXPECT_THROW(gather_to_root(HeightMap(slab.count + 1, 8), slab, MPI_COMM_WORLD), Error);
}

TEST(Slabs, AMistakeOnOneRankStopsEveryRankWithItsMessage) {
  // Only rank 0 passes a wrong slab: every rank must throw (none left waiting in a collective), with rank 0's
  // reason.
  const Slab slab = slab_of(8, 8, MPI_COMM_WORLD);
  const HeightMap local(rank_of(MPI_COMM_WORLD) == 0 ? slab.count + 1 : slab.count, 8);
  try {
    gather_to_root(local, slab, MPI_COMM_WORLD);
    ADD_FAILURE() << "no error on rank " << rank_of(MPI_COMM_WORLD);
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("gather_to_root: the local array is 8 x"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(scatter_from_root(HeightMap(3, 3), slab, MPI_COMM_WORLD), Error);
}

// The distributed operator on this rank's slab, gathered on rank 0, against the serial operator there.
void expect_operator_matches_serial(const Grid& grid) {
  const int rank = rank_of(MPI_COMM_WORLD);
  DistributedHalfSpace distributed(grid, kOperatorModulus, MPI_COMM_WORLD);
  const Slab& slab = distributed.slab();
  const HeightMap pressure = test_field(grid.nx, grid.ny, 11) * 1e6;
  HeightMap local = rows_of(pressure, slab);
  distributed.apply(local.data(), local.data());  // in place, as the solver uses it
  const HeightMap displacement = gather_to_root(local, slab, MPI_COMM_WORLD);
  // Applied twice: the operator keeps no state from one application to the next (the padding is re-zeroed).
  HeightMap again = rows_of(pressure, slab);
  distributed.apply(again.data(), again.data());
  EXPECT_TRUE((again == local).all());
  if (rank == 0) {
    HeightMap serial;
    make_half_space(grid, kOperatorModulus)->apply(pressure, serial);
    EXPECT_LT(relative_difference(displacement, serial), kOperatorTolerance)
        << grid.nx << " x " << grid.ny << (grid.periodic ? " periodic" : " non-periodic");
    const double serial_self = make_half_space_convolution<double>(grid, kOperatorModulus)->self_response();
    EXPECT_NEAR(distributed.self_response(), serial_self, kOperatorTolerance * serial_self);
  }
}

TEST(DistributedHalfSpace, PeriodicEqualsTheSerialOperator) {
  expect_operator_matches_serial({.nx = 64, .ny = 64, .lx = 1e-4, .ly = 1e-4, .periodic = true});
  // Odd and uneven sizes, rectangular pixels: no Nyquist row, slabs of different heights.
  expect_operator_matches_serial({.nx = 45, .ny = 31, .lx = 2e-4, .ly = 1e-4, .periodic = true});
}

TEST(DistributedHalfSpace, NonPeriodicEqualsTheSerialOperator) {
  expect_operator_matches_serial({.nx = 48, .ny = 40, .lx = 1e-4, .ly = 1e-4, .periodic = false});
  expect_operator_matches_serial({.nx = 27, .ny = 35, .lx = 1e-4, .ly = 2e-4, .periodic = false});
}

TEST(DistributedHalfSpace, ARankWithoutRowsStillTakesPart) {
  // 2 rows on up to 3 ranks: FFTW gives blocks of ceil(2 / ranks) rows, so the last rank may own none.
  expect_operator_matches_serial({.nx = 16, .ny = 2, .lx = 1e-4, .ly = 1e-5, .periodic = true});
  expect_operator_matches_serial({.nx = 16, .ny = 2, .lx = 1e-4, .ly = 1e-5, .periodic = false});
  // 2 columns: nx/2 + 1 = 2 spectral columns, so on 3 ranks one rank owns none (the slab engine's column
  // blocks and exchanges with nothing of its own).
  expect_operator_matches_serial({.nx = 2, .ny = 16, .lx = 1e-5, .ly = 1e-4, .periodic = true});
}

// The solver's filter, periodic, in double (the solver's) and on two ranks and more in single precision too
// (the slab engine's float transform). Against the serial float filter on the same input rounded to float:
// float transform pairs computed in different orders differ by a few float ulps times log2 n, ~1e-6 of the
// peak; 1e-5 catches any misplaced row or mode (errors of O(1)).
constexpr double kFloatFilterTolerance = 1e-5;

void expect_filter_matches_serial(const Grid& grid, bool single_precision) {
  const auto distributed =
      make_distributed_unit_preconditioner(grid, MPI_COMM_WORLD, 1, nullptr, single_precision);
  const Slab& slab = distributed->slab();
  const HeightMap residual = test_field(grid.nx, grid.ny, 5) - 1.5;
  HeightMap local = rows_of(residual, slab);
  distributed->apply(local.data(), local.data());
  const HeightMap filtered = gather_to_root(local, slab, MPI_COMM_WORLD);
  if (rank_of(MPI_COMM_WORLD) == 0) {
    const Eigen::Array<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> in = residual.cast<float>();
    Eigen::Array<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> out(grid.ny, grid.nx);
    make_unit_fourier_preconditioner<float>(grid)->apply(in.data(), out.data());
    EXPECT_LT(relative_difference(filtered, out.cast<double>()), kFloatFilterTolerance)
        << grid.nx << " x " << grid.ny << (single_precision ? " in float" : " in double");
  }
}

TEST(DistributedFilter, EqualsTheSerialSinglePrecisionFilter) {
  for (const bool single_precision : {false, true}) {
    expect_filter_matches_serial({.nx = 64, .ny = 64, .lx = 1e-4, .ly = 1e-4, .periodic = true},
                                 single_precision);
    expect_filter_matches_serial({.nx = 45, .ny = 31, .lx = 2e-4, .ly = 1e-4, .periodic = true},
                                 single_precision);
    expect_filter_matches_serial({.nx = 16, .ny = 2, .lx = 1e-4, .ly = 1e-5, .periodic = true},
                                 single_precision);
    expect_filter_matches_serial({.nx = 2, .ny = 16, .lx = 1e-5, .ly = 1e-4, .periodic = true},
                                 single_precision);
    expect_filter_matches_serial({.nx = 24, .ny = 20, .lx = 1e-4, .ly = 1e-4, .periodic = false},
                                 single_precision);
  }
}

// The transport of the slab engine's exchanges chosen for one scope on every rank (kExchangeVariable).
class ExchangeChoice {
 public:
  explicit ExchangeChoice(const char* value) {
    if (const char* before = std::getenv(kExchangeVariable)) before_ = before;
    setenv(kExchangeVariable, value, 1);
  }
  ~ExchangeChoice() {
    if (before_.empty())
      unsetenv(kExchangeVariable);
    else
      setenv(kExchangeVariable, before_.c_str(), 1);
  }
  ExchangeChoice(const ExchangeChoice&) = delete;
  ExchangeChoice& operator=(const ExchangeChoice&) = delete;

 private:
  std::string before_;
};

// The operator, and the float filter sharing its exchange buffers, applied by one transport: gathered on
// rank 0.
std::pair<HeightMap, HeightMap> operator_and_float_filter(const Grid& grid, const char* transport) {
  const ExchangeChoice choice(transport);
  DistributedHalfSpace half_space(grid, kOperatorModulus, MPI_COMM_WORLD);
  const auto filter =
      make_distributed_unit_preconditioner(grid, MPI_COMM_WORLD, 1, &half_space.convolution(), true);
  const Slab& slab = half_space.slab();
  HeightMap displacement = rows_of(test_field(grid.nx, grid.ny, 3), slab);
  HeightMap filtered = displacement;
  half_space.apply(displacement.data(), displacement.data());
  filter->apply(filtered.data(), filtered.data());
  half_space.apply(displacement.data(), displacement.data());  // again, after the filter used the buffers
  return {gather_to_root(displacement, slab, MPI_COMM_WORLD), gather_to_root(filtered, slab, MPI_COMM_WORLD)};
}

// Shared memory and messages move the same values into the same arithmetic: the same bits, periodic and
// padded, a rank without rows or without columns included (on one rank neither runs: the serial engine).
TEST(SlabExchange, SharedMemoryGivesTheBitsOfMessages) {
  for (const Grid& grid : {Grid{.nx = 64, .ny = 64, .lx = 1e-4, .ly = 1e-4, .periodic = true},
                           Grid{.nx = 45, .ny = 31, .lx = 2e-4, .ly = 1e-4, .periodic = true},
                           Grid{.nx = 27, .ny = 35, .lx = 1e-4, .ly = 2e-4, .periodic = false},
                           Grid{.nx = 16, .ny = 2, .lx = 1e-4, .ly = 1e-5, .periodic = true},
                           Grid{.nx = 2, .ny = 16, .lx = 1e-5, .ly = 1e-4, .periodic = false}}) {
    const auto [by_messages, filtered_by_messages] = operator_and_float_filter(grid, "messages");
    const auto [shared, filtered_shared] = operator_and_float_filter(grid, "shared_memory");
    if (rank_of(MPI_COMM_WORLD) == 0) {
      EXPECT_TRUE((by_messages == shared).all()) << grid.nx << " x " << grid.ny;
      EXPECT_TRUE((filtered_by_messages == filtered_shared).all()) << grid.nx << " x " << grid.ny;
    }
  }
}

TEST(SlabExchange, AnUnknownTransportIsRefusedOnEveryRankByName) {
  const ExchangeChoice choice("carrier_pigeon");
  const Grid grid{.nx = 16, .ny = 16, .lx = 1e-4, .ly = 1e-4, .periodic = true};
  if (size_of(MPI_COMM_WORLD) == 1) GTEST_SKIP() << "one rank runs the serial engine: no exchange";
  try {
    DistributedHalfSpace half_space(grid, kOperatorModulus, MPI_COMM_WORLD);
    ADD_FAILURE() << "accepted";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("CONTACTBENCH_MPI_EXCHANGE=carrier_pigeon"), std::string::npos) << message;
    EXPECT_NE(message.find("auto, messages, shared_memory"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace contactbench::mpi
