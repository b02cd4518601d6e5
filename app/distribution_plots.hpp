// Plots of the distributions a scene writes at its reference load (app/distributions_csv.hpp; docs/theory.md
// sections 12.7 and 12.8): each CSV drawn as PNG and SVG by gnuplot, the BEM's histogram as steps beside the
// theories' columns, on the axes each quantity is read on (pressure: linear; gap: logarithmic density, where
// an exponential tail is a straight line; patch sizes: log-log with the fitted power law).
#pragma once

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "contactbench/app/scene_run.hpp"

namespace contactbench {

enum class DistributionKind { pressure, gap, patch_sizes };

// What a distribution CSV holds, from its lines: the kind (by its column line), the load (from its comment),
// and the columns that have at least one number (a theory that could not answer is left out of the plot).
struct DistributionFile {
  DistributionKind kind = DistributionKind::pressure;
  std::string load;                    // as written in the file, "0.01"
  std::vector<std::string> columns;    // every column, in order
  std::vector<std::string> non_empty;  // the columns with a number in some row
  double largest_x = 0;                // the largest bin edge (the gap's, for its unit)
};

// Reads a CSV written by write_*_distribution_csv / write_patch_sizes_csv; nullopt when it is not one (its
// column line is not one of the three).
std::optional<DistributionFile> read_distribution_file(const std::filesystem::path& csv);

// The gnuplot script drawing `csv` (described by `file`) into `png` and `svg` (either may be empty).
void write_distribution_gnuplot_script(std::ostream& out, const DistributionFile& file,
                                       const std::string& csv, const std::string& title,
                                       const std::string& png, const std::string& svg);

// Draws `csv` into `png` and `svg` (either may be empty), each under a temporary name and renamed. Throws
// Error when the file is not a distribution CSV, or gnuplot is missing or fails.
void draw_distribution_picture(const std::filesystem::path& csv, const std::filesystem::path& png,
                               const std::filesystem::path& svg);

// After a run's report is written into `folder`: draws every <label>_*_distribution.csv and
// <label>_patch_sizes.csv there as .png and .svg. Returns false, with the reason on `warnings`, when gnuplot
// is missing or fails (the numbers are in the CSVs either way).
bool draw_distribution_plots(const std::filesystem::path& folder, const SceneReport& report,
                             std::ostream& warnings);

}  // namespace contactbench
