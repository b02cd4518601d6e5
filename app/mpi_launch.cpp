#include "contactbench/app/mpi_launch.hpp"

#include <algorithm>
#include <cstdlib>
#include <string>
#include <utility>

namespace contactbench {

namespace {

// A launcher's variable as a whole number >= 0, or -1 when unset or not a number.
int variable(const char* name) {
  const char* text = std::getenv(name);
  if (!text || !*text) return -1;
  char* end = nullptr;
  const long value = std::strtol(text, &end, 10);
  return (*end == '\0' && value >= 0 && value < (1L << 30)) ? static_cast<int>(value) : -1;
}

}  // namespace

MpiLaunch mpi_launch() {
  for (const auto& [size, rank] :
       {std::pair{"OMPI_COMM_WORLD_SIZE", "OMPI_COMM_WORLD_RANK"}, std::pair{"PMI_SIZE", "PMI_RANK"}}) {
    const int ranks = variable(size);
    if (ranks >= 1) return {ranks, std::max(variable(rank), 0)};
  }
  return {};
}

}  // namespace contactbench
