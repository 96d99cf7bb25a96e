#!/usr/bin/env python3
"""Write N random bicubic rect patches plus one transformed copy of each
(exact Möbius map in u and v, weight scaling, random reversal and u/v swap),
for timing `exact-bezier dedup` and `exact-bezier key` on 2N patches:

    python3 benches/make_dedup_input.py 50000 > /tmp/p100k.json
    python3 benches/make_dedup_input.py --jsonl 100000 > /tmp/p200k.jsonl
    time target/release/exact-bezier dedup /tmp/p200k.jsonl > /tmp/classes.jsonl

Without --jsonl the output is one JSON array; with it, JSON Lines (one
patch per line). The answer must be N classes, each {2k, 2k+1}.
"""
import json
import random
import sys
from math import gcd


class Q:
    """A positive fraction p/q in lowest terms (faster than Fraction here)."""

    def __init__(self, p, q=1):
        g = gcd(p, q)
        self.p, self.q = p // g, q // g

    def __str__(self):
        return str(self.p) if self.q == 1 else f"{self.p}/{self.q}"


def patch(rng):
    pts = [[[rng.randint(-50, 50) for _ in range(3)] for _ in range(4)] for _ in range(4)]
    w = [[Q(rng.randint(1, 9)) for _ in range(4)] for _ in range(4)]
    return pts, w


def transformed(rng, pts, w):
    # Möbius parameters a = A/10, b = B/10: the weight (i, j) is multiplied
    # by k (1 − a)^i a^(3−i) (1 − b)^j b^(3−j) = k (10−A)^i A^(3−i) (10−B)^j B^(3−j) / 10^6.
    a, b = rng.randint(1, 9), rng.randint(1, 9)
    k = rng.randint(1, 5)
    w = [[Q(w[i][j].p * k * (10 - a) ** i * a ** (3 - i) * (10 - b) ** j * b ** (3 - j), 10 ** 6)
          for j in range(4)] for i in range(4)]
    if rng.random() < 0.5:
        pts, w = pts[::-1], w[::-1]
    if rng.random() < 0.5:
        pts, w = [list(r) for r in zip(*pts)], [list(r) for r in zip(*w)]
    return pts, w


def as_json(pts, w):
    return {"kind": "rect", "degree": [3, 3], "points": pts,
            "weights": [[str(x) for x in row] for row in w]}


def main():
    args = sys.argv[1:]
    jsonl = "--jsonl" in args
    args = [a for a in args if a != "--jsonl"]
    n = int(args[0]) if args else 50000
    rng = random.Random(7)
    out = sys.stdout
    if not jsonl:
        out.write("[")
    for k in range(n):
        pts, w = patch(rng)
        pair = [as_json(pts, w), as_json(*transformed(rng, pts, w))]
        for j, p in enumerate(pair):
            if jsonl:
                out.write(json.dumps(p) + "\n")
            else:
                out.write((", " if k or j else "") + json.dumps(p))
    if not jsonl:
        out.write("]\n")


if __name__ == "__main__":
    main()
