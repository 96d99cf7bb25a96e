//! Our theorem: a trigonometric curve or surface of source 002 is exactly a
//! rational Bézier quartic (a rational (4, 4) patch) in the half-angle
//! parameter τ = tan(t/2), with weights 1, 1, 4/3, 2, 4.
//!
//! Established symbolically: for symbolic α (α₁, α₂), control points and τ,
//! the homogeneous value of `to_rational()` at τ equals `(1+τ²)²` times the
//! trigonometric value, where the right-hand side is expanded from the
//! definitions `s·(1+τ²) = 2τ`, `c·(1+τ²) = 1 − τ²` alone (not from the
//! table the code uses).

use super::{Claim, Verdict};
use exact_bezier::algebra::Poly;
use exact_bezier::trig::basis::TrigFn;
use exact_bezier::trig::curve::TrigCurve;
use exact_bezier::trig::surface::TrigRect;
use num_traits::Zero;

/// `(1+τ²)² f(s, c)` expanded from the half-angle definitions.
fn cleared(f: &TrigFn<Poly>, tau: &Poly) -> Poly {
    let d = Poly::from_int(1) + tau.pow(2);
    let sd = Poly::from_int(2) * tau;
    let cd = Poly::from_int(1) - tau.pow(2);
    let [a0, a1, a2, a3, a4] = f.coeffs();
    a0.clone() * d.pow(2)
        + a1.clone() * &sd * &d
        + a2.clone() * &cd * &d
        + a3.clone() * sd.pow(2)
        + a4.clone() * &sd * &cd
}

fn curve_claim() -> Claim {
    let tau = Poly::var("τ");
    let pts: Vec<Vec<Poly>> = Poly::vars("P", 4).into_iter().map(|p| vec![p]).collect();
    let c = TrigCurve::new(pts, Poly::var("α")).expect("four 1D points");
    let hom = c.to_rational().eval_hom(&tau);
    let basis = TrigFn::basis(c.alpha());
    let rhs: Poly = basis
        .iter()
        .zip(c.points())
        .fold(Poly::zero(), |acc, (x, p)| acc + cleared(x, &tau) * &p[0]);
    let weight_ok = *hom.weight() == (Poly::from_int(1) + tau.pow(2)).pow(2);
    let mut claim = Claim::identity(
        "a trig curve (source 002 eq. 1, any α) is the rational quartic to_rational() in τ = tan(t/2): numerator = (1+τ²)²·p(t)",
        "ours (half-angle substitution in 002 eq. 1)",
        Verdict::Proved,
        &hom.weighted()[0],
        &rhs,
        "symbolic α, P₀…P₃, τ",
    );
    if !weight_ok {
        claim.verdict = Verdict::Refuted;
        claim.detail = format!("weight function is {}, not (1+τ²)²", hom.weight());
    }
    claim
}

fn surface_claim() -> Claim {
    let (tu, tv) = (Poly::var("τu"), Poly::var("τv"));
    let net: Vec<Vec<Vec<Poly>>> = (0..4)
        .map(|i| {
            (0..4)
                .map(|j| vec![Poly::var(&format!("P{i}{j}"))])
                .collect()
        })
        .collect();
    let s = TrigRect::new(net, [Poly::var("α1"), Poly::var("α2")]).expect("4 × 4 net");
    let hom = s.to_rational().eval_hom(&tu, &tv);
    let (bu, bv) = (TrigFn::basis(&s.alpha()[0]), TrigFn::basis(&s.alpha()[1]));
    let mut rhs = Poly::zero();
    for (xi, row) in bu.iter().zip(s.points()) {
        let fu = cleared(xi, &tu);
        for (xj, p) in bv.iter().zip(row) {
            rhs = rhs + fu.clone() * &cleared(xj, &tv) * &p[0];
        }
    }
    Claim::identity(
        "a trig-rect (source 002, any α₁, α₂) is the rational (4,4) patch to_rational() in (tan(u/2), tan(v/2)): numerator = (1+τu²)²(1+τv²)²·S(u, v)",
        "ours (half-angle substitution in 002 eq. 1)",
        Verdict::Proved,
        &hom.weighted()[0],
        &rhs,
        "symbolic α₁, α₂, 16 control points, τu, τv",
    )
}

/// The family's claims.
pub fn claims() -> Vec<Claim> {
    vec![curve_claim(), surface_claim()]
}
