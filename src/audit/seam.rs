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

use crate::algebra::int::{common_denominator, Int};
use crate::algebra::{RealAlgebraic, Ring};
use crate::coincide::minimal::Reducible;
use crate::coincide::{boundary_curve, coincide, CoincideScalar, Edge, MobiusParam, Options};
use crate::error::Error;
use crate::hpoint::HPoint;
use crate::{Patch, RationalCurve, RectPatch};
use num_rational::BigRational;
use num_traits::{One, Zero};
use std::cmp::Ordering;

type Q = BigRational;

/// An exact scalar whose seams [`seam_continuity`] decides, and how: the
/// identities are checked in a ring [`SeamScalar::Jet`] — the integers for
/// rationals (each net over one common denominator, which scales every
/// identity by a positive factor), the numbers themselves for real
/// algebraic ones.
pub trait SeamScalar: CoincideScalar + Reducible {
    /// The ring the jets are computed in.
    type Jet: Ring;
    /// The coordinates, all scaled by one positive number, in the ring.
    fn scaled<'a>(coords: impl Iterator<Item = &'a Self> + Clone) -> Vec<Self::Jet>;
    /// The homogeneous parameter `(1 − t : t)`, scaled by a positive number.
    fn hom(t: &Self) -> (Self::Jet, Self::Jet);
    /// A small integer in the ring.
    fn small(k: i128) -> Self::Jet;
    /// The sign of a ring element.
    fn sign(x: &Self::Jet) -> Ordering;
    /// The quotient `num / den` (`den ≠ 0`) as text.
    fn ratio_text(num: &Self::Jet, den: &Self::Jet) -> String;
}

impl SeamScalar for Q {
    type Jet = Int;
    fn scaled<'a>(coords: impl Iterator<Item = &'a Self> + Clone) -> Vec<Int> {
        common_denominator::<Int>(coords).0
    }
    fn hom(t: &Q) -> (Int, Int) {
        (
            Int::from_bigint(t.denom() - t.numer()),
            Int::from_bigint(t.numer().clone()),
        )
    }
    fn small(k: i128) -> Int {
        Int::from(k)
    }
    fn sign(x: &Int) -> Ordering {
        x.to_bigint().sign().cmp(&num_bigint::Sign::NoSign)
    }
    fn ratio_text(num: &Int, den: &Int) -> String {
        Q::new(num.to_bigint(), den.to_bigint()).to_string()
    }
}

impl SeamScalar for RealAlgebraic {
    type Jet = RealAlgebraic;
    fn scaled<'a>(coords: impl Iterator<Item = &'a Self> + Clone) -> Vec<Self> {
        coords.cloned().collect()
    }
    fn hom(t: &Self) -> (Self, Self) {
        (Self::one() - t, t.clone())
    }
    fn small(k: i128) -> Self {
        <Self as crate::algebra::Scalar>::from_rational(&Q::from_integer(k.into()))
    }
    fn sign(x: &Self) -> Ordering {
        x.partial_cmp(&Self::zero()).unwrap_or(Ordering::Equal)
    }
    fn ratio_text(num: &Self, den: &Self) -> String {
        (num.clone() / den).to_string()
    }
}

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
pub fn turn_to_v0<T: SeamScalar>(r: &RectPatch<T>, edge: Edge) -> RectPatch<T> {
    match edge {
        Edge::V0 => r.clone(),
        Edge::V1 => r.reverse_v(),
        Edge::U0 => r.swap_uv(),
        Edge::U1 => r.reverse_u().swap_uv(),
    }
}

/// The `(u, v)` of a patch's edge point at edge parameter `t`.
pub fn edge_point<T: SeamScalar>(edge: Edge, t: &T) -> [T; 2] {
    let (z, o) = (T::zero(), T::one());
    match edge {
        Edge::U0 => [z, t.clone()],
        Edge::U1 => [o, t.clone()],
        Edge::V0 => [t.clone(), z],
        Edge::V1 => [t.clone(), o],
    }
}

/// The edge map `s = φ(t)` from a's boundary parameter to b's.
#[derive(Clone, Debug)]
struct EdgeMap<T> {
    alpha: Option<T>,
    reversed: bool,
}

impl<T: SeamScalar> EdgeMap<T> {
    fn apply(&self, t: &T) -> Result<T, Error> {
        let s = match &self.alpha {
            Some(a) => RationalCurve::mobius_param(a, t)?,
            None => t.clone(),
        };
        Ok(if self.reversed { T::one() - s } else { s })
    }
}

