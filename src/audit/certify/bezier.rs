//! Rational Bézier curves and tensor-product patches with interval control
//! points, and proved enclosures of their values and derivatives over
//! parameter boxes.
//!
//! **Enclosure over a box.** The Bernstein coefficients of the piece of a
//! polynomial `p` of degree `n` over `[a, b]` are its blossom values
//! `p[a^{n−k}, b^k]`, `k = 0..n` (Farin, *Curves and Surfaces for CAGD*,
//! ch. 4), computed by de Casteljau steps at `b` (k times) and `a`
//! (n − k times); every value of `p` on `[a, b]` lies between their least
//! and greatest (convex hull property). Tensor-product patches take the
//! piece in `u`, then in `v`. Run in outward-rounded interval arithmetic
//! from enclosures of the exact control points, the hull contains the
//! exact range. The width shrinks like the box squared around a value
//! (the control polygon of a small piece is nearly its chord), so a
//! constant or linear coordinate gets an enclosure as wide as the rounding.
//!
//! The homogeneous derivatives `∂^{a+b}H/∂u^a∂v^b` are formed exactly
//! (forward differences) before the control points are enclosed; the
//! Cartesian derivatives follow from `X = P/w` by the quotient rule:
//!
//! ```text
//! X_u  = (P_u − w_u X) / w
//! X_uv = (P_uv − w_u X_v − w_v X_u − w_uv X) / w
//! ```

use super::compose::NetRef;
use super::ivec::IVec;
use super::quad::Quad;
use super::Enclose;
use crate::algebra::{Interval, Scalar};
use crate::bernstein::bernstein_stages_into;
use crate::error::Error;
use crate::hpoint::HPoint;
use crate::widest::Job;
use crate::{RationalCurve, RectPatch};
use smallvec::SmallVec;

/// Scratch space for one row or column of control points: on the stack up
/// to degree 15.
type Row = SmallVec<[Quad; 16]>;

/// De Casteljau's algorithm at `t` in place, keeping one side: afterwards
/// `c` holds the control points of the piece over `[0, t]` (`left`) or over
/// `[t, 1]`, each step `d_i^r = (1 − t) d_i^{r−1} + t d_{i+1}^{r−1}`. The
/// left piece is `d_0^r`, `r = 0..n` (kept in place by storing `d_{i−r}^r`
/// at `c[i]`), the right piece `d_i^{n−i}`. The four homogeneous
/// coordinates go together, lane by lane ([`Quad`]).
#[inline(always)]
fn subdivide(c: &mut [Quad], t: Interval, left: bool) {
    let s = Interval::point(1.0).sub(&t);
    let n = c.len() - 1;
    for level in 1..=n {
        if left {
            for i in (level..=n).rev() {
                c[i] = c[i - 1].scale(&s).add(&c[i].scale(&t));
            }
        } else {
            for i in 0..=n - level {
                c[i] = c[i].scale(&s).add(&c[i + 1].scale(&t));
            }
        }
    }
}

/// The control points of the piece over `[a, b]` (`a ≤ b`, any reals) of
/// the Bézier curve with control points `c` (blossom values
/// `c[a^{n−k}, b^k]`), written to `out`, in two subdivisions: the piece
/// over `[0, b]`, then its part over `[a/b, 1]`; or, for `b < 1/2`, the
/// piece over `[a, 1]`, then its part over `[0, (b − a)/(1 − a)]` (the
/// divisor at least 1/2 either way). The parameters are enclosed: the exact
/// blossom values lie in the result (inclusion isotonicity). For `a = b`,
/// every control point is the value at `a`.
#[inline(always)]
fn piece(c: &[Quad], a: f64, b: f64, out: &mut Row) {
    let point = Interval::point;
    out.clear();
    out.extend_from_slice(c);
    if a == b {
        subdivide(out, point(a), false);
        let value = out[0];
        out.fill(value);
    } else if b >= 0.5 {
        subdivide(out, point(b), true);
        let ratio = point(a).div(&point(b)).expect("b ≥ 1/2");
        subdivide(out, ratio, false);
    } else {
        subdivide(out, point(a), false);
        let ratio = point(b)
            .sub(&point(a))
            .div(&point(1.0).sub(&point(a)))
            .expect("1 − a > 1/2");
        subdivide(out, ratio, true);
    }
}

