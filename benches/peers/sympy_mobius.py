"""SymPy peer of benches/poly.rs: the Möbius maps (2)(3) of source 000 keep
every point of a fully symbolic rational (m, m) patch.

Both homogeneous coordinates (p = ω·x and w = ω, symbols p_ij, w_ij) of

    new(s, t) = Σ_ij B_i^m(s) B_j^m(t) ω̃_ij,  ω̃_ij = ω_ij (1−α)^i α^(m−i) (1−β)^j β^(m−j)
    old       = Σ_ij C(m,i) C(m,j) ((1−α)s)^i (α(1−s))^(m−i) ((1−β)t)^j (β(1−t))^(m−j) ω_ij

are built and `expand(new − old) == 0` is checked, as in our bench. Time is
CPU seconds (time.process_time), the minimum over `--repeat` runs.

With `--criterion DIR` it also reads our medians from criterion's
`DIR/mobius identity/m=M/new/estimates.json` and prints the comparison
table with the growth exponents (least-squares slope of log time on log m).
"""

import argparse
import json
import math
import os
import time

import sympy as sp

DEGREES = [3, 5, 6, 8]


def check(m):
    a, b, s, t = sp.symbols("alpha beta s t")
    new = [0, 0]
    old = [0, 0]
    for i in range(m + 1):
        for j in range(m + 1):
            coords = sp.symbols(f"p{i}{j} w{i}{j}")
            mob = (1 - a) ** i * a ** (m - i) * (1 - b) ** j * b ** (m - j)
            bern = sp.binomial(m, i) * sp.binomial(m, j)
            basis = bern * s**i * (1 - s) ** (m - i) * t**j * (1 - t) ** (m - j)
            mapped = bern * ((1 - a) * s) ** i * (a * (1 - s)) ** (m - i)
            mapped *= ((1 - b) * t) ** j * (b * (1 - t)) ** (m - j)
            for k in range(2):
                new[k] += basis * mob * coords[k]
                old[k] += mapped * coords[k]
    return all(sp.expand(new[k] - old[k]) == 0 for k in range(2))


def cpu_seconds(m, repeat):
    best = math.inf
    for _ in range(repeat):
        sp.core.cache.clear_cache()
        start = time.process_time()
        assert check(m), f"identity fails at m={m}"
        best = min(best, time.process_time() - start)
    return best


def ours(criterion_dir, m):
    path = os.path.join(criterion_dir, "mobius identity", f"m={m}", "new", "estimates.json")
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
    args = ap.parse_args()
    peer = {m: cpu_seconds(m, args.repeat) for m in DEGREES}
    print(f"SymPy {sp.__version__}, CPU seconds, min of {args.repeat}")
    if not args.criterion:
        for m in DEGREES:
            print(f"({m},{m}) {peer[m]:.4f}")
        return
    mine = {m: ours(args.criterion, m) for m in DEGREES}
    print("| bidegree | ours (s) | SymPy (s) | SymPy / ours |")
    print("| --- | --- | --- | --- |")
    for m in DEGREES:
        print(f"| ({m},{m}) | {mine[m]:.5f} | {peer[m]:.4f} | {peer[m] / mine[m]:.1f}× |")
    print(f"growth exponent (time ~ m^k): ours k = {slope(DEGREES, [mine[m] for m in DEGREES]):.2f}, "
          f"SymPy k = {slope(DEGREES, [peer[m] for m in DEGREES]):.2f}")


if __name__ == "__main__":
    main()
