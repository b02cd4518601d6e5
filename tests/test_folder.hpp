// A fixture giving each test a fresh folder of its own in the temporary directory, removed afterwards, and
// writing files into it byte for byte. The folder is named after a prefix, the process and the test: the
// tests of one binary run in parallel under ctest, each in its own process.
#pragma once

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <system_error>

namespace contactbench::testing {

class FolderTest : public ::testing::Test {
 protected:
  explicit FolderTest(const std::string& prefix) {
    const std::string test_name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    folder_ =
        std::filesystem::temp_directory_path() / (prefix + std::to_string(::getpid()) + "_" + test_name);
    std::filesystem::remove_all(folder_);
    std::filesystem::create_directories(folder_);
  }
  ~FolderTest() override {
    std::error_code ignored;
    std::filesystem::remove_all(folder_, ignored);
  }

  // Writes the bytes exactly as given (binary: CRLF stays CRLF).
  std::filesystem::path write(const std::string& name, std::string_view content) const {
    const std::filesystem::path path = folder_ / name;
    std::ofstream out(path, std::ios::binary);
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    return path;
  }

  std::filesystem::path folder_;
};

}  // namespace contactbench::testing
