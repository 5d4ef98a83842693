#!/usr/bin/env bash
# The whole test suite: installs dependencies, builds, runs every test with CTest; then the flight
# tests cross-built for 32- and 64-bit ARM and run under qemu-user (scripts/cross_test.sh), each
# ending with its CTest summary line. VISORS_CROSS_TARGETS chooses the targets (default "armhf
# aarch64"; empty: none, said so). The reference data the tests read ship in data/
# (data/SOURCES.md); VISORS_DATA_PATH, when set, is searched first.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$here/scripts/build.sh"
ctest --test-dir "$here/build" --output-on-failure -j "$(nproc)" --timeout 600 "$@"
targets=${VISORS_CROSS_TARGETS-armhf aarch64}
if [[ -z $targets ]]; then
  echo "test.sh: no ARM cross-build (VISORS_CROSS_TARGETS is empty)" >&2
fi
for target in $targets; do
  echo "test.sh: the flight tests for $target under qemu-user (scripts/cross_test.sh $target)" >&2
  bash "$here/scripts/cross_test.sh" "$target" "$here/build-cross/$target"
done
