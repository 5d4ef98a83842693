#!/usr/bin/env bash
# The main job: installs dependencies, builds, and runs the formation preview of the mission's
# standby and science relative orbits (see README). Extra arguments go to `visors preview`.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
if [[ -z "${VISORS_DATA_PATH:-}" && -d "$here/../shared/data" ]]; then
  export VISORS_DATA_PATH="$(cd "$here/../shared/data" && pwd)"
fi
bash "$here/scripts/build.sh" visors
cd "$here"
"$here/build/apps/visors" preview "$@"
