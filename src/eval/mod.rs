//! Batch evaluation: a control net in one contiguous buffer, evaluated at
//! many parameters into a caller's buffer with a reusable workspace.
//!
//! A [`Net`] holds the homogeneous control points `(w·P, w)` of a curve, a
//! rect or a tri patch back to back, `stride = dim + 1` scalars each, and
//! the same points times their Bernstein coefficients (binomial or
//! trinomial), which the kernel sums. Evaluation is the homogeneous
//! Horner–Bernstein scheme, O(n) per point for a curve instead of de
//! Casteljau's O(n²), with ring operations only:
//!
//! ```text
//! curve:  G_i = C(n,i) H_i,              H(a : b) = Σ_i a^{n−i} bⁱ G_i
//!                                                 = (…((G_0·a + b G_1)·a + b² G_2)·a + …)
//! rect:   G_ij = C(m,i) C(n,j) H_ij,     H(u, v)  = Σ_i (1−u)^{m−i} uⁱ [Σ_j (1−v)^{n−j} vʲ G_ij]
//! tri:    G_ij = n!/(i! j! k!) H_ijk,    H(u, v, w) = Σ_j vʲ [Σ_i uⁱ w^{n−j−i} G_ij]
//!         (k = n − i − j;  n!/(i! j! k!) = C(n,j)·C(n−j,i))
//! X = H_d / H_w        (reduced at the end, one big gcd per point)
//! ```
//!
//! At `(a : b) = (1 − t : t)` the curve sum is `X(t)` in homogeneous form;
//! at `(q − p : p)` for `t = p/q` it is `qⁿ` times it, with integer
//! arithmetic throughout when the net is integral. That is how exact
//! evaluation stays fraction-free: [`Evaluator::eval_batch`] recognises
//! `BigRational` (by its type id), clears the denominators of the net
//! once, runs the same kernel on the narrowest integer type that provably holds its
//! values (`i128`, [`Wide`](crate::algebra::Wide),
//! [`Wide512`](crate::algebra::Wide512) or [`Int`](crate::algebra::Int): no
//! gcd, no allocation below 512 bits) and
//! reduces the point's coordinates over their common weight with one gcd
//! of the weight's size (`fraction_free`). Curves of high degree
//! keep one denominator per block of control points instead (`blocks`), so
//! that their block sums stay within 256 bits.
//!
//! [`Jets`] evaluate the first derivatives (`H'`, or `H_u`, `H_v`) the same
//! way, on difference nets, in batch.
//!
//! `f64` batches of nets of stride 3 or 4 run the kernel lane-major
//! (`lanes`): eight points at once, each value an array of eight `f64`
//! that the compiler vectorises, with the scalar kernel's operations in
//! its order, so the values are the same bit for bit; with the feature
//! `simd` also compiled for AVX-512 and for AVX2 (the widest the processor
//! has, chosen at run time; there curves, tri patches and bicubics go by
//! loops of their own in `pulp`'s vectors, the same operations), where
//! each multiply–add is fused: the values
//! then differ from the scalar kernel's within the tolerance that `lanes`
//! derives (a few ulps of the sum of absolute terms).
//!
//! For `f64` the scheme is the one of dhermes/bezier's `evaluate_multi`;
//! its rounding differs from de Casteljau's by a few ulps times the size of
//! the binomial-weighted terms (tests compare the two within `1e-12`
//! relative on nets of size 1 up to degree 40).
//!
//! In steady state ([`Evaluator::eval_into`] with a reused evaluator,
//! [`Evaluator::eval_batch`], [`Jets::eval_batch`]) an `f64` evaluation
//! makes no heap allocation (tests/alloc.rs counts them).
//!
//! Reference: the scheme is the "VS algorithm", W. Schumaker and W. Volk,
//! *Efficient evaluation of multivariate polynomials*, CAGD 3 (1986); the
//! homogeneous form avoids its division by `1 − t`.

mod blocks;
mod fraction_free;
mod jet;
mod lanes;

pub use jet::{Jet, Jets};

use crate::algebra::scalar::{pow, Field, MulAcc, Ring};
use crate::error::Error;
use crate::hpoint::HPoint;
use std::sync::OnceLock;

