#!/usr/bin/env python3
"""A formation design study with the visors building blocks: for standby formations with
parallel relative eccentricity and inclination vectors of size d (a*dey = a*diy = d), the passive
safety of the standby orbit (minimum separation normal to the flight direction over 2 days, 3-sigma
of a 1 m navigation error) and the delta-v of the closed-form transfer to the paper's science orbit
(2 orbits), as a table and, when matplotlib is installed, a figure.

    PYTHONPATH=build/python /usr/bin/python3 examples/formation_design.py [--no-plot] [--out FIG.svg]
"""
import argparse
import math

import numpy as np

import visors

# The mission chief (mean elements at t0: 500 km Sun-synchronous, LTAN 10:00), SI units and rad.
CHIEF = {"a": 6878136.3, "e": 0.004, "i": math.radians(97.8), "raan": math.radians(157.5),
         "argp": math.radians(90.0), "M": 0.0}
SCIENCE = [-2.62, 45.21, -34.51, 4.78, -18.72, 2.72]  # a*dROE [m], the paper's science orbit
MU = 3.986004418e14  # [m^3/s^2]


def study(sizes_m):
    period_s = 2 * math.pi * math.sqrt(CHIEF["a"] ** 3 / MU)
    cov_m2 = np.eye(6).tolist()  # 1 m^2 per a*dROE component
    rows = []
    for d in sizes_m:
        standby = [0.0, 0.0, 0.0, d, 0.0, d]
        safety = visors.tool("safety", {"chief": CHIEF, "roe": standby, "cov": cov_m2, "horizon": 2 * 86400.0,
                                        "plane": "rn", "q": 3.0})
        plan = visors.tool("plan", {"chief": CHIEF, "roe_start": standby, "roe_target": SCIENCE,
                                    "tf": 2.0 * period_s, "algorithm": "closed-form"})
        rows.append((d, safety["min_separation"], safety["min_separation_margin"], plan["dv_total"],
                     plan["dv_lower_bound"]))
    return np.array(rows, dtype=[("d_m", float), ("min_rn_m", float), ("margin_m", float),
                                 ("dv_mps", float), ("dv_bound_mps", float)])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--no-plot", action="store_true", help="print the table only")
    parser.add_argument("--out", default="formation_design.svg", help="figure file")
    args = parser.parse_args()

    table = study(np.linspace(50.0, 300.0, 6))
    print(f"visors {visors.__version__}: standby size d against safety and transfer cost")
    print(f"{'d [m]':>8} {'min RN [m]':>11} {'margin [m]':>11} {'dv [m/s]':>9} {'bound [m/s]':>12}")
    for row in table:
        print(f"{row['d_m']:8.0f} {row['min_rn_m']:11.2f} {row['margin_m']:11.2f} {row['dv_mps']:9.4f} "
              f"{row['dv_bound_mps']:12.4f}")
    if args.no_plot:
        return
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib not installed: no figure")
        return
    figure, left = plt.subplots()
    left.plot(table["d_m"], table["min_rn_m"], "o-", label="minimum RN separation")
    left.set_xlabel("standby a*dey = a*diy [m]")
    left.set_ylabel("minimum RN separation over 2 days [m]")
    right = left.twinx()
    right.plot(table["d_m"], table["dv_mps"], "s--", color="tab:red", label="transfer delta-v")
    right.set_ylabel("standby -> science delta-v [m/s]")
    figure.tight_layout()
    figure.savefig(args.out)
    print(f"figure {args.out}")


if __name__ == "__main__":
    main()
