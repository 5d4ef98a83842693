#!/usr/bin/env bash
# The default campaign (`visors run data/scenarios/campaign.toml`) over seeds 1..N: per run its
# observations, success rate, delta-v, minimum separation, wall time and the on-board navigation's
# figures (the headline run: seeds 1-5); then the pooled success rate over every attempt.
# Usage: scripts/campaign_seeds.sh [N (5)] [BUILD_DIR (build)] [WORK_DIR (out/campaign-seeds)] [MODE (scenario's)]
# VISORS_BIN overrides the binary (default BUILD_DIR/apps/visors).
set -euo pipefail
n=${1:-5}
build=${2:-build}
work=${3:-out/campaign-seeds}
mode=${4:-}
root=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$work"
for seed in $(seq 1 "$n"); do
  scenario="$work/seed$seed.toml"
  sed -e "s/^seed = .*/seed = $seed/" "$root/data/scenarios/campaign.toml" > "$scenario"
  if [ -n "$mode" ]; then sed -i "s/^mode = .*/mode = \"$mode\"/" "$scenario"; fi
  "${VISORS_BIN:-$build/apps/visors}" run "$scenario" --out "$work/run$seed" > /dev/null
done
/usr/bin/python3 - "$work" "$n" <<'PY'
import json, sys
work, n = sys.argv[1], int(sys.argv[2])
attempts = successes = 0
for seed in range(1, n + 1):
    s = json.load(open(f"{work}/run{seed}/summary.json"))
    obs = s["observations"]
    attempts += len(obs); successes += sum(o["success"] for o in obs)
    dv = s["delta_v_mps"]
    line = (f"seed {seed}: {len(obs)} attempts, {sum(o['success'] for o in obs)} successes; "
            f"lateral {1e3 * sum(o['lateral_error_m'] for o in obs) / max(len(obs), 1):.1f} mm mean; "
            f"dv OSC {dv['osc']['total']:.4f} DSC {dv['dsc']['total']:.4f} m/s; min RN {s['min_separation_rn_m']:.2f} m; "
            f"violations {s['safety_violations']}; wall {s['wall_s']:.1f} s")
    print(line)
    for craft, v in s.get("navigation", {}).items():
        o = v["outside_slews"]
        print(f"  {craft}: antennas {1e3 * v['relative_antenna_rms_m']:.2f} mm RMS ({1e3 * o['relative_antenna_rms_m']:.2f} outside slews, "
              f"worst {1e3 * o['relative_antenna_worst_m']:.2f}), centres of mass {1e3 * v['relative_position_rms_m']:.2f} mm, "
              f"velocity {1e6 * v['relative_velocity_rms_mps']:.1f} um/s; fix {100 * v['fix_rate']:.3f} %, "
              f"wrong {v['wrong_fix_epochs']}, TTFF {v['time_to_first_fix_s']:.0f} s")
print(f"pooled: {successes} of {attempts} attempts succeeded ({100 * successes / max(attempts, 1):.0f} %)")
PY
