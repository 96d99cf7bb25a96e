//! Conversions between rectangles and triangles (source 003 §2–3; source
//! 001, Hu 1996 and Hu 2001), each shown to keep the surface: the converted
//! patch at the mapped parameters equals the original **homogeneously**
//! (same weighted point, no scaling), which is stronger than equal points.
//!
//! Method: the conversion code runs on [`Poly`] with a symbolic control net
//! (`x_ij`, `w_ij` — the maps are linear in the net and treat coordinates
//! alike, so this covers every rational patch) and symbolic parameters;
//! split parameters are symbolic where stated, else the §4.2 split
//! (a = c = 3/10, b = d = e = f = 1/2). Degree bounds are in each claim.

use super::blossoms::symbolic_rect;
use super::triangles::symbolic_tri;
use super::{Claim, Verdict};
use exact_bezier::algebra::ratio;
use exact_bezier::algebra::Poly;
use exact_bezier::convert::{
    bilinear, degree_raising_matrix, rect_to_tri, square_corners, tri_to_degenerate_rect,
    tri_to_rect_hu, tri_to_rect_on_quad, tri_to_rects, tri_to_rects_operators, Half, Split,
};
use exact_bezier::hpoint::HPoint;
use exact_bezier::rect::RectPatch;
use exact_bezier::tri::TriPatch;
use num_rational::BigRational;
use num_traits::{One, Zero};

fn holds(claim: &str, source: &str, ok: bool, how: &str) -> Claim {
    Claim::check(claim, source, Verdict::Proved, ok, how.to_string())
}

fn v(name: &str) -> Poly {
    Poly::var(name)
}

fn symbolic_split() -> Split<Poly> {
    Split::new_unchecked(["a", "b", "c", "d", "e", "f"].map(v))
}

fn example_split() -> Split<Poly> {
    Split::new_unchecked(
        [(3, 10), (1, 2), (3, 10), (1, 2), (1, 2), (1, 2)].map(|(p, q)| ratio::<Poly>(p, q)),
    )
}

fn tri_at(t: &TriPatch<Poly>, b: &[Poly; 3]) -> HPoint<Poly> {
    t.eval_hom_bary(&b[0], &b[1], &b[2])
}

/// Theorem 2.3, eqs. (14) and (16), and Corollary 2.4.
fn rect_to_tri_claims() -> Vec<Claim> {
    let mut out = Vec::new();
    let (u, w) = (v("u"), v("v"));
    let bary = [u.clone(), w.clone(), Poly::one() - &u - &w];
    let pairs: Vec<(usize, usize)> = (1..=5).flat_map(|m| (1..=5).map(move |n| (m, n))).collect();
    for &(m, n) in &pairs {
        let r = symbolic_rect(m, n);
        for half in [Half::Lower, Half::Upper] {
            let t = rect_to_tri(&r, half);
            let (s, tt) = half.rect_param(&u, &w);
            let (eq, map) = match half {
                Half::Lower => ("(14)", "tri(u, v, w) = rect(u, v)"),
                Half::Upper => ("(16)", "tri(u, v, w) = rect(1 − u, 1 − v)"),
            };
            out.push(holds(
                &format!("Theorem 2.3 eq. {eq}, (m, n) = ({m}, {n}): the degree {} triangle keeps the surface, {map}", m + n),
                &format!("003 Theorem 2.3, eq. {eq}"),
                t.degree() == m + n && tri_at(&t, &bary) == r.eval_hom(&s, &tt),
                "symbolic control net, weights and (u, v)",
            ));
        }
    }
    for (m, n) in [(1, 1), (2, 2), (2, 3), (4, 4)] {
        let r = RectPatch::polynomial(vec![vec![vec![Poly::zero()]; n + 1]; m + 1]).expect("net");
        let t = rect_to_tri(&r, Half::Lower);
        let ok = t.weights().iter().flatten().all(|w| w.is_one());
        out.push(holds(
            &format!("Corollary 2.4 / eq. (15), ({m}, {n}): weights ω_ij = 1 give ω_rst = 1"),
            "003 Corollary 2.4",
            ok,
            "exact",
        ));
    }
    out
}

