#!/usr/bin/env bash
# Installs the build and test dependencies of the project from Debian 12 packages, and the extra
# packages given as arguments (scripts/cross_test.sh: a cross compiler, qemu-user).
# Idempotent: packages already present are skipped. Run as root (or with sudo available).
# Usage: scripts/install-deps.sh [extra packages...]
set -euo pipefail

PACKAGES=(
  build-essential cmake ninja-build pkg-config
  libeigen3-dev liberfa-dev nlohmann-json3-dev libtomlplusplus-dev libcli11-dev libfmt-dev
  libgtest-dev libgmock-dev libbenchmark-dev libgeographiclib-dev libsqlite3-dev
  openmpi-bin libopenmpi-dev
  python3 python3-cvxopt python3-numpy universal-ctags
  python3-dev pybind11-dev python3-pytest doxygen
  chromium
  "$@"
)

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if ((${#missing[@]} == 0)); then
  exit 0
fi

SUDO=""
if [[ $(id -u) -ne 0 ]]; then SUDO="sudo"; fi
echo "install-deps: installing ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get -o DPkg::Lock::Timeout=600 update -qq
$SUDO apt-get -o DPkg::Lock::Timeout=600 install -y -qq --no-install-recommends "${missing[@]}"
