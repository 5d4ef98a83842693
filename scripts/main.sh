#!/usr/bin/env bash
# The main job: installs dependencies, builds, and runs the mission campaign in closed loop
# (`visors run`, default scenario data/scenarios/campaign.toml; see README). Extra arguments go
# to `visors run` (a scenario file, --out DIR).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
if [[ -z "${VISORS_DATA_PATH:-}" && -d "$here/../shared/data" ]]; then
  export VISORS_DATA_PATH="$(cd "$here/../shared/data" && pwd)"
fi
bash "$here/scripts/build.sh" visors
cd "$here"
"$here/build/apps/visors" run "$@"
