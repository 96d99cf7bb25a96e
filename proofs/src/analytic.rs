//! Our constructions of `exact_bezier::analytic`: the pieces of every
//! analytic STEP curve and surface lie exactly on it.
//!
//! Established symbolically: the frame is a rational orthonormal one
//! (x̂ = (2, 2, 1)/3, ẑ = (1, −2, 2)/3, ŷ = ẑ × x̂ computed by the library),
//! the centre `(c₁, c₂, c₃)`, the radii `R`, `r`, the semi-axes `a`, `b`, the
//! cone slope `k` and the piece parameters `u`, `v` (or `t`) are symbols.
//! For every piece, the homogeneous point `(X, W)` of the piece at `(u, v)`
//! is put into the implicit equation of the surface, homogenised with `W`
//! (the frame coordinates `d = X − W·C`, `α = d·x̂`, `β = d·ŷ`, `η = d·ẑ`):
//!
//! ```text
//! cylinder  α² + β² − R²W²                              = 0
//! cone      α² + β² − (RW + kη)²                        = 0
//! sphere    α² + β² + η² − R²W²                         = 0
//! torus     (α² + β² + η² + (R² − r²)W²)² − 4R²W²(α² + β²) = 0
//! circle    η = 0,  α² + β² − R²W² = 0;  ellipse  η = 0,  b²α² + a²β² − a²b²W² = 0
//! ```
//!
//! and the result is the zero polynomial: it holds for all values of the
//! symbols. The circle's relation to the ISO angle is proved too: piece `k`
//! at `t` is the ISO point at `φ = k·90° + 2·atan t`, with `cos`, `sin`
//! expanded by the angle-sum formula and the half-angle identities, not by
//! the library's turning of the control points.

use super::{Claim, Verdict};
use exact_bezier::algebra::Poly;
use exact_bezier::analytic::{circle, cone, ellipse, sphere, torus, Frame};
use exact_bezier::hpoint::HPoint;
use exact_bezier::ratio;
use num_traits::Zero;

const SOURCE: &str = "ours (ISO 10303-42 §4.4; Piegl–Tiller §7.3–§8.5)";

fn frame() -> Frame<Poly> {
    let q = |n: i64| ratio::<Poly>(n, 3);
    let c = vec![Poly::var("c1"), Poly::var("c2"), Poly::var("c3")];
    Frame::from_axes(c, vec![q(2), q(2), q(1)], vec![q(1), q(-2), q(2)])
}

fn dot(a: &[Poly], b: &[Poly]) -> Poly {
    a.iter()
        .zip(b)
        .fold(Poly::zero(), |s, (x, y)| s + x.clone() * y)
}

/// Is the frame orthonormal (the precondition of every claim)?
fn orthonormal(f: &Frame<Poly>) -> bool {
    let axes = [&f.x, &f.y, &f.z];
    (0..3).all(|i| (0..3).all(|j| dot(axes[i], axes[j]) == Poly::from_int(i64::from(i == j))))
}

/// `(α, β, η, W)`: the frame coordinates of a homogeneous point, homogenised.
fn coords(f: &Frame<Poly>, h: &HPoint<Poly>) -> [Poly; 4] {
    let w = h.weight().clone();
    let d: Vec<Poly> = h
        .weighted()
        .iter()
        .zip(&f.origin)
        .map(|(x, c)| x.clone() - c.clone() * &w)
        .collect();
    [dot(&d, &f.x), dot(&d, &f.y), dot(&d, &f.z), w]
}

/// The first non-zero residual over the pieces (zero iff every residual
/// is), so that a refutation shows a counterexample polynomial.
fn first_nonzero(residuals: impl Iterator<Item = Poly>) -> Poly {
    residuals
        .into_iter()
        .find(|r| !r.is_zero())
        .unwrap_or_else(Poly::zero)
}

fn surface_claim(
    name: &str,
    patches: Vec<exact_bezier::RectPatch<Poly>>,
    f: &Frame<Poly>,
    implicit: impl Fn(&[Poly; 4]) -> Poly,
) -> Claim {
    let (u, v) = (Poly::var("u"), Poly::var("v"));
    let n = patches.len();
    let r = first_nonzero(
        patches
            .iter()
            .map(|p| implicit(&coords(f, &p.eval_hom(&u, &v)))),
    );
    Claim::identity(
        &format!("every one of the {n} {name} pieces satisfies the {name}'s implicit equation identically in (u, v)"),
        SOURCE,
        Verdict::Proved,
        &r,
        &Poly::zero(),
        "symbolic centre, radii, slope, u, v; rational orthonormal frame",
    )
    .given(orthonormal(f), "the frame is orthonormal")
}

fn sq(p: &Poly) -> Poly {
    p.clone() * p
}

