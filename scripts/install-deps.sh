#!/usr/bin/env bash
# Installs the Debian 12 packages that shpack needs to build, test and benchmark.
# Packages already installed are not touched, so a second run costs a few dpkg-query calls.
# Needs root (or sudo) only when something is missing.
set -euo pipefail

packages=(
  cmake g++ make                 # the toolchain
  ninja-build                    # scripts/test.sh's builds
  libopenimageio-dev             # image reading (lib/io)
  openimageio-tools              # iinfo, oiiotool: look at and make test images
  libopenexr-dev                 # OpenEXR, which OpenImageIO reads .exr with
  nlohmann-json3-dev             # JSON (lib/io)
  libssl-dev                     # SHA-256 of inputs (lib/io), with the CPU's SHA extensions
  libcli11-dev                   # the command line (cli/)
  libembree-dev                  # ray tracing of shpack bake's visibility effects (lib/bake)
  libvalijson-dev                # JSON Schema validation of scene files (lib/io)
  libgtest-dev                   # tests/
  libbenchmark-dev               # bench/
  mono-mcs mono-runtime          # tests/unity: the Unity package's C# compiled and run under Mono
  libnewtonsoft-json-cil-dev     # tests/unity: Json.NET, which the package reads documents with
  clang libclang-rt-14-dev       # tests/fuzz: libFuzzer targets (clang++ -fsanitize=fuzzer)
  gnuplot-nox                    # shpack bench --plot
  fonts-dejavu-core              # shpack preview's labels: DejaVu Sans, drawn through OpenImageIO's FreeType
  help2man                       # the man page that cmake --install installs, from shpack --help
  libfilament-tools              # tests/io: cmgen, against which --format filament is checked
  nodejs                         # tests/io: node runs three.js on --format threejs's output
  pybind11-dev python3-dev       # python/: the shpack module (SHPACK_BUILD_PYTHON)
  python3-numpy                  # tests/python: the module's arrays, with Debian's /usr/bin/python3
  python3-distributed            # shpack.dask: bakes on Dask distributed (python/shpack/dask.py)
)

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q '^install ok installed$'; then
    missing+=("$package")
  fi
done
# npm fetches three.js for that test; some nodejs builds carry it, Debian's comes apart.
command -v npm >/dev/null || missing+=(npm)
if ((${#missing[@]} == 0)); then
  exit 0
fi

as_root=()
if ((EUID != 0)); then
  if ! command -v sudo >/dev/null; then
    echo "install-deps: missing ${missing[*]}; run as root to install them" >&2
    exit 1
  fi
  as_root=(sudo)
fi
echo "install-deps: installing ${missing[*]}" >&2
"${as_root[@]}" apt-get update
"${as_root[@]}" env DEBIAN_FRONTEND=noninteractive \
  apt-get install -y --no-install-recommends "${missing[@]}"
