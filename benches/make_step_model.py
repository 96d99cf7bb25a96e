#!/usr/bin/env python3
"""Write a STEP (ISO 10303-21) file of N×N bicubic B-spline surfaces for
`exact-bezier audit` timing: the Bézier spans of one uniform bicubic
B-spline surface (so all 2N(N−1) interior seams are G2, the worst case for
the audit), each written as its own clamped B_SPLINE_SURFACE_WITH_KNOTS on
its own ADVANCED_FACE. De Boor points are 36·(i, j, h(i, j)) with integer h,
so every Bézier point is an integer and the file is exact.

    python3 benches/make_step_model.py 100 > /tmp/model.stp   # 10 000 surfaces
"""
import sys

n = int(sys.argv[1]) if len(sys.argv) > 1 else 100


def h(i, j):
    return ((i * 7 + j * 13) % 11) - 5 + ((i * j) % 3)


# De Boor net (n + 3)², scaled by 36.
P = [[(36 * i, 36 * j, 36 * h(i, j)) for j in range(n + 3)] for i in range(n + 3)]

# Uniform cubic B-spline → Bézier on one span, times 6: rows of weights.
M = [(1, 4, 1, 0), (0, 4, 2, 0), (0, 2, 4, 0), (0, 1, 4, 1)]


def bezier(a, b):
    """The 4×4 Bézier net of span (a, b), exact integers."""
    out = []
    for r in M:
        row = []
        for c in M:
            pt = [0, 0, 0]
            for i in range(4):
                for j in range(4):
                    k = r[i] * c[j]
                    if k:
                        p = P[a + i][b + j]
                        for d in range(3):
                            pt[d] += k * p[d]
            assert all(x % 36 == 0 for x in pt)
            row.append(tuple(x // 36 for x in pt))
        out.append(row)
    return out


w = sys.stdout.write
w("ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION(('exact-bezier audit benchmark'),'2;1');\n"
  "FILE_NAME('model.stp','',(''),(''),'','','');\nFILE_SCHEMA(('AUTOMOTIVE_DESIGN'));\nENDSEC;\nDATA;\n")
next_id = 1
for a in range(n):
    for b in range(n):
        ids = []
        for row in bezier(a, b):
            r = []
            for (x, y, z) in row:
                w(f"#{next_id}=CARTESIAN_POINT('',({x}.,{y}.,{z}.));\n")
                r.append(f"#{next_id}")
                next_id += 1
            ids.append("(" + ",".join(r) + ")")
        s = next_id
        w(f"#{s}=B_SPLINE_SURFACE_WITH_KNOTS('',3,3,({','.join(ids)}),.UNSPECIFIED.,.F.,.F.,.F.,"
          "(4,4),(4,4),(0.,1.),(0.,1.),.UNSPECIFIED.);\n")
        w(f"#{s + 1}=ADVANCED_FACE('',(),#{s},.T.);\n")
        next_id += 2
w("ENDSEC;\nEND-ISO-10303-21;\n")
