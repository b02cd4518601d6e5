#include "contactbench/core/memory_budget.hpp"

#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>

#include "contactbench/core/error.hpp"

namespace contactbench {

namespace {
constexpr std::uintmax_t kMax = std::numeric_limits<std::uintmax_t>::max();
}

std::uintmax_t saturating_product(std::uintmax_t a, std::uintmax_t b) {
  if (a != 0 && b > kMax / a) return kMax;
  return a * b;
}

std::uintmax_t saturating_sum(std::uintmax_t a, std::uintmax_t b) {
  return b > kMax - a ? kMax : a + b;
}

std::uintmax_t available_memory_bytes() {
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  std::uintmax_t kib = 0;
  std::string unit;
  while (meminfo >> key >> kib >> unit)
    if (key == "MemAvailable:") return saturating_product(kib, 1024);
  const long pages = ::sysconf(_SC_PHYS_PAGES), page_size = ::sysconf(_SC_PAGE_SIZE);
  if (pages > 0 && page_size > 0)
    return saturating_product(static_cast<std::uintmax_t>(pages), static_cast<std::uintmax_t>(page_size));
  return 0;
}

std::string format_bytes(std::uintmax_t bytes) {
  char text[64];
  const double b = static_cast<double>(bytes);
  if (bytes == kMax) return "more than 16 EiB";
  if (b >= 1024.0 * 1024 * 1024)
    std::snprintf(text, sizeof text, "%.1f GiB", b / (1024.0 * 1024 * 1024));
  else
    std::snprintf(text, sizeof text, "%.0f MiB", b / (1024.0 * 1024));
  return text;
}

void check_fits_in_memory(std::uintmax_t bytes, const std::string& what) {
  const std::uintmax_t available = available_memory_bytes();
  if (available == 0 || bytes <= available) return;
  throw Error(what + " needs about " + format_bytes(bytes) + " of memory; this machine has " +
              format_bytes(available) +
              " available: make the request smaller (fewer points, levels or loads)");
}

}  // namespace contactbench
