// What a request will need in memory, estimated from its parameters before anything is allocated, and the
// refusal when it cannot fit: a request that would grow until the kernel kills it is refused at once, with
// the estimate and what the machine has.
#pragma once

#include <cstdint>
#include <string>

#include "contactbench/core/types.hpp"

namespace contactbench {

// The memory the machine can give now without swapping [bytes]: MemAvailable of /proc/meminfo, or, where that
// cannot be read, the physical memory (sysconf); 0 when neither is known (then nothing is refused).
std::uintmax_t available_memory_bytes();

// Throws Error "<what> needs about X GiB of memory; this machine has Y GiB available ..." when `bytes`
// exceeds the available memory. `bytes` is an estimate of the peak (the callers' comments say what they
// count).
void check_fits_in_memory(std::uintmax_t bytes, const std::string& what);

// "12.3 GiB" / "512 MiB": for messages.
std::string format_bytes(std::uintmax_t bytes);

// Saturating products and sums, so that an absurd request (2^40 levels) estimates as huge, not as a wrapped
// small number.
std::uintmax_t saturating_product(std::uintmax_t a, std::uintmax_t b);
std::uintmax_t saturating_sum(std::uintmax_t a, std::uintmax_t b);

}  // namespace contactbench
