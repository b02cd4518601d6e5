#!/usr/bin/env bash
# Builds the peer ContactMechanics (the ContactEngineering Python stack) offline, against Debian 12's
# /usr/bin/python3, numpy and scipy, into one flat folder that PYTHONPATH points at. Nothing in the project
# (build, ctest, CI) uses the peer: only scripts/peers/side_by_side.py does (docs/peers.md).
#
# Usage: scripts/peers/build_contactmechanics.sh SRC PREFIX
#   SRC    a folder holding the source trees below, one subfolder each (names as listed);
#   PREFIX the install folder (flat: PREFIX/ContactMechanics, PREFIX/muGrid, ...). Then
#          PYTHONPATH=PREFIX /usr/bin/python3 -c "import ContactMechanics, SurfaceTopography, Adhesion"
#
# The source trees: public GitHub repositories, any clone or `git archive` of these commits (the ones measured
# in results/peers/; another commit may need other patches). The version each package reports is given here,
# since a `git archive` has no .git to discover it from (override with the environment variables named):
#   SRC/ContactMechanics   ContactEngineering/ContactMechanics 40ad18ea9caec4a613b297e188f33f9e3bc9f254 (1.8.3)
#   SRC/SurfaceTopography  ContactEngineering/SurfaceTopography 119cb66ade8917a0a62a878c82d459f959566760
#                          (1.22.0-6-g119cb66a)
#   SRC/Adhesion           ContactEngineering/Adhesion f923c56d4b3299f500d6adb586ac0057f10f9656 (0.92.1-5-gf923c56d)
#   SRC/NuMPI              muSpectre/NuMPI 4a7774e8302323535eb322a139fe98d6e4627720 (0.15.0)
#   SRC/muGrid             muSpectre/muGrid 5b49579457fa47b520371ac514ddf76ab2a919fe (1.0rc; it holds the FFT
#                          engine ContactMechanics uses, so muFFT is not needed)
#   SRC/DiscoverVersion    IMTEK-Simulation/DiscoverVersion 8b890aafa0a01be893cd64d6686c3054bd4c5237 (0.4.0; the
#                          packages import it at run time for their __version__)
#   SRC/pybind11           pybind/pybind11 tag v2.13.6 (muGrid needs >= 2.11; Debian 12 has 2.10)
#   SRC/dlpack             dmlc/dlpack tag v1.0 (a header muGrid's bindings include)
# For example, from bare snapshots G/<owner>+<name>:
#   git --git-dir=G/ContactEngineering+ContactMechanics archive HEAD | tar -x -C SRC/ContactMechanics
# (a snapshot that lacks some large test files: exclude them with `-- . ':(exclude)path'`; none is needed).
#
# Debian 12 packages it needs (apt-get install, as root):
#   to build: python3 python3-dev python3-numpy python3-scipy python3-pip g++ cmake ninja-build libeigen3-dev
#             meson python3-mesonpy flit python3-hatchling python3-hatch-vcs
#   what `import SurfaceTopography` imports (its file readers are imported eagerly): python3-pydantic
#             python3-defusedxml python3-h5py python3-tifffile python3-openpyxl python3-olefile python3-pandas
#             python3-zstandard python3-xmltodict python3-yaml python3-dateutil python3-requests python3-pil
#             python3-matplotlib
# No Python index is used (pip runs with --no-index --no-deps --no-build-isolation). FFTW is not used by the
# peer (muGrid has pocketfft built in). Declared dependencies nothing imports here (netCDF4, muTimer,
# numpyencoder, primefac) are not installed.
#
# Patches, applied to the trees in SRC (idempotent), because Debian 12 is older than the pins (numpy 1.24 where
# muGrid and SurfaceTopography want >= 2.1 and >= 2.0; Eigen 3.4, meson-python 0.12):
#   muGrid/CMakeLists.txt: find_package(Eigen3 5.0.1) -> 3.4 (Debian's Eigen; the build otherwise fetches
#     Eigen 5.0.1 from gitlab, which is offline here); the version string from git -> the given version;
#   muGrid's bindings (scripts/peers/patch_mugrid_dlpack.py): a host field's __dlpack__ also gives the legacy
#     capsule numpy 1.24's from_dlpack takes, and Field.py views the imported buffer writeable; without it
#     every FFT of the half-space fails ("PyCapsule_GetPointer called with incorrect name", then "assignment
#     destination is read-only");
#   SurfaceTopography/pyproject.toml: the [tool.meson-python] table (a key Debian's meson-python 0.12 rejects)
#     removed; SurfaceTopography/IO/IBW.py: igor2 (no Debian package; only .ibw files need it) imported
#     only if present;
#   PREFIX/tiffile.py: the PyPI package "tiffile" (SurfaceTopography's JPK reader imports it) is an alias of
#     tifffile; this one-line module stands in for it, over Debian's python3-tifffile.
set -euo pipefail