/// Do the edges have proportional homogeneous control points, in order or
/// reversed (the same parameterization up to reversal — the usual case)?
/// Then `φ` is the identity or `t ↦ 1 − t`, without a coincidence test.
fn direct_map<T: SeamScalar>(ca: &RationalCurve<T>, cb: &RationalCurve<T>) -> Option<EdgeMap<T>> {
    let (a, b) = (ca.ctrl(), cb.ctrl());
    if a.len() != b.len() {
        return None;
    }
    let proportional = |b: &mut dyn Iterator<Item = &HPoint<T>>| {
        let (wa, mut wb) = (a[0].weight(), None);
        a.iter().zip(b).all(|(p, q)| {
            let wb0 = wb.get_or_insert_with(|| q.weight().clone());
            p.coords
                .iter()
                .zip(&q.coords)
                .all(|(x, y)| x.clone() * &*wb0 == y.clone() * wa)
        })
    };
    if proportional(&mut b.iter()) {
        Some(EdgeMap {
            alpha: None,
            reversed: false,
        })
    } else if proportional(&mut b.iter().rev()) {
        Some(EdgeMap {
            alpha: None,
            reversed: true,
        })
    } else {
        None
    }
}

/// The edge map: [`direct_map`], else the candidates the coincidence
/// witness allows, checked on the curves.
fn edge_map<T: SeamScalar>(
    ca: &RationalCurve<T>,
    cb: &RationalCurve<T>,
) -> Result<Result<EdgeMap<T>, String>, Error> {
    if let Some(m) = direct_map(ca, cb) {
        return Ok(Ok(m));
    }
    let c = coincide(
        &Patch::Curve(ca.clone()),
        &Patch::Curve(cb.clone()),
        Options::default(),
    )?;
    let Some(w) = c.witness else {
        return Ok(Err(format!("the boundary curves differ: {}", c.reason)));
    };
    let alphas: Vec<Option<T>> = match &w.u {
        MobiusParam::None => vec![None],
        MobiusParam::Value { alpha, .. } => vec![None, Some(alpha.clone()), Some(T::one() - alpha)],
        MobiusParam::Power { exponent, power } => {
            return Ok(Err(format!(
                "the edge parameterizations differ by an irrational Möbius map (ρ^{exponent} = {power}); continuity not decided"
            )))
        }
    };
    let probes = [
        T::from_rational(&Q::new(1.into(), 3.into())),
        T::from_rational(&Q::new(3.into(), 7.into())),
    ];
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
    Ok(Err(
        "no Möbius map of the witness matches the edges pointwise".into(),
    ))
}

/// A turned patch's first three columns (`v`-rows `j = 0, 1, 2` of the net,
/// each a curve in `u`) as homogeneous points of the jet ring, all scaled
/// by one positive number ([`SeamScalar::scaled`]). Scaling a whole net by
/// a positive constant changes no verdict (every identity below is
/// homogeneous in each patch).
struct JetNet<R> {
    cols: Vec<Vec<Vec<R>>>,
    n: usize,
}

impl<R: Ring> JetNet<R> {
    fn new<T: SeamScalar<Jet = R>>(r: &RectPatch<T>) -> Self {
        let n = r.degree().1;
        let cols: Vec<Vec<HPoint<T>>> = (0..=n.min(2)).map(|j| r.column(j)).collect();
        let all = cols.iter().flatten().flat_map(|p| p.coords.iter());
        let nums = T::scaled(all);
        let len = cols[0][0].coords.len();
        let mut it = nums.into_iter();
        let cols = cols
            .iter()
            .map(|c| c.iter().map(|_| it.by_ref().take(len).collect()).collect())
            .collect();
        JetNet { cols, n }
    }
}

/// `Σ k_i v_i` for small integer `k_i`.
fn lin<T: SeamScalar>(terms: &[(&[T::Jet], i128)]) -> Vec<T::Jet> {
    let len = terms[0].0.len();
    (0..len)
        .map(|c| {
            terms.iter().fold(T::Jet::zero(), |acc, (v, k)| {
                acc + &(v[c].clone() * &T::small(*k))
            })
        })
        .collect()
}

