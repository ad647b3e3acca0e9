#!/usr/bin/python3
"""The leading term of LPF's symplecticity defect as an exact series in tau, independently of the
library (docs/results/schemes.md, "Classes of Lagrangians").

usage: /usr/bin/python3 scripts/lpf_defect_series.py [--m A..B] [--digits D]

LPF of degree m is the Nystrom collocation method for q'' = F(q, q') on its m - 1 interior nodes
with the Legendre map p = L_v(q, v) at both ends (include/geomint/schemes/lpf.hpp). Here every
quantity is a truncated power series in tau whose coefficients are first-order jets in the
initial state z0 = (q0, v0), with coefficients in mpmath at D digits (default 60). The collocation
polynomial x(tau theta) = q0 + tau theta v0 + tau^2 sum_k alpha_k theta^k is found by the
fixed-point iteration alpha = C^{-1} F(stages), which gains one power of tau per sweep, so after
as many sweeps as powers kept the series is exact to that power. The defect J^T Omega J - Omega
of the map (q0, p0) -> (q1, p1) is then a series in tau; the script prints the first power whose
coefficient is not zero (max entry above 10^(-D/2)), or "none" if no power below tau^(2 B + 2)
has one (B the largest m, default 6), for four Lagrangians:

  mass      L = m(q) v^2 / 2 - V(q), m = 1 + q/3 + q^2/5, V = q^2/2 + q^3/7 (1 dof)
  natural   L = v^2 / 2 - V(q), V = q^2/2 + q^3/7 + q^4/5 (1 dof)
  magnetic  L = |v|^2/2 + (x v_y - y v_x)/2 - V, V = r^2/2 + r^4/12 + 2xy/5 (2 dof; constant
            gyroscopic term, as the charged particle in a constant field or a rotating frame)
  gauge     L = |v|^2/2 + grad(x^2 y / 3) . v - V, V = |q|^2/2 + x^4/4 + xy/5 (2 dof; a closed
            gauge term: the Euler-Lagrange equations of a natural system)

at q0 = 1/2 (1 dof) or (1/2, -1/4), v0 = 1/3 or (1/3, 2/7).
"""
import sys

import mpmath as mp

POWERS = 14  # tau^0 .. tau^(POWERS - 1): 2 * (largest m) + 2 (main)


class Jet:
    """A series sum_j tau^j (c0_j + sum_k c_kj dz_k): c[0] the value, c[k] the derivative in z_k."""

    dirs = 0

    def __init__(self, c):
        self.c = c

    @classmethod
    def zero(cls):
        return cls([[mp.mpf(0)] * POWERS for _ in range(cls.dirs + 1)])

    @classmethod
    def const(cls, x, power=0, direction=None):
        j = cls.zero()
        j.c[0][power] = mp.mpf(x)
        if direction is not None:
            j.c[direction][0] = mp.mpf(1)
        return j

    def __add__(self, o):
        o = o if isinstance(o, Jet) else Jet.const(o)
        return Jet([[x + y for x, y in zip(r, t)] for r, t in zip(self.c, o.c)])

    __radd__ = __add__

    def __neg__(self):
        return Jet([[-x for x in r] for r in self.c])

    def __sub__(self, o):
        return self + (-(o if isinstance(o, Jet) else Jet.const(o)))

    def __rsub__(self, o):
        return (-self) + o

    @staticmethod
    def _conv(x, y):
        out = [mp.mpf(0)] * POWERS
        for i, xi in enumerate(x):
            if xi != 0:
                for j in range(POWERS - i):
                    out[i + j] += xi * y[j]
        return out

    def __mul__(self, o):
        if not isinstance(o, Jet):
            o = mp.mpf(o)
            return Jet([[x * o for x in r] for r in self.c])
        c = [self._conv(self.c[0], o.c[0])]
        for k in range(1, Jet.dirs + 1):
            c.append([x + y for x, y in zip(self._conv(self.c[0], o.c[k]), self._conv(self.c[k], o.c[0]))])
        return Jet(c)

    __rmul__ = __mul__

    def reciprocal(self):
        x = self.c[0]
        r = [mp.mpf(0)] * POWERS
        r[0] = 1 / x[0]
        for n in range(1, POWERS):
            r[n] = -sum(x[k] * r[n - k] for k in range(1, n + 1)) / x[0]
        r2 = self._conv(r, r)
        return Jet([r] + [[-v for v in self._conv(self.c[k], r2)] for k in range(1, Jet.dirs + 1)])

    def __truediv__(self, o):
        return self * o.reciprocal() if isinstance(o, Jet) else self * (1 / mp.mpf(o))


def interior_nodes(family, m):
    """The m - 1 interior nodes of geomint's node families on [0, 1] (core/nodes.hpp)."""
    def roots(f, degree):
        coeffs = mp.taylor(f, 0, degree)[::-1]
        return sorted((1 + x) / 2 for x in mp.polyroots(coeffs, maxsteps=400, extraprec=400))
    if family == "gauss-interior":
        return roots(lambda x: mp.legendre(m - 1, x), m - 1)
    if family == "lobatto":
        return roots(lambda x: mp.diff(lambda y: mp.legendre(m, y), x), m - 1)
    if family == "chebyshev":
        return sorted((1 - mp.cos(mp.pi * i / m)) / 2 for i in range(1, m))
    return [mp.mpf(i) / m for i in range(1, m)]  # equispaced