/// The shape of a [`Net`]: which Bernstein sum it evaluates.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Shape {
    /// A curve of degree `n`: `n + 1` points.
    Curve(usize),
    /// A rect patch of bidegree `(m, n)`: `(m + 1)(n + 1)` points, row `i`
    /// (the u index) holding the `n + 1` points of index `(i, 0) … (i, n)`.
    Rect(usize, usize),
    /// A tri patch of degree `n`: rows `j = 0 … n` of `n − j + 1` points
    /// `P_{i,j,k}`, `i = 0 … n − j` (the layout of
    /// [`TriPatch::rows`](crate::TriPatch::rows)).
    Tri(usize),
}

impl Shape {
    /// How many control points a net of this shape has.
    pub fn points(&self) -> usize {
        match *self {
            Shape::Curve(n) => n + 1,
            Shape::Rect(m, n) => (m + 1) * (n + 1),
            Shape::Tri(n) => (n + 1) * (n + 2) / 2,
        }
    }

    /// How many parameters a point takes: 1 for a curve, 2 for a patch.
    pub fn params(&self) -> usize {
        match self {
            Shape::Curve(_) => 1,
            _ => 2,
        }
    }

    /// The largest degree, which sizes the table of binomials.
    fn max_degree(&self) -> usize {
        match *self {
            Shape::Curve(n) | Shape::Tri(n) => n,
            Shape::Rect(m, n) => m.max(n),
        }
    }
}

/// A control net as one contiguous buffer of homogeneous coordinates,
/// with the same points times their Bernstein coefficients.
///
/// # Examples
///
/// ```
/// use exact_bezier::{eval::Net, RationalCurve, ratio};
/// use exact_bezier::BigRational;
/// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
/// let c = RationalCurve::polynomial(vec![p(10, 0), p(30, 60), p(130, 60), p(190, 0)]).unwrap();
/// let net = Net::from_curve(&c);
/// assert_eq!(net.stride(), 3);
/// // (1 − t : t) = (1 : 1) is t = 1/2 times 2³: the quiz point (85, 45), homogeneous.
/// let mut h = vec![ratio(0, 1); 3];
/// net.eval_hom_into(&[ratio(1, 1), ratio(1, 1)], &mut h, &mut net.workspace());
/// assert_eq!(h, vec![ratio(680, 1), ratio(360, 1), ratio(8, 1)]);
/// ```
#[derive(Clone, Debug)]
pub struct Net<T> {
    coords: Vec<T>,
    /// `coords` with each point times its Bernstein coefficient (`G` in
    /// the module's formulas): what the kernel sums, computed on first use
    /// (exact evaluation reads only `coords`).
    scaled: OnceLock<Vec<T>>,
    stride: usize,
    shape: Shape,
}

impl<T: PartialEq> PartialEq for Net<T> {
    /// Nets are equal when their shapes and points are.
    fn eq(&self, other: &Self) -> bool {
        (self.shape, self.stride) == (other.shape, other.stride) && self.coords == other.coords
    }
}

/// # Construction
impl<T: Ring> Net<T> {
    /// The net of `shape` from its homogeneous coordinates, `stride` per point.
    ///
    /// # Errors
    ///
    /// [`Error::Shape`] if `coords` does not hold `shape.points()` points of
    /// `stride ≥ 2` coordinates.
    pub fn new(coords: Vec<T>, stride: usize, shape: Shape) -> Result<Self, Error> {
        if stride < 2 || coords.len() != shape.points() * stride {
            return Err(Error::Shape(format!(
                "a {shape:?} net of stride {stride} needs {} coordinates, not {}",
                shape.points() * stride,
                coords.len()
            )));
        }
        Ok(Net::with_coords(coords, stride, shape))
    }

