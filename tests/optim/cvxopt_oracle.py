#!/usr/bin/python3
"""Independent oracle for the conic solver (src/visors/optim): generates seeded conic programs, solves
them with CVXOPT (Debian python3-cvxopt; conelp for LP/SOCP, coneqp for QP) at tight
tolerances and writes instances and reference results as JSON.

  cvxopt_oracle.py --out FILE            oracle instance set (read by test_conic_oracle.cpp)
  cvxopt_oracle.py --bench IN            time CVXOPT on the instances in IN (written by
                                         visors_bench_conic) and print "median_us max_us"

Problem form (CVXOPT's): minimise 1/2 x'Px + c'x s.t. Ax = b, Gx + s = h, s in K,
K = R+^l x Q^q1 x ... Classes: lp, socp, qp, fuel (min sum ||dv_k|| with 6 equality rows),
degenerate, primal_infeasible, dual_infeasible, badly_scaled.
"""
import argparse
import json
import sys
import time

import numpy as np
from cvxopt import matrix, solvers

TOL = 1e-10  # CVXOPT tolerances (abstol, reltol, feastol); instances it cannot finish are redrawn


def cone_point(rng, l, q, strict=True):
    """A point in the interior of K (or on its boundary in some coordinates if not strict)."""
    parts = [rng.uniform(0.1, 2.0, l)]
    for d in q:
        v = rng.normal(size=d)
        v[0] = np.linalg.norm(v[1:]) + rng.uniform(0.1, 2.0)
        parts.append(v)
    return np.concatenate(parts) if parts else np.zeros(0)


def random_dims(rng, n, with_soc):
    l = int(rng.integers(n, 2 * n + 5)) if not with_soc else int(rng.integers(0, n + 1))
    q = []
    if with_soc:
        for _ in range(int(rng.integers(2, 6))):
            q.append(int(rng.integers(1, 7)))
    return l, q


def feasible_bounded(rng, n, l, q, p, quadratic=False):
    """Random data with a strictly feasible primal point and a strictly feasible dual point."""
    m = l + sum(q)
    G = rng.normal(size=(m, n))
    A = rng.normal(size=(p, n))
    x0 = rng.normal(size=n)
    s0 = cone_point(rng, l, q)
    h = G @ x0 + s0
    b = A @ x0
    z0 = cone_point(rng, l, q)
    y0 = rng.normal(size=p)
    P = None
    c = -(G.T @ z0 + A.T @ y0)
    if quadratic:
        r = int(rng.integers(1, n + 1))  # possibly rank deficient
        F = rng.normal(size=(r, n))
        P = F.T @ F
        c = c - P @ rng.normal(size=n)
    return dict(n=n, l=l, q=q, p=p, c=c, G=G, h=h, A=A, b=b, P=P)