#[inline(always)]
fn hull(values: &[Quad]) -> Quad {
    values
        .iter()
        .copied()
        .reduce(|a, b| a.hull(&b))
        .expect("a Bézier net is never empty")
}

fn enclose_hpoint<T: Enclose>(p: &HPoint<T>) -> IVec {
    p.coords.iter().map(Enclose::enclose).collect()
}

/// A homogeneous control net of a 3D curve or patch (four coordinates per
/// point) with `rows × cols` points, stored twice: per coordinate,
/// `coords[d][i·cols + j]` is coordinate `d` of point `(i, j)` (for
/// [`NetRef`]), and point by point, `quads[i·cols + j]` (for de Casteljau's
/// steps on all four coordinates at once).
#[derive(Clone, Debug)]
struct Net {
    rows: usize,
    cols: usize,
    coords: Vec<Vec<Interval>>,
    quads: Vec<Quad>,
    /// The points' midpoints, for evaluation in `f64`.
    mids: Vec<[f64; 4]>,
}

/// The Bernstein bases `B_i^r(t) = C(r, i) tⁱ (1 − t)^{r−i}`, `i = 0..=r`,
/// at `t` in `f64` of the degrees `n − 2`, `n − 1`, `n` and 0 — those of a
/// patch's net and its derivative nets — from one recursion
/// `B_i^r = (1 − t) B_i^{r−1} + t B_{i−1}^{r−1}` ([`bernstein_stages_into`];
/// Farin, *Curves and Surfaces for CAGD*, 5th ed., §5.1), each bit for bit
/// the basis of its degree, on the stack for degrees up to 15.
struct Bases {
    n: usize,
    /// The bases of degrees `n − 2`, `n − 1`, `n` (those `≥ 0`).
    top: [SmallVec<[f64; 16]>; 3],
}

impl Bases {
    fn new(n: usize, t: f64) -> Bases {
        let mut b: SmallVec<[f64; 16]> = SmallVec::from_elem(0.0, n + 1);
        let mut top: [SmallVec<[f64; 16]>; 3] = Default::default();
        bernstein_stages_into(&t, &mut b, |r, basis| {
            if r + 2 >= n {
                top[r + 2 - n] = SmallVec::from_slice(basis);
            }
        });
        Bases { n, top }
    }

    /// The basis of degree `r` (`0` or `n − 2 ≤ r ≤ n`).
    fn of(&self, r: usize) -> &[f64] {
        if r == 0 {
            &[1.0]
        } else {
            &self.top[r + 2 - self.n]
        }
    }
}

impl Net {
    /// The net of the points `net[i][j]` (each a homogeneous `IVec` of
    /// four coordinates).
    fn new(net: &[Vec<IVec>]) -> Net {
        let quads: Vec<Quad> = net
            .iter()
            .flatten()
            .map(|p| Quad::new([p[0], p[1], p[2], p[3]]))
            .collect();
        Net {
            rows: net.len(),
            cols: net[0].len(),
            coords: (0..4)
                .map(|d| quads.iter().map(|q| q.lane(d)).collect())
                .collect(),
            mids: quads.iter().map(Quad::mids).collect(),
            quads,
        }
    }

    /// The homogeneous point `Σ_i Σ_j B_i(u) B_j(v) H_ij` at `(u, v)` in
    /// `f64` from the midpoints (not an enclosure), the bases taken from
    /// `bu` and `bv`; each sum in index order, as `Iterator::sum`.
    fn value_f64(&self, bu: &Bases, bv: &Bases) -> [f64; 4] {
        let (bu, bv) = (bu.of(self.rows - 1), bv.of(self.cols - 1));
        let mut out = [-0.0; 4];
        for (row, a) in self.mids.chunks(self.cols).zip(bu) {
            let mut inner = [-0.0; 4];
            for (x, b) in row.iter().zip(bv) {
                for k in 0..4 {
                    inner[k] += x[k] * b;
                }
            }
            for k in 0..4 {
                out[k] += a * inner[k];
            }
        }
        out
    }

    /// [`Net::value_f64`] at `(u, v)`.
    fn value_at(&self, u: f64, v: f64) -> [f64; 4] {
        self.value_f64(&Bases::new(self.rows - 1, u), &Bases::new(self.cols - 1, v))
    }

