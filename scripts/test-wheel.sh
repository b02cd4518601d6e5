#!/usr/bin/env bash
# The Python package as a pip user gets it: builds a wheel from this tree with pip (offline, against Debian's
# scikit-build, setuptools, wheel and pybind11: pyproject.toml), installs it into a fresh venv that sees Debian's
# numpy and pytest (--system-site-packages), and runs python/tests against the INSTALLED package from a folder
# outside the tree, so neither the build folder nor python/ can be imported by mistake. scripts/test.sh runs it
# in CI (CB_CI=1); by hand: scripts/test-wheel.sh
set -euo pipefail
cd "$(dirname "$0")/.."
source_dir=$PWD
python=/usr/bin/python3

# The build backends and venv support, from Debian (no Python index is reachable in CI).
packages=(python3-skbuild python3-setuptools python3-wheel python3-venv python3-pip pybind11-dev python3-dev
          python3-numpy python3-pytest cmake g++)
missing=()
for package in "${packages[@]}"; do
  [[ $(dpkg-query -W -f='${Status}' "$package" 2>/dev/null || true) == "install ok installed" ]] || missing+=("$package")
done
if [[ ${#missing[@]} -gt 0 ]]; then
  echo "test-wheel: installing ${missing[*]}" >&2
  sudo_cmd=()
  [[ $(id -u) -ne 0 ]] && sudo_cmd=(sudo)
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
start=$SECONDS
"$python" -m venv --system-site-packages "$work/venv"
venv_python=$work/venv/bin/python
# scikit-build keeps its CMake build in _skbuild/ (git-ignored): a second run rebuilds only what changed.
export CMAKE_BUILD_PARALLEL_LEVEL=${CMAKE_BUILD_PARALLEL_LEVEL:-$(nproc)}
"$venv_python" -m pip wheel --no-build-isolation --no-deps --no-index --wheel-dir "$work/wheels" "$source_dir"
wheel=$(echo "$work"/wheels/contactbench-*.whl)
echo "test-wheel: built $(basename "$wheel") in $((SECONDS - start)) s"
"$venv_python" -m pip install --no-index --no-deps "$wheel"

cd "$work"
"$venv_python" -c 'import contactbench, sys; assert contactbench.__file__.startswith(sys.argv[1]), contactbench.__file__' \
  "$work/venv/"
# The CLI is not in the wheel: the tests that compare with it use the release build's program when there is one.
cli=$source_dir/build/release/app/contactbench
[[ -x "$cli" ]] && export CB_CLI_PATH=$cli
CB_SOURCE_DIR=$source_dir OMP_WAIT_POLICY=PASSIVE CONTACTBENCH_FFTW_WISDOM=none "$venv_python" -m pytest -q -p no:cacheprovider \
  --rootdir "$source_dir/python/tests" "$source_dir/python/tests"
# Under an interpreter without numpy the import fails at once, saying what is missing (a venv without Debian's
# site packages has no numpy).
"$python" -m venv "$work/bare"
"$work/bare/bin/python" -m pip install --no-index --no-deps --quiet "$wheel"
if message=$("$work/bare/bin/python" -c 'import contactbench' 2>&1); then
  echo "test-wheel: contactbench imported without numpy" >&2
  exit 1
fi
grep -q "contactbench needs numpy" <<<"$message" || { echo "test-wheel: unclear error without numpy: $message" >&2; exit 1; }
echo "test-wheel: wheel built, installed and tested in $((SECONDS - start)) s"
