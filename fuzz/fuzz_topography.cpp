// libFuzzer target: any bytes as a topography file, read the way `contactbench stats FILE` reads one (format
// detected from the content). A refusal (contactbench::Error) is the right answer to bad bytes; anything else
// (a crash, a sanitizer report, another exception, a leak, a giant allocation) is a bug.
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
    const contactbench::Surface surface = contactbench::read_topography(path);
    (void)surface.rms_height();
  } catch (const contactbench::Error&) {
    // refused with a message: the expected outcome for most inputs
  }
  return 0;
}
