"""Peer benchmark of evaluation (issue 12): exact-bezier against
dhermes/bezier (Fortran speedups), geomdl and Python's `fractions`, on the
same random inputs, interleaved over several rounds.

Run through `benches/peers/run` (it makes the virtual environment and
builds our side). Alone:

    python peer_eval.py --ours BINARY [--rounds 3] [--repeat 3] [--ours-repeat 30]

where BINARY is the executable that `cargo bench --bench peer_eval --no-run`
names (target/release/deps/peer_eval-…).

Cases (per point, so batch sizes differ between cases):

- f64_curve3 / f64_curve10 / f64_curve40: planar polynomial curves,
  bezier `Curve.evaluate_multi` (200 000 parameters);
- f64_tri3: cubic triangle in space, bezier
  `Triangle.evaluate_cartesian_multi(verify=False)` (200 000 points);
- f64_bicubic: rational bicubic in space, geomdl `NURBS.Surface`
  (clamped knots, so the one Bézier patch) `evaluate_list` (2 000 points);
- exact_curve3/10/40, exact_tri3, exact_bicubic: the same homogeneous
  Horner–Bernstein sum
  as ours in Python with `Fraction` (200 points; coordinates decimals with
  two places (k/100, as CAD data in decimal text reads exactly), weights
  random p/q with p in 10000..20000 and q in 600..700 (like 12345/678),
  parameters k/100 or k/457).

The last line printed is the JSON object of ratios ours/peer, of
ours / the fixed-size kernel that peer_eval.rs keeps as the yardstick of
the SIMD lane kernels (`f64_curve3_vs_fixed_kernel`,
`f64_bicubic_vs_fixed_kernel`; 8 points at a time, vectorised by the
compiler), and of ours / the machine's bound for the five f64 cases
(`f64_curve3_vs_machine_bound` …, issue 31): the bound of a case is
max(flops / peak GFLOP/s, divides / peak divides per ns), with the flops
and divides per point of the scheme (src/eval/lanes.rs, an FMA counting
two flops) and the peak that `peer_eval --peak` measures in each round
(FMAs and divides of the widest vectors the processor has, on many
independent chains; the best round counts), given in the same line
(`machine_peak_gflops`, `machine_peak_divides_per_ns`,
`machine_clock_ghz`).
"""

import argparse
import json
import random
import statistics
import subprocess
import tempfile
import time
from fractions import Fraction
from math import comb

import bezier
import numpy as np
from geomdl import NURBS

F64_POINTS = 200_000
GEOMDL_POINTS = 2_000
EXACT_POINTS = 200


def rnd_coord(rng):
    return rng.randint(-1000, 1000) / 100


def frac_text(q):
    return f"{q.numerator}/{q.denominator}"