/// Theorem 3.2 (blossoming) against the mapped parameters, and the printed
/// operator formulas (23)–(25) and Hu's (5), (6) against it.
fn tri_to_rect_claims() -> Vec<Claim> {
    let mut out = Vec::new();
    let (s, t) = (v("s"), v("t"));
    for n in 1..=5usize {
        let tri = symbolic_tri(n, "");
        let (split, how) = if n <= 3 {
            (
                symbolic_split(),
                "symbolic split a…f, control net and (s, t)",
            )
        } else {
            (
                example_split(),
                "the §4.2 split; symbolic control net and (s, t)",
            )
        };
        let rects = tri_to_rects(&tri, &split);
        let ok = (0..3).all(|d| {
            let q = split.quad(d).expect("piece");
            rects[d].eval_hom(&s, &t) == tri_at(&tri, &bilinear(&q, &s, &t))
        });
        out.push(holds(
            &format!("Theorem 3.2 (eq. 22 + algorithm 26), n = {n}: rect_Dd(s, t) = tri(L_d(s, t)) on D1, D2, D3"),
            "003 Theorem 3.2, eqs. (20), (22), (26)",
            ok,
            how,
        ));
    }
    for n in 1..=5usize {
        let tri = symbolic_tri(n, "");
        let (split, how) = if n <= 4 {
            (
                symbolic_split(),
                "symbolic split a…f and control net; control nets compared",
            )
        } else {
            (
                example_split(),
                "the §4.2 split; symbolic control net; control nets compared",
            )
        };
        let blossoming = tri_to_rects(&tri, &split);
        let printed = tri_to_rects_operators(&tri, &split);
        for (d, eq) in ["(23)", "(24)", "(25)"].iter().enumerate() {
            out.push(holds(
                &format!("eq. {eq} as printed, n = {n}: the operator formula for D{} equals the blossoming conversion", d + 1),
                &format!("003 eq. {eq}"),
                printed[d] == blossoming[d],
                how,
            ));
        }
        out.push(holds(
            &format!("Hu 1996 eqs. (5), (6), n = {n}: P_ij = Σ_(k=0..i) Σ_(l=0..n−i), k+l=j C(i,k) C(n−i,l)/C(n,j) Q^(i)_kl equals the blossoming D1 exactly"),
            "001 lecture, Hu 1996 eqs. (5), (6)",
            tri_to_rect_hu(&tri, &split) == blossoming[0],
            how,
        ));
    }
    // Eq. (5)'s ranges: k = 0…i and l = 0…n−i with k + l = j select exactly
    // the non-zero weights, which then sum to 1 (Vandermonde, eq. 15).
    let ranges_ok = (0..=6usize).all(|n| {
        (0..=n).all(|i| {
            (0..=n).all(|j| {
                let total: BigRational = (0..=i)
                    .flat_map(|k| (0..=n - i).map(move |l| (k, l)))
                    .filter(|(k, l)| k + l == j)
                    .map(|(k, l)| {
                        BigRational::new(
                            exact_bezier::algebra::binomial(i, k)
                                * exact_bezier::algebra::binomial(n - i, l),
                            exact_bezier::algebra::binomial(n, j),
                        )
                    })
                    .sum();
                total == ratio(1, 1)
            })
        })
    });
    out.push(holds(
        "Hu 1996 eq. (5), n ≤ 6: over the printed ranges k = 0…i, l = 0…n−i, k + l = j, the weights C(i,k) C(n−i,l)/C(n,j) sum to 1 for every 0 ≤ i, j ≤ n (an affine combination; no term missing)",
        "001 lecture, Hu 1996 eq. (5); 003 eq. (15)",
        ranges_ok,
        "exact rationals",
    ));
    for n in [1usize, 2, 4] {
        let tri = TriPatch::polynomial(
            (0..=n)
                .map(|j| vec![vec![Poly::zero()]; n - j + 1])
                .collect(),
        )
        .expect("net");
        // p5 = eT1 + fT2 lies on the edge T1T2 only when e + f = 1 (eq. 19).
        let e = v("e");
        let split =
            Split::new_unchecked([v("a"), v("b"), v("c"), v("d"), e.clone(), Poly::one() - &e]);
        let ok = tri_to_rects(&tri, &split)
            .iter()
            .all(|r| r.weights().iter().flatten().all(|w| w.is_one()));
        out.push(holds(
            &format!("Corollary 3.3, n = {n}: weights ω_rst = 1 give ω_ij = 1 on D1, D2, D3 for every split"),
            "003 Corollary 3.3",
            ok,
            "symbolic split a, b, c, d, e with f = 1 − e",
        ));
    }
    out
}