/// Value and first two derivatives of a Bézier row at the homogeneous
/// parameter `(a : b)` (`t = b/(a + b)`), each scaled by
/// `(a + b)^{level}`: de Casteljau with the step `a·x + b·y`, keeping the
/// levels of 3 and 2 points (`C' = n Δb^{n−1}_0`, `C'' = n(n−1) Δ²b^{n−2}_0`).
fn curve_jet<T: SeamScalar>(pts: &[Vec<T::Jet>], a: &T::Jet, b: &T::Jet) -> [Vec<T::Jet>; 3] {
    let n = pts.len() - 1;
    let mut row: Vec<Vec<T::Jet>> = pts.to_vec();
    let mut three = (n == 2).then(|| row.clone());
    let mut two = (n == 1).then(|| row.clone());
    for k in (1..=n).rev() {
        for i in 0..k {
            row[i] = row[i]
                .iter()
                .zip(&row[i + 1])
                .map(|(x, y)| x.clone() * a + &(y.clone() * b))
                .collect();
        }
        if k == 3 {
            three = Some(row[..3].to_vec());
        }
        if k == 2 {
            two = Some(row[..2].to_vec());
        }
    }
    let zero = vec![T::Jet::zero(); pts[0].len()];
    let n = n as i128;
    let d1 = two.map_or(zero.clone(), |l| lin::<T>(&[(&l[1], n), (&l[0], -n)]));
    let d2 = three.map_or(zero, |l| {
        lin::<T>(&[
            (&l[2], n * (n - 1)),
            (&l[1], -2 * n * (n - 1)),
            (&l[0], n * (n - 1)),
        ])
    });
    [row.swap_remove(0), d1, d2]
}

/// `H, H_u, H_v, H_uu, H_uv, H_vv` of a turned patch at `((a : b), 0)`, as
/// 4-vectors (2D points padded with z = 0), each scaled by a positive power
/// of `a + b` that depends only on its order of u-differentiation (so every
/// identity checked is scaled by one positive factor per sample).
fn patch_jet<T: SeamScalar>(net: &JetNet<T::Jet>, a: &T::Jet, b: &T::Jet) -> [Vec<T::Jet>; 6] {
    let rows: Vec<[Vec<T::Jet>; 3]> = net.cols.iter().map(|c| curve_jet::<T>(c, a, b)).collect();
    let zero = vec![T::Jet::zero(); rows[0][0].len()];
    let n = net.n as i128;
    let (hv, huv) = if n >= 1 {
        (
            lin::<T>(&[(&rows[1][0], n), (&rows[0][0], -n)]),
            lin::<T>(&[(&rows[1][1], n), (&rows[0][1], -n)]),
        )
    } else {
        (zero.clone(), zero.clone())
    };
    let hvv = if n >= 2 {
        let k = n * (n - 1);
        lin::<T>(&[(&rows[2][0], k), (&rows[1][0], -2 * k), (&rows[0][0], k)])
    } else {
        zero
    };
    let [h, hu, huu] = rows[0].clone();
    [h, hu, hv, huu, huv, hvv].map(pad)
}

/// `(x, y, w)` → `(x, y, 0, w)`; 3D points unchanged.
fn pad<R: Ring>(mut v: Vec<R>) -> Vec<R> {
    if v.len() == 3 {
        v.insert(2, R::zero());
    }
    v
}

fn det3<R: Ring>(a: [&R; 3], b: [&R; 3], c: [&R; 3]) -> R {
    let m = |x: &R, y: &R| x.clone() * y;
    m(a[0], &(m(b[1], c[2]) - m(b[2], c[1]))) - m(a[1], &(m(b[0], c[2]) - m(b[2], c[0])))
        + m(a[2], &(m(b[0], c[1]) - m(b[1], c[0])))
}

fn pick<'a, R>(v: &'a [R], rows: &[usize]) -> [&'a R; 3] {
    [&v[rows[0]], &v[rows[1]], &v[rows[2]]]
}

/// The covector `y ↦ det(a, b, c, y)` of three 4-vectors (cofactors).
fn covector<R: Ring>(a: &[R], b: &[R], c: &[R]) -> Vec<R> {
    (0..4).map(|k| det_unit(a, b, c, k)).collect()
}

/// `det(a, b, c, e_k)`: the `k`-th cofactor alone.
fn det_unit<R: Ring>(a: &[R], b: &[R], c: &[R], k: usize) -> R {
    let rows: Vec<usize> = (0..4).filter(|&r| r != k).collect();
    let minor = det3(pick(a, &rows), pick(b, &rows), pick(c, &rows));
    if k % 2 == 1 {
        minor
    } else {
        -minor
    }
}

fn dot<R: Ring>(a: &[R], b: &[R]) -> R {
    a.iter()
        .zip(b)
        .fold(R::zero(), |s, (x, y)| s + &(x.clone() * y))
}

/// One sample: a's and b's jets at `t` and `s = φ(t)`, and a's tangent covector.
struct Sample<T: SeamScalar> {
    t: T,
    s: T,
    ja: [Vec<T::Jet>; 6],
    jb: [Vec<T::Jet>; 6],
    nu: Vec<T::Jet>,
}