fn circle_claims(f: &Frame<Poly>) -> Vec<Claim> {
    let t = Poly::var("t");
    let (rr, a, b) = (Poly::var("R"), Poly::var("a"), Poly::var("b"));
    let on_circle = first_nonzero(circle(f, &rr).iter().flat_map(|c| {
        let [al, be, eta, w] = coords(f, &c.eval_hom(&t));
        [eta, sq(&al) + sq(&be) - sq(&rr) * sq(&w)]
    }));
    let on_ellipse = first_nonzero(ellipse(f, &a, &b).iter().flat_map(|c| {
        let [al, be, eta, w] = coords(f, &c.eval_hom(&t));
        [
            eta,
            sq(&b) * sq(&al) + sq(&a) * sq(&be) - sq(&a) * sq(&b) * sq(&w),
        ]
    }));
    // Piece k at t against C + R(cos φ x̂ + sin φ ŷ), φ = k·90° + 2 atan t:
    // (1 + t²)cos φ = (1 − t²)cos(k·90°) − 2t sin(k·90°), likewise sin.
    let (cos_k, sin_k) = ([1, 0, -1, 0], [0, 1, 0, -1]);
    let one_t2 = Poly::from_int(1) + sq(&t);
    let param = first_nonzero(circle(f, &rr).iter().enumerate().flat_map(|(k, c)| {
        let (ck, sk) = (Poly::from_int(cos_k[k]), Poly::from_int(sin_k[k]));
        let cos_d = (Poly::from_int(1) - sq(&t)) * &ck - Poly::from_int(2) * &t * &sk;
        let sin_d = (Poly::from_int(1) - sq(&t)) * &sk + Poly::from_int(2) * &t * &ck;
        let iso = f.point(
            &(rr.clone() * &cos_d),
            &(rr.clone() * &sin_d),
            &Poly::zero(),
        );
        let h = c.eval_hom(&t);
        let mut diffs: Vec<Poly> = h
            .weighted()
            .iter()
            .zip(&iso)
            .zip(&f.origin)
            // iso = C + R(...)(1+t²)-scaled offsets: compare W·C + offsets.
            .map(|((x, p), o)| x.clone() - (p.clone() - o) - o.clone() * &one_t2)
            .collect();
        diffs.push(h.weight().clone() - &one_t2);
        diffs
    }));
    let ok = orthonormal(f);
    vec![
        Claim::identity(
            "every quarter arc of a circle lies in its plane and on its circle, identically in t",
            SOURCE, Verdict::Proved, &on_circle, &Poly::zero(),
            "symbolic centre, R, t; rational orthonormal frame",
        ).given(ok, "the frame is orthonormal"),
        Claim::identity(
            "every quarter arc of an ellipse lies in its plane and on its ellipse, identically in t",
            SOURCE, Verdict::Proved, &on_ellipse, &Poly::zero(),
            "symbolic centre, a, b, t; rational orthonormal frame",
        ).given(ok, "the frame is orthonormal"),
        Claim::identity(
            "circle piece k at t is the ISO point at φ = k·90° + 2·atan t, with weight function 1 + t²",
            SOURCE, Verdict::Proved, &param, &Poly::zero(),
            "cos φ, sin φ by the angle sum and half-angle identities; symbolic centre, R, t",
        ).given(ok, "the frame is orthonormal"),
    ]
}

/// The family's claims.
pub fn claims() -> Vec<Claim> {
    let f = frame();
    let (rr, r, k) = (Poly::var("R"), Poly::var("r"), Poly::var("k"));
    let (v0, v1) = (Poly::var("v0"), Poly::var("v1"));
    let mut out = circle_claims(&f);
    let radial = |c: &[Poly; 4]| sq(&c[0]) + sq(&c[1]);
    out.push(surface_claim(
        "cylinder",
        exact_bezier::analytic::cylinder(&f, &rr, [&v0, &v1]),
        &f,
        |c| radial(c) - sq(&rr) * sq(&c[3]),
    ));
    out.push(surface_claim(
        "cone",
        cone(&f, &rr, &k, [&v0, &v1]),
        &f,
        |c| radial(c) - sq(&(rr.clone() * &c[3] + k.clone() * &c[2])),
    ));
    out.push(surface_claim("sphere", sphere(&f, &rr), &f, |c| {
        radial(c) + sq(&c[2]) - sq(&rr) * sq(&c[3])
    }));
    out.push(surface_claim("torus", torus(&f, &rr, &r), &f, |c| {
        let w2 = sq(&c[3]);
        let s = radial(c) + sq(&c[2]) + (sq(&rr) - sq(&r)) * &w2;
        sq(&s) - Poly::from_int(4) * sq(&rr) * w2 * radial(c)
    }));
    out
}
