#include "contactbench/app/problems.hpp"

namespace contactbench {

void Problems::add(long line, std::string_view path, std::string_view reason, std::string_view accepted) {
  std::string text = origin_;
  if (line > 0) text.append(":").append(std::to_string(line));
  text.append(": ").append(path).append(": ").append(reason);
  if (!accepted.empty()) text.append("; accepted: ").append(accepted);
  lines_.push_back(std::move(text));
}

void Problems::add_syntax_error(long line, long column, std::string_view reason) {
  lines_.push_back(origin_ + ":" + std::to_string(line) + ":" + std::to_string(column) +
                   ": TOML syntax error: " + std::string(reason));
}

void Problems::throw_if_any() const {
  if (lines_.empty()) return;
  std::string message = "invalid scene " + origin_ + " (" + std::to_string(lines_.size()) +
                        (lines_.size() == 1 ? " problem):" : " problems):");
  for (const auto& line : lines_)
    message.append("\n").append(line);
  throw SceneError(message, lines_);
}

}  // namespace contactbench
