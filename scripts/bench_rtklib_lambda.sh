#!/usr/bin/env bash
# RTKLIB's lambda() and visors' IntegerLeastSquares on the same IAR benchmark instances, back to
# back on this machine, so that their ratio is measured in one session (RTKLIB's own time at n = 24
# varies by ~1.5x between sessions: docs/results.md "Performance").
# Usage: scripts/bench_rtklib_lambda.sh RTKLIB_SOURCE_DIR [BUILD_DIR]
#   RTKLIB_SOURCE_DIR: a checkout of RTKLIB (its src/ holds lambda.c, rtkcmn.c, rtklib.h), e.g.
#   git clone https://github.com/tomojitakasu/RTKLIB (2.4.2 p13 was used in docs/results.md).
# Needs the build's visors_export_ambiguity_instances and visors_bench_ambiguity.
set -euo pipefail
rtklib=${1:?usage: $0 RTKLIB_SOURCE_DIR [BUILD_DIR]}
build=${2:-build}
root=$(cd "$(dirname "$0")/.." && pwd)
[[ -f "$rtklib/src/lambda.c" ]] || { echo "error: $rtklib/src/lambda.c not found" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# RTKLIB's own optimisation level in its makefiles is -O3; -O2 is the level of the comparison
# docs/results.md reports ("Performance").
gcc -O2 -I "$rtklib/src" -o "$work/driver" "$root/bench/peers/rtklib_lambda_driver.c" \
  "$rtklib/src/lambda.c" "$rtklib/src/rtkcmn.c" -lm -lpthread 2> "$work/gcc.log" || { cat "$work/gcc.log" >&2; exit 1; }
"$build/bench/visors_export_ambiguity_instances" "$work/instances.bin"
"$work/driver" "$work/instances.bin" 2> /dev/null  # lambda.c prints each loop-cap overflow on stderr
"$build/bench/visors_bench_ambiguity" 2> /dev/null | grep '^BM_' | awk '{printf "visors ILS     %-26s %s  %s  %s (per sweep of 50)\n", $1, $(NF-1), $NF, $(NF-4)}'
