#!/usr/bin/env bash
# Builds the libFuzzer targets (the records' decoder; the component's input handling) with clang
# (a separate build folder, build-fuzz/) and runs each for
# SECONDS (default 60) on its corpus folder (out/fuzz/<target>, created and kept between runs).
# A crash leaves its input in the current folder (crash-*) and exits non-zero. Needs Debian's
# clang (apt install clang).
# Usage: scripts/fuzz.sh [SECONDS] [BUILD_DIR (build-fuzz)]
set -euo pipefail
seconds=${1:-60}
build=${2:-build-fuzz}
root=$(cd "$(dirname "$0")/.." && pwd)
command -v clang++ > /dev/null || { echo "fuzz.sh: clang++ not found (apt install clang)" >&2; exit 2; }
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo -DVISORS_FUZZ=ON \
  -DVISORS_BUILD_TESTS=OFF -DVISORS_BUILD_BENCH=OFF -DVISORS_FLIGHT_PROFILE=OFF > /dev/null
cmake --build "$build" --target fuzz_channel_record fuzz_record_interface
for target in channel_record record_interface; do
  corpus="$root/out/fuzz/$target"
  mkdir -p "$corpus"
  "$build/fuzz/fuzz_$target" -max_total_time="$seconds" -print_final_stats=1 "$corpus"
done
