#!/usr/bin/env bash
# The whole test suite: installs dependencies, builds, runs every test with CTest.
# Reference data are found through VISORS_DATA_PATH; when unset, ../shared/data beside the
# checkout is used if present (tests needing data skip with a message otherwise).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
if [[ -z "${VISORS_DATA_PATH:-}" && -d "$here/../shared/data" ]]; then
  export VISORS_DATA_PATH="$(cd "$here/../shared/data" && pwd)"
fi
bash "$here/scripts/build.sh"
ctest --test-dir "$here/build" --output-on-failure -j "$(nproc)" --timeout 600 "$@"
