#!/usr/bin/env bash
# Installs the Debian/Ubuntu packages the project builds and tests with, if any are
# missing: with apt-get as root, with sudo if it needs no password, otherwise it prints
# the exact command and stops. With --opencsg it adds the packages lesson 14's benchmark beside
# OpenCSG needs (tests/bench/csg_opencsg_benchmark.cpp); the default build does without them.
# With --web it adds what the course in a browser needs (cmake --preset web, ctest -L web):
# Emscripten, pandoc for the pages, Chromium for the tests; the native course does without them.
set -euo pipefail

packages=(
  build-essential cmake pkg-config   # toolchain
  python3-glad                       # generates the GL loader at configure time
  libglm-dev libstb-dev              # maths, PNG files
  libegl-dev libegl-mesa0 libgl1-mesa-dri  # EGL headless contexts (llvmpipe without a GPU)
  libgl1 libglx-mesa0                # GLX for the window (GLFW loads libGL at run time)
  libglfw3-dev libimgui-dev          # the window and its panel
  libtinyobjloader-dev               # OBJ meshes in scene files
  libembree-dev                      # the converged soft-shadow reference (Embree 3; optional)
  nlohmann-json3-dev                 # the --stats JSON, written and read
  python3-matplotlib                 # the sweeps' plots (tests/sweeps/plot_sweeps.py)
  libgtest-dev libbenchmark-dev      # unit tests, micro-benchmarks
  xvfb xauth xdotool                 # the window tests run under a virtual display and press keys
)
optional=(libosmesa6-dev)            # newer Mesa releases dropped OSMesa; EGL then serves
for group in "$@"; do
  case "$group" in
    --opencsg) packages+=(libopencsg-dev libglew-dev libx11-dev libgl-dev) ;;  # OpenCSG 1.5 draws through GLEW on GLX
    # Emscripten's optimizer needs acorn (node-acorn, found through NODE_PATH=/usr/share/nodejs).
    --web) packages+=(emscripten node-acorn pandoc chromium) ;;
    *) echo "install-deps.sh: unknown group '$group' (--opencsg, --web)" >&2; exit 2 ;;
  esac
done

installed() { dpkg-query -W -f='${Status}' "$1" 2>/dev/null | grep -q "install ok installed"; }

missing=()
for p in "${packages[@]}"; do installed "$p" || missing+=("$p"); done
missing_optional=()
for p in "${optional[@]}"; do installed "$p" || missing_optional+=("$p"); done
[ ${#missing[@]} -eq 0 ] && [ ${#missing_optional[@]} -eq 0 ] && exit 0

if [ "$(id -u)" -eq 0 ]; then
  sudo=()
elif command -v sudo >/dev/null && sudo -n true 2>/dev/null; then
  sudo=(sudo)
else
  echo "Missing packages. Install them with:" >&2
  echo "  sudo apt-get update && sudo apt-get install -y ${missing[*]} ${missing_optional[*]}" >&2
  exit 1
fi

echo "Installing: ${missing[*]} ${missing_optional[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -qq
# Optional packages only where this release still has them.
for p in "${missing_optional[@]}"; do
  if apt-cache show "$p" >/dev/null 2>&1; then missing+=("$p"); else echo "($p is not in this release: skipped)" >&2; fi
done
"${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