    /// The net of `shape` from homogeneous points `(w·P, w)`, in the order
    /// of [`Shape`]. The nets of curves and patches are
    /// [`Net::from_curve`], [`Net::from_rect`] and [`Net::from_tri`].
    ///
    /// # Errors
    ///
    /// [`Error::Shape`] if the points differ in length, or are not
    /// `shape.points()` points of at least 2 coordinates.
    ///
    /// ```
    /// use exact_bezier::eval::{Net, Shape};
    /// use exact_bezier::hpoint::HPoint;
    /// let h = |x: f64, w: f64| HPoint { coords: vec![x * w, w] };
    /// let net = Net::from_points(&[h(0.0, 1.0), h(1.0, 2.0)], Shape::Curve(1)).unwrap();
    /// assert_eq!(net.coords(), &[0.0, 1.0, 2.0, 2.0]);
    /// assert!(Net::from_points(&[h(0.0, 1.0)], Shape::Curve(1)).is_err());
    /// ```
    pub fn from_points<'a>(
        points: impl IntoIterator<Item = &'a HPoint<T>>,
        shape: Shape,
    ) -> Result<Self, Error> {
        let mut coords = Vec::with_capacity(shape.points() * 4);
        let mut stride = None;
        for p in points {
            if *stride.get_or_insert(p.coords.len()) != p.coords.len() {
                return Err(Error::Shape(format!(
                    "the points of a {shape:?} net differ in length"
                )));
            }
            coords.extend(p.coords.iter().cloned());
        }
        Net::new(coords, stride.unwrap_or(0), shape)
    }
}

/// # Access
impl<T> Net<T> {
    /// Coordinates per point: the dimension plus one (the weight, last).
    pub fn stride(&self) -> usize {
        self.stride
    }

    /// The spatial dimension, `stride − 1`.
    pub fn dim(&self) -> usize {
        self.stride - 1
    }

    /// The shape of the net.
    pub fn shape(&self) -> Shape {
        self.shape
    }

    /// All homogeneous coordinates, point after point.
    pub fn coords(&self) -> &[T] {
        &self.coords
    }

    /// The net of the same shape and stride with the coordinates `coords`
    /// (e.g. the integers of this net over a common denominator, in another
    /// ring).
    ///
    /// **Panics if `coords` is not as long as [`Net::coords`].**
    pub fn map_coords<U: Ring>(&self, coords: Vec<U>) -> Net<U> {
        assert_eq!(
            coords.len(),
            self.coords.len(),
            "a mapped net keeps its size"
        );
        Net::with_coords(coords, self.stride, self.shape)
    }
}

impl<T: Ring> Net<T> {
    /// The net of validated `coords`.
    fn with_coords(coords: Vec<T>, stride: usize, shape: Shape) -> Self {
        Net {
            coords,
            scaled: OnceLock::new(),
            stride,
            shape,
        }
    }

    /// Each point times its Bernstein coefficient, `C(n,i)`,
    /// `C(m,i)·C(n,j)` or `C(n,j)·C(n−j,i)` (in the order of [`Shape`]).
    fn scaled(&self) -> &[T] {
        self.scaled.get_or_init(|| {
            let table = pascal::<T>(self.shape.max_degree());
            let c = |k: usize, i: usize| &table[k * (k + 1) / 2 + i];
            let mut scaled = Vec::with_capacity(self.coords.len());
            let mut points = self.coords.chunks_exact(self.stride);
            let mut push = |f: T| {
                let point = points.next().expect("one point per coefficient");
                scaled.extend(point.iter().map(|x| f.clone() * x));
            };
            match self.shape {
                Shape::Curve(n) => {
                    for i in 0..=n {
                        push(c(n, i).clone());
                    }
                }
                Shape::Rect(m, n) => {
                    for i in 0..=m {
                        for j in 0..=n {
                            push(c(m, i).clone() * c(n, j));
                        }
                    }
                }
                Shape::Tri(n) => {
                    for j in 0..=n {
                        for i in 0..=n - j {
                            push(c(n, j).clone() * c(n - j, i));
                        }
                    }
                }
            }
            scaled
        })
    }
}

/// Rows `0 … n` of Pascal's triangle by additions alone (so the table
/// exists in every ring, the integers included).
fn pascal<T: Ring>(n: usize) -> Vec<T> {
    let mut table: Vec<T> = Vec::with_capacity((n + 1) * (n + 2) / 2);
    for k in 0..=n {
        let prev = k.saturating_sub(1) * k / 2;
        for i in 0..=k {
            let value = if i == 0 || i == k {
                T::one()
            } else {
                table[prev + i - 1].clone() + &table[prev + i]
            };
            table.push(value);
        }
    }
    table
}

