#!/usr/bin/env bash
# Cross-builds the flight layers and their tests (VISORS_FLIGHT_ONLY, cmake/flight_only.cmake) for
# a 32- or 64-bit ARM Linux target and runs them under qemu-user through CTest; ends with CTest's
# summary line. Installs what it needs (Debian packages: the cross compiler with its own C and C++
# libraries, qemu-user, GoogleTest's sources) and unpacks the target's ERFA, the packages of the
# host's liberfa-dev version for that architecture fetched from the Debian archive, into
# BUILD_DIR/sysroot: no foreign architecture is added to dpkg.
# Usage: scripts/cross_test.sh armhf|aarch64 [BUILD_DIR (build-cross/<target>)] [ctest arguments...]
# VISORS_DEBIAN_MIRROR overrides the archive (default http://deb.debian.org/debian).
set -euo pipefail
target=${1:-}
case $target in
  armhf) triplet=arm-linux-gnueabihf; debian_arch=armhf; compiler=crossbuild-essential-armhf ;;
  aarch64) triplet=aarch64-linux-gnu; debian_arch=arm64; compiler=g++-aarch64-linux-gnu ;;
  *) echo "cross_test.sh: target '$target': must be armhf or aarch64" >&2; exit 2 ;;
esac
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${2:-$root/build-cross/$target}
shift $(($# < 2 ? $# : 2))
bash "$root/scripts/install-deps.sh" "$compiler" qemu-user googletest curl > /dev/null

sysroot=$build/sysroot
if [[ ! -f $sysroot/usr/lib/$triplet/pkgconfig/erfa.pc ]]; then
  version=$(dpkg-query -W -f='${Version}' liberfa-dev)
  version=${version#*:}  # no epoch in the file name
  mirror=${VISORS_DEBIAN_MIRROR:-http://deb.debian.org/debian}
  mkdir -p "$sysroot"
  for package in liberfa1 liberfa-dev; do
    deb="$build/${package}_${version}_${debian_arch}.deb"
    curl -fsSL -o "$deb" "$mirror/pool/main/e/erfa/${package}_${version}_${debian_arch}.deb"
    dpkg-deb -x "$deb" "$sysroot"
  done
fi

export VISORS_TARGET_SYSROOT=$sysroot
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DVISORS_FLIGHT_ONLY=ON \
  -DCMAKE_TOOLCHAIN_FILE="$root/cmake/toolchains/$target.cmake" -DVISORS_TARGET_SYSROOT="$sysroot" > /dev/null
cmake --build "$build"
# Every flight test but the few that take 20 s to 2 min each under emulation (seconds on the host,
# where the test suite runs them): the randomised slot bookkeeping (1e5 epochs), the transfer
# and standby legs flown with and without the drag aim, the multipath filter fixtures, the
# passive-safety margins against dense sampling and Monte Carlo, the acceptance statistics at
# 16 and 24 ambiguities (8 and 12 run).
slow='^(AmbiguitySlotsAgainstResizingFilter\.(HundredThousand|FlightDynamicRange)|FlightComponent\.(TransferLegs|StandbyPlan)|CdgpsFilterMultipath\.|PassiveSafety\.(ClosedFormMatchesDense|QSigmaMargin|HorizonMinimumMatchesDense)|SingleFrequencyDd/AcceptanceStatistics\..*/n(16|24))'
ctest --test-dir "$build" --output-on-failure -j "$(nproc)" --timeout 900 -E "$slow" "$@"
