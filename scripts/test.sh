#!/usr/bin/env bash
# The whole test suite: installs dependencies, builds, runs every test with CTest.
# The reference data the tests read ship in data/ (data/SOURCES.md); VISORS_DATA_PATH, when set,
# is searched first.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$here/scripts/build.sh"
ctest --test-dir "$here/build" --output-on-failure -j "$(nproc)" --timeout 600 "$@"
