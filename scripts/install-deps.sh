#!/usr/bin/env bash
# Installs the Debian 12 packages ncbridge builds and tests with; only the missing ones.
# Usage: scripts/install-deps.sh [--tests]   (root, or sudo available)
set -euo pipefail

packages=(
  build-essential cmake ninja-build ccache pkg-config git
  protobuf-compiler libprotobuf-dev
  cyclonedds-dev cyclonedds-tools
  libeigen3-dev libcgal-dev libgmp-dev libmpfr-dev
  libpolyclipping-dev  # Clipper: the recogniser's integer-grid Boolean operations
  libspdlog-dev libfmt-dev
  libcli11-dev libyaml-cpp-dev nlohmann-json3-dev
  googletest libgtest-dev libgmock-dev libbenchmark-dev
  libpugixml-dev libcurl4-openssl-dev  # live capture: MTConnect agents' XML over HTTP
  libssl-dev  # SHA-256 of written files (services), openssl for the DDS Security test PKI
  libjs-three  # three.js, inlined into convert --html's 3D view at build time
  # Open CASCADE: STEP B-rep part files (part_reader only)
  libocct-foundation-dev libocct-modeling-data-dev libocct-modeling-algorithms-dev libocct-data-exchange-dev
  libtbb-dev  # the OCCT CMake targets link libtbb.so, which only the -dev package provides
)
if [[ "${1:-}" == "--tests" ]]; then
  # clang + its runtime for libFuzzer targets and sanitizer builds; iproute2 for multi-host tests.
  packages+=(clang libclang-rt-14-dev iproute2 python3)
  # podman + runc: the container test of the services (installs in ~20 s; the test takes ~20 s).
  packages+=(openssl podman runc procps)
  # The reference tools the tests compare with: LinuxCNC's standalone interpreter `rs274` and its
  # simulated controller (linuxcnc-uspace), and a headless browser for the HTML pages.
  packages+=(linuxcnc-uspace chromium)
  # The install test: bash completion run as bash runs it, the man page rendered, the .deb made.
  packages+=(bash-completion groff-base man-db dpkg-dev)
  # scripts/make-doc-pictures.sh: the docs' screenshots (Chromium) made small.
  packages+=(pngquant optipng)
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]} == 0)); then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi
echo "install-deps: installing ${missing[*]}"
SUDO=""
[[ $(id -u) -ne 0 ]] && SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
