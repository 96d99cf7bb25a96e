//! [`Jets`]: a curve's or a patch's homogeneous point and first
//! derivatives — `H`, `H'` or `H`, `H_u`, `H_v` — at many parameter points,
//! each by the Horner–Bernstein kernel on a derivative net built once (what
//! tangents, normals and meshes need), in batch into a caller's buffer.
//!
//! ```text
//! curve n:      H'  = n Σ (H_{i+1} − H_i) B_{i,n−1}(t)
//! rect (m, n):  H_u = m Σ (H_{i+1,j} − H_{i,j}) B_{i,m−1}(u) B_{j,n}(v)
//!               H_v = n Σ (H_{i,j+1} − H_{i,j}) B_{i,m}(u) B_{j,n−1}(v)
//! tri n:        H_u = n Σ (H_{i+1,j,k} − H_{i,j,k+1}) B^{n−1}_{ijk}(u, v, w)
//!               H_v = n Σ (H_{i,j+1,k} − H_{i,j,k+1}) B^{n−1}_{ijk}(u, v, w)
//! ```
//!
//! (`w = 1 − u − v`, so `∂/∂u` of the tri patch is the directional
//! derivative along `(1, 0, −1)`.) Ring operations only: exact for exact
//! scalars and symbolic for `Poly`. The Cartesian derivative follows by the
//! quotient rule, `X' = (w·P' − w'·P)/w²` with `H = (w·P, w)`.
//!
//! Reference: source 001 (lecture), derivatives of Bézier curves and
//! surfaces ("导矢"), and of triangular patches (directional derivatives).

use super::{Net, Shape, Workspace};
use crate::algebra::scalar::Scalar;
use crate::error::Error;
use crate::hpoint::HPoint;

/// A homogeneous point and its first partial derivatives at one parameter
/// point: `H(u, v)`, `∂H/∂u`, `∂H/∂v` (each `(w·P, w)`-shaped).
#[derive(Clone, Debug, PartialEq)]
pub struct Jet<T> {
    /// `H(u, v)`.
    pub value: HPoint<T>,
    /// `∂H/∂u`.
    pub du: HPoint<T>,
    /// `∂H/∂v`.
    pub dv: HPoint<T>,
}

/// The nets of `H` and its first derivatives (`H'` for a curve, `H_u`,
/// `H_v` for a patch), with their workspaces.
///
/// # Examples
///
/// ```
/// use exact_bezier::{eval::Jets, RectPatch, ratio};
/// use exact_bezier::BigRational;
/// // The bilinear patch X(u, v) = (u, v, u·v).
/// let p = |x: i64, y: i64, z: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1), ratio(z, 1)];
/// let r = RectPatch::polynomial(vec![vec![p(0, 0, 0), p(0, 1, 0)], vec![p(1, 0, 0), p(1, 1, 1)]]).unwrap();
/// let j = Jets::rect(&r).jet(&ratio(1, 2), &ratio(1, 4));
/// assert_eq!(j.du.coords, vec![ratio(1, 1), ratio(0, 1), ratio(1, 4), ratio(0, 1)]);
/// assert_eq!(j.dv.coords, vec![ratio(0, 1), ratio(1, 1), ratio(1, 2), ratio(0, 1)]);
/// ```
#[derive(Clone, Debug)]
pub struct Jets<T> {
    /// `H`, then one derivative net per parameter.
    pub(super) nets: Vec<Net<T>>,
    workspaces: Vec<Workspace<T>>,
    /// The homogeneous parameters of the point being evaluated.
    hom: [T; 4],
    /// Scratch rows of the `f64` lane kernels (`super::lanes`).
    lane_rows: Vec<f64>,
}

impl<T: Scalar> Jets<T> {
    /// The jets of a net: `H` and `H'` for a curve, `H`, `H_u`, `H_v` for
    /// a patch (`w = 1 − u − v` for a tri patch), each derivative on a
    /// difference net of `net` built here. The jets of curves and patches
    /// are [`Jets::curve`], [`Jets::rect`] and [`Jets::tri`].
    pub fn new(net: Net<T>) -> Self {
        let derivatives = match net.shape() {
            Shape::Curve(n) => vec![difference_net(
                &net,
                Shape::Curve(n.saturating_sub(1)),
                n,
                |i, _| (n > 0).then(|| (i + 1, i)),
            )],
            Shape::Rect(m, n) => {
                let at = |i: usize, j: usize| i * (n + 1) + j;
                vec![
                    difference_net(&net, Shape::Rect(m.saturating_sub(1), n), m, |i, j| {
                        (m > 0).then(|| (at(i + 1, j), at(i, j)))
                    }),
                    difference_net(&net, Shape::Rect(m, n.saturating_sub(1)), n, |i, j| {
                        (n > 0).then(|| (at(i, j + 1), at(i, j)))
                    }),
                ]
            }
            Shape::Tri(n) => {
                // Row j starts after the n + 1, n, …, n − j + 2 points of rows 0 … j − 1.
                let at = |i: usize, j: usize| j * (n + 1) - j * j.saturating_sub(1) / 2 + i;
                let lower = Shape::Tri(n.saturating_sub(1));
                vec![
                    difference_net(&net, lower, n, |i, j| {
                        (n > 0).then(|| (at(i + 1, j), at(i, j)))
                    }),
                    difference_net(&net, lower, n, |i, j| {
                        (n > 0).then(|| (at(i, j + 1), at(i, j)))
                    }),
                ]
            }
        };
        let mut nets = vec![net];
        nets.extend(derivatives);
        let workspaces = nets.iter().map(Net::workspace).collect();
        Jets {
            nets,
            workspaces,
            hom: std::array::from_fn(|_| T::zero()),
            lane_rows: Vec::new(),
        }
    }

