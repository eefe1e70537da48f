#!/usr/bin/env bash
# Installs what Rigsmith needs (Debian 12), builds it (Release) and opens the
# editor on the sample biped guide.
#   ./run.sh                 build and open the editor
#   ./run.sh --build-only    install and build, do not open anything
#   ./run.sh -- ARGS...      pass ARGS to the editor instead of the sample guide
set -euo pipefail
cd "$(dirname "$0")"

# libopenblas0-serial becomes the system's BLAS (Debian's alternatives): CHOLMOD's
# supernodal Cholesky (weight inpainting) is 4-8x slower on the reference BLAS. Serial,
# not -pthread: on two cores shared with other work, BLAS threads spin in sched_yield
# and took 2.5x the wall time (core/skin/README.md).
PACKAGES=(
  build-essential cmake ninja-build pkg-config
  qt6-base-dev libqt6opengl6-dev qt6-svg-dev libqt6svg6 qt6-qpa-plugins
  libgl-dev libepoxy-dev libglfw3-dev libgl1-mesa-dri
  libyaml-cpp-dev libglm-dev libtinygltf-dev nlohmann-json3-dev libassimp-dev
  libeigen3-dev libembree-dev libtbb-dev libnanoflann-dev libsuitesparse-dev libopenblas0-serial
  libjemalloc-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  xvfb xauth
)
# Used by the test suite only: real consumers of our exports (Blender, Godot 3's
# headless server), the meshes of
# assimp-testmodels (a human to bind), and clang with its runtime libraries
# (libFuzzer, sanitizers) for the fuzz targets.
TEST_PACKAGES=(blender python3-numpy assimp-testmodels clang libclang-rt-dev godot3-server)

build_only=0
editor_args=()
while [ $# -gt 0 ]; do
  case "$1" in
    --build-only) build_only=1 ;;
    --with-test-tools)
      PACKAGES+=("${TEST_PACKAGES[@]}")
      command -v npm >/dev/null || PACKAGES+=(nodejs npm) ;;
    --) shift; editor_args=("$@"); break ;;
    *) echo "run.sh: unknown option $1" >&2; exit 2 ;;
  esac
  shift
done

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "Installing: ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -q
  $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

BUILD_DIR=${RIGSMITH_BUILD_DIR:-build}
cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$BUILD_DIR" -j"$(nproc)"

[ "$build_only" -eq 1 ] && exit 0

[ ${#editor_args[@]} -eq 0 ] && editor_args=(resources/samples/biped.yml)
if [ -z "${DISPLAY:-}" ] && [ -z "${WAYLAND_DISPLAY:-}" ]; then
  echo "No display found: starting the editor on a virtual X server (xvfb-run)." >&2
  exec xvfb-run -a -s "-screen 0 1600x1000x24" "$BUILD_DIR/app/rigsmith" "${editor_args[@]}"
fi
exec "$BUILD_DIR/app/rigsmith" "${editor_args[@]}"
