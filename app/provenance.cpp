#include "contactbench/app/provenance.hpp"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <string>

#include "contactbench/app/mpi_launch.hpp"
#include "contactbench/build_info.hpp"

namespace contactbench {

namespace {

std::string cpu_model() {
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line;
  while (std::getline(cpuinfo, line))
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      if (colon != std::string::npos) return line.substr(line.find_first_not_of(' ', colon + 1));
    }
  return "unknown CPU";
}

// The command as one line of text: a control character of a file name (a newline would end a CSV comment
// header and start a data row) written as \n, \t or \xNN.
std::string printable(const std::string& text) {
  std::string out;
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '\n') {
      out += "\\n";
    } else if (c == '\t') {
      out += "\\t";
    } else if (byte < 0x20 || byte == 0x7f) {
      char escaped[5];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", byte);
      out += escaped;
    } else {
      out += c;
    }
  }
  return out;
}

}  // namespace

Provenance current_provenance(int threads, const std::string& command) {
  Provenance p;
  p.commit = CB_GIT_COMMIT;
  const std::time_t now = std::time(nullptr);
  std::array<char, 32> date{};
  std::tm utc{};
  gmtime_r(&now, &utc);
  std::strftime(date.data(), date.size(), "%Y-%m-%dT%H:%M:%SZ", &utc);
  p.date = date.data();
  p.threads = threads;
  std::array<char, 256> host{};
  if (gethostname(host.data(), host.size() - 1) != 0) host[0] = '\0';
  p.machine = std::string(host.data()) + " (" + cpu_model() + ")";
  // Run as K MPI ranks (app/distributed_stages.hpp): the command that reruns it says so.
  const MpiLaunch launch = mpi_launch();
  p.ranks = std::max(launch.ranks, 1);
  p.command =
      printable(launch.ranks > 1 ? "mpiexec -np " + std::to_string(launch.ranks) + " " + command : command);
  return p;
}

std::string threads_text(const Provenance& p) {
  return (p.ranks > 1 ? std::to_string(p.ranks) + " ranks x " : std::string()) + std::to_string(p.threads) +
         " threads";
}

std::string version_line() {
  return std::string("contactbench ") + CB_VERSION + " (commit " + CB_GIT_COMMIT + ")";
}

}  // namespace contactbench
