"""SymPy peer of benches/poly.rs: the Möbius maps (2)(3) of source 000 keep
every point of a fully symbolic rational (m, m) patch (symbols p_ij = ω·x,
w_ij = ω, α, β, s, t). Two formulations, each the same computation as ours:

- "steps": what our library does (`mobius_u`, `mobius_v`, de Casteljau in t
  on each row then in s, for the new patch at (s, t) and for the old one at
  the homogeneous parameters (α(1−s), (1−α)s; β(1−t), (1−β)t)), with
  `expand` after each step so every intermediate is a canonical polynomial
  as in ours;
- "sums": both sides as the defining double Bernstein sums (the peer of
  both of our formulations, see FORMULATIONS),
      new = Σ_ij B_i^m(s) B_j^m(t) ω̃_ij c_ij,  ω̃ = (1−α)^i α^(m−i) (1−β)^j β^(m−j)
      old = Σ_ij C(m,i) C(m,j) ((1−α)s)^i (α(1−s))^(m−i) ((1−β)t)^j (β(1−t))^(m−j) c_ij
  with each side expanded to its canonical polynomial and the two compared
  (`check_sums`), as ours does.

`expand(new − old) == 0` is not a peer: SymPy's automatic evaluation
distributes the integer powers ((1−α)s)^i → (1−α)^i s^i, so every summand
of `old` is the same expression tree as one of `new`, `new − old` cancels to
0 while the sum is built, and `expand` receives 0 — nothing is expanded.
It is printed as "SymPy, structural cancellation" for reference only.

Time is CPU seconds (time.process_time), the minimum over `--repeat` runs,
with SymPy's cache cleared before each. With `--criterion DIR` it reads our
medians from criterion's estimates and prints the comparison table with the
growth exponents (least-squares slope of log time on log m).
"""

import argparse
import json
import math
import os
import time

import sympy as sp

DEGREES = [3, 5, 6, 8]


def net(m):
    return [[sp.symbols(f"p{i}{j} w{i}{j}") for j in range(m + 1)] for i in range(m + 1)]


def casteljau(points, h0, h1):
    """de Casteljau at the homogeneous parameter (h0, h1), per coordinate."""
    row = [list(p) for p in points]
    for k in range(len(row) - 1, 0, -1):
        for i in range(k):
            row[i] = [sp.expand(h0 * x + h1 * y) for x, y in zip(row[i], row[i + 1])]
    return row[0]


def check_steps(m):
    a, b, s, t = sp.symbols("alpha beta s t")
    c = net(m)
    fu = [sp.expand((1 - a) ** i * a ** (m - i)) for i in range(m + 1)]
    fv = [sp.expand((1 - b) ** j * b ** (m - j)) for j in range(m + 1)]
    moved = [[[sp.expand(sp.expand(x * fu[i]) * fv[j]) for x in c[i][j]] for j in range(m + 1)]
             for i in range(m + 1)]
    new = casteljau([casteljau(row, 1 - t, t) for row in moved], 1 - s, s)
    old = casteljau([casteljau(row, b * (1 - t), (1 - b) * t) for row in c], a * (1 - s), (1 - a) * s)
    return all(sp.expand(x - y) == 0 for x, y in zip(new, old))


def sums(m):
    """Both sides as unexpanded double Bernstein sums, per coordinate."""
    a, b, s, t = sp.symbols("alpha beta s t")
    c = net(m)
    new = [0, 0]
    old = [0, 0]
    for i in range(m + 1):
        for j in range(m + 1):
            mob = (1 - a) ** i * a ** (m - i) * (1 - b) ** j * b ** (m - j)
            bern = sp.binomial(m, i) * sp.binomial(m, j)
            basis = bern * s**i * (1 - s) ** (m - i) * t**j * (1 - t) ** (m - j)
            mapped = bern * ((1 - a) * s) ** i * (a * (1 - s)) ** (m - i)
            mapped *= ((1 - b) * t) ** j * (b * (1 - t)) ** (m - j)
            for k in range(2):
                new[k] += basis * mob * c[i][j][k]
                old[k] += mapped * c[i][j][k]
    return new, old


def check_sums(m):
    """Each side expanded to its canonical form, then compared."""
    new, old = sums(m)
    return all(sp.expand(x) == sp.expand(y) for x, y in zip(new, old))


def check_cancel(m):
    """`expand(new − old) == 0`: the difference is already 0 before expand."""
    new, old = sums(m)
    return all(sp.expand(x - y) == 0 for x, y in zip(new, old))


# SymPy mirroring our steps takes seconds at (3, 3) and more than 5 minutes
# at (5, 5), so both of our formulations are compared with SymPy's sums;
# `--steps 3` times the step-by-step mirror at the given bidegrees.
FORMULATIONS = {
    "library algorithms (de Casteljau)": (check_sums, "mobius identity"),
    "Bernstein sums": (check_sums, "mobius identity, Bernstein sums"),
}


def cpu_seconds(check, m, repeat):
    best = math.inf
    for _ in range(repeat):
        sp.core.cache.clear_cache()
        start = time.process_time()
        assert check(m), f"identity fails at m={m}"
        best = min(best, time.process_time() - start)
    return best


def ours(criterion_dir, group, m):
    path = os.path.join(criterion_dir, group, f"m={m}", "new", "estimates.json")
    with open(path) as f:
        return json.load(f)["median"]["point_estimate"] / 1e9


def slope(ms, ts):
    xs = [math.log(m) for m in ms]
    ys = [math.log(t) for t in ts]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--criterion", help="criterion output directory (target/criterion)")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--steps", type=int, nargs="*", default=[], metavar="M",
                    help="also time SymPy mirroring our de Casteljau steps at these m")
    args = ap.parse_args()
    for m in args.steps:
        print(f"SymPy, our steps (de Casteljau, expand per step), ({m},{m}): "
              f"{cpu_seconds(check_steps, m, 1):.3f} s CPU")
    print(f"SymPy {sp.__version__}; CPU seconds, min of {args.repeat}; ours: criterion median")
    cancel = {m: cpu_seconds(check_cancel, m, args.repeat) for m in DEGREES}
    print("SymPy, structural cancellation (no expansion, not a peer): "
          + ", ".join(f"({m},{m}) {cancel[m]:.4f}" for m in DEGREES))
    timed = {}
    for name, (check, group) in FORMULATIONS.items():
        if check not in timed:
            timed[check] = {m: cpu_seconds(check, m, args.repeat) for m in DEGREES}
        peer = timed[check]
        print(f"\nours: {name} (criterion group '{group}'); SymPy: {check.__name__}")
        if not args.criterion:
            for m in DEGREES:
                print(f"({m},{m}) {peer[m]:.4f}")
            continue
        mine = {m: ours(args.criterion, group, m) for m in DEGREES}
        print("| bidegree | ours (s) | SymPy (s) | SymPy / ours |")
        print("| --- | --- | --- | --- |")
        for m in DEGREES:
            print(f"| ({m},{m}) | {mine[m]:.5f} | {peer[m]:.4f} | {peer[m] / mine[m]:.1f}× |")
        print(f"growth exponent (time ~ m^k): ours k = {slope(DEGREES, [mine[m] for m in DEGREES]):.2f}, "
              f"SymPy k = {slope(DEGREES, [peer[m] for m in DEGREES]):.2f}")


if __name__ == "__main__":
    main()