    /// The net of the derivative in `u` (`along_u`) or in `v`: degree
    /// times the forward differences, or a single zero point for degree 0.
    fn difference(&self, along_u: bool) -> Net {
        let (rows, cols) = if along_u {
            (self.rows.saturating_sub(1), self.cols)
        } else {
            (self.rows, self.cols.saturating_sub(1))
        };
        if rows == 0 || cols == 0 {
            return Net::new(&[vec![vec![Interval::point(0.0); 4]]]);
        }
        let degree = Interval::point(if along_u { rows } else { cols } as f64);
        let step = if along_u { self.cols } else { 1 };
        let net: Vec<Vec<IVec>> = (0..rows)
            .map(|i| {
                (0..cols)
                    .map(|j| {
                        let k = i * self.cols + j;
                        self.coords
                            .iter()
                            .map(|c| c[k + step].sub(&c[k]).mul(&degree))
                            .collect()
                    })
                    .collect()
            })
            .collect();
        Net::new(&net)
    }

    /// Every point's homogeneous coordinates.
    fn points(&self) -> impl Iterator<Item = IVec> + '_ {
        self.quads.iter().map(|q| q.lanes().to_vec())
    }

    /// Range over `[u0, u1] × [v0, v1]`, per homogeneous coordinate, of
    /// the net translated by `−centre` (the coefficients `H − centre·W`,
    /// formed before the range is taken): the hull of the piece's net (the
    /// piece in `v` of every row, then in `u` of every column).
    fn range(&self, u: Interval, v: Interval, centre: &[f64]) -> IVec {
        let shift = [0, 1, 2].map(|d| centre.get(d).copied().filter(|x| *x != 0.0));
        let moved: Vec<Quad> = self
            .quads
            .iter()
            .map(|p| {
                let mut q = *p;
                for (d, x) in shift.iter().enumerate() {
                    if let Some(x) = x {
                        q.set(d, p.lane(d).sub(&Interval::point(*x).mul(&p.lane(3))));
                    }
                }
                q
            })
            .collect();
        crate::widest::run(PieceHull {
            net: &moved,
            cols: self.cols,
            u,
            v,
        })
        .lanes()
        .to_vec()
    }
}

/// The hull of the control points of the piece over `u × v` of a net
/// with `cols` points per row ([`Net::range`]'s work: the piece in `v` of
/// every row, then in `u` of every column), run on the widest vector
/// instructions the processor has ([`crate::widest`]).
struct PieceHull<'a> {
    net: &'a [Quad],
    cols: usize,
    u: Interval,
    v: Interval,
}

impl Job for PieceHull<'_> {
    type Output = Quad;

    #[inline(always)]
    fn run(self) -> Quad {
        let (u, v, cols) = (self.u, self.v, self.cols);
        let (mut rows, mut column, mut out) = (Vec::new(), Row::new(), Row::new());
        for row in self.net.chunks(cols) {
            piece(row, v.lo, v.hi, &mut out);
            rows.extend_from_slice(&out);
        }
        let mut range: Option<Quad> = None;
        // At a point `v`, every row's piece is its value repeated: the
        // columns are equal, one is enough.
        let columns = if v.lo == v.hi { 1 } else { cols };
        for j in 0..columns {
            column.clear();
            column.extend(rows.iter().skip(j).step_by(cols).copied());
            piece(&column, u.lo, u.hi, &mut out);
            let h = hull(&out);
            range = Some(range.map_or(h, |r| r.hull(&h)));
        }
        range.expect("a Bézier net is never empty")
    }
}

/// Split the homogeneous `h` into `(P, w)`.
fn split(h: &IVec) -> (&[Interval], Interval) {
    (&h[..h.len() - 1], h[h.len() - 1])
}

/// Refuse a box where the weight's enclosure reaches 0 (possible only
/// outside `[0, 1]`, the weights being checked positive).
fn positive(w: &Interval) -> Result<(), Error> {
    if w.lo > 0.0 {
        Ok(())
    } else {
        Err(Error::Domain(format!(
            "the weight's enclosure [{:e}, {:e}] over a parameter box is not positive",
            w.lo, w.hi
        )))
    }
}

