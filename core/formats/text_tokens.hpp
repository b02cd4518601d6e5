// The tokenizer the text readers share (internal to core/formats/): a text without its outer separators, and
// the runs of non-separators in it. Each reader says what separates: blanks (space, tab) in the text
// topographies, any white space in SDF, a space alone in Nanoscope's header values.
#pragma once

#include <cctype>
#include <string_view>
#include <vector>

namespace contactbench::formats {

inline bool is_blank(char c) {
  return c == ' ' || c == '\t';
}

inline bool is_space(char c) {
  return std::isspace(static_cast<unsigned char>(c)) != 0;
}

template <typename IsSeparator>
std::string_view trim(std::string_view text, IsSeparator is_separator) {
  while (!text.empty() && is_separator(text.front()))
    text.remove_prefix(1);
  while (!text.empty() && is_separator(text.back()))
    text.remove_suffix(1);
  return text;
}

// Calls visit(token) for every run of non-separators, in order.
template <typename IsSeparator, typename Visit>
void for_each_token(std::string_view text, IsSeparator is_separator, Visit&& visit) {
  std::size_t position = 0;
  while (position < text.size()) {
    while (position < text.size() && is_separator(text[position]))
      ++position;
    const std::size_t start = position;
    while (position < text.size() && !is_separator(text[position]))
      ++position;
    if (position > start) visit(text.substr(start, position - start));
  }
}

template <typename IsSeparator>
std::vector<std::string_view> split_tokens(std::string_view text, IsSeparator is_separator) {
  std::vector<std::string_view> tokens;
  for_each_token(text, is_separator, [&](std::string_view token) { tokens.push_back(token); });
  return tokens;
}

}  // namespace contactbench::formats
