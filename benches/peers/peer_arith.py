"""The arithmetic peer benchmark of issue 30 (run by benches/peers/arith).

Writes the polynomial cases (powers, and the Möbius and quadratic-map
identities of proofs/ written once in each engine; the Sylvester
resultants of integer polynomials, FLINT's ``fmpz_poly`` on its side), runs our side (the `peer_arith` bench target,
``--ours``) and FLINT's ``fmpq_mpoly`` (python-flint) on the same inputs,
``--rounds`` times interleaved, checks that every result is identical term
by term, and prints a table of medians and a final JSON line::

    {"symbolic_vs_flint": worst ours/FLINT, "sylvester_vs_flint": worst
     ours/FLINT on the resultants, "exact_vs_gmp": worst ours/GMP,
     "gcd_vs_gmp": worst ours/GMP, "key_vs_gmp": worst ours/GMP,
     "roots_vs_gmp": worst ours/GMP, "prove_seconds": s, ...}

``--prove EXE`` times ``EXE prove`` (the release CLI) once per round.
``--gmp EXE`` runs the GMP harness (``benches/peers/gmp``: exact evaluation,
gcds, the coincidence key and real root isolation by rug next to ours,
results checked there) once per round and takes each case's median.
"""

import argparse
import json
import math
import random
import statistics
import subprocess
import sys
import tempfile
import time
from fractions import Fraction

import flint


def random_poly(rng, nvars, nterms, max_exp):
    """`nterms` distinct monomials with small rational coefficients."""
    terms = {}
    while len(terms) < nterms:
        e = tuple(rng.randint(0, max_exp) for _ in range(nvars))
        c = Fraction(rng.choice([-1, 1]) * rng.randint(1, 9), rng.randint(1, 7))
        terms[e] = c
    return terms


def cases():
    rng = random.Random(30)
    dense = {(0, 0, 0, 0): Fraction(1)}
    for i in range(4):
        e = [0, 0, 0, 0]
        e[i] = 1
        dense[tuple(e)] = Fraction(1)
    return [
        ("(p)^6, 5 terms", random_poly(rng, 4, 5, 3), 6),
        ("(p)^8, 10 terms", random_poly(rng, 4, 10, 3), 8),
        ("(1+x0+x1+x2+x3)^20", dense, 20),
    ]


MOBIUS = [3, 5, 6]


def flint_mobius(m, repeat):
    """The Möbius identity of proofs/ (yang_yong::mobius_uv_sides) on FLINT,
    the same steps as ours: the weights of the fully symbolic (m, m) net
    times (1−α)^i α^(m−i) (1−β)^j β^(m−j) (maps (2)(3) by rule (4)), de
    Casteljau in t on each row then in s at (s, t); the old net by de
    Casteljau at the homogeneous parameters (α(1−s), (1−α)s; β(1−t),
    (1−β)t); the two checked equal. Returns the median ns and the new
    side's weight coordinate as {((name, e), …): Fraction}."""
    names = ([f"p{i}{j}" for i in range(m + 1) for j in range(m + 1)]
             + [f"w{i}{j}" for i in range(m + 1) for j in range(m + 1)] + ["alpha", "beta", "s", "t"])
    ctx = flint.fmpq_mpoly_ctx.get(tuple(names), "lex")
    g = dict(zip(names, ctx.gens()))
    a, b, s, t = g["alpha"], g["beta"], g["s"], g["t"]

    def casteljau(points, h0, h1):
        row = [list(p) for p in points]
        for k in range(len(row) - 1, 0, -1):
            for i in range(k):
                row[i] = [h0 * x + h1 * y for x, y in zip(row[i], row[i + 1])]
        return row[0]

    def identity():
        c = [[(g[f"p{i}{j}"], g[f"w{i}{j}"]) for j in range(m + 1)] for i in range(m + 1)]
        fu = [(1 - a) ** i * a ** (m - i) for i in range(m + 1)]
        fv = [(1 - b) ** j * b ** (m - j) for j in range(m + 1)]
        moved = [[[x * fu[i] * fv[j] for x in c[i][j]] for j in range(m + 1)] for i in range(m + 1)]
        new = casteljau([casteljau(row, 1 - t, t) for row in moved], 1 - s, s)
        old = casteljau([casteljau(row, b * (1 - t), (1 - b) * t) for row in c], a * (1 - s), (1 - a) * s)
        if new != old:
            sys.exit(f"FLINT: the Möbius identity fails at m = {m}")
        return new[1]

    return timed_identity(identity, names, repeat)


# FLINT's variable names are ASCII
ASCII = {"α": "alpha", "β": "beta", "α1": "alpha1", "α2": "alpha2", "β1": "beta1", "β2": "beta2"}


