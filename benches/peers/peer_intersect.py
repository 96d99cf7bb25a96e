"""Peer comparison of curve intersection (issue 18): exact-bezier against
dhermes/bezier's floating-point `Curve.intersect`, on the same random
planar polynomial pairs of degrees 1 to 5, in one run.

Run through `benches/peers/intersect` (it makes the virtual environment and
builds our side). Alone:

    python peer_intersect.py --ours BINARY [--pairs 200]

where BINARY is the executable that `cargo bench --bench peer_intersect --no-run`
names (target/release/deps/peer_intersect-…).

Control points are decimals k/100 in [0, 1] (exact as text), so most pairs
cross. Agreement: every (s, t) the peer reports is within 1e-9 of one of
ours and the counts match, on the pairs where the peer succeeds (it raises
on some, e.g. tangencies and overlaps; those are counted, not compared).
Our filtered path is checked against our exact path on every pair (each
certified box holds exactly one exact crossing), and so is our f64 path
(tolerance 1e-12: the same count, each (s, t) within 1e-9 of an exact
one, where the exact path finds no overlap). Speed: the best of
`--repeat` runs per pair, for the cubic pairs, bezier `Curve.intersect`
against our filtered path (certified boxes where interval arithmetic
decides, exact answers elsewhere), our exact path and our f64 path; the
last lines print the medians and their ratios.
"""

import argparse
import json
import random
import statistics
import subprocess
import tempfile
import time

import bezier
import numpy as np


def make_pairs(seed, count):
    rng = random.Random(seed)
    pairs = []
    for k in range(count):
        m, n = (3, 3) if k % 4 == 0 else (rng.randint(1, 5), rng.randint(1, 5))
        curve = lambda d: {"kind": "curve", "degree": d,
                           "points": [[rng.randint(0, 100) / 100, rng.randint(0, 100) / 100]
                                      for _ in range(d + 1)]}
        pairs.append({"a": curve(m), "b": curve(n)})
    return pairs


def peer_curve(c):
    return bezier.Curve(np.asfortranarray(np.array(c["points"], dtype=float).T), degree=c["degree"])


def peer_intersect(pair, repeat):
    a, b = peer_curve(pair["a"]), peer_curve(pair["b"])
    best = float("inf")
    found = None
    for _ in range(repeat):
        start = time.perf_counter()
        found = a.intersect(b)
        best = min(best, time.perf_counter() - start)
    return found.T.tolist(), best * 1e6


def agree(peer, ours, tol):
    if len(peer) != len(ours):
        return False
    return all(any(abs(s - p) <= tol and abs(t - q) <= tol for p, q in ours) for s, t in peer)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--ours", required=True)
    ap.add_argument("--pairs", type=int, default=200)
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--seed", type=int, default=18)
    args = ap.parse_args()
    pairs = make_pairs(args.seed, args.pairs)
    with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
        json.dump(pairs, f)
    ours = json.loads(subprocess.run([args.ours, f.name, "--repeat", str(args.repeat)],
                                     check=True, capture_output=True, text=True).stdout)
    agreed, disagreed, peer_failed, ours_failed = 0, [], 0, 0
    decided = {"intervals": 0, "exact": 0}
    filtered_disagreed = [k for k, mine in enumerate(ours) if not mine.get("filtered_agrees", True)]
    f64_disagreed = [k for k, mine in enumerate(ours)
                     if "error" not in mine and mine["overlaps"] == 0
                     and (mine["f64_overlaps"] > 0 or not agree(mine["f64_points"], mine["points"], 1e-9))]
    cubic = {"peer": [], "filtered": [], "exact": [], "f64": []}
    for k, (pair, mine) in enumerate(zip(pairs, ours)):
        if "error" in mine:
            ours_failed += 1
            continue
        decided[mine["decided_by"]] += 1
        try:
            peer, peer_us = peer_intersect(pair, args.repeat)
        except Exception:
            peer_failed += 1
            continue
        if agree(peer, mine["points"], 1e-9) and mine["overlaps"] == 0:
            agreed += 1
        else:
            disagreed.append({"pair": k, "peer": peer, "ours": mine["points"]})
        if pair["a"]["degree"] == pair["b"]["degree"] == 3:
            cubic["peer"].append(peer_us)
            for path in ("filtered", "exact", "f64"):
                cubic[path].append(mine["us"][path])
    print(json.dumps({"pairs": len(pairs), "agreed": agreed, "disagreed": len(disagreed),
                      "peer_raised": peer_failed, "ours_raised": ours_failed,
                      "filtered_decided_by": decided,
                      "filtered_disagrees_with_exact": filtered_disagreed,
                      "f64_disagrees_with_exact": f64_disagreed}))
    for d in disagreed:
        print(json.dumps(d))
    med = {k: statistics.median(v) for k, v in cubic.items() if v}
    ratios = {k: round(med[k] / med["peer"], 4) for k in ("filtered", "exact", "f64")}
    # The last line: the ratios benches/peers/run gathers into its own last line.
    print(json.dumps({"cubic_pairs": len(cubic["peer"]), "median_us": med, "ours_over_peer": ratios,
                      **{f"intersect_{k}_vs_bezier": v for k, v in ratios.items()}}))


if __name__ == "__main__":
    main()
