#!/usr/bin/env bash
# Dermis set-up: installs missing Debian packages, configures and builds into
# build/, then runs one job.
#
#   tools/setup.sh demo            render content/scenes/default.json to out/default.png
#                                  and print the per-pass timings table
#   tools/setup.sh test            run the whole test suite (ctest)
#   tools/setup.sh test --quick    skip tests labelled "slow"
#   tools/setup.sh build           only install and build
#   tools/setup.sh sanitize        build the unit tests into build-asan/ with
#                                  AddressSanitizer and UBSan instead, and run
#                                  them there (all but those labelled "slow")
#
# Run as root on Debian bookworm (apt-get needs it); elsewhere install the
# packages listed below yourself.
set -euo pipefail
cd "$(dirname "$0")/.."

usage="usage: tools/setup.sh demo|test [--quick]|build|sanitize"
job="${1:-demo}"
shift || true
case "$job" in
  demo|test|build|sanitize) ;;
  -h|--help|help)
    sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'
    echo "$usage"
    exit 0
    ;;
  *)
    echo "$usage" >&2
    exit 2
    ;;
esac

packages=(
  cmake ninja-build g++ pkg-config python3 python3-glad ccache
  libglfw3-dev libglm-dev libopenimageio-dev libtinygltf-dev nlohmann-json3-dev libimgui-dev libstb-dev
  libosmesa6-dev libegl1-mesa-dev libegl-mesa0 libgl1-mesa-dri
  libgtest-dev libgmock-dev libbenchmark-dev libembree-dev libtbb-dev libmeshoptimizer-dev gltfpack libdraco-dev draco
  xvfb xauth python3-matplotlib parallel
  dpkg-dev file  # cpack: the .deb's dependencies (dpkg-shlibdeps)
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

# build_into DIR TARGET [CMAKE_ARGS...]: configures the project into DIR and
# builds TARGET ("all" for everything).
build_into() {
  local dir="$1" target="$2"
  shift 2
  echo "setup: configuring and building into $dir/" >&2
  # ccache (in ~/.cache/ccache) keeps compiled objects across clones: a CI run
  # on a fresh clone recompiles only what changed since the last one. Paths
  # under the clone are hashed relative to it.
  export CCACHE_BASEDIR="$PWD"
  cmake -S . -B "$dir" -G Ninja -DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache "$@" >/dev/null
  cmake --build "$dir" -j "$(nproc)" --target "$target"
}

if [ "$job" = sanitize ]; then
  # Debug information for the sanitizers' stack traces; the build/ tree is
  # left alone.
  build_into build-asan dermis_unit_tests -DCMAKE_BUILD_TYPE=RelWithDebInfo -DDERMIS_SANITIZE=ON
  # Docs.FrontDoorAndLinks reads the docs and runs build-asan/dermis, which this job does not build.
  ctest --test-dir build-asan -L unit -LE slow -E '^Docs[.]' --output-on-failure -j "$(nproc)"
  exit
fi

# The demo needs only the program; the tests and benchmarks are built by the
# jobs that run them.
if [ "$job" = demo ]; then
  build_into build dermis -DCMAKE_BUILD_TYPE=Release
else
  build_into build all -DCMAKE_BUILD_TYPE=Release
fi

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
esac