QUADRATIC = [2, 3, 4]

# The Sylvester resultant (the elimination step of exact intersections):
# (degree of both polynomials, decimal digits of the coefficients).
RESULTANT = [(3, 10), (6, 10), (9, 30), (12, 30)]


def resultant_name(d, k):
    return f"resultant, degree {d}, {k} digits"


def resultant_pair(d, k):
    """Two random integer polynomials of degree d with k-digit coefficients
    (lowest degree first), the same on every run."""
    rng = random.Random(1000 * d + k)
    draw = lambda: [rng.choice([-1, 1]) * rng.randint(10 ** (k - 1), 10 ** k - 1) for _ in range(d + 1)]
    return draw(), draw()


# The resultant in t of two polynomials in s and t of degree d in each
# (two cubics' intersection equations are of degree 3 in each parameter),
# k-digit coefficients: the elimination step of exact intersections.
RESULTANT_T = [(3, 10), (4, 10), (6, 10)]


def resultant_t_name(d, k):
    return f"resultant in t, bidegree ({d}, {d}), {k} digits"


def resultant_t_pair(d, k):
    """Two random polynomials Σ c_ij s^i t^j, i, j ≤ d, as rows (one per
    power of t) of coefficients in s, the same on every run."""
    rng = random.Random(7000 + 100 * d + k)
    draw = lambda: [[rng.choice([-1, 1]) * rng.randint(10 ** (k - 1), 10 ** k - 1)
                     for _ in range(d + 1)] for _ in range(d + 1)]
    return draw(), draw()


def flint_resultant_t(f, g, repeat):
    """FLINT's fmpz_mpoly resultant in t of the pair; the median ns and the
    result in s made monic, as {(k,): value}."""
    ctx = flint.fmpz_mpoly_ctx.get(("s", "t"), "lex")
    as_mpoly = lambda rows: ctx.from_dict({(i, j): c for j, row in enumerate(rows)
                                           for i, c in enumerate(row)})
    pf, pg = as_mpoly(f), as_mpoly(g)
    times = []
    for _ in range(repeat):
        start = time.perf_counter_ns()
        r = pf.resultant(pg, "t")
        times.append(time.perf_counter_ns() - start)
    coeffs = {e[0]: Fraction(int(c)) for e, c in r.to_dict().items()}
    lead = coeffs[max(coeffs)]
    return statistics.median(times), {(k,): c / lead for k, c in coeffs.items()}


def flint_resultant(f, g, repeat):
    """FLINT's fmpz_poly_resultant of the pair; the median ns and the value
    as the constant term {(): value}."""
    pf, pg = flint.fmpz_poly(f), flint.fmpz_poly(g)
    times = []
    for _ in range(repeat):
        start = time.perf_counter_ns()
        r = pf.resultant(pg)
        times.append(time.perf_counter_ns() - start)
    return statistics.median(times), {(): Fraction(int(r))}


def bernstein_times_linear(g, f):
    """Bernstein coefficients of g·(f0(1 − x) + f1 x), degree p → p + 1."""
    p = len(g) - 1
    out = []
    for k in range(p + 2):
        acc = 0
        if k <= p:
            acc += g[k] * f[0] * flint.fmpq(p + 1 - k, p + 1)
        if k > 0:
            acc += g[k - 1] * f[1] * flint.fmpq(k, p + 1)
        out.append(acc)
    return out


def linear_product(c, factors):
    """Bernstein coefficients of c·Π f^e for linear factors f = (f0, f1)."""
    g = [c]
    for f, e in factors:
        for _ in range(e):
            g = bernstein_times_linear(g, f)
    return g