impl<T: SeamScalar> Sample<T> {
    fn new(a: &JetNet<T::Jet>, b: &JetNet<T::Jet>, t: T, s: T) -> Self {
        let ((p, q), (r, u)) = (T::hom(&t), T::hom(&s));
        let (ja, jb) = (patch_jet::<T>(a, &p, &q), patch_jet::<T>(b, &r, &u));
        let nu = covector(&ja[0], &ja[1], &ja[2]);
        Sample { t, s, ja, jb, nu }
    }
}

/// The exact continuity across the shared edge `ea` of `a` and `eb` of `b`.
///
/// # Errors
///
/// [`Error::Weight`] for non-positive weights; [`Error::Shape`] for points
/// of dimension other than 2 or 3.
pub fn seam_continuity<T: SeamScalar>(
    a: &RectPatch<T>,
    ea: Edge,
    b: &RectPatch<T>,
    eb: Edge,
) -> Result<SeamVerdict, Error> {
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
    let (na, nb) = (JetNet::new(&ta), JetNet::new(&tb));
    let verdict = |continuity, reason| SeamVerdict {
        continuity,
        reason,
        reversed: map.reversed,
        reparameterized: map.alpha.is_some(),
    };
    let g1_samples = 3 * ma + mb + 1;
    let g2_samples = 9 * ma + 2 * mb + 1;
    let sample_at = |k: usize| -> Result<Sample<T>, Error> {
        let t = T::from_rational(&Q::new((k as i64).into(), ((g2_samples + 1) as i64).into()));
        let s = map.apply(&t)?;
        Ok(Sample::new(&na, &nb, t, s))
    };
    let where_ = |x: &Sample<T>| {
        let [u, v] = edge_point(ea, &x.t);
        let [p, q] = edge_point(eb, &x.s);
        format!("a at (u, v) = ({u}, {v}), b at ({p}, {q})")
    };
    let mut samples = Vec::with_capacity(g2_samples);
    let mut probe: Option<usize> = None;
    for k in 1..=g1_samples {
        let x = sample_at(k)?;
        if !dot(&x.nu, &x.jb[2]).is_zero() {
            return Ok(verdict(
                Some(Continuity::G0),
                format!("tangent planes differ at {}", where_(&x)),
            ));
        }
        let regular_b = covector(&x.jb[0], &x.jb[1], &x.jb[2])
            .iter()
            .any(|c| !c.is_zero());
        if let Some(kk) = x.nu.iter().position(|c| !c.is_zero()).filter(|_| regular_b) {
            let beta = det_unit(&x.ja[0], &x.ja[1], &x.jb[2], kk) * &x.nu[kk];
            if T::sign(&beta).is_gt() {
                return Ok(verdict(
                    Some(Continuity::G0),
                    format!(
                        "the patches fold over (same tangent plane, same side) at {}",
                        where_(&x)
                    ),
                ));
            }
            probe.get_or_insert(kk);
        }
        samples.push(x);
    }
    let Some(kk) = probe else {
        return Ok(verdict(
            None,
            "the tangent planes are degenerate all along the edge; continuity not decided".into(),
        ));
    };
    for k in g1_samples + 1..=g2_samples {
        samples.push(sample_at(k)?);
    }
    for x in &samples {
        let (ja, jb, nu) = (&x.ja, &x.jb, &x.nu);
        let d = &nu[kk];
        let beta = det_unit(&ja[0], &ja[1], &jb[2], kk);
        let gamma = det_unit(&ja[0], &jb[2], &ja[2], kk);
        let lhs = jb[0][3].clone() * &dot(nu, &jb[5]) * d * d;
        let rhs = ja[0][3].clone()
            * &(beta.clone() * &beta * &dot(nu, &ja[5])
                + &(T::small(2) * &beta * &gamma * &dot(nu, &ja[4]))
                + &(gamma.clone() * &gamma * &dot(nu, &ja[3])));
        if lhs != rhs {
            let jump = if rhs.is_zero() {
                "b's normal curvature across the seam is not 0, a's is".to_owned()
            } else {
                format!(
                    "b's normal curvature across the seam is {} times a's",
                    T::ratio_text(&lhs, &rhs)
                )
            };
            return Ok(verdict(
                Some(Continuity::G1),
                format!("{jump} at {}", where_(x)),
            ));
        }
    }
    Ok(verdict(
        Some(Continuity::G2),
        format!(
            "G2 identity holds at {g2_samples} samples, above its degree bound {}",
            g2_samples - 1
        ),
    ))
}

#[cfg(test)]
mod tests;