/// Scratch space for [`Net::eval_hom_into`]: the partial sums of the rows
/// of a patch and of one block of a blocked Horner sum (sized on first
/// use), `stride` scalars each, reused for every point.
#[derive(Clone, Debug)]
pub struct Workspace<T> {
    rows: Vec<T>,
    block: Vec<T>,
}

/// # Evaluation (ring operations only)
impl<T: MulAcc> Net<T> {
    /// A workspace sized for this net.
    pub fn workspace(&self) -> Workspace<T> {
        let rows = match self.shape {
            Shape::Curve(_) => 0,
            Shape::Rect(m, _) => m + 1,
            Shape::Tri(_) => 1,
        };
        Workspace {
            rows: vec![T::zero(); rows * self.stride],
            block: Vec::new(),
        }
    }

    /// The homogeneous point at homogeneous parameters, written into `out`
    /// (`stride` scalars): `(a, b)` for a curve (`t = b/(a + b)`),
    /// `(a_u, b_u, a_v, b_v)` for a rect, `(u, v, w)` barycentric for a tri
    /// patch. The value is `(a + b)ⁿ` (curve), `(a_u + b_u)^m (a_v + b_v)ⁿ`
    /// (rect) or `(u + v + w)ⁿ` (tri) times the homogeneous point at the
    /// affine parameter: the same projective point.
    ///
    /// **Panics if `hom` has the wrong length for the shape** (2, 4 or 3),
    /// or `out` is not `stride` long.
    pub fn eval_hom_into(&self, hom: &[T], out: &mut [T], ws: &mut Workspace<T>) {
        self.eval_hom_blocked(hom, out, ws, |_, _| 1);
    }

    /// [`Net::eval_hom_into`] with each Horner sum at a homogeneous
    /// parameter `(a : b)` taken in blocks of `block(a, b)` points
    /// ([`horner`]): the same values, faster for big integers at
    /// machine-word parameters (the fraction-free kernel's `Int` lane).
    pub(crate) fn eval_hom_blocked(
        &self,
        hom: &[T],
        out: &mut [T],
        ws: &mut Workspace<T>,
        block: impl Fn(&T, &T) -> usize + Copy,
    ) {
        let s = self.stride;
        let sum = |points: &[T], a: &T, b: &T, out: &mut [T], scratch: &mut Vec<T>| {
            horner(points, s, a, b, block(a, b), out, scratch)
        };
        match self.shape {
            Shape::Curve(_) => sum(self.scaled(), &hom[0], &hom[1], out, &mut ws.block),
            Shape::Rect(_, n) => {
                let row_len = (n + 1) * s;
                for (row, out) in self
                    .scaled()
                    .chunks_exact(row_len)
                    .zip(ws.rows.chunks_mut(s))
                {
                    sum(row, &hom[2], &hom[3], out, &mut ws.block);
                }
                sum(&ws.rows, &hom[0], &hom[1], out, &mut ws.block);
            }
            Shape::Tri(n) => self.tri_into(n, hom, out, ws, block),
        }
    }

    /// `Σ_j vʲ R_j` with `R_j = Σ_i uⁱ w^{n−j−i} G_ij`.
    fn tri_into(
        &self,
        n: usize,
        hom: &[T],
        out: &mut [T],
        ws: &mut Workspace<T>,
        block: impl Fn(&T, &T) -> usize,
    ) {
        let (u, v, w) = (&hom[0], &hom[1], &hom[2]);
        let s = self.stride;
        let mut start = 0;
        let mut vpow = T::one();
        for j in 0..=n {
            let len = (n - j + 1) * s;
            horner(
                &self.scaled()[start..start + len],
                s,
                w,
                u,
                block(w, u),
                &mut ws.rows,
                &mut ws.block,
            );
            start += len;
            for (o, r) in out.iter_mut().zip(&ws.rows) {
                *o = if j == 0 {
                    r.clone()
                } else {
                    std::mem::replace(o, T::zero()) + &(vpow.clone() * r)
                };
            }
            if j < n {
                vpow = vpow * v;
            }
        }
    }
}

