#!/usr/bin/env bash
# Installs animkit's build dependencies from Debian 12's own packages; with --tests, what
# `make test` and `make fuzz` add, kept apart so `make demo` stays light; with --docs, what
# `make docs` needs.
# Idempotent: when every package is already installed it does nothing (no network).
set -euo pipefail

packages=(
  build-essential cmake make ninja-build git pkg-config
  libeigen3-dev nlohmann-json3-dev libcli11-dev
  # Image decoding and PNG writing.
  libpng-dev libjpeg62-turbo-dev
  # Text drawings: FreeType and the default font, DejaVu Sans.
  libfreetype-dev fonts-dejavu-core
  libgtest-dev libgmock-dev libbenchmark-dev
  # The glTF exporters' tests read the files back with an independent reader, tinygltf.
  libtinygltf-dev
  # Pictures and the viewer: OpenGL through glvnd, Mesa's software renderer (llvmpipe) for EGL
  # without a display and GLX in a window, GLFW and Dear ImGui.
  libgl-dev libopengl-dev libegl-dev libegl-mesa0 libgl1-mesa-dri libglx-mesa0 libglfw3-dev
  libimgui-dev
  # Videos (--video) and the viewer's window test under a virtual display.
  ffmpeg xvfb xauth
  # The SVG tests check drawing.svg with a real XML parser (xmllint).
  libxml2-utils
  # Contact tests and benchmarks only: CGAL's exact triangle intersection tests audit every
  # frame (code independent of the solver's), and Bullet's soft body is the drape benchmark's
  # point of comparison. The library itself uses neither.
  libcgal-dev libbullet-dev
  # Tree IK benchmark only: Orocos KDL's tree solvers are its point of comparison.
  liborocos-kdl-dev
  # The Python module (python/): pybind11 and Debian's Python 3.11 with numpy, which Blender
  # 3.4 runs too.
  pybind11-dev python3-dev python3-numpy
)
if [ "${1:-}" = "--docs" ]; then
  # The documentation site (make docs): mkdocs and its Material theme, Doxygen for the C++
  # API reference.
  packages=(mkdocs mkdocs-material doxygen)
elif [ "${1:-}" = "--tests" ]; then
  # The tests only: Blender (Debian's 3.4, the version docs/blender.md uses) opens the
  # BVH files animkit writes and compares them with what animkit computed, and runs the add-on
  # headless; pytest runs the Python module's tests, matplotlib the examples' plots.
  # Dask (python3-distributed) runs the parameter sweep example on a local cluster.
  # The sanitizer tree (tests under ASan + UBSan, and the fuzz targets) is built with clang 16:
  # its runtime libraries (libFuzzer, ASan, UBSan).
  packages=(blender python3-pytest python3-matplotlib clang-16 libclang-rt-16-dev
            python3-distributed)
  # The glTF files are checked by the Khronos validator and three.js, npm packages run by
  # Node.js (tests/gltf/): Debian's nodejs and npm when the machine has no node of its own.
  if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
    packages+=(nodejs npm)
  fi
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
# The npm packages of the glTF checks (tests/gltf/package.json, versions pinned by its
# package-lock.json), into tests/gltf/node_modules; nothing to do once they are there.
install_npm_packages() {
  [ "${1:-}" = "--tests" ] || return 0
  local dir
  dir="$(cd "$(dirname "$0")/../tests/gltf" && pwd)"
  if [ -d "$dir/node_modules/gltf-validator" ] && [ -d "$dir/node_modules/three" ]; then
    return 0
  fi
  echo "install-deps: installing the npm packages of tests/gltf"
  (cd "$dir" && npm ci --no-audit --no-fund)
}

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages already installed"
  install_npm_packages "${1:-}"
  exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install-deps: run as root or install sudo" >&2; exit 1; }
  sudo="sudo"
fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update
$sudo apt-get install -y --no-install-recommends "${missing[@]}"
install_npm_packages "${1:-}"