def flint_quadratic(m, repeat):
    """The quadratic map's point identity of proofs/ (yang_yong::
    quadratic_identity) on FLINT, the same steps as ours: the map (9)–(17)
    on the (m, m) net of symbolic weights w_ij (c′ and e′ by Bernstein
    products, then eq. (17)'s sums), the coefficient of each w_ij (a
    derivative: the result is linear in them), the old side's Bernstein
    coefficients built factor by factor, and every coefficient compared.
    Returns the median ns and the weight (m, m) of the map's output."""
    n, d = m, 2 * m
    ws = [f"w{i}{j}" for i in range(m + 1) for j in range(n + 1)]
    names = ws + ["alpha1", "alpha2", "beta1", "beta2"]
    ctx = flint.fmpq_mpoly_ctx.get(tuple(names), "lex")
    g = dict(zip(names, ctx.gens()))
    one, zero = ctx.from_dict({(0,) * len(names): 1}), ctx.from_dict({})
    alpha, beta = (g["alpha2"], g["alpha1"]), (g["beta2"], g["beta1"])
    comp = lambda x: (1 - x[0], 1 - x[1])
    C = math.comb

    def coefficients(k, a):
        return [linear_product(one, [(a, k - i), (comp(a), i)]) for i in range(k + 1)]

    def identity():
        c, e = coefficients(m, alpha), coefficients(n, beta)
        weights = [[zero] * (d + 1) for _ in range(d + 1)]
        for k1 in range(d + 1):
            for k2 in range(d + 1):
                acc = zero
                for i in range(m + 1):
                    for j in range(n + 1):
                        l2, l1 = k1 - i, k2 - j
                        if 0 <= l2 <= n and 0 <= l1 <= m:
                            f = flint.fmpq(C(m, i) * C(n, l2) * C(m, l1) * C(n, j), C(d, k1) * C(d, k2))
                            acc += g[f"w{i}{j}"] * e[j][l2] * c[i][l1] * f
                weights[k1][k2] = acc
        s, one_minus_s = (zero, one), (one, zero)
        for i0 in range(m + 1):
            for j0 in range(n + 1):
                w = f"w{i0}{j0}"
                a = linear_product(one * C(m, i0), [(s, i0), (one_minus_s, m - i0),
                                                   (comp(beta), j0), (beta, n - j0)])
                b = linear_product(one * C(n, j0), [(s, j0), (one_minus_s, n - j0),
                                                   (comp(alpha), i0), (alpha, m - i0)])
                for k1 in range(d + 1):
                    for k2 in range(d + 1):
                        if weights[k1][k2].derivative(w) != a[k1] * b[k2]:
                            sys.exit(f"FLINT: the quadratic identity fails at m = {m}")
        return weights[m][m]

    return timed_identity(identity, names, repeat)


def timed_identity(identity, names, repeat):
    """The median ns of `repeat` runs of `identity`, and its polynomial
    result as {((name, e), …): Fraction}."""
    times = []
    for _ in range(repeat):
        start = time.perf_counter_ns()
        w = identity()
        times.append(time.perf_counter_ns() - start)
    result = {tuple(sorted((names[k], e) for k, e in enumerate(exps) if e)): Fraction(str(c))
              for exps, c in w.to_dict().items()}
    return statistics.median(times), result


def named(terms):
    """Our named terms [[[name, e], …], "p/q"] as FLINT's dictionary."""
    return {tuple(sorted((ASCII.get(v, v), e) for v, e in vars_ if e)): Fraction(c)
            for vars_, c in terms}


def to_json(terms):
    return [[list(e), str(c)] for e, c in terms.items()]


def flint_power(terms, k, repeat):
    ctx = flint.fmpq_mpoly_ctx.get(("x", 4), "lex")
    p = ctx.from_dict({e: flint.fmpq(c.numerator, c.denominator) for e, c in terms.items()})
    times = []
    for _ in range(repeat):
        start = time.perf_counter_ns()
        r = p**k
        times.append(time.perf_counter_ns() - start)
    result = {tuple(e): Fraction(str(c)) for e, c in r.to_dict().items()}
    return statistics.median(times), result


def ours(exe, path, repeat):
    out = subprocess.run([exe, path, "--repeat", str(repeat)], check=True,
                         capture_output=True, text=True).stdout
    data = json.loads(out)
    return {name: (v["ns"], named(v["terms"]) if name.startswith(("Möbius", "quadratic"))
                   else {tuple(e): Fraction(c) for e, c in v["terms"]})
            for name, v in data.items()}


def mobius_name(m):
    return f"Möbius identity ({m}, {m})"


