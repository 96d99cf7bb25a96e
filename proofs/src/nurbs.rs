//! NURBS → Bézier (ours; The NURBS Book §5.2, Ramshaw's blossoming
//! principle): every Bézier piece of a (rational) B-spline reproduces the
//! B-spline on its knot span.
//!
//! Method: the pieces come from [`NurbsCurve::bezier_pieces`] (blossom values
//! `f(u_k^{p−j}, u_{k+1}^j)`, i.e. knot insertion); the reference is de
//! Boor's algorithm ([`NurbsCurve::eval_hom_in_span`]), a different
//! computation of the same B-spline. Both run on [`Poly`] with **symbolic
//! homogeneous control points** `(x_i, w_i)` (weights included, so rational
//! B-splines are covered) and a **symbolic parameter** `s`; the claim is
//! the polynomial identity `piece(s) = deBoor(a + (b − a)s)` on every span.
//!
//! Knots are exact rationals, not symbols: knot insertion divides by knot
//! differences and [`Poly`] is a ring, so the knot vectors are enumerated —
//! every degree 1–3 with clamped, unclamped, uniform and non-uniform
//! vectors, simple, double and (p+1)-fold inner knots. The coefficients are
//! then rational constants and no division of polynomials is needed.

use super::{Claim, Verdict};
use exact_bezier::algebra::Poly;
use exact_bezier::hpoint::HPoint;
use exact_bezier::nurbs::{Knots, NurbsCurve, NurbsSurface};
use num_rational::BigRational;

fn q(n: i64, d: i64) -> BigRational {
    BigRational::new(n.into(), d.into())
}

/// Symbolic homogeneous points `(x_i, y_i, w_i)`.
fn symbolic(prefix: &str, count: usize) -> Vec<HPoint<Poly>> {
    (0..count)
        .map(|i| HPoint {
            coords: vec![
                Poly::var(&format!("{prefix}x{i}")),
                Poly::var(&format!("{prefix}y{i}")),
                Poly::var(&format!("{prefix}w{i}")),
            ],
        })
        .collect()
}

/// `a + (b − a)·s` as a polynomial in `s`.
fn affine(span: &[BigRational; 2], s: &Poly) -> Poly {
    Poly::constant(span[0].clone()) + &(s.clone() * &Poly::constant(&span[1] - &span[0]))
}

/// The knot vectors checked for degree `p` (with their labels).
fn knot_vectors(p: usize) -> Vec<(&'static str, Vec<BigRational>)> {
    let ints = |v: &[i64]| v.iter().map(|&x| q(x, 1)).collect::<Vec<_>>();
    let clamp = |inner: &[BigRational]| {
        let mut k = vec![q(0, 1); p + 1];
        k.extend_from_slice(inner);
        k.extend(vec![q(5, 1); p + 1]);
        k
    };
    vec![
        (
            "clamped, non-uniform simple knots",
            clamp(&[q(1, 3), q(2, 1)]),
        ),
        ("clamped, a double inner knot", clamp(&[q(3, 2), q(3, 2)])),
        (
            "clamped, a (p+1)-fold inner knot",
            clamp(&vec![q(2, 1); p + 1]),
        ),
        (
            "unclamped uniform",
            ints(&(0..(2 * p as i64 + 4)).collect::<Vec<_>>()),
        ),
        ("unclamped non-uniform", {
            let mut k: Vec<BigRational> = (0..(2 * p + 3)).map(|i| q((i * i) as i64, 2)).collect();
            k.sort();
            k
        }),
    ]
}

fn curve_claims() -> Vec<Claim> {
    let s = Poly::var("s");
    let mut out = Vec::new();
    for p in 1..=3 {
        for (label, knots) in knot_vectors(p) {
            let count = knots.len() - p - 1;
            let k = Knots::new(p, knots, count).expect("a valid knot vector");
            let c = NurbsCurve::new(k.clone(), symbolic("", count)).expect("a valid curve");
            let pieces = c.bezier_pieces();
            let ok = k.spans().iter().zip(&pieces).all(|(&span, piece)| {
                piece.curve.eval_hom(&s) == c.eval_hom_in_span(span, &affine(&piece.span, &s))
            });
            out.push(Claim::check(
                &format!(
                    "degree {p}, {label} ({} knots): each of the {} rational Bézier pieces equals the B-spline on its span, for all control points, weights and s",
                    count + p + 1,
                    pieces.len()
                ),
                "ours (The NURBS Book §5.2; blossoming)",
                Verdict::Proved,
                ok && pieces.len() == k.spans().len(),
                "symbolic (x_i, y_i, w_i) and s; piece(s) = de Boor(a + (b − a)s) as polynomials".into(),
            ));
        }
    }
    out
}

/// A surface: biquadratic × linear with an inner knot in u and in v.
fn surface_claim() -> Claim {
    let (s, t) = (Poly::var("s"), Poly::var("t"));
    let ku = Knots::new(
        2,
        vec![
            q(0, 1),
            q(0, 1),
            q(0, 1),
            q(1, 2),
            q(2, 1),
            q(2, 1),
            q(2, 1),
        ],
        4,
    )
    .expect("valid");
    let kv = Knots::new(1, vec![q(0, 1), q(0, 1), q(1, 1), q(3, 1), q(3, 1)], 3).expect("valid");
    let net = (0..4).map(|i| symbolic(&format!("r{i}"), 3)).collect();
    let surf = NurbsSurface::new(ku.clone(), kv.clone(), net).expect("valid");
    let spans: Vec<(usize, usize)> = ku
        .spans()
        .into_iter()
        .flat_map(|k| kv.spans().into_iter().map(move |l| (k, l)))
        .collect();
    let pieces = surf.bezier_pieces();
    let ok = pieces.len() == 4
        && spans.iter().zip(&pieces).all(|(&kl, piece)| {
            piece.patch.eval_hom(&s, &t)
                == surf.eval_hom_in_span(kl, &affine(&piece.u, &s), &affine(&piece.v, &t))
        });
    Claim::check(
        "bidegree (2, 1) with inner knots 1/2 in u and 1 in v: each of the 4 rational Bézier patches equals the B-spline surface on its spans, for all control points, weights, s and t",
        "ours (tensor product of the curve decomposition)",
        Verdict::Proved,
        ok,
        "symbolic net (x_ij, y_ij, w_ij), symbolic (s, t); patch(s, t) = de Boor in v then u".into(),
    )
}

/// Every claim of the family.
pub fn claims() -> Vec<Claim> {
    let mut out = curve_claims();
    out.push(surface_claim());
    out
}