/// Refuse non-positive weights (their enclosures must be positive).
fn check_weights(weights: impl IntoIterator<Item = IVec>) -> Result<(), Error> {
    for (k, h) in weights.into_iter().enumerate() {
        let w = h[h.len() - 1];
        if w.lo <= 0.0 {
            return Err(Error::Weight {
                index: format!("w_{k}"),
                value: format!("enclosed by [{:e}, {:e}]", w.lo, w.hi),
            });
        }
    }
    Ok(())
}

/// `(P − Σ wᵢ Yᵢ) / w`: the quotient rule's common step.
fn quotient(p: &[Interval], terms: &[(Interval, &[Interval])], w: &Interval) -> IVec {
    p.iter()
        .enumerate()
        .map(|(k, pk)| {
            let num = terms
                .iter()
                .fold(*pk, |acc, (wi, y)| acc.sub(&wi.mul(&y[k])));
            num.div(w).expect("the weight enclosure is positive")
        })
        .collect()
}

/// A rational Bézier curve with enclosed control points of `H` and `H'`.
#[derive(Clone, Debug)]
pub struct ICurve {
    h: Net,
    dh: Net,
    ddh: Net,
}

/// A curve's point, tangent and second derivative enclosed over a parameter
/// interval.
#[derive(Clone, Debug)]
pub struct CurveJet {
    /// `C(t)`.
    pub x: IVec,
    /// `C'(t)`.
    pub dx: IVec,
    /// `C''(t)`.
    pub ddx: IVec,
}

impl ICurve {
    /// Enclose `c` (dimension 3, positive weights): its homogeneous control
    /// points and those of its first and second hodographs, formed exactly
    /// then enclosed.
    ///
    /// # Errors
    ///
    /// [`Error::Shape`] unless the curve is in 3D; [`Error::Weight`] for a
    /// weight whose enclosure is not positive.
    pub fn new<T: Scalar + Enclose>(c: &RationalCurve<T>) -> Result<ICurve, Error> {
        if c.dim() != 3 {
            return Err(Error::Shape(format!(
                "an edge curve in {}D, not 3D",
                c.dim()
            )));
        }
        let column = |points: &[HPoint<T>]| {
            if points.is_empty() {
                Net::new(&[vec![vec![Interval::point(0.0); 4]]])
            } else {
                Net::new(
                    &points
                        .iter()
                        .map(|p| vec![enclose_hpoint(p)])
                        .collect::<Vec<_>>(),
                )
            }
        };
        let h = column(c.ctrl());
        check_weights(h.points())?;
        Ok(ICurve {
            h,
            dh: column(&c.hodograph(1)),
            ddh: column(&c.hodograph(2)),
        })
    }

    /// The Bernstein coefficients of the homogeneous coordinates (`x, y, z,
    /// w`) of the piece over `t` (`t.lo ≤ t.hi`), enclosed.
    pub fn piece_over(&self, t: Interval) -> Vec<Vec<Interval>> {
        let mut out = Row::new();
        piece(&self.h.quads, t.lo, t.hi, &mut out);
        (0..4)
            .map(|d| out.iter().map(|q| q.lane(d)).collect())
            .collect()
    }

    /// `C(t)` in `f64` arithmetic: *not* an enclosure (point intervals near
    /// the point), for Newton's guesses; `None` where the weight is not
    /// positive.
    pub fn approximate_point(&self, t: f64) -> Option<IVec> {
        let h = self.h.value_at(t, 0.0);
        (h[3] > 0.0).then(|| h[..3].iter().map(|x| Interval::point(x / h[3])).collect())
    }

    /// `C`, `C'` and `C''` over all parameters in `t` (enclosures):
    /// `C'' = (P'' − 2w'C' − w''C)/w`, on the net translated by the
    /// curve's point at the middle of `t` (as [`IPatch::jet`]).
    ///
    /// # Errors
    ///
    /// [`Error::Domain`] when the weight's enclosure reaches 0 there.
    pub fn jet(&self, t: Interval) -> Result<CurveJet, Error> {
        let point = Interval::point(0.0);
        let centre: Vec<f64> = self
            .approximate_point(t.mid())
            .filter(|c| c.iter().all(|x| x.mid().is_finite()))
            .map_or_else(Vec::new, |c| c.iter().map(Interval::mid).collect());
        let [h, dh, ddh] = [&self.h, &self.dh, &self.ddh].map(|n| n.range(t, point, &centre));
        let ((p, w), (dp, dw), (ddp, ddw)) = (split(&h), split(&dh), split(&ddh));
        positive(&w)?;
        let x = quotient(p, &[], &w);
        let dx = quotient(dp, &[(dw, &x)], &w);
        let ddx = quotient(ddp, &[(dw.mul(&Interval::point(2.0)), &dx), (ddw, &x)], &w);
        let x = x
            .iter()
            .zip(centre.iter().chain(std::iter::repeat(&0.0)))
            .map(|(x, c)| x.add(&Interval::point(*c)))
            .collect();
        Ok(CurveJet { x, dx, ddx })
    }
}