def quadratic_name(m):
    return f"quadratic identity ({m}, {m})"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--ours", required=True)
    ap.add_argument("--prove", help="the release exact-bezier executable")
    ap.add_argument("--gmp", help="the GMP harness executable (benches/peers/gmp)")
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--repeat", type=int, default=9)
    ap.add_argument("--allocator", default="not stated",
                    help="the allocators of the two sides, for the final JSON line")
    args = ap.parse_args()
    cs = cases()
    with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
        json.dump([{"name": n, "vars": 4, "terms": to_json(t), "power": k} for n, t, k in cs]
                  + [{"name": mobius_name(m), "mobius": m} for m in MOBIUS]
                  + [{"name": quadratic_name(m), "quadratic": m} for m in QUADRATIC]
                  + [{"name": resultant_name(d, k), "resultant": [[str(c) for c in p] for p in resultant_pair(d, k)]}
                     for d, k in RESULTANT]
                  + [{"name": resultant_t_name(d, k), "resultant_t": [[[str(c) for c in row] for row in p]
                                                                    for p in resultant_t_pair(d, k)]}
                     for d, k in RESULTANT_T], f)
        path = f.name
    symbolic = ([n for n, _, _ in cs] + [mobius_name(m) for m in MOBIUS]
                + [quadratic_name(m) for m in QUADRATIC])
    sylvester = ([resultant_name(d, k) for d, k in RESULTANT]
                 + [resultant_t_name(d, k) for d, k in RESULTANT_T])
    names = symbolic + sylvester
    t_ours = {n: [] for n in names}
    t_flint = {n: [] for n in names}
    sizes = {}
    prove = []
    gmp = {}
    for _ in range(args.rounds):
        if args.gmp:
            run = subprocess.run([args.gmp, "--repeat", str(args.repeat)], check=True,
                                 capture_output=True, text=True).stdout
            line = json.loads(run.splitlines()[-1])
            for name, case in {**line["cases"], **line["gcd"], **line["key"], **line["roots"]}.items():
                gmp.setdefault(name, []).append((case["ours_ns"], case["gmp_ns"]))
        mine = ours(args.ours, path, args.repeat)
        runs = [(n, lambda t=t, k=k: flint_power(t, k, args.repeat)) for n, t, k in cs]
        runs += [(mobius_name(m), lambda m=m: flint_mobius(m, args.repeat)) for m in MOBIUS]
        runs += [(quadratic_name(m), lambda m=m: flint_quadratic(m, args.repeat)) for m in QUADRATIC]
        runs += [(resultant_name(d, k), lambda d=d, k=k: flint_resultant(*resultant_pair(d, k), args.repeat))
                 for d, k in RESULTANT]
        runs += [(resultant_t_name(d, k), lambda d=d, k=k: flint_resultant_t(*resultant_t_pair(d, k), args.repeat))
                 for d, k in RESULTANT_T]
        for n, run in runs:
            ns, theirs = run()
            ns_ours, result = mine[n]
            if result != theirs:
                sys.exit(f"{n}: results differ ({len(result)} terms against {len(theirs)})")
            sizes[n] = len(result)
            t_ours[n].append(ns_ours)
            t_flint[n].append(ns)
        if args.prove:
            start = time.perf_counter()
            subprocess.run([args.prove, "prove"], check=True, capture_output=True)
            prove.append(time.perf_counter() - start)
    print(f"{'case':<44} {'terms':>7} {'ours ms':>9} {'FLINT ms':>9} {'ours/FLINT':>10}")
    ratios = {}
    for n in names:
        a, b = statistics.median(t_ours[n]) / 1e6, statistics.median(t_flint[n]) / 1e6
        ratios[n] = round(a / b, 3)
        print(f"{n:<44} {sizes[n]:>7} {a:>9.3f} {b:>9.3f} {a / b:>10.2f}")
    line = {"symbolic_vs_flint": round(max(ratios[n] for n in symbolic), 3),
            "ratios": {n: ratios[n] for n in symbolic},
            "sylvester_vs_flint": round(max(ratios[n] for n in sylvester), 3),
            "sylvester_ratios": {n: ratios[n] for n in sylvester},
            "allocator": args.allocator}
    if gmp:
        print(f"\n{'exact evaluation (per point), gcd, key, roots':<44} {'ours ns':>9} {'GMP ns':>9} {'ours/GMP':>9}")
        exact = {}
        for name, runs in gmp.items():
            a = statistics.median(o for o, _ in runs)
            b = statistics.median(g for _, g in runs)
            exact[name] = round(a / b, 3)
            print(f"{name:<44} {a:>9.0f} {b:>9.0f} {a / b:>9.2f}")
        gcd = {n: r for n, r in exact.items() if n.startswith("gcd")}
        key = {n: r for n, r in exact.items() if n.startswith("key")}
        roots = {n: r for n, r in exact.items() if n.startswith("roots")}
        exact = {n: r for n, r in exact.items() if n not in gcd and n not in key and n not in roots}
        line["exact_vs_gmp"] = max(exact.values())
        line["exact_ratios"] = exact
        line["gcd_vs_gmp"] = max(gcd.values())
        line["gcd_ratios"] = gcd
        line["key_vs_gmp"] = max(key.values())
        line["key_ratios"] = key
        line["roots_vs_gmp"] = max(roots.values())
        line["roots_ratios"] = roots
    if prove:
        line["prove_seconds"] = round(statistics.median(prove), 3)
        print(f"exact-bezier prove: {line['prove_seconds']} s (median of {len(prove)})")
    print(json.dumps(line))


if __name__ == "__main__":
    main()
