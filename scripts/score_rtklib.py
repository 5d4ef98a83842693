#!/usr/bin/python3
"""Scores an RTKLIB moving-base solution (rnx2rtkp, out-solformat=enu) against a `visors gnss-sim`
run's truth, with the figures `visors nav` reports.

Usage:
  score_rtklib.py SOLUTION.pos RUN_DIR [--out DIR] [--faults FAULTS.json] [--label TEXT]
                  [--runtime SECONDS]
  (normally run by scripts/rtklib_moving_base.sh). Prints a summary; with --out, also writes
  DIR/summary.json. Needs numpy (run with /usr/bin/python3).

What RTKLIB's solution is. In moving-base mode (rtkpos.c, 2.4.3) each epoch's solution time is
the rover's time tag minus its single-point receiver clock estimate (pntpos: sol.time = obs time -
dtr), i.e. the rover's reception instant t_r = T - dt_osc. The base position rtk.rb is the base's
single point solution at its own reception instant t_b = T - dt_dsc, moved to t_r with its
Doppler velocity (rb += v * age, age = t_r - t_b). The base's ranges, however, are computed from
rb to the satellites at the base's own transmission instants, so the double differences solve for
the rover's phase centre at t_r minus the base's phase centre at t_b: the output baseline (rr - rb,
outenu) is r_osc(t_r) - r_dsc(t_b) (the rb shift cancels: it moves rr by the same amount). RTKLIB
nevertheless labels it t_r. So three truth baselines are computed here (ITRF = the ECEF of the
broadcast ephemerides; both are the Earth-fixed axes of the reception instant):
  * "solution instant" (the headline figures): r_osc(t) - r_dsc(t) at t = the solution's time tag
    as RTKLIB prints it (GPST time of week, 9 decimals): the baseline a user of the file gets.
    This includes RTKLIB's moving-base time-alignment error v_dsc (t_b - t_r) = v_dsc (dt_osc -
    dt_dsc) / c (~2.5 mm per 100 m of clock difference at 7.6 km/s).
  * "time tag": r_osc(T) - r_dsc(T), the instant `visors nav`'s filter estimates (the RINEX tags).
  * "reception instants": truth.csv's rows differenced as they are (x/y/z_apc_itrf_m of OSC minus
    DSC at the same t_s, each at its receiver's reception instant T - dt_r): what RTKLIB's double
    differences actually determine; the RTKLIB estimation error without the time-alignment error.
A phase centre at an instant t: p(t) = p_row + v (t - (T - dt_r)), with p_row the truth.csv apc
columns, dt_r = receiver_clock_m / c, and v the ITRF velocity of the phase centre from second-order
central differences of the apc columns over their reception instants (|t - (T - dt_r)| < 1 us:
the linearisation error is below 1e-8 m).
The ENU baseline is rotated back to ECEF with the geodetic latitude/longitude (WGS84) of the true
DSC phase centre; RTKLIB uses its rb (the base single point solution, a few metres off): the
rotation differs by ~1e-6 rad, < 0.1 mm on a 50 m baseline.
RTN components: radial along the DSC's position, normal along r x v_inertial with v_inertial =
v_itrf + omega_E x r (Earth rotation about the ITRF z axis; precession-nutation and polar motion
are irrelevant for the direction of a mm-level error vector), so no GCRF rotation is needed; the
3D figures do not depend on the axes.
Wrong fix: RTKLIB does not output its integers; a fixed epoch (Q=1) whose baseline error (solution
instant) exceeds 5 cm counts as a wrong fix (one wrong L1 integer, 19 cm, moves the baseline by
several cm at this geometry).
"""
import argparse
import datetime
import json
import math
import os
import sys

import numpy as np

C = 299792458.0
OMEGA_E = 7.2921151467e-5
WRONG_FIX_M = 0.05


def read_solution(path):
    rows = []
    for line in open(path):
        if line.startswith("%") or not line.strip():
            continue
        f = line.split()
        # week tow e n u Q ns sde sdn sdu sden sdnu sdue age ratio
        rows.append([float(f[0]), float(f[1]), float(f[2]), float(f[3]), float(f[4]), int(f[5]), int(f[6]),
                     float(f[13]), float(f[14])])
    a = np.array(rows, dtype=float).reshape(-1, 9)
    return {"gps_s": a[:, 0] * 604800.0 + a[:, 1], "enu": a[:, 2:5], "q": a[:, 5].astype(int),
            "ns": a[:, 6].astype(int), "age": a[:, 7], "ratio": a[:, 8]}