/// A rational patch with enclosed control nets of `H` and its partial
/// derivatives up to order 2.
#[derive(Clone, Debug)]
pub struct IPatch {
    /// Nets of `H`, `H_u`, `H_v`, `H_uu`, `H_uv`, `H_vv`.
    nets: [Net; 6],
}

/// A patch's point and derivatives up to order 2, enclosed over a box.
#[derive(Clone, Debug)]
pub struct PatchJet {
    /// `S`.
    pub x: IVec,
    /// `S_u`.
    pub xu: IVec,
    /// `S_v`.
    pub xv: IVec,
    /// `S_uu`.
    pub xuu: IVec,
    /// `S_uv`.
    pub xuv: IVec,
    /// `S_vv`.
    pub xvv: IVec,
}

impl PatchJet {
    /// The jet of `[S, S_u, S_v, S_uu, S_uv, S_vv]`.
    pub fn from_parts([x, xu, xv, xuu, xuv, xvv]: [IVec; 6]) -> PatchJet {
        PatchJet {
            x,
            xu,
            xv,
            xuu,
            xuv,
            xvv,
        }
    }
}

const ORDERS: [(usize, usize); 6] = [(0, 0), (1, 0), (0, 1), (2, 0), (1, 1), (0, 2)];

impl IPatch {
    /// Enclose `r` (dimension 3): its homogeneous net and its derivative
    /// nets, formed exactly then enclosed.
    ///
    /// # Errors
    ///
    /// [`Error::Shape`] unless the patch is in 3D; [`Error::Weight`] for a
    /// weight whose enclosure is not positive.
    pub fn new<T: Scalar + Enclose>(r: &RectPatch<T>) -> Result<IPatch, Error> {
        if r.dim() != 3 {
            return Err(Error::Shape(format!(
                "a face patch in {}D, not 3D",
                r.dim()
            )));
        }
        let net = |(a, b): (usize, usize)| -> Net {
            match r.derivative_patch(a, b) {
                Some(d) => Net::new(
                    &d.ctrl()
                        .iter()
                        .map(|row| row.iter().map(enclose_hpoint).collect())
                        .collect::<Vec<_>>(),
                ),
                None => Net::new(&[vec![vec![Interval::point(0.0); 4]]]),
            }
        };
        let nets = ORDERS.map(net);
        check_weights(nets[0].points())?;
        Ok(IPatch { nets })
    }