/// Source 001 (Hu 2001): the printed A_k (refuted) and the corrected one.
fn degenerate_claims() -> Vec<Claim> {
    let mut out = Vec::new();
    // (a) Shapes: A_1 ⋯ A_i must take n − i + 1 entries to n + 1.
    let mismatch = (1..=5usize)
        .flat_map(|n| (1..=n).map(move |i| (n, i)))
        .find(|&(n, i)| i != n - i + 1);
    out.push(Claim::check(
        "Hu 2001: A_k is (k+1) × k, so A_1 A_2 ⋯ A_i maps (T_i0, …, T_i,n−i) to (P_i0, …, P_in)",
        "001 lecture, 转化为一个退化的矩形域曲面",
        Verdict::Refuted,
        mismatch.is_none(),
        match mismatch {
            Some((n, i)) => format!(
                "n = {n}, i = {i}: A_{i} would be {}×{i} but the row T_{i}0…T_{i},{} has {} entries, and A_1 (2×1) cannot yield the {} entries P_{i}0…P_{i}{n}. Corrected: A_k is (n−k+2)×(n−k+1), raising degree n−k to n−k+1",
                i + 1,
                n - i,
                n - i + 1,
                n + 1
            ),
            None => "shapes chain".into(),
        },
    ));
    // (b) Affine invariance: every row of a degree-raising matrix sums to 1.
    // Printed second row of A_k: (1, (n−k)/(n+1−k), 0, …); take n = 3, k = 1.
    let (n, k) = (3i64, 1usize);
    let printed_row = [
        ratio::<BigRational>(1, 1),
        ratio(n - k as i64, n + 1 - k as i64),
    ];
    let row_sum: BigRational = printed_row.iter().sum();
    let corrected = degree_raising_matrix::<BigRational>(n as usize, k).expect("1 ≤ k ≤ n");
    out.push(Claim::check(
        "Hu 2001: every row of the printed A_k sums to 1 (an affine, degree-raising map)",
        "001 lecture, 升阶算子 A_k",
        Verdict::Refuted,
        row_sum == ratio(1, 1),
        format!(
            "n = {n}, k = {k}: printed row 2 = (1, (n−k)/(n+1−k)) = (1, {}) sums to {row_sum}; it duplicates the true row 2 (1/(n+1−k), (n−k)/(n+1−k)) printed below it. Corrected A_{k} for n = {n}: rows {:?}",
            printed_row[1],
            corrected
                .iter()
                .map(|r| r.iter().map(|x| x.to_string()).collect::<Vec<_>>().join(" "))
                .collect::<Vec<_>>()
        ),
    ));
    // (c) The corrected operators keep the surface.
    let (s, t) = (v("s"), v("t"));
    for n in 1..=5usize {
        let tri = symbolic_tri(n, "");
        let rect = tri_to_degenerate_rect(&tri);
        let one_s = Poly::one() - &s;
        let image = [s.clone(), one_s.clone() * &t, one_s * (Poly::one() - &t)];
        out.push(holds(
            &format!("Hu 2001 corrected, n = {n}: with A_k = (n−k+2)×(n−k+1) raising matrices, rect(s, t) = tri(s, (1−s)t, (1−s)(1−t))"),
            "001 lecture, Hu 2001 (corrected)",
            rect.eval_hom(&s, &t) == tri_at(&tri, &image),
            "symbolic control net, weights and (s, t)",
        ));
    }
    out
}

