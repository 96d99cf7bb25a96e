//! The exact continuity of two rational patches along a shared boundary,
//! whatever the parameterizations: reversed, Möbius-reparameterized or
//! degree-elevated edges included.
//!
//! Each patch is first turned so that the shared edge is `v = 0`, run by
//! `u`, with `v` pointing into the patch. `φ` maps a's edge parameter `t` to
//! b's `s` (a Möbius map, possibly reversed, from the coincidence witness of
//! the two boundary curves). With homogeneous patches `H = (w X, w)`,
//! `ν(y) = det(H_a, H_a,u, H_a,v, y)` (the tangent plane of a as a covector):
//!
//! * **G1** (tangent-plane continuity, without a fold): `ν(H_b,v) = 0` along
//!   the edge — b's cross derivative lies in a's tangent plane — and b lies
//!   on the other side of the edge: writing
//!   `X_b,v = β X_a,v + γ X_a,u` (Cartesian), `β < 0`. `β > 0` is a *fold*
//!   (the patches overlap: same tangent plane, same side).
//! * **G2** (curvature continuity): G1 and equal second fundamental forms on
//!   the common tangent plane: `II_b(X_b,v, X_b,v) = II_a(X_b,v, X_b,v)`,
//!   i.e. every normal curvature at every point of the seam agrees (the
//!   along-edge and mixed terms agree automatically once the normals do).
//!   Homogeneously, with `D = ν(e_k)`, `β'' = det(H_a, H_a,u, H_b,v, e_k)`,
//!   `γ'' = det(H_a, H_b,v, H_a,v, e_k)` (Cramer):
//!
//!   ```text
//!   w_b ν(H_b,vv) D² = w_a (β''² ν(H_a,vv) + 2β''γ'' ν(H_a,uv) + γ''² ν(H_a,uu))
//!   ```
//!
//!   using `ν(H_ij) = w ⟨n, X_ij⟩` for second derivatives (the terms in
//!   `(X, 1)` and first derivatives vanish on the tangent plane).
//!
//! **Exactness.** Along the edge each side is `c(t) · P(t)` with `c ≠ 0`
//! and `P` a polynomial of degree at most `3m_a + m_b` (G1) or
//! `9m_a + 2m_b` (G2), `m_a`, `m_b` the degrees along the edge (b's
//! Möbius map multiplies by a power of its non-vanishing denominator). So
//! `P ≡ 0` iff it vanishes at that many plus one distinct rational `t`:
//! the test is exact, and a failing sample is an exact witness.

use crate::coincide::{boundary_curve, coincide_curves, Edge, MobiusParam};
use crate::error::Error;
use crate::hpoint::HPoint;
use crate::{RationalCurve, RectPatch};
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

type Q = BigRational;

/// The continuity verdict of a seam.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Continuity {
    /// Positions agree; tangent planes do not (or the patches fold over).
    G0,
    /// Tangent planes agree along the seam and the patches lie on opposite sides.
    G1,
    /// G1 and every normal curvature agrees along the seam.
    G2,
}

impl std::fmt::Display for Continuity {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Continuity::G0 => "G0",
            Continuity::G1 => "G1",
            Continuity::G2 => "G2",
        })
    }
}

/// A seam's verdict with its reason (the failing parameter, exactly).
#[derive(Clone, Debug, PartialEq)]
pub struct SeamVerdict {
    /// The highest continuity established (`None`: undecided, see `reason`).
    pub continuity: Option<Continuity>,
    /// Why it is not higher, or how it was established.
    pub reason: String,
    /// b's edge runs against a's.
    pub reversed: bool,
    /// The edge map `s = φ(t)` is not an identity or reversal.
    pub reparameterized: bool,
}

/// `r` turned so that `edge` is `v = 0`, run by `u` in the direction of
/// [`boundary_curve`], `v` pointing inward.
pub fn turn_to_v0(r: &RectPatch<Q>, edge: Edge) -> RectPatch<Q> {
    match edge {
        Edge::V0 => r.clone(),
        Edge::V1 => r.reverse_v(),
        Edge::U0 => r.swap_uv(),
        Edge::U1 => r.reverse_u().swap_uv(),
    }
}