def read_truth(run):
    with open(os.path.join(run, "truth.csv")) as f:
        names = f.readline().strip().split(",")
        rows = [l.strip().split(",") for l in f if l.strip()]
    col = {n: i for i, n in enumerate(names)}
    out = {}
    for craft in ("dsc", "osc"):
        sel = [r for r in rows if r[col["spacecraft"]] == craft]
        num = lambda n: np.array([float(r[col[n]]) for r in sel])
        t = num("t_s")
        order = np.argsort(t)
        d = {"t": t[order], "clock_m": num("receiver_clock_m")[order],
             "apc": np.column_stack([num(f"{a}_apc_itrf_m") for a in "xyz"])[order],
             "v_gcrf": np.column_stack([num(f"v{a}_gcrf_mps") for a in "xyz"])[order]}
        d["t_rec"] = d["t"] - d["clock_m"] / C
        d["v_apc"] = np.column_stack([np.gradient(d["apc"][:, k], d["t_rec"]) for k in range(3)])
        out[craft] = d
    if not np.array_equal(out["dsc"]["t"], out["osc"]["t"]):
        raise SystemExit("truth.csv: the two spacecraft's epochs differ")
    return out


def geodetic(r):
    """WGS84 latitude and longitude [rad] of ECEF points (N,3)."""
    a, f = 6378137.0, 1.0 / 298.257223563
    e2 = f * (2 - f)
    p = np.hypot(r[:, 0], r[:, 1])
    lat = np.arctan2(r[:, 2], p * (1 - e2))
    for _ in range(6):
        n = a / np.sqrt(1 - e2 * np.sin(lat) ** 2)
        h = p / np.cos(lat) - n
        lat = np.arctan2(r[:, 2], p * (1 - e2 * n / (n + h)))
    return lat, np.arctan2(r[:, 1], r[:, 0])


def enu_to_ecef(enu, lat, lon):
    sl, cl, sp, cp = np.sin(lon), np.cos(lon), np.sin(lat), np.cos(lat)
    e_hat = np.column_stack([-sl, cl, np.zeros_like(sl)])
    n_hat = np.column_stack([-sp * cl, -sp * sl, cp])
    u_hat = np.column_stack([cp * cl, cp * sl, sp])
    return enu[:, :1] * e_hat + enu[:, 1:2] * n_hat + enu[:, 2:3] * u_hat


def stats(err, rtn=None):
    if len(err) == 0:
        return {"epochs": 0}
    n3 = np.linalg.norm(err, axis=1)
    s = {"epochs": int(len(err)), "rms_3d_m": float(np.sqrt(np.mean(n3 ** 2))), "worst_3d_m": float(n3.max()),
         "mean_xyz_m": [float(x) for x in err.mean(axis=0)]}
    if rtn is not None:
        s["rms_rtn_m"] = [float(x) for x in np.sqrt(np.mean(rtn ** 2, axis=0))]
        s["mean_rtn_m"] = [float(x) for x in rtn.mean(axis=0)]
    return s


