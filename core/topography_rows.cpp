#include "contactbench/core/topography_rows.hpp"

#include <cmath>
#include <cstring>
#include <span>
#include <utility>
#include <vector>

#include "contactbench/core/error.hpp"
#include "contactbench/core/formats/text_lines.hpp"
#include "contactbench/core/formats/text_readers.hpp"
#include "contactbench/core/formats/text_tokens.hpp"

namespace contactbench {

namespace fs = std::filesystem;

std::unique_ptr<TopographyRowReader> TopographyRowReader::open(const fs::path& path,
                                                               const TopographyReadOptions& options) {
  if (options.channel || options.unit || options.fill != FillMethod::none || options.crop ||
      options.align_rows != RowAlignment::none || options.level != Levelling::none)
    return nullptr;
  // The format as read_topography detects it (the file's head; its errors the same).
  if (detect_topography_format(path) != TopographyFormat::project) return nullptr;
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, "cannot be opened for reading");
  auto reader = std::unique_ptr<TopographyRowReader>(
      new TopographyRowReader(path, std::move(in), Grid{}, formats::PromisedShape{}, 0, options.threads));
  // The first two non-blank lines are the header (a lone CR ending lines would make the file one line for
  // getline: such a file is read whole).
  std::string texts[2];
  std::vector<formats::Line> lines;
  for (std::string& text : texts) {
    long number = 0;
    if (!reader->next_line(text, number)) break;
    if (text.find('\r') != std::string::npos) return nullptr;
    lines.push_back({text, number});
  }
  if (lines.empty()) throw InputError(path, 0, "is empty");
  const formats::ProjectHeader header = formats::read_project_header(path, lines, options);
  formats::require_height_unit(path, header.quantity, header.unit);
  reader->shape_ = header.shape;
  reader->grid_ = Grid{.nx = header.shape.cols,
                       .ny = header.shape.rows,
                       .lx = header.lx,
                       .ly = header.ly,
                       .periodic = options.periodic.value_or(header.periodic)};
  const std::string what = path.string();
  validate(reader->grid_, what.c_str());
  return reader;
}

TopographyRowReader::TopographyRowReader(fs::path path, std::ifstream in, Grid grid,
                                         formats::PromisedShape shape, long line, int threads)
    : path_(std::move(path)),
      in_(std::move(in)),
      grid_(grid),
      shape_(std::move(shape)),
      line_(line),
      threads_(threads) {}

bool TopographyRowReader::next_line(std::string& text, long& number) {
  std::string raw;
  while (std::getline(in_, raw)) {
    ++line_;
    if (line_ == 1 && raw.starts_with("\xEF\xBB\xBF")) raw.erase(0, 3);  // as non_blank_lines
    if (!raw.empty() && raw.back() == '\r') raw.pop_back();              // CRLF
    const std::string_view trimmed = formats::trim(std::string_view(raw), formats::is_blank);
    if (trimmed.empty()) continue;
    text.assign(trimmed);
    number = line_;
    return true;
  }
  if (in_.bad()) throw InputError(path_, line_, "could not be read");
  return false;
}

void TopographyRowReader::read(Index rows, Real* out) {
  // The rows' text, then the whole-file reader's parser on them (its messages, its threads).
  std::vector<std::string> texts(static_cast<std::size_t>(rows));
  std::vector<formats::Line> lines;
  lines.reserve(texts.size());
  for (std::string& text : texts) {
    long number = 0;
    if (!next_line(text, number))
      throw InputError(path_, shape_.rows_line,
                       "the header's " + shape_.rows_name + " promises " + std::to_string(shape_.rows) +
                           " rows but the file has " +
                           std::to_string(rows_read_ + static_cast<Index>(lines.size())) + " data rows");
    if (text.find('\r') != std::string::npos)
      throw InputError(path_, number, "lines ended by a lone CR: not read in slabs");
    lines.push_back({text, number});
  }
  if (rows == 0) return;
  if (rows_read_ + rows > shape_.rows)
    throw InputError(path_, lines.front().number, "more data rows than the header's " + shape_.rows_name);
  formats::PromisedShape chunk = shape_;
  chunk.rows = rows;
  const formats::DataBlock block = formats::parse_data(path_, lines, 1.0, chunk, " after the header",
                                                       formats::header_text_syntax(), threads_);
  for (std::size_t k = 0; k < block.values.size(); ++k) {
    if (!std::isfinite(block.values[k]))
      throw InputError(path_, lines[k / static_cast<std::size_t>(shape_.cols)].number,
                       "an invalid point (NaN or Inf): read in slabs (under mpiexec) a surface must have "
                       "none; a scene's surface.fill fills them, on the whole surface");
    out[k] = block.values[k];
  }
  rows_read_ += rows;
}

void TopographyRowReader::finish() {
  std::string text;
  long number = 0;
  if (rows_read_ < shape_.rows) {
    throw InputError(path_, shape_.rows_line,
                     "the header's " + shape_.rows_name + " promises " + std::to_string(shape_.rows) +
                         " rows but only " + std::to_string(rows_read_) + " were read");
  }
  if (next_line(text, number))
    throw InputError(path_, number, "more data rows than the header's " + shape_.rows_name);
}

}  // namespace contactbench