    /// The enclosed homogeneous control net (rows along `u`).
    pub fn homogeneous(&self) -> NetRef<'_> {
        let [h, ..] = self.first_order_nets();
        h
    }

    /// The enclosed homogeneous nets of `H`, `H_u` and `H_v`.
    pub fn first_order_nets(&self) -> [NetRef<'_>; 3] {
        [0, 1, 2].map(|k| {
            let h = &self.nets[k];
            NetRef {
                rows: h.rows,
                cols: h.cols,
                coords: &h.coords,
            }
        })
    }

    /// Enclose `r` (dimension 3) as [`IPatch::new`] does, but form the
    /// derivative nets from the enclosed net in interval arithmetic
    /// (forward differences: `H_u` has the points `m(H_{i+1,j} − H_{ij})`,
    /// and so on). A little wider where control points nearly coincide,
    /// and far cheaper for control points that are long rationals (the
    /// Bézier pieces of a B-spline surface with decimal knots: the 1 790
    /// pieces tail_section_asm.stp's audit encloses took 6.5 s with exact
    /// derivative nets, under 1 ms so).
    ///
    /// # Errors
    ///
    /// Those of [`IPatch::new`].
    pub fn with_enclosed_derivatives<T: Scalar + Enclose>(
        r: &RectPatch<T>,
    ) -> Result<IPatch, Error> {
        if r.dim() != 3 {
            return Err(Error::Shape(format!(
                "a face patch in {}D, not 3D",
                r.dim()
            )));
        }
        let h = Net::new(
            &r.ctrl()
                .iter()
                .map(|row| row.iter().map(enclose_hpoint).collect())
                .collect::<Vec<_>>(),
        );
        check_weights(h.points())?;
        let (hu, hv) = (h.difference(true), h.difference(false));
        let nets = [
            h,
            hu.clone(),
            hv.clone(),
            hu.difference(true),
            hu.difference(false),
            hv.difference(false),
        ];
        Ok(IPatch { nets })
    }

    /// `S` and its derivatives over all `(u, v)` in the box `u × v`.
    ///
    /// # Errors
    ///
    /// [`Error::Domain`] when the weight's enclosure reaches 0 there.
    ///
    /// The nets are first translated by the point `c` of the surface at the
    /// box's centre (in `f64`; any `c` is exact, `S_u` and the others do
    /// not move): the quotient rule's `P_u − w_u·S` then subtracts small
    /// numbers, where far from the origin it would subtract two wide
    /// enclosures of large ones (a patch 80 units from the origin: widths
    /// of 20 on a box 1/16 wide, against 10⁻¹ when centred).
    pub fn jet(&self, u: Interval, v: Interval) -> Result<PatchJet, Error> {
        let centre = self
            .approximate_point(u.mid(), v.mid())
            .filter(|c| c.iter().all(|x| x.is_finite()))
            .unwrap_or([0.0; 3]);
        let mut jet = cartesian(self.nets.each_ref().map(|n| n.range(u, v, &centre)))?;
        for (x, c) in jet.x.iter_mut().zip(centre) {
            *x = x.add(&Interval::point(c));
        }
        Ok(jet)
    }

    /// `S` and its derivatives at `(u, v)` in `f64` arithmetic: *not* an
    /// enclosure (point intervals near the values), for Newton's guesses.
    ///
    /// # Errors
    ///
    /// [`Error::Domain`] when the weight there is not positive.
    pub fn approximate_jet(&self, u: f64, v: f64) -> Result<PatchJet, Error> {
        Ok(PatchJet::from_parts(
            self.jet_f64(u, v)?
                .map(|a| a.iter().map(|c| Interval::point(*c)).collect()),
        ))
    }

    /// [`IPatch::approximate_jet`] as plain numbers ([`Jet64`]).
    ///
    /// # Errors
    ///
    /// [`Error::Domain`] when the weight there is not positive.
    pub fn jet_f64(&self, u: f64, v: f64) -> Result<Jet64, Error> {
        let h = &self.nets[0];
        let (bu, bv) = (Bases::new(h.rows - 1, u), Bases::new(h.cols - 1, v));
        cartesian_f64(self.nets.each_ref().map(|n| n.value_f64(&bu, &bv)))
    }

    /// `S(u, v)` in `f64` arithmetic: *not* an enclosure; `None` where the
    /// weight is not positive or the point not finite.
    pub fn approximate_point(&self, u: f64, v: f64) -> Option<[f64; 3]> {
        let h = self.nets[0].value_at(u, v);
        let w = h[3];
        let x = [0, 1, 2].map(|k| h[k] / w);
        (w > 0.0 && x.iter().all(|c| c.is_finite())).then_some(x)
    }
}

/// The Cartesian jet from the homogeneous `H`, `H_u`, `H_v`, `H_uu`,
/// `H_uv`, `H_vv` by the quotient rule.
fn cartesian([h, hu, hv, huu, huv, hvv]: [IVec; 6]) -> Result<PatchJet, Error> {
    let (p, w) = split(&h);
    positive(&w)?;
    let [(pu, wu), (pv, wv), (puu, wuu), (puv, wuv), (pvv, wvv)] =
        [&hu, &hv, &huu, &huv, &hvv].map(split);
    let x = quotient(p, &[], &w);
    let xu = quotient(pu, &[(wu, &x)], &w);
    let xv = quotient(pv, &[(wv, &x)], &w);
    let two = Interval::point(2.0);
    let xuu = quotient(puu, &[(wu.mul(&two), &xu), (wuu, &x)], &w);
    let xuv = quotient(puv, &[(wu, &xv), (wv, &xu), (wuv, &x)], &w);
    let xvv = quotient(pvv, &[(wv.mul(&two), &xv), (wvv, &x)], &w);
    Ok(PatchJet::from_parts([x, xu, xv, xuu, xuv, xvv]))
}

