#!/usr/bin/env bash
# Installs missing dependencies (Debian 12 packages), configures and builds the project into
# build/ (Release, Ninja). Safe to run repeatedly: only what changed is rebuilt.
# Arguments, if any, are the CMake targets to build (default: everything).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$here/scripts/install-deps.sh"
jobs="${VISORS_BUILD_JOBS:-$(nproc)}"
if [[ ! -f "$here/build/build.ninja" ]]; then
  cmake -S "$here" -B "$here/build" -G Ninja -DCMAKE_BUILD_TYPE=Release ${VISORS_CMAKE_ARGS:-} >/dev/null
fi
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build "$here/build" -j "$jobs" "${targets[@]}"