/// The `(u, v)` of a patch's edge point at edge parameter `t`.
pub fn edge_point(edge: Edge, t: &Q) -> [Q; 2] {
    let (z, o) = (Q::zero(), Q::one());
    match edge {
        Edge::U0 => [z, t.clone()],
        Edge::U1 => [o, t.clone()],
        Edge::V0 => [t.clone(), z],
        Edge::V1 => [t.clone(), o],
    }
}

/// The edge map `s = φ(t)` from a's boundary parameter to b's.
#[derive(Clone, Debug)]
struct EdgeMap {
    alpha: Option<Q>,
    reversed: bool,
}

impl EdgeMap {
    fn apply(&self, t: &Q) -> Result<Q, Error> {
        let s = match &self.alpha {
            Some(a) => RationalCurve::mobius_param(a, t)?,
            None => t.clone(),
        };
        Ok(if self.reversed { Q::one() - s } else { s })
    }
}

/// The candidates the coincidence witness allows, checked on the curves.
fn edge_map(ca: &RationalCurve<Q>, cb: &RationalCurve<Q>) -> Result<Result<EdgeMap, String>, Error> {
    let c = coincide_curves(ca, cb)?;
    let Some(w) = c.witness else {
        return Ok(Err(format!("the boundary curves differ: {}", c.reason)));
    };
    let alphas: Vec<Option<Q>> = match &w.u {
        MobiusParam::None => vec![None],
        MobiusParam::Value { alpha, .. } => vec![None, Some(alpha.clone()), Some(Q::one() - alpha)],
        MobiusParam::Power { exponent, power } => {
            return Ok(Err(format!(
                "the edge parameterizations differ by an irrational Möbius map (ρ^{exponent} = {power}); continuity not decided"
            )))
        }
    };
    let probes = [Q::new(1.into(), 3.into()), Q::new(3.into(), 7.into())];
    for alpha in alphas {
        for reversed in [w.symmetry.reverse_u, !w.symmetry.reverse_u] {
            let m = EdgeMap {
                alpha: alpha.clone(),
                reversed,
            };
            let fits = probes.iter().all(|t| {
                m.apply(t).is_ok_and(|s| {
                    ca.eval_hom(t)
                        .same_projective_point(&cb.eval_hom(&s), crate::Tolerance::EXACT)
                })
            });
            if fits {
                return Ok(Ok(m));
            }
        }
    }
    Ok(Err("no Möbius map of the witness matches the edges pointwise".into()))
}

/// Value and first two derivatives of a row of homogeneous points at `t`:
/// de Casteljau, keeping the levels of 3 and 2 points
/// (`C' = n Δb^{n−1}_0`, `C'' = n(n−1) Δ²b^{n−2}_0`).
fn curve_jet(pts: &[HPoint<Q>], t: &Q) -> [Vec<Q>; 3] {
    let n = pts.len() - 1;
    let mut row: Vec<HPoint<Q>> = pts.to_vec();
    let mut three = (n == 2).then(|| row.clone());
    let mut two = (n == 1).then(|| row.clone());
    for k in (1..=n).rev() {
        for i in 0..k {
            row[i] = row[i].lerp(&row[i + 1], t);
        }
        if k == 3 {
            three = Some(row[..3].to_vec());
        }
        if k == 2 {
            two = Some(row[..2].to_vec());
        }
    }
    let zero = vec![Q::zero(); pts[0].coords.len()];
    let scaled = |v: HPoint<Q>, k: usize| -> Vec<Q> {
        let k = Q::from_integer((k as i64).into());
        v.coords.into_iter().map(|x| x * &k).collect()
    };
    let d1 = two.map_or(zero.clone(), |l| scaled(l[1].sub(&l[0]), n));
    let d2 = three.map_or(zero, |l| scaled(l[2].sub(&l[1]).sub(&l[1].sub(&l[0])), n * (n - 1)));
    [row[0].coords.clone(), d1, d2]
}

