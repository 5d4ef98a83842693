#!/usr/bin/python3
"""Independent reference for tests/nav/test_gauss_markov.cpp: the transition Phi and process noise
Q of the Gauss-Markov chain r' = v, v' = a, a' = -a/tau + w (PSD q = 2 sigma^2 / tau) by Van Loan's
method (IEEE TAC 23(3), 1978): E = expm([[-A, G q G'], [0, A']] dt), Phi = E22', Q = Phi E12,
with the 6x6 exponential by scaling and squaring of its Taylor series in 200-digit decimal
arithmetic (Python's decimal module; 200 digits because at dt/tau = 100 the blocks of E span
e^(+-100), 87 digits, which Q = Phi E12 cancels). No closed form, no double rounding; the inputs
are the exact values of the doubles the test uses. Prints C++ initialisers {x, dt, tau, sigma,
Phi_ra, Phi_va, Phi_aa, Q_rr, Q_rv, Q_ra, Q_vv, Q_va, Q_aa}, each the double nearest the 200-digit
value, to 17 significant digits (which round-trip). dt/tau = 1.4, 2 and 5 put cases on both sides
of the implementation's switch from series to closed forms (dt/tau = 1.5).

  /usr/bin/python3 tests/nav/gauss_markov_reference.py
"""
from decimal import Decimal, getcontext

getcontext().prec = 200
SIGMA = 5e-8  # [m/s^2]
DT = 10.0     # [s]
RATIOS = ["1e-8", "1e-6", "1e-4", "1e-3", "1e-2", "0.1", "1", "1.4", "2", "5", "10", "100"]


def matmul(a, b):
    n, m, p = len(a), len(b), len(b[0])
    return [[sum(a[i][k] * b[k][j] for k in range(m)) for j in range(p)] for i in range(n)]


def expm(m):
    """exp(m) = exp(m / 2^s)^(2^s), s such that the norm of m / 2^s is below 1/2; the Taylor series
    of exp(m / 2^s) summed until a term's largest entry is below 1e-210."""
    n = len(m)
    s = 0
    while max(sum(abs(v) for v in row) for row in m) / 2**s > Decimal("0.5"):
        s += 1
    scaled = [[v / 2**s for v in row] for row in m]
    total = [[Decimal(int(i == j)) for j in range(n)] for i in range(n)]
    term = [row[:] for row in total]
    k = 0
    while max(abs(v) for row in term for v in row) > Decimal("1e-210"):
        k += 1
        term = [[v / k for v in row] for row in matmul(term, scaled)]
        total = [[total[i][j] + term[i][j] for j in range(n)] for i in range(n)]
    for _ in range(s):
        total = matmul(total, total)
    return total


def chain(dt_f, tau_f, sigma_f):
    dt, tau, sigma = Decimal(dt_f), Decimal(tau_f), Decimal(sigma_f)  # exact double values
    q = 2 * sigma * sigma / tau
    z = Decimal(0)
    a = [[z, Decimal(1), z], [z, z, Decimal(1)], [z, z, -1 / tau]]
    m = [[z] * 6 for _ in range(6)]
    for i in range(3):
        for j in range(3):
            m[i][j] = -a[i][j] * dt          # -A dt
            m[3 + i][3 + j] = a[j][i] * dt   # A' dt
    m[2][5] = q * dt                         # G q G' dt, G = e3
    e = expm(m)
    phi = [[e[3 + j][3 + i] for j in range(3)] for i in range(3)]  # (E22)'
    e12 = [[e[i][3 + j] for j in range(3)] for i in range(3)]
    return phi, matmul(phi, e12)


def main():
    print("// x, dt, tau, sigma, Phi_ra, Phi_va, Phi_aa, Q_rr, Q_rv, Q_ra, Q_vv, Q_va, Q_aa")
    for r in RATIOS:
        tau = DT / float(r)
        phi, q = chain(DT, tau, SIGMA)
        vals = [phi[0][2], phi[1][2], phi[2][2], q[0][0], q[0][1], q[0][2], q[1][1], q[1][2], q[2][2]]
        print("{%s, %r, %r, %r, %s}," % (r, DT, tau, SIGMA, ", ".join("%.17g" % v for v in vals)))


if __name__ == "__main__":
    main()
