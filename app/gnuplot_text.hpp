// Text that the gnuplot scripts of the load-area plots and the field maps write (app/load_area_plots.cpp,
// app/field_picture.cpp): paths quoted for the shell, strings for gnuplot, numbers that read back exactly.
#pragma once

#include <string>

namespace contactbench {

// A path inside single quotes for the shell: a quote in it becomes '\''.
std::string shell_quote(const std::string& text);

// Text inside gnuplot's single quotes, where a quote is written twice (titles and notes are free text).
std::string gnuplot_quote(const std::string& text);

// A number for a data block or a range: the shortest decimal that reads back to the same double; NaN as
// gnuplot reads it.
std::string gnuplot_number(double value);

// Whether a gnuplot is on the PATH.
bool gnuplot_available();

}  // namespace contactbench