def make_cases(seed):
    rng = random.Random(seed)
    cases = []
    for n in (3, 10, 40):
        pts = [[rnd_coord(rng), rnd_coord(rng)] for _ in range(n + 1)]
        ts = [rng.random() for _ in range(F64_POINTS)]
        cases.append({"name": f"f64_curve{n}", "patch": {"kind": "curve", "degree": n, "points": pts},
                      "params": ts, "exact": False})
    tri = [[[rnd_coord(rng) for _ in range(3)] for _ in range(4 - j)] for j in range(4)]
    uv = []
    for _ in range(F64_POINTS):
        u, v = rng.random(), rng.random()
        if u + v > 1:
            u, v = 1 - u, 1 - v
        uv += [u, v]
    cases.append({"name": "f64_tri3", "patch": {"kind": "tri", "degree": 3, "points": tri},
                  "params": uv, "exact": False})
    rect = [[[rnd_coord(rng) for _ in range(3)] for _ in range(4)] for _ in range(4)]
    weights = [[rng.randint(50, 200) / 100 for _ in range(4)] for _ in range(4)]
    cases.append({"name": "f64_bicubic", "patch": {"kind": "rect", "degree": [3, 3], "points": rect,
                                                    "weights": weights},
                  "params": [rng.random() for _ in range(2 * GEOMDL_POINTS)], "exact": False})
    # Exact: rational coordinates and weights, parameters k/100 and p/457.
    def exact_param():
        return Fraction(rng.randint(0, 100), 100) if rng.random() < 0.5 else Fraction(rng.randint(0, 457), 457)
    rect_q = [[[Fraction(rng.randint(-10000, 10000), 100) for _ in range(3)] for _ in range(4)]
              for _ in range(4)]
    w_q = [[Fraction(rng.randint(10000, 20000), rng.randint(600, 700)) for _ in range(4)] for _ in range(4)]
    cases.append({"name": "exact_bicubic",
                  "patch": {"kind": "rect", "degree": [3, 3],
                            "points": [[[frac_text(x) for x in p] for p in row] for row in rect_q],
                            "weights": [[frac_text(w) for w in row] for row in w_q]},
                  "params": [frac_text(exact_param()) for _ in range(2 * EXACT_POINTS)], "exact": True})
    for n in (3, 10, 40):
        curve_q = [[Fraction(rng.randint(-10000, 10000), 100) for _ in range(2)] for _ in range(n + 1)]
        cw_q = [Fraction(rng.randint(10000, 20000), rng.randint(600, 700)) for _ in range(n + 1)]
        cases.append({"name": f"exact_curve{n}",
                      "patch": {"kind": "curve", "degree": n,
                                "points": [[frac_text(x) for x in p] for p in curve_q],
                                "weights": [frac_text(w) for w in cw_q]},
                      "params": [frac_text(exact_param()) for _ in range(EXACT_POINTS)], "exact": True})
    tri_q = [[[Fraction(rng.randint(-10000, 10000), 100) for _ in range(3)] for _ in range(4 - j)] for j in range(4)]
    tw_q = [[Fraction(rng.randint(10000, 20000), rng.randint(600, 700)) for _ in range(4 - j)] for j in range(4)]
    uv_q = []
    for _ in range(EXACT_POINTS):
        u, v = exact_param(), exact_param()
        if u + v > 1:
            u, v = 1 - u, 1 - v
        uv_q += [frac_text(u), frac_text(v)]
    cases.append({"name": "exact_tri3",
                  "patch": {"kind": "tri", "degree": 3,
                            "points": [[[frac_text(x) for x in p] for p in row] for row in tri_q],
                            "weights": [[frac_text(w) for w in row] for row in tw_q]},
                  "params": uv_q, "exact": True})
    return cases


# Flops (an FMA counts two) and divides per point of our scheme
# (src/eval/lanes.rs): curve n, stride s: 1 + n(3s + 1) and s − 1; tri n:
# 2 + n(n + 1)/2·(3s + 1) + n(2s + 1); rect (m, n): 2 + (m + 1)·n(3s + 1)
# + m(3s + 1), but a spatial bicubic in the vector builds (AVX2, AVX-512)
# by its Bernstein values: 2 + 12 + 4·4·7 + 4·7 = 154 (rect_bernstein),
# and a curve of degree n >= 4 there by blocks of 4 terms (curve_blocks):
# 9 + (k0 − 1)(3s + 1) + (Q − 1) + 10sQ with k0 = n + 1 mod 4 in 1..=4,
# Q = (n + 1 − k0)/4: 90 for degree 10 (k0 = 3, Q = 2), 318 for degree 40
# (k0 = 1, Q = 10); all s − 1 divides. The bound is that of the scheme the
# build runs.
COST = {
    "f64_curve3": (31, 2),
    "f64_curve10": (90, 2),
    "f64_curve40": (318, 2),
    "f64_tri3": (107, 3),
    "f64_bicubic": (154, 3),
}


def peak_rates(peaks):
    """The best FMA GFLOP/s and divides per ns over the rounds, of the
    widest vectors measured (8-wide where the processor has AVX-512)."""
    gflops = max(p.get("fma8_gflops", p.get("fma4_gflops", 0)) for p in peaks)
    divides = max(p.get("div8_per_ns", p.get("div4_per_ns", 0)) for p in peaks)
    clock = max(p.get("clock_ghz", 0) for p in peaks)
    return gflops, divides, clock