/// `H, H_u, H_v, H_uu, H_uv, H_vv` of a turned patch at `(t, 0)`, as 4-vectors
/// (2D points padded with z = 0).
fn patch_jet(r: &RectPatch<Q>, t: &Q) -> [Vec<Q>; 6] {
    let (_, n) = r.degree();
    let rows: Vec<[Vec<Q>; 3]> = (0..=n.min(2)).map(|j| curve_jet(&r.column(j), t)).collect();
    let zero = vec![Q::zero(); rows[0][0].len()];
    let lin = |a: &[Q], b: &[Q], ka: i64, kb: i64| -> Vec<Q> {
        a.iter()
            .zip(b)
            .map(|(x, y)| x * Q::from_integer(ka.into()) + y * Q::from_integer(kb.into()))
            .collect()
    };
    let n = n as i64;
    let (hv, huv) = if n >= 1 {
        (lin(&rows[1][0], &rows[0][0], n, -n), lin(&rows[1][1], &rows[0][1], n, -n))
    } else {
        (zero.clone(), zero.clone())
    };
    let hvv = if n >= 2 {
        let a = lin(&rows[2][0], &rows[1][0], 1, -2);
        lin(&a, &rows[0][0], n * (n - 1), n * (n - 1))
    } else {
        zero
    };
    let [h, hu, huu] = rows[0].clone();
    [h, hu, hv, huu, huv, hvv].map(pad)
}

/// `(x, y, w)` → `(x, y, 0, w)`; 3D points unchanged.
fn pad(mut v: Vec<Q>) -> Vec<Q> {
    if v.len() == 3 {
        v.insert(2, Q::zero());
    }
    v
}

fn det3(a: [&Q; 3], b: [&Q; 3], c: [&Q; 3]) -> Q {
    a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0])
}

fn pick<'a>(v: &'a [Q], rows: &[usize]) -> [&'a Q; 3] {
    [&v[rows[0]], &v[rows[1]], &v[rows[2]]]
}

/// `det(a, b, c, d)` of four 4-vectors (columns), by expansion along `d`.
fn det4(a: &[Q], b: &[Q], c: &[Q], d: &[Q]) -> Q {
    (0..4).fold(Q::zero(), |acc, k| {
        let rows: Vec<usize> = (0..4).filter(|&r| r != k).collect();
        let minor = det3(pick(a, &rows), pick(b, &rows), pick(c, &rows));
        let term = &d[k] * minor;
        if (k + 3) % 2 == 0 {
            acc + term
        } else {
            acc - term
        }
    })
}

fn unit(k: usize) -> Vec<Q> {
    (0..4).map(|i| if i == k { Q::one() } else { Q::zero() }).collect()
}

fn dot(a: &[Q], b: &[Q]) -> Q {
    a.iter().zip(b).fold(Q::zero(), |s, (x, y)| s + x * y)
}