def runs(flags_t):
    """Number of runs of consecutive epochs (1 s apart) in a sorted time list."""
    if len(flags_t) == 0:
        return 0
    return int(1 + np.sum(np.diff(flags_t) > 1.5))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("solution")
    ap.add_argument("run_dir")
    ap.add_argument("--out")
    ap.add_argument("--faults")
    ap.add_argument("--label", default="")
    ap.add_argument("--runtime", type=float)
    a = ap.parse_args()

    summ = json.load(open(os.path.join(a.run_dir, "summary.json")))
    t0 = summ["t0"]["week"] * 604800.0 + summ["t0"]["seconds_of_week"]
    truth = read_truth(a.run_dir)
    dsc, osc = truth["dsc"], truth["osc"]
    tt = dsc["t"]
    sol = read_solution(a.solution)

    t_sol = sol["gps_s"] - t0  # the solution's instant [s since t0]
    idx = np.clip(np.searchsorted(tt, t_sol - 0.5), 0, len(tt) - 1)
    idx = np.where((idx + 1 < len(tt)) & (np.abs(tt[np.minimum(idx + 1, len(tt) - 1)] - t_sol) < np.abs(tt[idx] - t_sol)),
                   idx + 1, idx)
    off = t_sol - tt[idx]
    if len(off) and np.abs(off).max() > 1e-3:
        raise SystemExit(f"solution instants do not match the truth's tags (max offset {np.abs(off).max():.3g} s)")
    tag = tt[idx]

    def at(d, t):  # phase centre at instant t (per solution epoch)
        return d["apc"][idx] + d["v_apc"][idx] * (t - d["t_rec"][idx])[:, None]

    refs = {
        "solution_instant": at(osc, t_sol) - at(dsc, t_sol),
        "time_tag": at(osc, tag) - at(dsc, tag),
        "reception_instants": osc["apc"][idx] - dsc["apc"][idx],
    }
    lat, lon = geodetic(dsc["apc"][idx])
    est = enu_to_ecef(sol["enu"], lat, lon)

    r = dsc["apc"][idx]
    v_in = dsc["v_apc"][idx] + np.cross(np.array([0.0, 0.0, OMEGA_E]), r)
    rh = r / np.linalg.norm(r, axis=1)[:, None]
    nh = np.cross(r, v_in)
    nh /= np.linalg.norm(nh, axis=1)[:, None]
    th = np.cross(nh, rh)
    speed_check = float(np.abs(np.linalg.norm(v_in, axis=1) - np.linalg.norm(dsc["v_gcrf"][idx], axis=1)).max()) \
        if len(idx) else 0.0

    fixed = sol["q"] == 1
    res = {"label": a.label, "run_dir": os.path.abspath(a.run_dir), "solution": os.path.abspath(a.solution),
           "epochs": int(len(tt)), "solution_epochs": int(len(t_sol)), "fixed_epochs": int(fixed.sum()),
           "float_epochs": int((sol["q"] == 2).sum()), "rnx2rtkp_s": a.runtime,
           "inertial_speed_check_mps": speed_check, "wrong_fix_criterion": f"fixed epoch with |error| > {WRONG_FIX_M} m"}
    if a.faults:
        res["faults"] = json.load(open(a.faults))
    if fixed.any():
        first = tag[fixed].min()
        after = int(np.sum(tt >= first - 1e-9))
        res["first_fix_s"] = float(first)
        res["time_to_first_fix_s"] = float(first - tt[0])
        res["fix_rate_after_first_fix"] = fixed.sum() / after
        res["epochs_after_first_fix"] = after
    else:
        res["first_fix_s"] = None
        res["fix_rate_after_first_fix"] = 0.0
    res["fix_rate_of_solutions"] = float(fixed.mean()) if len(fixed) else 0.0
    res["errors"] = {}
    for name, ref in refs.items():
        err = est - ref
        rtn = np.column_stack([np.sum(err * rh, 1), np.sum(err * th, 1), np.sum(err * nh, 1)])
        res["errors"][name] = {"fixed": stats(err[fixed], rtn[fixed]), "all": stats(err, rtn)}
        if name == "solution_instant":
            n3 = np.linalg.norm(err, axis=1)
            wrong = fixed & (n3 > WRONG_FIX_M)
            ok = fixed & ~wrong
            res["wrong_fix_epochs"] = int(wrong.sum())
            res["wrong_fix_episodes"] = runs(np.sort(tag[wrong]))
            res["wrong_fix_first_s"] = [float(x) for x in np.sort(tag[wrong])[:5]]
            res["wrong_fix_worst_m"] = float(n3[wrong].max()) if wrong.any() else 0.0
            res["errors"]["solution_instant"]["fixed_correct"] = stats(err[ok], rtn[ok])
    # the time-alignment part: |v_dsc| (dt_osc - dt_dsc)/c over the solution epochs
    align = np.linalg.norm(refs["solution_instant"] - refs["reception_instants"], axis=1)
    res["time_alignment_m"] = {"rms": float(np.sqrt(np.mean(align ** 2))) if len(align) else 0.0,
                               "max": float(align.max()) if len(align) else 0.0}

    mm = lambda x: f"{1e3 * x:7.2f}"
    p = print
    p(f"RTKLIB 2.4.3 moving base on {a.run_dir}  {a.label}")
    if a.runtime is not None:
        p(f"  rnx2rtkp wall time            {a.runtime:.2f} s")
    p(f"  epochs {res['epochs']}, solution epochs {res['solution_epochs']} "
      f"(fixed {res['fixed_epochs']}, float {res['float_epochs']})")
    if res["first_fix_s"] is not None:
        p(f"  first fix at t = {res['first_fix_s']:.0f} s (time to first fix {res['time_to_first_fix_s']:.0f} s)")
        p(f"  fix rate: {100 * res['fix_rate_after_first_fix']:.2f} % of the run's epochs after the first fix, "
          f"{100 * res['fix_rate_of_solutions']:.2f} % of the solutions")
    p(f"  relative position error [mm] (baseline OSC - DSC phase centres):")
    p(f"    {'truth at':22s} {'set':14s} {'epochs':>6s} {'RMS 3D':>7s} {'worst':>7s}  RMS R / T / N")
    for name in ("solution_instant", "time_tag", "reception_instants"):
        for sset in ("fixed", "fixed_correct", "all"):
            s = res["errors"][name].get(sset)
            if not s or s["epochs"] == 0:
                continue
            rtn = " / ".join(mm(x).strip() for x in s["rms_rtn_m"])
            p(f"    {name:22s} {sset:14s} {s['epochs']:6d} {mm(s['rms_3d_m'])} {mm(s['worst_3d_m'])}  {rtn}")
    p(f"  wrong fixes (criterion: fixed epoch with error > {WRONG_FIX_M * 100:.0f} cm at the solution instant): "
      f"{res['wrong_fix_epochs']} epochs in {res['wrong_fix_episodes']} episodes"
      + (f", worst {res['wrong_fix_worst_m']:.3f} m, first at t = {res['wrong_fix_first_s']}" if res['wrong_fix_epochs'] else ""))
    p(f"  RTKLIB moving-base time alignment |v_dsc (dt_osc - dt_dsc)/c|: RMS {mm(res['time_alignment_m']['rms']).strip()} mm,"
      f" max {mm(res['time_alignment_m']['max']).strip()} mm")
    if a.out:
        os.makedirs(a.out, exist_ok=True)
        with open(os.path.join(a.out, "summary.json"), "w") as f:
            json.dump(res, f, indent=2)
        p(f"  wrote {os.path.join(a.out, 'summary.json')}")


if __name__ == "__main__":
    main()