def bound_ns(name, gflops, divides):
    """The machine's bound of a case, ns per point."""
    flops, divs = COST[name]
    return max(flops / gflops, divs / divides)


def best(repeat, points, f):
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        f()
        times.append((time.perf_counter() - start) * 1e9 / points)
    return min(times)


def horner_fraction(hs, a, b):
    """Σ C(n,i) a^{n−i} bⁱ H_i in Fractions (the scheme of our kernel)."""
    n = len(hs) - 1
    out = list(hs[0])
    bpow = Fraction(1)
    for i in range(1, n + 1):
        bpow *= b
        c = comb(n, i) * bpow
        out = [o * a + c * x for o, x in zip(out, hs[i])]
    return out


def exact_hom(points, weights):
    return [[Fraction(x) * Fraction(w) for x in p] + [Fraction(w)] for p, w in zip(points, weights)]


def theirs(cases, repeat):
    result = {}
    for case in cases:
        name, patch, params = case["name"], case["patch"], case["params"]
        if name.startswith("f64_curve"):
            nodes = np.asfortranarray(np.array(patch["points"], dtype=float).T)
            curve = bezier.Curve(nodes, degree=patch["degree"], copy=False, verify=False)
            s = np.array(params)
            result[name] = best(repeat, len(params), lambda: curve.evaluate_multi(s))
        elif name == "f64_tri3":
            nodes = np.asfortranarray(np.array([p for row in patch["points"] for p in row], dtype=float).T)
            tri = bezier.Triangle(nodes, degree=3, copy=False, verify=False)
            uv = np.asfortranarray(np.array(params).reshape(-1, 2))
            result[name] = best(repeat, len(uv), lambda: tri.evaluate_cartesian_multi(uv, verify=False))
        elif name == "f64_bicubic":
            surf = NURBS.Surface()
            surf.degree_u, surf.degree_v = 3, 3
            surf.set_ctrlpts([p for row in patch["points"] for p in row], 4, 4)
            surf.weights = [w for row in patch["weights"] for w in row]
            surf.knotvector_u = [0, 0, 0, 0, 1, 1, 1, 1]
            surf.knotvector_v = [0, 0, 0, 0, 1, 1, 1, 1]
            uv = [tuple(params[i:i + 2]) for i in range(0, len(params), 2)]
            result[name] = best(repeat, len(uv), lambda: surf.evaluate_list(uv))
        elif name.startswith("exact_curve"):
            hs = exact_hom(patch["points"], patch["weights"])
            ts = [Fraction(t) for t in params]

            def run():
                for t in ts:
                    h = horner_fraction(hs, 1 - t, t)
                    [x / h[-1] for x in h[:-1]]
            result[name] = best(repeat, len(ts), run)
        elif name == "exact_tri3":
            rows = [exact_hom(p, w) for p, w in zip(patch["points"], patch["weights"])]
            uv = [(Fraction(params[i]), Fraction(params[i + 1])) for i in range(0, len(params), 2)]

            def run():
                for u, v in uv:
                    w = 1 - u - v
                    # Σ_j C(3,j) vʲ [Σ_i C(3−j,i) uⁱ w^{3−j−i} H_ij], as ours.
                    h = [Fraction(0)] * 4
                    for j, row in enumerate(rows):
                        r = horner_fraction(row, w, u)
                        c = comb(3, j) * v**j
                        h = [a + c * b for a, b in zip(h, r)]
                    [x / h[-1] for x in h[:-1]]
            result[name] = best(repeat, len(uv), run)
        elif name == "exact_bicubic":
            rows = [exact_hom(p, w) for p, w in zip(patch["points"], patch["weights"])]
            uv = [(Fraction(params[i]), Fraction(params[i + 1])) for i in range(0, len(params), 2)]

            def run():
                for u, v in uv:
                    col = [horner_fraction(r, 1 - v, v) for r in rows]
                    h = horner_fraction(col, 1 - u, u)
                    [x / h[-1] for x in h[:-1]]
            result[name] = best(repeat, len(uv), run)
    return result


