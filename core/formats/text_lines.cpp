#include "contactbench/core/formats/text_lines.hpp"

#include <algorithm>
#include <cstring>

#include "contactbench/core/error.hpp"
#include "contactbench/core/formats/text_tokens.hpp"

namespace contactbench::formats {

namespace fs = std::filesystem;

std::vector<Line> non_blank_lines(std::string_view content) {
  constexpr std::string_view utf8_byte_order_mark = "\xEF\xBB\xBF";
  if (content.starts_with(utf8_byte_order_mark)) content.remove_prefix(utf8_byte_order_mark.size());
  std::vector<Line> lines;
  long number = 0;
  std::size_t start = 0;
  // The next LF and the next CR at or after `start`, each found by one memchr over the bytes it passes and
  // kept until `start` passes it: linear in the file whatever its line ends (find_first_of("\r\n") calls
  // memchr once a byte, and a whole-file search per line would be quadratic in a file of lone CRs).
  const auto next = [&](char end_of_line, std::size_t from) {
    if (from >= content.size()) return content.size();  // memchr must not see the null of an empty view
    const void* found = std::memchr(content.data() + from, end_of_line, content.size() - from);
    return found ? static_cast<std::size_t>(static_cast<const char*>(found) - content.data())
                 : content.size();
  };
  std::size_t next_lf = next('\n', 0), next_cr = next('\r', 0);
  while (start < content.size()) {
    if (next_lf < start) next_lf = next('\n', start);
    if (next_cr < start) next_cr = next('\r', start);
    const std::size_t end = std::min(next_lf, next_cr);
    ++number;
    const std::string_view text = trim(content.substr(start, end - start), is_blank);
    if (!text.empty()) lines.push_back({text, number});
    start = end;
    if (start < content.size()) {
      const bool crlf = content[start] == '\r' && start + 1 < content.size() && content[start + 1] == '\n';
      start += crlf ? 2 : 1;
    }
  }
  return lines;
}

std::string line_range(std::span<const Line> lines) {
  if (lines.empty()) return "no lines";
  if (lines.size() == 1) return "line " + std::to_string(lines.front().number);
  return "lines " + std::to_string(lines.front().number) + "-" + std::to_string(lines.back().number);
}

void check_is_text(const fs::path& path, std::string_view bytes) {
  if (bytes.starts_with("\xff\xfe") || bytes.starts_with("\xfe\xff"))
    throw InputError(path, 0,
                     "is UTF-16 text (it starts with a UTF-16 byte order mark): save it as UTF-8 or ASCII "
                     "text, or give a format contactbench reads (docs/formats.md)");
  const std::size_t nul = bytes.substr(0, 65536).find('\0');
  if (nul != std::string_view::npos)
    throw InputError(path, 0,
                     "holds binary data (a NUL byte at offset " + std::to_string(nul) +
                         ") in none of the binary formats contactbench reads (docs/formats.md lists them); a "
                         "text topography holds numbers as text");
}

}  // namespace contactbench::formats
