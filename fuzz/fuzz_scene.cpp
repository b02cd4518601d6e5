// libFuzzer target: any bytes as a scene file, parsed and validated as `contactbench run SCENE` does before
// any work. A refusal (contactbench::Error, listing the problems) is the right answer to bad input; anything
// else is a bug. Files the scene names are looked up relative to a folder that does not exist, so nothing is
// read.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "contactbench/app/scene.hpp"
#include "contactbench/core/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const contactbench::Scene scene =
        contactbench::parse_scene(text, "/nonexistent/contactbench-fuzz/scene.toml");
    (void)scene;
  } catch (const contactbench::Error&) {
    // refused with a message
  }
  return 0;
}
