#include "contactbench/core/fftw_wisdom.hpp"

#include <cstdlib>
#include <memory>

#include <fftw3.h>

#include "contactbench/core/atomic_file.hpp"
#include "contactbench/core/bounded_read.hpp"
#include "contactbench/core/error.hpp"
#include "contactbench/core/fft.hpp"

namespace contactbench {

namespace {

// The file: this line, the key, a newline, then each precision's block after its marker line.
constexpr const char* kHeader = "contactbench FFTW wisdom for ";
constexpr const char* kDoubleMarker = "\n[fftw double]\n";
constexpr const char* kFloatMarker = "\n[fftw float]\n";
// A wisdom file holds a few hundred bytes per planned shape; anything near this bound is not one.
constexpr std::uintmax_t kMaxWisdomBytes = std::uintmax_t{64} << 20;

// FFTW's export, which the caller must free().
std::string exported(char* text) {
  const std::unique_ptr<char, decltype(&std::free)> owner(text, &std::free);
  return text ? std::string(text) : std::string();
}

}  // namespace

std::string fftw_wisdom_key(int threads, bool distributed) {
  return std::string(fftw_version) + ", " + std::to_string(threads) + " threads, FFTW_MEASURE" +
         (distributed ? ", with FFTW-MPI" : "");
}

std::string fftw_wisdom_text(const std::string& key) {
  auto lock = lock_fftw_planner();
  return kHeader + key + kDoubleMarker + exported(fftw_export_wisdom_to_string()) + kFloatMarker +
         exported(fftwf_export_wisdom_to_string());
}

WisdomImport import_fftw_wisdom(const std::filesystem::path& path, const std::string& key) {
  WisdomImport result;
  std::error_code code;
  const auto status = std::filesystem::status(path, code);
  if (status.type() == std::filesystem::file_type::not_found) return result;
  result.found = true;
  std::string text;
  try {
    text = read_file_bounded(path, kMaxWisdomBytes, "an FFTW wisdom file");
  } catch (const Error& error) {
    result.problem = std::string("cannot be read: ") + error.what();
    return result;
  }
  const std::string header(kHeader);
  if (text.compare(0, header.size(), header) != 0) {
    result.problem = "is not a contactbench FFTW wisdom file (its first line is not \"" + header + "...\")";
    return result;
  }
  result.wisdom_file = true;
  const std::size_t line_end = text.find('\n');
  if (line_end == std::string::npos) {
    result.problem = "is damaged (it has no line after its header)";
    return result;
  }
  const std::string file_key = text.substr(header.size(), line_end - header.size());
  if (file_key != key) {
    result.problem = "was made for " + file_key + ", not for this run's " + key + " (foreign: not used)";
    return result;
  }
  const std::size_t double_at = text.find(kDoubleMarker), float_at = text.find(kFloatMarker);
  if (double_at != line_end || float_at == std::string::npos || float_at < double_at) {
    result.problem = "is damaged (its [fftw double] and [fftw float] sections are missing or out of order)";
    return result;
  }
  const std::string double_text = text.substr(double_at + std::string(kDoubleMarker).size(),
                                              float_at - double_at - std::string(kDoubleMarker).size());
  const std::string float_text = text.substr(float_at + std::string(kFloatMarker).size());
  // FFTW checks each block against its own build (version, precision, codelets) and keeps the wisdom it had
  // when it refuses one. All or nothing: when the second is refused, the first is taken back.
  auto lock = lock_fftw_planner();
  const std::string double_before = exported(fftw_export_wisdom_to_string());
  const bool double_ok = fftw_import_wisdom_from_string(double_text.c_str()) != 0;
  const bool float_ok = double_ok && fftwf_import_wisdom_from_string(float_text.c_str()) != 0;
  if (double_ok && !float_ok) {
    fftw_forget_wisdom();
    fftw_import_wisdom_from_string(double_before.c_str());
  }
  result.imported = float_ok;
  if (!result.imported)
    result.problem = std::string("is damaged: FFTW refused its ") + (double_ok ? "float" : "double") +
                     " wisdom (nothing of it is used)";
  return result;
}

void export_fftw_wisdom(const std::filesystem::path& path, const std::string& key) {
  const std::string text = fftw_wisdom_text(key);
  write_file_atomically(path, [&](std::ostream& out) { out << text; });
}

void forget_fftw_wisdom() {
  auto lock = lock_fftw_planner();
  fftw_forget_wisdom();
  fftwf_forget_wisdom();
}

}  // namespace contactbench
