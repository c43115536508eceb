#!/usr/bin/env bash
# Installs the Debian 12 packages duet needs, and only those that are missing.
# Idempotent: a second run installs nothing and does not touch the network.
set -euo pipefail

# One line per package, grouped by the part of duet that needs it. Later issues add to this list.
packages=(
  # build
  cmake ninja-build ccache g++ pkg-config git
  # Cortex-M4 firmware
  gcc-arm-none-eabi binutils-arm-none-eabi libnewlib-arm-none-eabi libstdc++-arm-none-eabi-newlib
  # Cortex-A7 Linux (armhf) side
  g++-arm-linux-gnueabihf
  # running firmware without hardware
  qemu-system-arm qemu-user-static
  # host libraries
  libasio-dev libboost-dev libcli11-dev nlohmann-json3-dev libyaml-cpp-dev libfmt-dev libspdlog-dev libeigen3-dev
  # FMI: FMU archives are zip files (libzip), their modelDescription.xml is read and written with pugixml
  libzip-dev libpugixml-dev
  # tests, benchmarks and code checks
  googletest libgtest-dev libgmock-dev libbenchmark-dev clang-format clang-tidy
  # the bridge's benchmark compares with socat
  socat
  # docs/VERIFICATION.md loads the machine with stress-ng for the thesis' real-time test
  stress-ng
  # duet model render draws block diagrams with Graphviz
  graphviz
  # fuzzing (libFuzzer comes with clang's runtime libraries)
  clang libclang-rt-14-dev
  # the dashboard's browser tests drive Debian's Chromium (web/, docs/DASHBOARD.md)
  chromium
)
# The dashboard's front end is built with Node.js and npm: Debian's, unless a Node.js (which brings its own npm) is
# there already.
command -v node >/dev/null && command -v npm >/dev/null || packages+=(nodejs npm)

missing=()
for package in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$package" 2>/dev/null || true)
  [[ $status == "install ok installed" ]] || missing+=("$package")
done

# The front end's npm packages (web/package-lock.json), when they are not there or the lock file changed.
web_packages() {
  if [[ ! -f web/node_modules/.package-lock.json || web/package-lock.json -nt web/node_modules/.package-lock.json ]]; then
    echo "setup: installing the dashboard's npm packages (web/)"
    (cd web && npm ci --no-audit --no-fund --loglevel=error)
  fi
}

if ((${#missing[@]} == 0)); then
  echo "setup: all ${#packages[@]} packages are installed"
  web_packages
  exit 0
fi

sudo=()
if ((EUID != 0)); then
  command -v sudo >/dev/null || { echo "setup: not root and no sudo; install: ${missing[*]}" >&2; exit 1; }
  sudo=(sudo)
fi

echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -q
"${sudo[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
echo "setup: installed ${#missing[@]} packages"
web_packages
