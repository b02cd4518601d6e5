// A topography file read a few rows at a time (docs/mpi.md "Where the surface is"): for a reader that sends
// each MPI rank its slab as it goes and never holds the whole surface. Only where the format allows it: the
// project's own format (its header states the shape, sizes, periodicity and unit, and each line is a row of
// heights in metres), with the reading options that change nothing but the sizes and periodicity. Any other
// format or option is read whole (read_topography), and open() says so by returning nothing.
#pragma once

#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "contactbench/core/formats/height_rows.hpp"
#include "contactbench/core/grid.hpp"
#include "contactbench/core/topography_io.hpp"

namespace contactbench {

class TopographyRowReader {
 public:
  // The file's header read and checked as read_topography checks it (the same InputErrors); nullptr when the
  // format is not the project's, or the options ask for a channel, a unit, invalid points filled, a crop, a
  // row alignment or levelling (read_topography does those on the whole file).
  static std::unique_ptr<TopographyRowReader> open(const std::filesystem::path& path,
                                                   const TopographyReadOptions& options);

  // The grid the file holds (options.periodic, when given, overriding the file's flag).
  const Grid& grid() const { return grid_; }

  // The next `rows` rows, rows * nx heights in metres into `out`, exactly as read_topography returns them
  // (the same parser: bit for bit). InputError naming the line for a defective row, missing rows, or an
  // invalid point (NaN or Inf: read_topography refuses them too unless told to fill them, which needs the
  // whole surface). Holds one row's text at a time.
  void read(Index rows, Real* out);
  // After the last row: InputError if the file has more data rows than its header promised.
  void finish();

 private:
  TopographyRowReader(std::filesystem::path path, std::ifstream in, Grid grid, formats::PromisedShape shape,
                      long line, int threads);
  // The next non-blank line (trimmed) and its number; false at the end of the file.
  bool next_line(std::string& text, long& number);

  std::filesystem::path path_;
  std::ifstream in_;
  Grid grid_;
  formats::PromisedShape shape_;
  long line_ = 0;  // the last line read
  Index rows_read_ = 0;
  int threads_ = 1;
};

}  // namespace contactbench
