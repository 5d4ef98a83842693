#!/usr/bin/env python3
"""Reading a Monte Carlo results store (`visors mc`'s results.sqlite): the success rate and the
lateral alignment error of the observation attempts per swept value, as a table and, when
matplotlib is installed, the sensitivity figure.

    PYTHONPATH=build/python /usr/bin/python3 examples/monte_carlo_store.py out/mc/paper_sensitivity/results.sqlite [--no-plot]
"""
import argparse

import numpy as np

import visors


def per_value(store):
    runs, observations = store["runs"], store["observations"]
    value_of_run = dict(zip(runs["run"], runs["sweep_value"]))
    key = runs["sweep_key"][0] if runs.size else ""
    values = np.array([value_of_run[r] for r in observations["run"]], dtype=float)
    rows = []
    for value in np.unique(runs["sweep_value"]):
        chosen = observations[values == value] if not np.isnan(value) else observations[np.isnan(values)]
        runs_here = int(np.sum((runs["sweep_value"] == value) | (np.isnan(value) & np.isnan(runs["sweep_value"]))))
        success = int(chosen["success"].sum()) if chosen.size else 0
        median_mm = 1e3 * float(np.median(chosen["lateral_error_m"])) if chosen.size else float("nan")
        rows.append((value, runs_here, chosen.size, success, median_mm))
    return key, rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("store", help="results.sqlite of a campaign")
    parser.add_argument("--no-plot", action="store_true", help="print the table only")
    parser.add_argument("--out", default="sensitivity.svg", help="figure file")
    args = parser.parse_args()

    store = visors.read_store(args.store)
    key, rows = per_value(store)
    print(f"campaign {store['campaign']['name'][0]}: {store['runs'].size} runs, swept key '{key}'")
    print(f"{'value':>10} {'runs':>5} {'attempts':>9} {'success':>8} {'lateral median [mm]':>20}")
    for value, runs, attempts, success, median_mm in rows:
        print(f"{value:10.4g} {runs:5d} {attempts:9d} {success:8d} {median_mm:20.1f}")
    if args.no_plot or not rows:
        return
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib not installed: no figure")
        return
    values = [r[0] for r in rows]
    rate = [100.0 * r[3] / r[2] if r[2] else 0.0 for r in rows]
    figure, left = plt.subplots()
    left.plot(values, [r[4] for r in rows], "o-")
    left.set_xlabel(key)
    left.set_ylabel("lateral error, median [mm]")
    right = left.twinx()
    right.plot(values, rate, "s--", color="tab:green")
    right.set_ylabel("success [%]")
    figure.tight_layout()
    figure.savefig(args.out)
    print(f"figure {args.out}")


if __name__ == "__main__":
    main()