/// `Σ_i a^{n−i} bⁱ G_i` by Horner in `a`, into `out`: the points `G_i`
/// (already times their binomials) are the `stride`-long chunks of
/// `points`.
///
/// For blocks of `k > 1` points (big integers at machine-word parameters,
/// see `fraction_free`), the sum goes block by block, `block` holding one
/// block's sum:
///
/// ```text
/// C_j = Σ_{r<k_j} a^{k_j−1−r} bʳ G_{s_j+r}        (powers of a, b below k: machine words)
/// acc ← acc·a^{k_j} + b^{s_j}·C_j                   (s_j = first index of block j)
/// ```
///
/// so that a product of two big numbers (`b^{s_j}·C_j`) comes once per
/// block instead of once per point.
fn horner<T: MulAcc>(
    points: &[T],
    stride: usize,
    a: &T,
    b: &T,
    k: usize,
    out: &mut [T],
    block: &mut Vec<T>,
) {
    if k <= 1 {
        return horner_lanes::<T, 1>(points, stride, [a], [b], out);
    }
    block.resize(stride, T::zero());
    let (a_k, b_k) = (pow(a, k as u32), pow(b, k as u32));
    let mut b_start = T::one();
    for (j, chunk) in points.chunks(k * stride).enumerate() {
        horner_lanes::<T, 1>(chunk, stride, [a], [b], block);
        if j == 0 {
            out.swap_with_slice(block);
        } else {
            let len = chunk.len() / stride;
            let a_len = if len == k {
                a_k.clone()
            } else {
                pow(a, len as u32)
            };
            for (o, c) in out.iter_mut().zip(block.iter()) {
                T::mul_acc(o, &a_len, &b_start, c);
            }
        }
        b_start = b_start * &b_k;
    }
}

/// [`horner`] at `L` parameters at once, lane `l` into
/// `out[l·stride .. (l+1)·stride]`: the lanes' Horner chains are
/// independent, so the processor overlaps them (for a high degree the
/// chain's latency, not the arithmetic, bounds one lane).
///
/// The body is [`horner_width`], instantiated for the common strides 3
/// (planar) and 4 (spatial) so that the coordinate loop has a length known
/// at compile time (unrolled, no bounds checks), and for any other stride.
fn horner_lanes<T: MulAcc, const L: usize>(
    points: &[T],
    stride: usize,
    a: [&T; L],
    b: [&T; L],
    out: &mut [T],
) {
    match stride {
        3 => horner_width::<T, 3, L>(points, stride, a, b, out),
        4 => horner_width::<T, 4, L>(points, stride, a, b, out),
        _ => horner_width::<T, 0, L>(points, stride, a, b, out),
    }
}

/// [`horner_lanes`] with the stride `W` fixed at compile time (`W = 0`:
/// the run-time `stride`).
#[inline(always)]
fn horner_width<T: MulAcc, const W: usize, const L: usize>(
    points: &[T],
    stride: usize,
    a: [&T; L],
    b: [&T; L],
    out: &mut [T],
) {
    let s = if W == 0 { stride } else { W };
    for lane in out[..L * s].chunks_exact_mut(s) {
        lane.clone_from_slice(&points[..s]);
    }
    let mut bpow: [T; L] = std::array::from_fn(|_| T::one());
    for point in points.chunks_exact(s).skip(1) {
        for (l, lane) in out[..L * s].chunks_exact_mut(s).enumerate() {
            bpow[l] = std::mem::replace(&mut bpow[l], T::zero()) * b[l];
            for (o, x) in lane.iter_mut().zip(&point[..s]) {
                T::mul_acc(o, a[l], &bpow[l], x);
            }
        }
    }
}

/// # Homogeneous parameters
impl<T: Ring> Net<T> {
    /// The homogeneous parameters of an affine parameter point: `(1 − t, t)`,
    /// `(1 − u, u, 1 − v, v)` or `(u, v, 1 − u − v)`.
    fn hom_params(&self, params: &[T], hom: &mut [T; 4]) {
        let one = T::one();
        match self.shape {
            Shape::Curve(_) => {
                hom[0] = one - &params[0];
                hom[1] = params[0].clone();
            }
            Shape::Rect(..) => {
                hom[0] = one.clone() - &params[0];
                hom[1] = params[0].clone();
                hom[2] = one - &params[1];
                hom[3] = params[1].clone();
            }
            Shape::Tri(_) => {
                hom[0] = params[0].clone();
                hom[1] = params[1].clone();
                hom[2] = one - &params[0] - &params[1];
            }
        }
    }
}

