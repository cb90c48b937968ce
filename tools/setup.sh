#!/usr/bin/env bash
# Dermis set-up: installs missing Debian packages, configures and builds into
# build/, then runs one job.
#
#   tools/setup.sh demo            render content/scenes/default.json to out/default.png
#                                  and print the per-pass timings table
#   tools/setup.sh test            run the whole test suite (ctest)
#   tools/setup.sh test --quick    skip tests labelled "slow"
#   tools/setup.sh build           only install and build
#
# Run as root on Debian bookworm (apt-get needs it); elsewhere install the
# packages listed below yourself.
set -euo pipefail
cd "$(dirname "$0")/.."

job="${1:-demo}"
shift || true

packages=(
  cmake ninja-build g++ pkg-config python3 python3-glad
  libglfw3-dev libglm-dev libopenimageio-dev libtinygltf-dev nlohmann-json3-dev libimgui-dev libstb-dev
  libosmesa6-dev libegl1-mesa-dev libegl-mesa0 libgl1-mesa-dri
  libgtest-dev libgmock-dev libbenchmark-dev
  xvfb xauth python3-matplotlib
)

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}" >&2
  if [ "$(id -u)" -ne 0 ]; then
    echo "setup: these packages are missing and installing them needs root: ${missing[*]}" >&2
    exit 1
  fi
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -q >&2
  apt-get install -y -q --no-install-recommends "${missing[@]}" >&2
fi

echo "setup: configuring and building into build/" >&2
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j "$(nproc)"

case "$job" in
  build)
    ;;
  demo)
    mkdir -p out
    start=$(date +%s%N)
    build/dermis render content/scenes/default.json --size 640x360 --frames 10 \
      --out out/default.png --timings out/default.timings.json "$@"
    end=$(date +%s%N)
    echo "setup: render step took $(( (end - start) / 1000000 )) ms (out/default.png, out/default.timings.json)" >&2
    ;;
  test)
    labels=()
    if [ "${1:-}" = "--quick" ]; then labels=(-LE slow); fi
    ctest --test-dir build --output-on-failure -j "$(nproc)" "${labels[@]}"
    ;;
  *)
    echo "usage: tools/setup.sh demo|test [--quick]|build" >&2
    exit 2
    ;;
esac