if [[ $# -ne 2 ]]; then
  sed -n '2,12p' "$0" >&2
  exit 2
fi
SRC=$(realpath "$1")
PREFIX=$(realpath -m "$2")
for tree in ContactMechanics SurfaceTopography Adhesion NuMPI muGrid DiscoverVersion pybind11 dlpack; do
  [[ -d "$SRC/$tree" ]] || { echo "build_contactmechanics: $SRC/$tree is missing (see the list in $0)" >&2; exit 1; }
done

: "${CM_VERSION:=1.8.3}"
: "${ST_VERSION:=1.22.0.dev6+g119cb66a}"
: "${ADHESION_VERSION:=0.92.1.dev5+gf923c56d}"
: "${NUMPI_VERSION:=0.15.0}"
: "${MUGRID_VERSION:=1.0rc}"
: "${MUGRID_COMMIT:=5b49579457fa47b520371ac514ddf76ab2a919fe}"
: "${DISCOVERVERSION_VERSION:=0.4.0}"
JOBS=${JOBS:-2}

# Debian's interpreter, also as `python` (SurfaceTopography's meson.build calls `python -m DiscoverVersion`),
# ahead of any pyenv/conda on PATH.
TOOLS="$PREFIX/.build/bin"
mkdir -p "$TOOLS" "$PREFIX"
ln -sf /usr/bin/python3 "$TOOLS/python"
export PATH="$TOOLS:/usr/local/bin:/usr/bin:/bin"
export PYTHONPATH="$PREFIX"
PY=/usr/bin/python3
pip_install() { # version-variable-assignment tree [pip options]
  # A previous install of the package is removed first, not by pip's --upgrade: with --target, --upgrade lets
  # a wheel's data files (SurfaceTopography's ChangeLog.md) replace the package folder of the same name.
  local lower
  lower=$(echo "$2" | tr '[:upper:]' '[:lower:]')
  rm -rf "${PREFIX:?}/$2" "$PREFIX/$lower"-*.dist-info "$PREFIX/_$2".*.so
  env "$1" $PY -m pip install --no-index --no-deps --no-build-isolation --target "$PREFIX" "${@:3}" "$SRC/$2"
}

echo "== DiscoverVersion, NuMPI (pure Python)"
pip_install DISCOVER_VERSION="$DISCOVERVERSION_VERSION" DiscoverVersion
pip_install SETUPTOOLS_SCM_PRETEND_VERSION="$NUMPI_VERSION" NuMPI

echo "== muGrid (CMake, C++ with Python bindings; no MPI, no NetCDF)"
$PY "$(dirname "$(realpath "$0")")/patch_mugrid_dlpack.py" "$SRC/muGrid"
sed -i 's/find_package(Eigen3 5.0.1 QUIET)/find_package(Eigen3 3.4 QUIET)/' "$SRC/muGrid/CMakeLists.txt"
sed -i "s/set(MUGRID_VERSION_STRING \"unknown\")/set(MUGRID_VERSION_STRING \"v$MUGRID_VERSION\")/; \
s/set(MUGRID_GIT_HASH \"unknown\")/set(MUGRID_GIT_HASH \"$MUGRID_COMMIT\")/" "$SRC/muGrid/CMakeLists.txt"
cmake -S "$SRC/muGrid" -B "$PREFIX/.build/muGrid" -G Ninja -DCMAKE_BUILD_TYPE=Release -DSKBUILD=ON \
  -DCMAKE_INSTALL_PREFIX="$PREFIX" -DMUGRID_ENABLE_MPI=OFF -DMUGRID_ENABLE_NETCDF=OFF \
  -DMUGRID_ENABLE_TESTS=OFF -DMUGRID_ENABLE_EXAMPLES=OFF -DFETCHCONTENT_FULLY_DISCONNECTED=ON \
  -DFETCHCONTENT_SOURCE_DIR_PYBIND11="$SRC/pybind11" -DFETCHCONTENT_SOURCE_DIR_DLPACK="$SRC/dlpack" \
  -DPython_EXECUTABLE=$PY -DPYBIND11_FINDPYTHON=ON
cmake --build "$PREFIX/.build/muGrid" -j "$JOBS"
cmake --install "$PREFIX/.build/muGrid"

echo "== SurfaceTopography (meson-python, a C++ extension)"
sed -i '/^\[tool.meson-python\]/,/^allow-windows-internal-shared-libs/d' "$SRC/SurfaceTopography/pyproject.toml"
$PY - "$SRC/SurfaceTopography/SurfaceTopography/IO/IBW.py" <<'PATCH'
import sys
path = sys.argv[1]
text = open(path).read()
old = "from igor2.binarywave import load as loadibw\n"
new = ("try:\n    from igor2.binarywave import load as loadibw\n"
       "except ImportError:  # igor2 is no Debian package: only .ibw files need it (contactbench's peer build)\n"
       "    loadibw = None\n")
if new not in text:
    if text.count(old) != 1:
        sys.exit(f"build_contactmechanics: {path} is not the expected SurfaceTopography source")
    open(path, "w").write(text.replace(old, new))
PATCH
cat > "$PREFIX/tiffile.py" <<'TIFFILE'
# The PyPI package "tiffile" is an alias of tifffile; Debian has python3-tifffile only (contactbench peer build).
from tifffile import *  # noqa: F401,F403
from tifffile import TiffFile, TiffFileError, __version__  # noqa: F401
TIFFILE
pip_install DISCOVER_VERSION="$ST_VERSION" SurfaceTopography --config-settings=compile-args=-j$JOBS

echo "== ContactMechanics, Adhesion (pure Python; flit imports them, so they come after their dependencies)"
pip_install DISCOVER_VERSION="$CM_VERSION" ContactMechanics
pip_install DISCOVER_VERSION="$ADHESION_VERSION" Adhesion

$PY -c "import ContactMechanics, SurfaceTopography, Adhesion, muGrid, NuMPI
for m in (ContactMechanics, SurfaceTopography, Adhesion, muGrid, NuMPI):
    print(m.__name__, m.__version__)"
echo "build_contactmechanics: done; use PYTHONPATH=$PREFIX /usr/bin/python3"
