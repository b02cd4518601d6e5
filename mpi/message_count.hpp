// MPI counts and displacements are ints: a value count between two ranks checked to fit one (docs/mpi.md).
#pragma once

#include <climits>
#include <string>

#include "contactbench/core/error.hpp"
#include "contactbench/core/types.hpp"

namespace contactbench::mpi {

// `values` as an MPI count; Error naming `exchange` (e.g. "a row exchange") beyond 2^31 - 1.
inline int message_count(Index values, const char* exchange) {
  if (values > INT_MAX)
    throw Error(std::string("mpi: ") + exchange + " moves more than 2^31 values between two ranks");
  return static_cast<int>(values);
}

}  // namespace contactbench::mpi
