#!/usr/bin/env bash
# Peer comparison: RTKLIB 2.4.3 rnx2rtkp in moving-base mode on a `visors gnss-sim` run directory,
# scored like `visors nav` (fix rate, time to first fix, relative position error on fixed epochs,
# wrong fixes) by scripts/score_rtklib.py.
#
# Usage:
#   scripts/rtklib_moving_base.sh RTKLIB_SOURCE RUN_DIR [--outage START_S DUR_S]
#                                 [--crosslink-drop P] [--seed N] [--out DIR]
#
#   RTKLIB_SOURCE  a checkout of RTKLIB's rtklib_2.4.3 branch (src/ and
#                  app/consapp/rnx2rtkp/rnx2rtkp.c or app/rnx2rtkp/rnx2rtkp.c). It is only read:
#                  rnx2rtkp is compiled (gcc -O2 -I RTKLIB_SOURCE/src, -lm -lpthread) into a
#                  mktemp -d folder that is removed on exit, with everything else this script makes.
#   RUN_DIR        a `visors gnss-sim` output: osc.rnx (rover), dsc.rnx (base), brdc.rnx,
#                  truth.csv, summary.json.
#   --outage START_S DUR_S  removes every epoch with START_S <= t_s < START_S + DUR_S from both
#                  observation files and sets the LLI loss-of-lock bit (bit 0) on every satellite's
#                  L1C at each receiver's first epoch back (as `visors nav --outage`).
#   --crosslink-drop P      removes each base (dsc.rnx) epoch with probability P (numpy
#                  default_rng(--seed), default seed 1; as `visors nav --crosslink-drop`). A loss of
#                  lock flagged on a removed base epoch is carried to that satellite's next kept
#                  epoch (a receiver's LLI reports a loss of lock since the previous record sent).
#   --out DIR      also write summary.json, the RTKLIB solution (rtklib.pos) and options
#                  (rtklib.conf) there; default: print only.
#
# RTKLIB configuration (option names checked in 2.4.3's src/options.c):
#   pos1-posmode=movingbase (base position = base single point solution each epoch), L1 only,
#   forward filter, elevation mask 5 deg, ionosphere and troposphere off, broadcast ephemerides,
#   GPS only, pos2-armode=continuous, pos2-arthres=3, other settings RTKLIB's defaults;
#   no antenna PCV files, antenna types empty and antenna deltas 0 for both receivers. The
#   RINEX header's "ANTENNA: DELTA X/Y/Z" (body-frame antenna position) is ignored by 2.4.3's
#   RINEX reader (rinex.c: "opt ver.3", not stored) and "ANTENNA: DELTA H/E/N" is 0, so the
#   observations refer to the phase centres, as truth.csv's apc columns do.
#   Output: out-solformat=enu, i.e. the baseline rover - base (sol.rr - rtk.rb) in the local
#   east/north/up axes at the base, time tags GPST time of week with 9 decimals.
# How the truth instant is matched: see the header of scripts/score_rtklib.py.
set -euo pipefail

usage() { sed -n '5,25p' "$0" >&2; exit 2; }
[[ $# -ge 2 ]] || usage
SRC=$(cd "$1" && pwd)
RUN=$(cd "$2" && pwd)
shift 2
OUTAGE_START="" OUTAGE_DUR="" DROP=0 SEED=1 OUT=""
while [[ $# -gt 0 ]]; do
  case "$1" in
    --outage) OUTAGE_START=$2; OUTAGE_DUR=$3; shift 3 ;;
    --crosslink-drop) DROP=$2; shift 2 ;;
    --seed) SEED=$2; shift 2 ;;
    --out) OUT=$2; shift 2 ;;
    *) usage ;;
  esac
done
HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
PY=/usr/bin/python3

for f in osc.rnx dsc.rnx brdc.rnx truth.csv summary.json; do
  [[ -f "$RUN/$f" ]] || { echo "missing $RUN/$f" >&2; exit 1; }
done
MAIN=""
for c in app/consapp/rnx2rtkp/rnx2rtkp.c app/rnx2rtkp/rnx2rtkp.c; do
  [[ -f "$SRC/$c" ]] && MAIN="$SRC/$c" && break