    /// Coordinates per homogeneous point: the dimension plus one.
    pub fn stride(&self) -> usize {
        self.nets[0].stride()
    }

    /// Parameters per point: 1 for a curve, 2 for a patch.
    pub fn params(&self) -> usize {
        self.nets[0].shape().params()
    }

    /// `H` and its derivatives at the parameter point `params` (`[t]` or
    /// `[u, v]`), written into `out`: `stride` scalars each, `H` first.
    /// Allocates nothing.
    ///
    /// **Panics if `params` or `out` have the wrong length.**
    pub fn eval_into(&mut self, params: &[T], out: &mut [T]) {
        self.nets[0].hom_params(params, &mut self.hom);
        let s = self.stride();
        for ((net, ws), h) in self
            .nets
            .iter()
            .zip(&mut self.workspaces)
            .zip(out.chunks_exact_mut(s))
        {
            net.eval_hom_into(&self.hom, h, ws);
        }
    }

    /// [`Jets::eval_into`] at a batch of parameter points (`params` holds
    /// one value per point for a curve, two for a patch, back to back):
    /// `out` receives `2·stride` (curve) or `3·stride` (patch) scalars per
    /// point. `f64` nets of stride 3 or 4 take the lane-major kernels of
    /// `lanes` (the same values bit for bit, or within its tolerance in
    /// the fused AVX2 and AVX-512 builds). In steady state an `f64`
    /// batch allocates nothing (tests/alloc.rs).
    ///
    /// # Errors
    ///
    /// [`Error::Shape`] if the buffer lengths do not match.
    pub fn eval_batch(&mut self, params: &[T], out: &mut [T]) -> Result<(), Error> {
        let (k, per_point) = (self.params(), self.nets.len() * self.stride());
        super::check_batch(params.len(), k, per_point, out.len())?;
        if super::lanes::jets_batch(
            super::lanes::Isa::detect(),
            &self.nets,
            params,
            out,
            &mut self.lane_rows,
        )
        .is_some()
        {
            return Ok(());
        }
        for (p, o) in params.chunks_exact(k).zip(out.chunks_exact_mut(per_point)) {
            self.eval_into(p, o);
        }
        Ok(())
    }

    /// `H`, `H_u`, `H_v` of a patch at `(u, v)` (`w = 1 − u − v` for a tri
    /// patch), as homogeneous points.
    ///
    /// **Panics for the jets of a curve** (use [`Jets::eval_into`]).
    pub fn jet(&mut self, u: &T, v: &T) -> Jet<T> {
        assert_eq!(self.nets.len(), 3, "a jet (H, H_u, H_v) is a patch's");
        let s = self.stride();
        let mut out = vec![T::zero(); 3 * s];
        self.eval_into(&[u.clone(), v.clone()], &mut out);
        let mut parts = out.chunks_exact(s).map(|h| HPoint { coords: h.to_vec() });
        let mut next = || parts.next().expect("three parts");
        Jet {
            value: next(),
            du: next(),
            dv: next(),
        }
    }
}

/// The net of `shape` whose point `(i, j)` (row `i`, position `j` for a
/// rect; row `j`, position `i` for a tri, as [`Shape`] orders them) is
/// `k·(H_a − H_b)` for `pair(i, j) = Some((a, b))`, with `H_a` the point of
/// index `a` of `net`, or the zero net when the degree `k` is 0.
fn difference_net<T: Scalar>(
    net: &Net<T>,
    shape: Shape,
    k: usize,
    pair: impl Fn(usize, usize) -> Option<(usize, usize)>,
) -> Net<T> {
    let factor = T::from_i64(k as i64);
    let s = net.stride();
    let point = |p: usize| &net.coords()[p * s..(p + 1) * s];
    let mut coords = Vec::with_capacity(shape.points() * s);
    let mut push = |i: usize, j: usize| match pair(i, j) {
        Some((a, b)) => coords.extend(
            point(a)
                .iter()
                .zip(point(b))
                .map(|(x, y)| (x.clone() - y) * &factor),
        ),
        None => coords.extend((0..s).map(|_| T::zero())),
    };
    match shape {
        Shape::Rect(m, n) => (0..=m).for_each(|i| (0..=n).for_each(|j| push(i, j))),
        Shape::Tri(n) => (0..=n).for_each(|j| (0..=n - j).for_each(|i| push(i, j))),
        Shape::Curve(n) => (0..=n).for_each(|i| push(i, 0)),
    }
    Net::new(coords, s, shape).expect("a difference net has its shape")
}