def gen_lp(rng):
    n = int(rng.integers(2, 25))
    l, q = random_dims(rng, n, False)
    p = int(rng.integers(0, n // 2 + 1))
    return feasible_bounded(rng, n, l, q, p)


def gen_socp(rng):
    n = int(rng.integers(3, 25))
    l, q = random_dims(rng, n, True)
    p = int(rng.integers(0, n // 3 + 1))
    return feasible_bounded(rng, n, l, q, p)


def gen_qp(rng):
    n = int(rng.integers(2, 20))
    with_soc = rng.uniform() < 0.3
    l, q = random_dims(rng, n, with_soc)
    p = int(rng.integers(0, n // 2 + 1))
    return feasible_bounded(rng, n, l, q, p, quadratic=True)


def fuel_instance(rng, count):
    """min sum t_k s.t. sum_k B_k dv_k = target (6 rows), ||dv_k|| <= t_k.
    Variables [dv_1..dv_N (3N), t_1..t_N]; cone k: (t_k, dv_k) = -G x (h = 0)."""
    n = 4 * count
    B = rng.normal(size=(6, 3 * count))
    A = np.hstack([B, np.zeros((6, count))])
    b = rng.normal(size=6)
    G = np.zeros((4 * count, n))
    for k in range(count):
        G[4 * k, 3 * count + k] = -1.0
        for i in range(3):
            G[4 * k + 1 + i, 3 * k + i] = -1.0
    c = np.concatenate([np.zeros(3 * count), np.ones(count)])
    return dict(n=n, l=0, q=[4] * count, p=6, c=c, G=G, h=np.zeros(4 * count), A=A, b=b, P=None)


def gen_fuel(rng):
    return fuel_instance(rng, int(rng.choice([2, 4, 8, 12, 20])))


def gen_degenerate(rng):
    """LPs/SOCPs without strict complementarity or with redundant rows: some coordinates
    have s = z = 0 at the solution, and duplicated constraints and equality rows."""
    n = int(rng.integers(3, 15))
    with_soc = rng.uniform() < 0.4
    l, q = random_dims(rng, n, with_soc)
    l = max(l, 2)
    p = int(rng.integers(1, n // 2 + 2))
    m = l + sum(q)
    G = rng.normal(size=(m, n))
    A = rng.normal(size=(p, n))
    if p >= 2:
        A[-1] = A[0] * 2.0  # dependent equality row (consistent: b follows)
    x0 = rng.normal(size=n)
    s0 = cone_point(rng, l, q)
    z0 = cone_point(rng, l, q)
    k = int(rng.integers(1, l + 1))
    s0[:k] = 0.0   # active at x0
    z0[:k // 2] = 0.0  # ... with zero multipliers on some of them
    z0[k:l] = 0.0
    G[1] = G[0]    # duplicated row
    s0[1] = s0[0]
    z0[1] = 0.0
    y0 = rng.normal(size=p)
    if p >= 2:
        y0[-1] = 0.0
    h = G @ x0 + s0
    b = A @ x0
    c = -(G.T @ z0 + A.T @ y0)
    return dict(n=n, l=l, q=q, p=p, c=c, G=G, h=h, A=A, b=b, P=None)


def gen_primal_infeasible(rng):
    """A Farkas certificate is planted: z0 in K, y0 with G'z0 + A'y0 = 0 and h'z0 + b'y0 = -1."""
    n = int(rng.integers(2, 15))
    l, q = random_dims(rng, n, rng.uniform() < 0.5)
    l = max(l, 1)
    p = int(rng.integers(0, n // 2 + 1))
    m = l + sum(q)
    G = rng.normal(size=(m, n))
    A = rng.normal(size=(p, n))
    z0 = cone_point(rng, l, q)
    y0 = rng.normal(size=p)
    G[0] = -(G[1:].T @ z0[1:] + A.T @ y0) / z0[0]
    h = rng.normal(size=m)
    b = rng.normal(size=p)
    h[0] = (-1.0 - h[1:] @ z0[1:] - b @ y0) / z0[0]
    # c from a strictly dual feasible point, so that the dual is feasible (and unbounded) and
    # the status is unambiguous.
    c = -(G.T @ cone_point(rng, l, q) + A.T @ rng.normal(size=p))
    return dict(n=n, l=l, q=q, p=p, c=c, G=G, h=h, A=A, b=b, P=None)


def gen_dual_infeasible(rng):
    """A primal ray is planted: A d = 0, -G d in int K, c'd = -1, plus a feasible point."""
    n = int(rng.integers(3, 15))
    l, q = random_dims(rng, n, rng.uniform() < 0.5)
    p = int(rng.integers(0, n // 2))
    m = l + sum(q)
    d = rng.normal(size=n)
    A = rng.normal(size=(p, n))
    A = A - np.outer(A @ d, d) / (d @ d)
    G = rng.normal(size=(m, n))
    k = cone_point(rng, l, q)
    G = G + np.outer(-k - G @ d, d) / (d @ d)
    c = rng.normal(size=n)
    c = c - (c @ d + 1.0) * d / (d @ d)
    x0 = rng.normal(size=n)
    h = G @ x0 + cone_point(rng, l, q)
    b = A @ x0
    return dict(n=n, l=l, q=q, p=p, c=c, G=G, h=h, A=A, b=b, P=None)


def gen_badly_scaled(rng):
    """A feasible LP/SOCP/QP with rows and columns scaled over six orders of magnitude."""
    kind = rng.uniform()
    inst = gen_lp(rng) if kind < 0.4 else (gen_socp(rng) if kind < 0.8 else gen_qp(rng))
    n, l, q = inst["n"], inst["l"], inst["q"]
    col = 10.0 ** rng.uniform(-3, 3, n)
    row = list(10.0 ** rng.uniform(-3, 3, l))
    for d in q:
        row += [10.0 ** rng.uniform(-3, 3)] * d
    row = np.array(row)
    erow = 10.0 ** rng.uniform(-3, 3, inst["p"])
    inst["G"] = row[:, None] * inst["G"] * col[None, :]
    inst["h"] = row * inst["h"]
    inst["A"] = erow[:, None] * inst["A"] * col[None, :]
    inst["b"] = erow * inst["b"]
    inst["c"] = col * inst["c"]
    if inst["P"] is not None:
        inst["P"] = col[:, None] * inst["P"] * col[None, :]
    return inst


def cvx_solve(inst, tol=TOL):
    n, l, q, p = inst["n"], inst["l"], inst["q"], inst["p"]
    solvers.options.update(dict(show_progress=False, abstol=tol, reltol=tol, feastol=tol,
                                maxiters=200))
    dims = {"l": l, "q": list(q), "s": []}
    args = dict(G=matrix(inst["G"]), h=matrix(inst["h"]), dims=dims)
    if p > 0:
        args.update(A=matrix(inst["A"]), b=matrix(inst["b"]))
    t0 = time.perf_counter()
    if inst["P"] is None:
        sol = solvers.conelp(matrix(inst["c"]), **args)
    else:
        sol = solvers.coneqp(matrix(inst["P"]), matrix(inst["c"]), **args)
    elapsed = time.perf_counter() - t0
    return sol, elapsed


def cvx_reference(inst):
    """CVXOPT's answer at the tightest tolerance it reaches (1e-10, 1e-9, then 1e-8). An
    'unknown' stop (CVXOPT cannot progress further) is accepted as optimal when its residuals
    are below 1e-9 and its relative gap below 1e-9. Returns (solution, status) or (None, None)."""
    for tol in (TOL, 1e-9, 1e-8):
        try:
            sol, _ = cvx_solve(inst, tol)
        except (ValueError, ArithmeticError):  # CVXOPT's own numerical failure
            continue
        if sol["status"] in STATUS:
            return sol, STATUS[sol["status"]]
        pinf, dinf, gap = sol["primal infeasibility"], sol["dual infeasibility"], sol["relative gap"]
        if None not in (pinf, dinf, gap) and max(pinf, dinf) <= 1e-9 and gap <= 1e-9:
            return sol, "optimal"
    return None, None


STATUS = {"optimal": "optimal", "primal infeasible": "primal_infeasible",
          "dual infeasible": "dual_infeasible"}

CLASSES = [("lp", gen_lp, 60), ("socp", gen_socp, 60), ("qp", gen_qp, 50), ("fuel", gen_fuel, 40),
           ("degenerate", gen_degenerate, 30), ("primal_infeasible", gen_primal_infeasible, 25),
           ("dual_infeasible", gen_dual_infeasible, 25), ("badly_scaled", gen_badly_scaled, 30)]


def listed(a):
    return np.asarray(a, dtype=float).tolist()


def oracle(path, seed):
    rng = np.random.default_rng(seed)
    out = []
    redrawn = 0
    for name, gen, count in CLASSES:
        made = 0
        while made < count:
            inst = gen(rng)
            sol, status = cvx_reference(inst)
            if status is None:  # CVXOPT could not certify it: draw another instance
                redrawn += 1
                continue
            rec = dict(cls=name, n=inst["n"], l=inst["l"], q=inst["q"], p=inst["p"],
                       c=listed(inst["c"]), G=listed(inst["G"]), h=listed(inst["h"]),
                       A=listed(inst["A"]).copy() if inst["p"] > 0 else [], b=listed(inst["b"]),
                       status=status, iterations=int(sol["iterations"]))
            if inst["P"] is not None:
                rec["P"] = listed(inst["P"])
            if status == "optimal":
                rec["objective"] = float(sol["primal objective"])
                rec["x"] = listed(np.array(sol["x"]).ravel())
            out.append(rec)
            made += 1
    with open(path, "w") as f:
        json.dump({"seed": seed, "tolerance": TOL, "redrawn": redrawn, "instances": out}, f)
    print(f"wrote {len(out)} instances ({redrawn} redrawn) to {path}")


def bench(path):
    with open(path) as f:
        instances = json.load(f)["instances"]
    times = []
    for inst in instances:
        inst = dict(inst)
        for key in ("c", "G", "h", "A", "b"):
            inst[key] = np.array(inst[key], dtype=float)
        inst["P"] = None
        best = min(cvx_solve(inst, tol=1e-8)[1] for _ in range(3))  # CVXOPT default-like tolerances
        times.append(best * 1e6)
    print(f"{np.median(times):.3f} {np.max(times):.3f}")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", help="write the oracle instance set here")
    parser.add_argument("--seed", type=int, default=20261122)
    parser.add_argument("--bench", help="time CVXOPT on the instances of this JSON file")
    args = parser.parse_args()
    if args.bench:
        bench(args.bench)
    elif args.out:
        oracle(args.out, args.seed)
    else:
        parser.error("give --out or --bench")
    return 0


if __name__ == "__main__":
    sys.exit(main())
