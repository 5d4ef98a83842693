#!/usr/bin/env bash
# Instructions per step of the flight software (docs/flight-software-process.md#cost-per-step):
# runs SCENARIO with both spacecraft's flight software as visors-fsw processes, the one of CRAFT
# under valgrind's callgrind with a dump after every step (gnc::RecordInterface::step: the step
# and the reading of its records), and prints the count of the creation with the first step and
# the median, p99, p99.9 and max of the other steps, with the worst steps' numbers (step n is the
# simulated second n - 1). Valgrind slows the process about fifty times: an hour of the campaign
# takes a few minutes. Not a test. Needs valgrind and the host build (scripts/build.sh).
# Usage: scripts/fsw_step_instructions.sh SCENARIO [CRAFT (osc)] [OUT_DIR (a temporary one)]
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
scenario=${1:?usage: fsw_step_instructions.sh SCENARIO [CRAFT] [OUT_DIR]}
craft=${2:-osc}
out=${3:-$(mktemp -d)}
bash "$root/scripts/install-deps.sh" valgrind > /dev/null
mkdir -p "$out/callgrind"
cat > "$out/fsw.sh" <<WRAPPER
#!/bin/sh
case "\$*" in
  *"--craft $craft"*) cd "$out/callgrind" && exec valgrind --tool=callgrind --callgrind-out-file="$out/callgrind/cg.out" \
      --dump-after='visors::gnc::RecordInterface::step*' --dump-instr=no --dump-line=no "$root/build/apps/visors-fsw" "\$@" ;;
  *) exec "$root/build/apps/visors-fsw" "\$@" ;;
esac
WRAPPER
chmod +x "$out/fsw.sh"
# One dump file per step: each is read for its total and removed as the run goes (all but the
# newest), so the folder stays small.
collect() {
  /usr/bin/python3 - "$out/callgrind" "$out/steps.csv" "$1" <<'PY'
import os, re, sys
folder, table, final = sys.argv[1], sys.argv[2], sys.argv[3] == "final"
numbers = sorted(int(n.rsplit(".", 1)[1]) for n in os.listdir(folder) if re.fullmatch(r"cg\.out\.\d+", n))
with open(table, "a") as out:
    for n in numbers if final else numbers[:-1]:
        path = f"{folder}/cg.out.{n}"
        total = next((int(l.split()[1]) for l in open(path, errors="replace") if l.startswith("totals:")), None)
        if total is not None:
            out.write(f"{n},{total}\n")
        os.remove(path)
PY
}
: > "$out/steps.csv"
"$root/build/apps/visors" run "$scenario" --out "$out/run" --threads 1 --fsw process --fsw-command "$out/fsw.sh" > "$out/run.log" &
run=$!
while kill -0 "$run" 2> /dev/null; do collect running; sleep 5; done
wait "$run"
collect final
/usr/bin/python3 - "$out/steps.csv" <<'PY'
import sys
import numpy as np
d = np.loadtxt(sys.argv[1], delimiter=",", dtype=np.int64, ndmin=2)
d = d[np.argsort(d[:, 0])]
steps = d[d[:, 0] >= 2]
ir = steps[:, 1]
print(f"creation and step 1: {d[0, 1]:,} instructions")
print(f"steps 2..{int(steps[-1, 0])}: median {np.median(ir):,.0f}, p99 {np.percentile(ir, 99):,.0f}, "
      f"p99.9 {np.percentile(ir, 99.9):,.0f}, max {ir.max():,} instructions")
worst = np.argsort(ir)[-5:][::-1]
print("worst steps (step: instructions):", ", ".join(f"{int(steps[i, 0])}: {int(ir[i]):,}" for i in worst))
PY
echo "fsw_step_instructions.sh: the run in $out/run, the counts in $out/steps.csv"