/// Check a batch's buffers: `params` values, `k` per point, need an
/// output of `per_point` values per point.
///
/// # Errors
///
/// [`Error::Shape`] if the lengths do not match.
fn check_batch(params: usize, k: usize, per_point: usize, out: usize) -> Result<(), Error> {
    if !params.is_multiple_of(k) || out != params / k * per_point {
        return Err(Error::Shape(format!(
            "a batch of {params} parameter values ({k} per point) needs an output of {} values, not {out}",
            params / k * per_point
        )));
    }
    Ok(())
}

/// Divide a homogeneous point `h = (w·X, w)` into `out = X`.
///
/// # Errors
///
/// [`Error::PointAtInfinity`] if `w` is zero.
pub(crate) fn project_into<T: Field>(h: &[T], out: &mut [T]) -> Result<(), Error> {
    let (x, w) = h.split_at(h.len() - 1);
    if w[0].is_zero() {
        return Err(Error::PointAtInfinity);
    }
    for (o, xi) in out.iter_mut().zip(x) {
        *o = xi.clone() / &w[0];
    }
    Ok(())
}

/// An evaluator: a [`Net`], its workspace and a homogeneous scratch point,
/// so that repeated evaluations allocate nothing (for `f64`).
///
/// # Examples
///
/// ```
/// use exact_bezier::{eval::Evaluator, RectPatch};
/// let p = |x: f64, y: f64, z: f64| vec![x, y, z];
/// let r = RectPatch::polynomial(vec![vec![p(0.0, 0.0, 0.0), p(0.0, 1.0, 1.0)],
///                                    vec![p(1.0, 0.0, 1.0), p(1.0, 1.0, 0.0)]]).unwrap();
/// let mut ev = Evaluator::rect(&r);
/// let params = [0.5, 0.5, 0.25, 1.0]; // (u, v) = (0.5, 0.5) and (0.25, 1)
/// let mut out = vec![0.0; 6];
/// ev.eval_batch(&params, &mut out).unwrap();
/// assert_eq!(out, vec![0.5, 0.5, 0.5, 0.25, 1.0, 0.75]);
/// ```
#[derive(Clone, Debug)]
pub struct Evaluator<T> {
    net: Net<T>,
    ws: Workspace<T>,
    hom: [T; 4],
    point: Vec<T>,
    /// [`LANES`] homogeneous points of a curve batch (sized by the first
    /// batch of at least [`LANES`] points).
    lanes: Vec<T>,
    /// The rows of a rect patch for the `f64` kernels of `lanes` (sized on
    /// first use).
    lane_rows: Vec<f64>,
}

/// Curve points evaluated together in a batch ([`horner_lanes`]).
const LANES: usize = 4;

/// The fewest points of an `f64` batch that go to the lane kernels of
/// `lanes` (which evaluate a whole group of points at once): a single
/// `eval` call took 20–70 % longer through them than through the scalar
/// kernel (criterion, 2026-11-27).
const FEWEST_FOR_LANES: usize = 4;

impl<T: Field> Evaluator<T> {
    /// An evaluator of `net` (of a curve or a patch:
    /// [`Evaluator::curve`], [`Evaluator::rect`], [`Evaluator::tri`]).
    pub fn new(net: Net<T>) -> Self {
        let ws = net.workspace();
        let point = vec![T::zero(); net.stride];
        Evaluator {
            net,
            ws,
            hom: [T::zero(), T::zero(), T::zero(), T::zero()],
            point,
            lanes: Vec::new(),
            lane_rows: Vec::new(),
        }
    }

    /// The net being evaluated.
    pub fn net(&self) -> &Net<T> {
        &self.net
    }

