#include "contactbench/app/fftw_wisdom_file.hpp"

#include <cstdlib>
#include <system_error>

#include "contactbench/core/error.hpp"
#include "contactbench/core/fftw_wisdom.hpp"

namespace contactbench {

namespace {

// A variable's value, empty when unset.
std::string variable(const char* name) {
  const char* value = std::getenv(name);
  return value ? std::string(value) : std::string();
}

// The user's cache folder for contactbench (XDG base directories: a relative XDG_CACHE_HOME is ignored).
std::optional<std::filesystem::path> cache_folder() {
  const std::filesystem::path xdg = variable("XDG_CACHE_HOME");
  if (xdg.is_absolute()) return xdg / "contactbench";
  const std::string home = variable("HOME");
  if (!home.empty()) return std::filesystem::path(home) / ".cache" / "contactbench";
  return std::nullopt;
}

// The key as a file name: letters, digits, '-' and '.' kept, any run of other characters one '_'
// ("fftw-wisdom_fftw-3.3.10-sse2-avx_2_threads_FFTW_MEASURE.txt").
std::string file_name_of(const std::string& key) {
  std::string name = "fftw-wisdom_";
  for (const char c : key) {
    const bool kept =
        (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '.';
    if (kept)
      name += c;
    else if (name.back() != '_')
      name += '_';
  }
  return name + ".txt";
}

}  // namespace

void add_fftw_wisdom_option(CLI::App& command, std::string& file) {
  command
      .add_option("--fftw-wisdom", file,
                  std::string("FFTW wisdom file: the plans FFTW measured, kept between runs so that planning "
                              "is paid once ('none': keep none). Default: the variable ") +
                      kFftwWisdomVariable + ", else a file in $XDG_CACHE_HOME/contactbench/ or " +
                      "~/.cache/contactbench/")
      ->check(CLI::Validator(
          [](const std::string& text) { return text.empty() ? std::string("the file name is empty") : ""; },
          "FILE"));
}

std::optional<std::filesystem::path> fftw_wisdom_path(const std::string& option, int threads,
                                                      bool distributed) {
  const std::string chosen = option.empty() ? variable(kFftwWisdomVariable) : option;
  if (chosen == "none") return std::nullopt;
  if (!chosen.empty()) return std::filesystem::path(chosen);
  const auto folder = cache_folder();
  if (!folder) return std::nullopt;
  return *folder / file_name_of(fftw_wisdom_key(threads, distributed));
}

FftwWisdomFile::FftwWisdomFile(const std::string& option, int threads, bool distributed, Warn warn)
    : path_(fftw_wisdom_path(option, threads, distributed)),
      key_(fftw_wisdom_key(threads, distributed)),
      warn_(std::move(warn)),
      work_before_(fft_work()) {
  if (!path_) {
    set_fft_work({.wisdom_kept = false, .expected_applications = work_before_.expected_applications});
    return;
  }
  const WisdomImport read = import_fftw_wisdom(*path_, key_);
  imported_ = read.imported;
  replaceable_ = !read.found || read.wisdom_file;
  learned_by_start_ = fftw_wisdom_text(key_);
  set_fft_work({.wisdom_kept = kept(), .expected_applications = work_before_.expected_applications});
  if (read.problem.empty()) return;
  warn_("FFTW wisdom file " + path_->string() + " " + read.problem + "; FFTW plans by measuring" +
        (replaceable_ ? " and the file is rewritten with what it learns"
                      : "; the file is left untouched (choose another with --fftw-wisdom FILE or " +
                            std::string(kFftwWisdomVariable) + ")"));
}

FftwWisdomFile::~FftwWisdomFile() {
  try {
    save();
  } catch (...) {  // a destructor must not throw; save() warns on its own and is not expected to throw
  }
  set_fft_work(work_before_);
}

void FftwWisdomFile::save() {
  if (saved_ || !path_ || !replaceable_) return;
  saved_ = true;
  if (fftw_wisdom_text(key_) == learned_by_start_) return;  // nothing was planned that the file lacks
  // Merged first with what the file holds now: another process may have written it since the start.
  import_fftw_wisdom(*path_, key_);
  try {
    const std::filesystem::path folder = path_->parent_path();
    if (!folder.empty()) {
      std::error_code code;
      std::filesystem::create_directories(folder, code);
      if (code) throw Error("cannot create its folder " + folder.string() + ": " + code.message());
    }
    export_fftw_wisdom(*path_, key_);
  } catch (const std::exception& error) {
    warn_("FFTW wisdom file " + path_->string() + " not written (the next run plans again): " + error.what());
  }
}

std::string FftwWisdomFile::describe() const {
  if (!path_) return "no wisdom file";
  return imported_ ? "wisdom read from its file" : "no wisdom read";
}

}  // namespace contactbench
