#!/usr/bin/env python3
"""The NumPy path of the Python package on 10⁶ points (issue 29): our
`eval_many` against the Rust batch evaluator on the same points (the cost
of the Python call) and against dhermes/bezier's `Curve.evaluate_multi` and
`Triangle.evaluate_cartesian_multi` called the same way.

Run in a benchmark virtual environment (never in CI):

    python3 -m venv /tmp/eb-bench && . /tmp/eb-bench/bin/activate
    pip install ./python bezier
    python3 benches/peers/python_numpy.py [--points 1000000] [--rust]

`--rust` also runs `cargo bench --bench peer_eval` on the same cases
(written to a temporary JSON file) for the Rust batch time. Cases: a
polynomial cubic curve in the plane and a polynomial cubic triangle in
space (bezier evaluates polynomial Bézier forms only), parameters from a
fixed seed. Times are the best of --repeat runs, in nanoseconds per point.
"""

import argparse
import json
import os
import subprocess
import tempfile
import time

import numpy as np

import exact_bezier as eb

CURVE = [[0, 0], [1, 3], [3, 3], [4, 0]]
# Rows by j (points[j][i] = P_{i,j,3−i−j}), as exact_bezier.TriPatch takes them.
TRI = [
    [[0, 0, 0], [1, 0, 1], [2, 0, 0], [3, 0, 1]],
    [[0, 1, 1], [1, 1, 2], [2, 1, 1]],
    [[0, 2, 0], [1, 2, 1]],
    [[0, 3, 1]],
]


def best(f, repeat):
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        f()
        times.append(time.perf_counter() - t0)
    return min(times)


def bezier_nodes_tri():
    """bezier's node order for a triangle: by rows of increasing v, u
    increasing in each (the points as columns)."""
    pts = [TRI[j][i] for j in range(4) for i in range(4 - j)]
    return np.asfortranarray(np.array(pts, dtype=float).T)


def rust_times(ts, uv, repeat):
    cases = [
        {"name": "curve", "patch": {"kind": "curve", "points": CURVE},
         "params": [repr(float(t)) for t in ts], "exact": False},
        {"name": "tri", "patch": {"kind": "tri", "points": TRI},
         "params": [repr(float(x)) for x in uv.ravel()], "exact": False},
    ]
    with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
        json.dump(cases, f)
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    out = subprocess.run(
        ["cargo", "bench", "--bench", "peer_eval", "--", f.name, "--repeat", str(repeat)],
        cwd=root, check=True, capture_output=True, text=True,
    ).stdout
    os.unlink(f.name)
    return json.loads(out.strip().splitlines()[-1])


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--points", type=int, default=1_000_000)
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--rust", action="store_true")
    a = ap.parse_args()
    n = a.points
    rng = np.random.default_rng(29)
    ts = rng.random(n)
    u, v = rng.random(n), rng.random(n)
    flip = u + v > 1
    u[flip], v[flip] = 1 - u[flip], 1 - v[flip]
    uv = np.column_stack([u, v])

    curve, tri = eb.Curve(CURVE), eb.TriPatch(TRI)
    ours = {
        "curve": best(lambda: curve.eval_many(ts), a.repeat) / n * 1e9,
        "tri": best(lambda: tri.eval_many(uv), a.repeat) / n * 1e9,
    }
    result = {"points": n, "exact_bezier_ns_per_point": ours}
    try:
        import bezier
    except ImportError:
        result["bezier"] = "not installed (pip install bezier)"
    else:
        bc = bezier.Curve.from_nodes(np.asfortranarray(np.array(CURVE, dtype=float).T))
        bt = bezier.Triangle(bezier_nodes_tri(), degree=3)
        # The same points: bezier's triangle takes (s, t) = our (u, v).
        ours_pts = tri.eval_many(uv[:5])
        theirs = bt.evaluate_cartesian_multi(np.asfortranarray(uv[:5])).T
        assert np.allclose(ours_pts, theirs), (ours_pts, theirs)
        assert np.allclose(curve.eval_many(ts[:5]), bc.evaluate_multi(ts[:5]).T)
        peer = {
            "curve": best(lambda: bc.evaluate_multi(ts), a.repeat) / n * 1e9,
            "tri": best(lambda: bt.evaluate_cartesian_multi(np.asfortranarray(uv)), a.repeat) / n * 1e9,
        }
        result["bezier_ns_per_point"] = peer
        result["ours_over_bezier"] = {k: ours[k] / peer[k] for k in ours}
    if a.rust:
        rust = rust_times(ts, uv, a.repeat)
        result["rust_batch_ns_per_point"] = {k: rust[k] for k in ("curve", "tri")}
        result["python_over_rust"] = {k: ours[k] / rust[k] for k in ours}
    print(json.dumps(result, indent=2))


if __name__ == "__main__":
    main()
