#!/usr/bin/env bash
# NEES and NIS of the navigation filter over seeds (the consistency acceptance,
# docs/requirements.md#navigation-acceptance-figures: within their two-sided 95 % chi-square
# bounds averaged over >= 20 seeds). For seeds 1..N: `visors gnss-sim` of the default
# scenario (one orbit, or DURATION_S) with that seed, then `visors nav`; then, per filter, the
# fraction of epochs (from 300 s after the first fix) whose NEES of the antennas' relative
# position averaged over the N runs, and whose pooled NIS (all scalars, then GRAPHIC and SDCP
# alone), lie inside their 95 % bounds.
# Usage: scripts/nav_seeds.sh [N (20)] [DURATION_S (5700)] [BUILD_DIR (build)] [WORK_DIR (out/nav-seeds)]
set -euo pipefail
n=${1:-20}
duration=${2:-5700}
build=${3:-build}
work=${4:-out/nav-seeds}
root=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$work"
for seed in $(seq 1 "$n"); do
  scenario="$work/seed$seed.toml"
  sed -e "s/^seed = .*/seed = $seed/" -e "0,/^duration_s = .*/s//duration_s = $duration/" \
    "$root/data/scenarios/gnss_sim.toml" > "$scenario"
  "$build/apps/visors" gnss-sim "$scenario" --out "$work/run$seed" > /dev/null
  "$build/apps/visors" nav "$work/run$seed" --out "$work/nav$seed" > /dev/null
done
/usr/bin/python3 - "$work" "$n" <<'PY'
import csv, json, sys
from statistics import mean
work, n = sys.argv[1], int(sys.argv[2])

def chi2_quantile(dof, z):  # Wilson-Hilferty approximation of the chi-square quantile
    return dof * (1 - 2 / (9 * dof) + z * (2 / (9 * dof)) ** 0.5) ** 3

for craft in ("dsc", "osc"):
    nees_by_t, nis_by_t, antenna, fix, wrong, absolute = {}, {}, [], [], 0, []
    for seed in range(1, n + 1):
        s = next(f for f in json.load(open(f"{work}/nav{seed}/summary.json"))["filters"] if f["filter"] == craft)
        c = s["converged"]
        absolute.append(c["absolute_position_rms_m"]); antenna.append(c["relative_antenna_rms_m"]); fix.append(c["fix_rate"]); wrong += c["wrong_fix_epochs"]
        start = s["start_s"] + s["time_to_first_fix_s"] + 300.0
        for row in csv.DictReader(open(f"{work}/nav{seed}/nav_{craft}.csv")):
            t = float(row["t_s"])
            if t < start or row["status"] == "outage":
                continue
            nees_by_t.setdefault(t, []).append(float(row["antenna_nees"]))
            a = nis_by_t.setdefault(t, [0.0] * 6)
            for i, (total, count) in enumerate((("nis_sum", "nis_count"), ("graphic_nis_sum", "graphic"),
                                                ("sdcp_nis_sum", "sdcp_used"))):
                a[2 * i] += float(row[total]); a[2 * i + 1] += int(row[count])
    # Per epoch, the mean over the runs of NEES (3 dof each) against chi2(3 N)/N, and the pooled
    # NIS against chi2(M)/M, M the scalars of that epoch over all runs (Bar-Shalom, Li &
    # Kirubarajan 2001, sec. 5.4): the fraction of epochs inside the two-sided 95 % bounds.
    inside_nees = total = 0
    inside_nis, nis_means = [0, 0, 0], [[], [], []]
    nees_means = []
    for t, values in nees_by_t.items():
        if len(values) != n:
            continue
        m = mean(values)
        lo, hi = chi2_quantile(3 * n, -1.959964) / n, chi2_quantile(3 * n, 1.959964) / n
        inside_nees += lo <= m <= hi
        for i in range(3):
            s, k = nis_by_t[t][2 * i], nis_by_t[t][2 * i + 1]
            if k == 0:
                continue
            q = s / k
            inside_nis[i] += chi2_quantile(k, -1.959964) / k <= q <= chi2_quantile(k, 1.959964) / k
            nis_means[i].append(q)
        nees_means.append(m); total += 1
    nis = ", ".join(f"{name} {mean(nis_means[i]):.2f} ({100 * inside_nis[i] / len(nis_means[i]):.1f} %)"
                    for i, name in enumerate(("all", "GRAPHIC", "SDCP")))
    print(f"{craft} filter over {n} seeds: NEES {mean(nees_means):.2f} (epochs inside the 95 % bounds "
          f"{100 * inside_nees / total:.1f} %), NIS {nis}; antennas {1e3 * mean(antenna):.2f} mm RMS (worst run "
          f"{1e3 * max(antenna):.2f}); fix rate {100 * mean(fix):.2f} %; wrong-fix epochs {wrong}; absolute "
          f"{mean(absolute):.2f} m RMS")
PY
