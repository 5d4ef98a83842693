#!/usr/bin/env bash
# The main job: installs dependencies, builds, and runs the mission campaign in closed loop
# (`visors run`, default scenario data/scenarios/campaign.toml; see README.md). Extra arguments go
# to `visors run` (a scenario file, --out DIR).
set -euo pipefail
# The data it reads ship in data/ (data/SOURCES.md); VISORS_DATA_PATH, when set, is searched first.
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$here/scripts/build.sh" visors
cd "$here"
"$here/build/apps/visors" run "$@"
