// Errors that reach a user: each says what was wrong and where (file and line, or key).
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

namespace contactbench {

// Any refusal of bad input or of an impossible request.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Bad content in a file: the message reads "path:line: reason" (line 0 when the file as a whole is wrong).
class InputError : public Error {
 public:
  InputError(const std::filesystem::path& path, long line, const std::string& reason)
      : Error(located(path, line, reason)), path_(path), line_(line) {}
  const std::filesystem::path& path() const { return path_; }
  long line() const { return line_; }

 private:
  static std::string located(const std::filesystem::path& path, long line, const std::string& reason) {
    std::string message = path.string();
    if (line > 0) message.append(":").append(std::to_string(line));
    return message.append(": ").append(reason);
  }
  std::filesystem::path path_;
  long line_;
};

}  // namespace contactbench