def defect_series(family, m, n, force, momentum, q0, v0):
    """max |(J^T Omega J - Omega)_ij| per power of tau, J = d(q1, p1)/d(q0, p0)."""
    Jet.dirs = 2 * n
    c = interior_nodes(family, m)
    ks = list(range(2, m + 1))
    C = mp.matrix([[k * (k - 1) * ci ** (k - 2) for k in ks] for ci in c]) ** -1
    Q0 = [Jet.const(q0[d], direction=1 + d) for d in range(n)]
    V0 = [Jet.const(v0[d], direction=1 + n + d) for d in range(n)]
    tau, tau2 = Jet.const(1, 1), Jet.const(1, 2)
    alpha = [[Jet.zero() for _ in range(n)] for _ in ks]
    for _ in range(POWERS + 1):
        stages = []
        for ci in c:
            x = [Q0[d] + V0[d] * tau * ci + tau2 * sum((alpha[j][d] * ci ** k for j, k in enumerate(ks)), Jet.zero())
                 for d in range(n)]
            v = [V0[d] + tau * sum((alpha[j][d] * (k * ci ** (k - 1)) for j, k in enumerate(ks)), Jet.zero())
                 for d in range(n)]
            stages.append(force(x, v))
        alpha = [[sum((C[j, i] * stages[i][d] for i in range(len(c))), Jet.zero()) for d in range(n)]
                 for j in range(len(ks))]
    q1 = [Q0[d] + V0[d] * tau + tau2 * sum((a[d] for a in alpha), Jet.zero()) for d in range(n)]
    v1 = [V0[d] + tau * sum((alpha[j][d] * k for j, k in enumerate(ks)), Jet.zero()) for d in range(n)]
    D = 2 * n

    def jacobian(rows):  # per power of tau: d(rows)/d(q0, v0)
        return [mp.matrix([[r.c[k][j] for k in range(1, D + 1)] for r in rows]) for j in range(POWERS)]

    A, B = jacobian(q1 + momentum(q1, v1)), jacobian(Q0 + momentum(Q0, V0))
    omega = mp.zeros(D, D)
    for i in range(n):
        omega[i, n + i], omega[n + i, i] = 1, -1
    to_qp = B[0] ** -1  # (q0, v0) -> (q0, p0): B has no tau dependence
    out = []
    for j in range(POWERS):
        form = mp.zeros(D, D)
        for i in range(j + 1):
            form += A[i].T * omega * A[j - i] - B[i].T * omega * B[j - i]
        out.append(max(abs(x) for x in to_qp.T * form * to_qp))
    return out


def third(x):
    return mp.mpf(x) / 3


LAGRANGIANS = {
    "mass": (1, lambda x, v: [(-(third(1) + x[0] * (mp.mpf(2) / 5)) * v[0] * v[0] * mp.mpf(0.5)
                               - (x[0] + x[0] * x[0] * (mp.mpf(3) / 7))) / (1 + x[0] * third(1) + x[0] * x[0] / 5)],
             lambda x, v: [(1 + x[0] * third(1) + x[0] * x[0] / 5) * v[0]], [mp.mpf(1) / 2], [third(1)]),
    "natural": (1, lambda x, v: [-(x[0] + x[0] * x[0] * (mp.mpf(3) / 7) + x[0] * x[0] * x[0] * (mp.mpf(4) / 5))],
                lambda x, v: [v[0]], [mp.mpf(1) / 2], [third(1)]),
    "magnetic": (2, lambda x, v: [v[1] - (x[0] + x[0] * (x[0] * x[0] + x[1] * x[1]) * third(1) + x[1] * (mp.mpf(2) / 5)),
                                  -v[0] - (x[1] + x[1] * (x[0] * x[0] + x[1] * x[1]) * third(1) + x[0] * (mp.mpf(2) / 5))],
                 lambda x, v: [v[0] - x[1] * mp.mpf(0.5), v[1] + x[0] * mp.mpf(0.5)],
                 [mp.mpf(1) / 2, -mp.mpf(1) / 4], [third(1), mp.mpf(2) / 7]),
    "gauge": (2, lambda x, v: [-(x[0] + x[0] * x[0] * x[0] + x[1] / 5), -(x[1] + x[0] / 5)],
              lambda x, v: [v[0] + x[0] * x[1] * third(2), v[1] + x[0] * x[0] * third(1)],
              [mp.mpf(1) / 2, -mp.mpf(1) / 4], [third(1), mp.mpf(2) / 7]),
}


def main(argv):
    lo, hi, digits = 2, 6, 60
    args = list(argv)
    while args:
        flag = args.pop(0)
        if flag == "--m" and args:
            text = args.pop(0)
            lo, hi = (int(t) for t in text.split("..")) if ".." in text else (int(text), int(text))
        elif flag == "--digits" and args:
            digits = int(args.pop(0))
        else:
            sys.exit(__doc__)
    global POWERS
    POWERS = 2 * hi + 2
    mp.mp.dps = digits
    zero = mp.mpf(10) ** (-digits // 2)
    print("family,m,lagrangian,leading_power,leading_coefficient")
    for family in ("gauss-interior", "equispaced", "lobatto", "chebyshev"):
        for m in range(lo, hi + 1):
            for name, (n, force, momentum, q0, v0) in LAGRANGIANS.items():
                series = defect_series(family, m, n, force, momentum, q0, v0)
                lead = next((j for j, x in enumerate(series) if x > zero), None)
                print(f"{family},{m},{name},{'none' if lead is None else lead},"
                      f"{'0' if lead is None else mp.nstr(series[lead], 6)}")


if __name__ == "__main__":
    main(sys.argv[1:])