/// The exact continuity across the shared edge `ea` of `a` and `eb` of `b`.
///
/// # Errors
///
/// [`Error::Weight`] for non-positive weights; [`Error::Shape`] for points
/// of dimension other than 2 or 3.
pub fn seam_continuity(a: &RectPatch<Q>, ea: Edge, b: &RectPatch<Q>, eb: Edge) -> Result<SeamVerdict, Error> {
    if !(2..=3).contains(&a.dim()) || a.dim() != b.dim() {
        return Err(Error::Shape(format!(
            "continuity needs 2D or 3D patches, not dimensions {} and {}",
            a.dim(),
            b.dim()
        )));
    }
    let (ca, cb) = (boundary_curve(a, ea), boundary_curve(b, eb));
    let map = match edge_map(&ca, &cb)? {
        Ok(m) => m,
        Err(reason) => {
            return Ok(SeamVerdict {
                continuity: None,
                reason,
                reversed: false,
                reparameterized: false,
            })
        }
    };
    let (ta, tb) = (turn_to_v0(a, ea), turn_to_v0(b, eb));
    let (ma, mb) = (ta.degree().0, tb.degree().0);
    let verdict = |continuity, reason| SeamVerdict {
        continuity,
        reason,
        reversed: map.reversed,
        reparameterized: map.alpha.is_some(),
    };
    let g1_samples = 3 * ma + mb + 1;
    let g2_samples = 9 * ma + 2 * mb + 1;
    let denom = Q::from_integer(((g2_samples + 1) as i64).into());
    let mut jets = Vec::with_capacity(g2_samples);
    let mut probe: Option<usize> = None;
    let where_ = |t: &Q, s: &Q| {
        let [u, v] = edge_point(ea, t);
        let [p, q] = edge_point(eb, s);
        format!("a at (u, v) = ({u}, {v}), b at ({p}, {q})")
    };
    for k in 1..=g1_samples {
        let t = Q::from_integer((k as i64).into()) / &denom;
        let s = map.apply(&t)?;
        let (ja, jb) = (patch_jet(&ta, &t), patch_jet(&tb, &s));
        let nu: Vec<Q> = (0..4).map(|i| det4(&ja[0], &ja[1], &ja[2], &unit(i))).collect();
        let det = dot(&nu, &jb[2]);
        if !det.is_zero() {
            return Ok(verdict(
                Some(Continuity::G0),
                format!("tangent planes differ at {}", where_(&t, &s)),
            ));
        }
        let nu_b: Vec<Q> = (0..4).map(|i| det4(&jb[0], &jb[1], &jb[2], &unit(i))).collect();
        if let Some(kk) = nu.iter().position(|x| !x.is_zero()).filter(|_| nu_b.iter().any(|x| !x.is_zero())) {
            let r = unit(kk);
            let beta = det4(&ja[0], &ja[1], &jb[2], &r) * &nu[kk];
            if beta.is_positive() {
                return Ok(verdict(
                    Some(Continuity::G0),
                    format!("the patches fold over (same tangent plane, same side) at {}", where_(&t, &s)),
                ));
            }
            probe.get_or_insert(kk);
        }
        jets.push((t, s, ja, jb, nu));
    }
    let Some(kk) = probe else {
        return Ok(verdict(None, "the tangent planes are degenerate all along the edge; continuity not decided".into()));
    };
    for k in g1_samples + 1..=g2_samples {
        let t = Q::from_integer((k as i64).into()) / &denom;
        let s = map.apply(&t)?;
        let (ja, jb) = (patch_jet(&ta, &t), patch_jet(&tb, &s));
        let nu: Vec<Q> = (0..4).map(|i| det4(&ja[0], &ja[1], &ja[2], &unit(i))).collect();
        jets.push((t, s, ja, jb, nu));
    }
    let r = unit(kk);
    for (t, s, ja, jb, nu) in &jets {
        let d = nu[kk].clone();
        let beta = det4(&ja[0], &ja[1], &jb[2], &r);
        let gamma = det4(&ja[0], &jb[2], &ja[2], &r);
        let lhs = jb[0][3].clone() * dot(nu, &jb[5]) * &d * &d;
        let rhs = ja[0][3].clone()
            * (beta.clone() * &beta * dot(nu, &ja[5])
                + Q::from_integer(2.into()) * &beta * &gamma * dot(nu, &ja[4])
                + gamma.clone() * &gamma * dot(nu, &ja[3]));
        if lhs != rhs {
            let jump = if rhs.is_zero() {
                "b's normal curvature across the seam is not 0, a's is".to_owned()
            } else {
                format!("b's normal curvature across the seam is {} times a's", lhs / rhs)
            };
            return Ok(verdict(Some(Continuity::G1), format!("{jump} at {}", where_(t, s))));
        }
    }
    Ok(verdict(
        Some(Continuity::G2),
        format!("G2 identity holds at {g2_samples} samples, above its degree bound {}", g2_samples - 1),
    ))
}

#[cfg(test)]
mod tests;
