#include "contactbench/mpi/distributed_selection.hpp"

#include <array>
#include <bit>
#include <cstdint>
#include <string>

#include "contactbench/core/error.hpp"

namespace contactbench::mpi {

namespace {

// A double's bits as an unsigned key in the values' order: negatives (sign bit set) reversed, positives
// above them.
std::uint64_t order_key(double value) {
  const auto bits = std::bit_cast<std::uint64_t>(value);
  return (bits >> 63) != 0 ? ~bits : bits | (std::uint64_t{1} << 63);
}

double value_of(std::uint64_t key) {
  return std::bit_cast<double>((key >> 63) != 0 ? key & ~(std::uint64_t{1} << 63) : ~key);
}

}  // namespace

double kth_largest_over_ranks(const std::vector<double>& values, std::size_t k, MPI_Comm comm) {
  unsigned long long total = values.size();
  MPI_Allreduce(MPI_IN_PLACE, &total, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, comm);
  if (k == 0 || k > total)
    throw Error("mpi: the " + std::to_string(k) + "-th largest of " + std::to_string(total) +
                " values does not exist");
  // The key's bytes from the highest: those of the keys that share the bytes fixed so far, counted by their
  // next byte; the k-th largest lies in the bin where the counts from the top reach k.
  std::uint64_t prefix = 0;
  unsigned long long rank_from_top = k;  // the k-th largest among the keys that share the prefix
  for (int shift = 56; shift >= 0; shift -= 8) {
    std::array<unsigned long long, 256> histogram{};
    const std::uint64_t fixed_mask = shift == 56 ? 0 : ~std::uint64_t{0} << (shift + 8);
    for (const double value : values) {
      const std::uint64_t key = order_key(value);
      if ((key & fixed_mask) == prefix) ++histogram[(key >> shift) & 0xff];
    }
    MPI_Allreduce(MPI_IN_PLACE, histogram.data(), 256, MPI_UNSIGNED_LONG_LONG, MPI_SUM, comm);
    int bin = 255;
    for (; histogram[static_cast<std::size_t>(bin)] < rank_from_top; --bin)
      rank_from_top -= histogram[static_cast<std::size_t>(bin)];
    prefix |= static_cast<std::uint64_t>(bin) << shift;
  }
  return value_of(prefix);
}

}  // namespace contactbench::mpi
