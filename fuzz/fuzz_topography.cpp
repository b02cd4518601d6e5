// libFuzzer target: any bytes as a topography file, read the way `contactbench stats FILE` reads one (format
// detected from the content; a size of 1e-5 m given to the formats that carry none). A refusal
// (contactbench::Error) is the right answer to bad bytes; anything else (a crash, a sanitizer report, another
// exception, a leak, a giant allocation) is a bug.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>

#include "contactbench/core/error.hpp"
#include "contactbench/core/topography_io.hpp"

namespace {

// One file per fuzzing process, rewritten for every input (the readers take a path).
const std::filesystem::path& scratch_file() {
  static const std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("contactbench_fuzz_topography_" + std::to_string(::getpid()));
  return path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path& path = scratch_file();
  if (std::FILE* file = std::fopen(path.c_str(), "wb")) {
    if (size > 0) std::fwrite(data, 1, size, file);
    std::fclose(file);
  } else {
    return 0;
  }
  try {
    // A lateral size for the formats that carry none (npy, plain matrices), as `stats --size` gives one:
    // without it they are refused after parsing, before the surface is built, filled and levelled.
    contactbench::TopographyReadOptions options;
    if (!contactbench::format_carries_sizes(contactbench::detect_topography_format(path))) options.lx = 1e-5;
    const contactbench::Surface surface = contactbench::read_topography(path, options);
    (void)surface.rms_height();
  } catch (const contactbench::Error&) {
    // refused with a message: the expected outcome for most inputs
  }
  return 0;
}