done
[[ -n "$MAIN" && -f "$SRC/src/rtklib.h" ]] || { echo "not an RTKLIB 2.4.3 checkout: $SRC" >&2; exit 1; }

TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT

# ---- build rnx2rtkp (one compiler process, niced) ----
MODULES="rtkcmn rinex rtkpos postpos solution lambda geoid sbas preceph pntpos ephemeris options
         ppp ppp_ar rtcm rtcm2 rtcm3 rtcm3e ionex tides"
SOURCES=("$MAIN")
for m in $MODULES; do SOURCES+=("$SRC/src/$m.c"); done
if git -C "$SRC" rev-parse HEAD >/dev/null 2>&1; then
  echo "RTKLIB: $SRC $(git -C "$SRC" rev-parse --abbrev-ref HEAD) $(git -C "$SRC" rev-parse HEAD)"
fi
BUILD_START=$(date +%s%N)
(cd "$TMP" && nice gcc -O2 -w -I"$SRC/src" -o "$TMP/rnx2rtkp" "${SOURCES[@]}" -lm -lpthread)
echo "built rnx2rtkp in $(( ($(date +%s%N) - BUILD_START) / 1000000 )) ms"

# ---- observation files, with the faults ----
ROVER="$RUN/osc.rnx" BASE="$RUN/dsc.rnx"
if [[ -n "$OUTAGE_START" || "$DROP" != "0" ]]; then
  "$PY" - "$RUN" "$TMP" "${OUTAGE_START:-nan}" "${OUTAGE_DUR:-0}" "$DROP" "$SEED" <<'PYEOF'
import sys, json, numpy as np

run, tmp = sys.argv[1], sys.argv[2]
o_start, o_dur, drop, seed = float(sys.argv[3]), float(sys.argv[4]), float(sys.argv[5]), int(sys.argv[6])
t0 = json.load(open(f"{run}/summary.json"))["t0"]
t0_gps = t0["week"] * 604800.0 + t0["seconds_of_week"]

def gps_seconds(y, mo, d, h, mi, s):
    # days since the GPS epoch 1980-01-06 (proleptic Gregorian, via the ordinal day number)
    import datetime
    days = (datetime.date(y, mo, d) - datetime.date(1980, 1, 6)).days
    return days * 86400.0 + h * 3600.0 + mi * 60.0 + s

def read(path):
    lines = open(path).read().splitlines()
    h = next(i for i, l in enumerate(lines) if l[60:73] == "END OF HEADER") + 1
    header, epochs, i = lines[:h], [], h
    while i < len(lines):
        l = lines[i]
        if not l.startswith(">"):
            raise SystemExit(f"{path}: line {i + 1}: expected an epoch record")
        flag, n = int(l[31]), int(l[32:35])
        body = lines[i + 1:i + 1 + n]
        t = gps_seconds(int(l[2:6]), int(l[7:9]), int(l[10:12]), int(l[13:15]), int(l[16:18]), float(l[18:29]))
        epochs.append({"t_s": round(t - t0_gps, 6), "flag": flag, "head": l, "body": body})
        i += 1 + n
    return header, epochs

def set_lli(rec, field, bits):
    # record: 'Gnn' then 16-character fields: F14.3, LLI (I1), SSI (I1)
    col = 3 + 16 * field + 14
    rec = rec.ljust(col + 2)
    old = rec[col].strip()
    v = (int(old) if old else 0) | bits
    return rec[:col] + str(v) + rec[col + 1:]

def phase_field(header):
    types = []
    for l in header:
        if l[60:79].strip() == "SYS / # / OBS TYPES" and l[0] == "G":
            types += l[7:58].split()
    return types.index("L1C")

def write(path, header, epochs):
    with open(path, "w") as f:
        f.write("\n".join(header) + "\n")
        for e in epochs:
            f.write(e["head"] + "\n")
            if e["body"]:
                f.write("\n".join(e["body"]) + "\n")

def in_outage(t):
    return o_start == o_start and o_start <= t < o_start + o_dur

