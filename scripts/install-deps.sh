#!/usr/bin/env bash
# Installs the Debian 12 packages contactbench needs, if any is missing. Both README commands call this.
# Run as root (or with sudo available); does nothing when everything is already there.
set -euo pipefail

packages=(
  g++ cmake make pkg-config git   # toolchain
  libfftw3-dev                    # FFT engine (with its OpenMP library, libfftw3_omp)
  libopenmpi-dev openmpi-bin      # optional distributed build (mpi/, docs/mpi.md): MPI and mpiexec for its tests
  libfftw3-mpi-dev                # ... with FFTW's distributed transforms; without these, CB_WITH_MPI stays off
  libeigen3-dev                   # array arithmetic and small dense algebra
  libgtest-dev                    # tests
  libbenchmark-dev                # benchmarks
  libcli11-dev                    # command line
  libtomlplusplus-dev             # scene files
  libzip-dev libpugixml-dev       # .x3p topographies (zip archive, XML)
  clang-format                    # the formatting check in the test command
  gnuplot-nox                     # load-area and accuracy-vs-time plots
  python3                         # renders benchmark JSON as Markdown tables (scripts/render_bench.py)
  python3-dev pybind11-dev        # the Python module (python/), built for Debian's /usr/bin/python3
  python3-numpy python3-pytest    # its arrays and its tests
  python3-matplotlib              # optional: the plots of examples/python/
)

# `install-deps.sh asan`: also clang with its sanitizer runtimes, libFuzzer and its OpenMP runtime (the asan
# preset, whose build has the fuzz targets; scripts/test.sh asan and scripts/fuzz.sh).
if [[ "${1:-}" == "asan" ]]; then
  packages+=(clang-14 libclang-rt-14-dev libomp-14-dev)
fi

missing=()
for package in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$package" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$package")
done
[[ ${#missing[@]} -eq 0 ]] && exit 0

echo "install-deps: installing ${missing[*]}" >&2
sudo_cmd=()
if [[ $(id -u) -ne 0 ]]; then
  command -v sudo >/dev/null || { echo "install-deps: run as root to install: ${missing[*]}" >&2; exit 1; }
  sudo_cmd=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