    /// The Cartesian point at `params` (`[t]` or `[u, v]`), into `out`
    /// (`dim` scalars), by the generic kernel on `T`.
    ///
    /// # Errors
    ///
    /// [`Error::PointAtInfinity`] if the weight vanishes there.
    ///
    /// **Panics if `params` or `out` have the wrong length.**
    pub fn eval_into(&mut self, params: &[T], out: &mut [T]) -> Result<(), Error> {
        self.net.hom_params(params, &mut self.hom);
        self.net
            .eval_hom_into(&self.hom, &mut self.point, &mut self.ws);
        project_into(&self.point, out)
    }

    /// The points at a batch of parameters: `params` holds one parameter
    /// (curve) or two (patch) per point, back to back; `out` receives `dim`
    /// coordinates per point. `BigRational` takes the fraction-free path
    /// of the module documentation, batches of four or more points on
    /// `f64` nets of stride 3 or 4 the lane-major kernels of `lanes`
    /// (several points at once in vector registers: the same values bit
    /// for bit in the baseline build, within the tolerance of `lanes` in
    /// the fused AVX2 and AVX-512 builds), everything else the generic
    /// kernel (the values are the same).
    ///
    /// # Errors
    ///
    /// [`Error::Shape`] if the buffer lengths do not match;
    /// [`Error::PointAtInfinity`] at the first point where the weight
    /// vanishes.
    pub fn eval_batch(&mut self, params: &[T], out: &mut [T]) -> Result<(), Error> {
        check_batch(
            params.len(),
            self.net.shape.params(),
            self.net.dim(),
            out.len(),
        )?;
        let points = params.len() / self.net.shape.params();
        fraction_free::eval_batch(self, params, out)
            .or_else(|| {
                // The lanes compute a whole group of points: for one to
                // three the scalar kernel is cheaper (the same values
                // within the tolerance of `lanes`).
                (points >= FEWEST_FOR_LANES)
                    .then(|| {
                        lanes::eval_batch(
                            lanes::Isa::detect(),
                            &self.net,
                            params,
                            out,
                            &mut self.lane_rows,
                        )
                    })
                    .flatten()
            })
            .unwrap_or_else(|| self.eval_batch_generic(params, out))
    }

    /// The generic batch: [`Evaluator::eval_into`] point after point.
    /// Curves go [`LANES`] points at a time ([`horner_lanes`]); the rest,
    /// and patches, one at a time.
    fn eval_batch_generic(&mut self, params: &[T], out: &mut [T]) -> Result<(), Error> {
        let (k, d) = (self.net.shape.params(), self.net.dim());
        let mut done = 0;
        if let (Shape::Curve(_), true) = (self.net.shape, params.len() >= LANES) {
            let s = self.net.stride;
            self.lanes.resize(LANES * s, T::zero());
            let mut groups = params
                .chunks_exact(LANES)
                .zip(out.chunks_exact_mut(LANES * d));
            for (ts, o) in &mut groups {
                let a: [T; LANES] = std::array::from_fn(|l| T::one() - &ts[l]);
                let b: [&T; LANES] = std::array::from_fn(|l| &ts[l]);
                horner_lanes(self.net.scaled(), s, a.each_ref(), b, &mut self.lanes);
                for (h, x) in self.lanes.chunks_exact(s).zip(o.chunks_exact_mut(d)) {
                    project_into(h, x)?;
                }
                done += LANES;
            }
        }
        for (p, o) in params[done * k..]
            .chunks(k)
            .zip(out[done * d..].chunks_mut(d))
        {
            self.eval_into(p, o)?;
        }
        Ok(())
    }
}

/// The points of `net` at the parameter points `params` (one or two values
/// each), `dim` coordinates per point: the batch form of `eval`.
pub(crate) fn eval_points<T: Field>(net: Net<T>, params: &[T]) -> Result<Vec<T>, Error> {
    let k = net.shape.params();
    if !params.len().is_multiple_of(k) {
        return Err(Error::Shape(format!(
            "{} parameter values do not make whole points of {k} parameters",
            params.len()
        )));
    }
    let mut out = vec![T::zero(); params.len() / k * net.dim()];
    Evaluator::new(net).eval_batch(params, &mut out)?;
    Ok(out)
}

#[cfg(test)]
mod tests;