/// A patch's point and derivatives up to order 2 at a point in `f64` (not
/// an enclosure): `[S, S_u, S_v, S_uu, S_uv, S_vv]`.
pub type Jet64 = [[f64; 3]; 6];

/// [`cartesian`] in `f64` (not an enclosure): the same quotient rule on
/// the homogeneous values.
fn cartesian_f64([h, hu, hv, huu, huv, hvv]: [[f64; 4]; 6]) -> Result<Jet64, Error> {
    let w = h[3];
    if w.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
        return Err(Error::Domain(format!(
            "the weight {w:e} at a point is not positive"
        )));
    }
    let rule = |p: &[f64; 4], terms: &[(f64, &[f64; 3])]| -> [f64; 3] {
        [0, 1, 2].map(|k| (terms.iter().fold(p[k], |a, (wi, y)| a - wi * y[k])) / w)
    };
    let x = rule(&h, &[]);
    let xu = rule(&hu, &[(hu[3], &x)]);
    let xv = rule(&hv, &[(hv[3], &x)]);
    let xuu = rule(&huu, &[(2.0 * hu[3], &xu), (huu[3], &x)]);
    let xuv = rule(&huv, &[(hu[3], &xv), (hv[3], &xu), (huv[3], &x)]);
    let xvv = rule(&hvv, &[(2.0 * hv[3], &xv), (hvv[3], &x)]);
    Ok([x, xu, xv, xuu, xuv, xvv])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bernstein::bernstein_all_into;
    use num_rational::BigRational;
    use proptest::prelude::*;

    /// The blossom `c[a^{n−k}, b^k]` exactly: de Casteljau's recursion with
    /// the arguments `a` first, then `b` (the route [`piece`] does not take).
    fn blossom(c: &[i64], a: &BigRational, b: &BigRational, k: usize) -> BigRational {
        let n = c.len() - 1;
        let mut v: Vec<BigRational> = c
            .iter()
            .map(|&x| BigRational::from_integer(x.into()))
            .collect();
        for level in 0..n {
            let t = if level < n - k { a } else { b };
            let s = BigRational::from_integer(1.into()) - t;
            v = v.windows(2).map(|w| &w[0] * &s + &w[1] * t).collect();
        }
        v.swap_remove(0)
    }

    /// A rational patch of degree `(m, n)` from small integers, weights in
    /// `1..=4`.
    fn patch(m: usize, n: usize, seed: &[i64]) -> RectPatch<BigRational> {
        let q = |k: usize| BigRational::from_integer(seed[k % seed.len()].into());
        let points = (0..=m)
            .map(|i| {
                (0..=n)
                    .map(|j| (0..3).map(|d| q(7 * i + 3 * j + d)).collect())
                    .collect()
            })
            .collect();
        let weights = (0..=m)
            .map(|i| {
                (0..=n)
                    .map(|j| {
                        BigRational::from_integer(
                            (1 + (seed[(i + j) % seed.len()].rem_euclid(4))).into(),
                        )
                    })
                    .collect()
            })
            .collect();
        RectPatch::new(points, weights).unwrap()
    }

    proptest! {
        /// The `f64` jet (Bernstein basis on the net, the quotient rule in
        /// `f64`) lies within a relative `10⁻⁹` of the jet enclosed over
        /// the point box (interval de Casteljau on the exact derivative
        /// nets: another route).
        #[test]
        fn approximate_jet_is_near_the_enclosed_jet(
            m in 1usize..=4, n in 1usize..=4,
            seed in proptest::collection::vec(-20i64..=20, 5..=12),
            u in 0i64..=64, v in 0i64..=64,
        ) {
            let p = IPatch::new(&patch(m, n, &seed)).unwrap();
            let (u, v) = (u as f64 / 64.0, v as f64 / 64.0);
            let got = p.approximate_jet(u, v).unwrap();
            let want = p.jet(Interval::point(u), Interval::point(v)).unwrap();
            let pairs = [(&got.x, &want.x), (&got.xu, &want.xu), (&got.xv, &want.xv),
                (&got.xuu, &want.xuu), (&got.xuv, &want.xuv), (&got.xvv, &want.xvv)];
            for (g, w) in pairs {
                for (a, b) in g.iter().zip(w) {
                    let slack = 1e-9 * (1.0 + b.mag());
                    prop_assert!(a.lo >= b.lo - slack && a.hi <= b.hi + slack, "{:?} vs {:?}", a, b);
                }
            }
        }

        /// The `f64` value of a net from the shared bases is bit for bit
        /// the double sum taken coordinate by coordinate with bases of the
        /// net's own degrees (`Iterator::sum`).
        #[test]
        fn value_from_shared_bases_is_the_plain_double_sum(
            m in 1usize..=5, n in 1usize..=5,
            seed in proptest::collection::vec(-20i64..=20, 5..=12),
            u in -0.5f64..1.5, v in -0.5f64..1.5,
        ) {
            let p = IPatch::new(&patch(m, n, &seed)).unwrap();
            let (bu, bv) = (Bases::new(m, u), Bases::new(n, v));
            for net in &p.nets {
                let basis = |r: usize, t: f64| {
                    let mut b = vec![0.0; r + 1];
                    bernstein_all_into(&t, &mut b);
                    b
                };
                let (au, av) = (basis(net.rows - 1, u), basis(net.cols - 1, v));
                let got = net.value_f64(&bu, &bv);
                for (d, c) in net.coords.iter().enumerate() {
                    let want: f64 = c
                        .chunks(net.cols)
                        .zip(&au)
                        .map(|(row, a)| a * row.iter().zip(&av).map(|(x, b)| x.mid() * b).sum::<f64>())
                        .sum();
                    prop_assert_eq!(got[d].to_bits(), want.to_bits());
                }
            }
        }

        /// Every control point of the piece encloses the exact blossom
        /// value, in each lane (the coefficients `c`, `−c`, `3c` and `c − 7`),
        /// for parameters inside and outside `[0, 1]`, and a point piece is
        /// the value there. The width is that of rounding: at most
        /// `10⁻¹³ (1 + max |c|) g` with `g = ∏ (|1 − t| + |t|)ⁿ` over the
        /// two subdivision parameters `t`, the factor by which de
        /// Casteljau's steps can magnify a coefficient's error when they
        /// extrapolate (`g = 1` inside `[0, 1]`).
        #[test]
        fn piece_encloses_the_exact_blossom_values(
            c in proptest::collection::vec(-1000i64..=1000, 1..=9),
            ends in (-64i64..=128, -64i64..=128),
        ) {
            let (lo, hi) = (ends.0.min(ends.1), ends.0.max(ends.1));
            let (a, b) = (lo as f64 / 64.0, hi as f64 / 64.0);
            let exact = |x: i64| BigRational::new(x.into(), 64.into());
            let lanes = |x: i64| [x, -x, 3 * x, x - 7];
            let points: Vec<Quad> = c
                .iter()
                .map(|&x| Quad::new(lanes(x).map(|y| Interval::point(y as f64))))
                .collect();
            let mut out = Row::new();
            piece(&points, a, b, &mut out);
            prop_assert_eq!(out.len(), c.len());
            let (first, second) = if a == b {
                (a, 0.0)
            } else if b >= 0.5 {
                (b, a / b)
            } else {
                (a, (b - a) / (1.0 - a))
            };
            let growth = [first, second]
                .map(|t| ((1.0 - t).abs() + t.abs()).powi(c.len() as i32 - 1))
                .iter()
                .product::<f64>();
            let largest = c.iter().map(|x| (3 * x.abs() + 7) as f64).fold(0.0, f64::max);
            let rounding = 1e-13 * (1.0 + largest) * growth;
            for d in 0..4 {
                let lane: Vec<i64> = c.iter().map(|&x| lanes(x)[d]).collect();
                for (k, got) in out.iter().map(|q| q.lane(d)).enumerate() {
                    let want = blossom(&lane, &exact(lo), &exact(hi), k);
                    let inside = BigRational::from_float(got.lo).unwrap() <= want
                        && want <= BigRational::from_float(got.hi).unwrap();
                    prop_assert!(inside, "lane {}, k = {}: {:?} misses {}", d, k, got, want);
                    prop_assert!(got.width() <= rounding, "{:?} wider than {}", got, rounding);
                }
            }
        }
    }
}