PEERS = {
    "f64_curve3": ("f64_curve3_vs_bezier", "bezier Curve.evaluate_multi"),
    "f64_curve10": ("f64_curve10_vs_bezier", "bezier Curve.evaluate_multi"),
    "f64_curve40": ("f64_curve40_vs_bezier", "bezier Curve.evaluate_multi"),
    "f64_tri3": ("f64_tri3_vs_bezier", "bezier Triangle.evaluate_cartesian_multi"),
    "f64_bicubic": ("f64_bicubic_vs_geomdl", "geomdl NURBS.Surface.evaluate_list"),
    "exact_curve3": ("exact_curve3_vs_fractions", "Python fractions, same Horner scheme"),
    "exact_curve10": ("exact_curve10_vs_fractions", "Python fractions, same Horner scheme"),
    "exact_tri3": ("exact_tri3_vs_fractions", "Python fractions, same Horner scheme"),
    "exact_bicubic": ("exact_bicubic_vs_fractions", "Python fractions, same Horner scheme"),
    "exact_curve40": ("exact_curve40_vs_fractions", "Python fractions, same Horner scheme"),
}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--ours", required=True, help="path of the peer_eval bench binary")
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--repeat", type=int, default=3, help="passes of each peer (best counts)")
    # Ours is cheap (a pass of an f64 case takes 0.4-2 ms): 30 passes, so
    # that one descheduling on a shared machine does not decide the best.
    ap.add_argument("--ours-repeat", type=int, default=30, help="passes of ours (best counts)")
    ap.add_argument("--seed", type=int, default=12)
    args = ap.parse_args()
    cases = make_cases(args.seed)
    with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
        json.dump(cases, f)
        path = f.name
    ours_runs, theirs_runs, peaks = [], [], []
    for r in range(args.rounds):
        peaks.append(json.loads(subprocess.run([args.ours, "--peak"], check=True,
                                               capture_output=True, text=True).stdout))
        out = subprocess.run([args.ours, path, "--repeat", str(args.ours_repeat)], check=True,
                             capture_output=True, text=True).stdout
        ours_runs.append(json.loads(out))
        theirs_runs.append(theirs(cases, args.repeat))
        print(f"round {r + 1}/{args.rounds} done", flush=True)
    med = lambda runs, k: statistics.median(run[k] for run in runs)
    print(f"\n| case | ours (ns/point) | fixed-size kernel | peer | peer (ns/point) | ours / peer |")
    print("| --- | --- | --- | --- | --- | --- |")
    ratios = {}
    for name, (key, peer) in PEERS.items():
        o, t = med(ours_runs, name), med(theirs_runs, name)
        ref = f"{med(ours_runs, name + '_reference'):.1f}" if name + "_reference" in ours_runs[0] else ""
        ratios[key] = round(o / t, 4)
        print(f"| {name} | {o:.1f} | {ref} | {peer} | {t:.1f} | {o / t:.3g} |")
    # The lane kernels against the vectorised fixed-size kernel of the same scheme.
    for name in ("f64_curve3", "f64_bicubic"):
        ratios[f"{name}_vs_fixed_kernel"] = round(med(ours_runs, name) / med(ours_runs, name + "_reference"), 4)
    # The lane kernels against the machine's bound.
    gflops, divides, clock = peak_rates(peaks)
    print(f"\nmachine peak: {gflops:.1f} GFLOP/s (FMA), {divides:.3f} divides/ns, clock {clock:.2f} GHz")
    print("\n| case | flops | divides | bound (ns/point) | ours (ns/point) | ours / bound |")
    print("| --- | --- | --- | --- | --- | --- |")
    for name, (flops, divs) in COST.items():
        b, o = bound_ns(name, gflops, divides), med(ours_runs, name)
        ratios[f"{name}_vs_machine_bound"] = round(o / b, 4)
        print(f"| {name} | {flops} | {divs} | {b:.2f} | {o:.2f} | {o / b:.3g} |")
    ratios["machine_peak_gflops"] = round(gflops, 2)
    ratios["machine_peak_divides_per_ns"] = round(divides, 4)
    ratios["machine_clock_ghz"] = round(clock, 3)
    print()
    print(json.dumps(ratios))


if __name__ == "__main__":
    main()