/// Round trips rect → two tris → rect.
fn round_trip_claims() -> Vec<Claim> {
    let mut out = Vec::new();
    let (s, t) = (v("s"), v("t"));
    for (m, n) in [
        (1, 1),
        (1, 2),
        (2, 1),
        (2, 2),
        (2, 3),
        (3, 3),
        (2, 5),
        (4, 4),
        (5, 3),
        (5, 5),
    ] {
        let r = symbolic_rect(m, n);
        let tris = [rect_to_tri(&r, Half::Lower), rect_to_tri(&r, Half::Upper)];
        let elevated = r.elevate(n, m);
        let back = [Half::Lower, Half::Upper]
            .iter()
            .zip(&tris)
            .all(|(&h, tri)| tri_to_rect_on_quad(tri, &square_corners(h)) == elevated);
        out.push(holds(
            &format!("round trip ({m}, {n}): rect → tri on Δ1 (and on Δ2) → rect over the whole square is the original elevated to ({0}, {0}), control point for control point", m + n),
            "ours (003 eqs. 14, 16, 22)",
            back,
            "symbolic control net; exact equality of homogeneous nets",
        ));
        let degenerate = tri_to_degenerate_rect(&tris[0]);
        let one_s = Poly::one() - &s;
        out.push(holds(
            &format!(
                "round trip ({m}, {n}): rect → tri on Δ1 → degenerate rect gives rect(s, (1 − s)t)"
            ),
            "ours (003 eq. 14, Hu 2001 corrected)",
            degenerate.eval_hom(&s, &t) == r.eval_hom(&s, &(one_s * &t)),
            "symbolic control net and (s, t)",
        ));
    }
    out
}

/// Source 003 §3.2, conversion algorithm step (II): the recursion
/// `f^(r)_k = (n−i+r−(j−k))/(n−i+r) f^(r−1)_k + (j−k)/(n−i+r) f^(r−1)_(k+1)`,
/// `f^(0)_k = Q^(i)_(k,j−k)`, `P_ij = f^(i)_0`, against the sum of eq. (22)
/// `Σ_k C(i,k) C(n−i,j−k)/C(n,j) Q^(i)_(k,j−k)`. Every `Q^(i)_(k,j−k)` is a
/// distinct symbol, including those with `j − k` outside `0…n−i` (which
/// must drop out).
fn algorithm_ii_claims() -> Vec<Claim> {
    (1..=6usize)
        .map(|n| {
            let mut bad = None;
            for (i, j) in (0..=n).flat_map(|i| (0..=n).map(move |j| (i, j))) {
                let q: Vec<Poly> = (0..=i).map(|k| v(&format!("Q{k}"))).collect();
                let direct = (0..=i).fold(Poly::zero(), |acc, k| {
                    let in_range = k <= j && j - k <= n - i;
                    if !in_range {
                        return acc;
                    }
                    let w = BigRational::new(
                        exact_bezier::algebra::binomial(i, k) * exact_bezier::algebra::binomial(n - i, j - k),
                        exact_bezier::algebra::binomial(n, j),
                    );
                    acc + q[k].clone() * Poly::constant(w)
                });
                let mut f = q.clone();
                for r in 1..=i {
                    let den = (n - i + r) as i64;
                    for k in 0..=i - r {
                        let jk = j as i64 - k as i64;
                        f[k] = f[k].clone() * ratio::<Poly>(den - jk, den)
                            + f[k + 1].clone() * ratio::<Poly>(jk, den);
                    }
                }
                if f[0] != direct && bad.is_none() {
                    bad = Some(format!("n = {n}, i = {i}, j = {j}: recursion gives {}, eq. (22) gives {}", f[0], direct));
                }
            }
            holds(
                &format!("§3.2 algorithm (II), n = {n}: the f^(r) recursion computes P_ij = Σ_k C(i,k) C(n−i,j−k)/C(n,j) Q^(i)_(k,j−k) for all i, j"),
                "003 §3.2, conversion algorithm (II)",
                bad.is_none(),
                &bad.unwrap_or_else(|| "symbolic Q^(i)_(k,l), out-of-range ones included".into()),
            )
        })
        .collect()
}

/// All claims of the family.
pub fn claims() -> Vec<Claim> {
    let mut out = rect_to_tri_claims();
    out.extend(tri_to_rect_claims());
    out.extend(degenerate_claims());
    out.extend(round_trip_claims());
    out.extend(algorithm_ii_claims());
    out
}