rng = np.random.default_rng(seed)
summary = {}
for name in ("dsc", "osc"):
    header, epochs = read(f"{run}/{name}.rnx")
    fl = phase_field(header)
    obs_epochs = [e for e in epochs if e["flag"] <= 1]
    # one draw per base epoch (all of the run's epochs, in order), as a fixed sequence
    draws = rng.random(len(obs_epochs)) if name == "dsc" else None
    kept, pending, back, n_out, n_drop = [], {}, False, 0, 0
    for k, e in enumerate(obs_epochs):
        if in_outage(e["t_s"]):
            n_out += 1
            back = True
            continue
        body = list(e["body"])
        if back:  # first epoch after the outage: every satellite lost lock
            body = [set_lli(r, fl, 1) for r in body]
            back = False
        if name == "dsc" and drop > 0 and draws[k] < drop:
            n_drop += 1
            for r in body:  # carry the loss-of-lock flags to the next kept record
                col = 3 + 16 * fl + 14
                c = r[col:col + 1].strip()
                if c and int(c) & 1:
                    pending[r[:3]] = True
            continue
        if pending:  # satellites absent from this record stay pending
            body = [set_lli(r, fl, 1) if pending.pop(r[:3], False) else r for r in body]
        head = e["head"][:32] + f"{len(body):3d}" + e["head"][35:]
        kept.append({"head": head, "body": body})
    write(f"{tmp}/{name}.rnx", header, kept)
    summary[name] = {"epochs_in": len(obs_epochs), "removed_outage": n_out, "removed_drop": n_drop, "kept": len(kept)}
print("faults:", json.dumps(summary))
json.dump(summary, open(f"{tmp}/faults.json", "w"))
PYEOF
  ROVER="$TMP/osc.rnx" BASE="$TMP/dsc.rnx"
fi

# ---- options ----
cat >"$TMP/rtklib.conf" <<'EOF'
pos1-posmode       =movingbase
pos1-frequency     =l1
pos1-soltype       =forward
pos1-elmask        =5
pos1-snrmask_r     =off
pos1-snrmask_b     =off
pos1-dynamics      =off
pos1-tidecorr      =off
pos1-ionoopt       =off
pos1-tropopt       =off
pos1-sateph        =brdc
pos1-navsys        =1
pos2-armode        =continuous
pos2-gloarmode     =off
pos2-arthres       =3
out-solformat      =enu
out-outhead        =on
out-outopt         =on
out-timesys        =gpst
out-timeform       =tow
out-timendec       =9
out-outstat        =off
ant1-anttype       =
ant1-antdele       =0
ant1-antdeln       =0
ant1-antdelu       =0
ant2-postype       =llh
ant2-pos1          =0
ant2-pos2          =0
ant2-pos3          =0
ant2-anttype       =
ant2-antdele       =0
ant2-antdeln       =0
ant2-antdelu       =0
file-satantfile    =
file-rcvantfile    =
EOF

# ---- run: rover first, base second, navigation last ----
/usr/bin/time -f "rnx2rtkp: %e s %M KB" -o "$TMP/time.txt" \
  "$TMP/rnx2rtkp" -k "$TMP/rtklib.conf" -o "$TMP/rtklib.pos" "$ROVER" "$BASE" "$RUN/brdc.rnx" 2>"$TMP/rnx2rtkp.log" \
  || { cat "$TMP/rnx2rtkp.log" >&2; exit 1; }
cat "$TMP/time.txt"

SCORE_ARGS=("$TMP/rtklib.pos" "$RUN")
[[ -f "$TMP/faults.json" ]] && SCORE_ARGS+=(--faults "$TMP/faults.json")
SCORE_ARGS+=(--label "outage=${OUTAGE_START:-none}${OUTAGE_DUR:+/$OUTAGE_DUR} crosslink_drop=$DROP seed=$SEED"
             --runtime "$(cut -d' ' -f2 "$TMP/time.txt")")
if [[ -n "$OUT" ]]; then
  mkdir -p "$OUT"
  cp "$TMP/rtklib.pos" "$TMP/rtklib.conf" "$OUT/"
  SCORE_ARGS+=(--out "$OUT")
fi
"$PY" "$HERE/score_rtklib.py" "${SCORE_ARGS[@]}"
