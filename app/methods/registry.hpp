// Methods found by name (docs/architecture.md: an unknown name is an error listing the known ones, never a
// silent default). The built-in methods are listed in app/methods/registry.cpp, one line each; a program
// or a test may add its own.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "contactbench/app/methods/method.hpp"

namespace contactbench {

using MethodFactory = std::function<std::unique_ptr<Method>()>;

class MethodRegistry {
 public:
  // The registry of the program, built-in methods first.
  static MethodRegistry& global();

  // Adds a method; Error if the name is taken or not a portable name (letters, digits, '_', '-').
  void add(std::string name, MethodFactory factory);
  // Removes a method added by add() (tests that register one); no effect for an unknown name.
  void remove(std::string_view name);

  // A new, unconfigured method of that name; nullptr when no method has it.
  std::unique_ptr<Method> make(std::string_view name) const;
  std::vector<std::string> names() const;  // in the order they were added
  std::string names_text() const;          // "bem, plateau, ..." for messages

 private:
  struct Entry {
    std::string name;
    MethodFactory factory;
  };
  std::vector<Entry> entries_;
};

}  // namespace contactbench
