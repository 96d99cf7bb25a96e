//! [`Jets`]: a patch's homogeneous point and first partial derivatives
//! `H`, `H_u`, `H_v` at many parameter points, each by the Horner–Bernstein
//! kernel on a derivative net built once (what meshes and normals need).
//!
//! ```text
//! rect (m, n):  H_u = m Σ (H_{i+1,j} − H_{i,j}) B_{i,m−1}(u) B_{j,n}(v)
//!               H_v = n Σ (H_{i,j+1} − H_{i,j}) B_{i,m}(u) B_{j,n−1}(v)
//! tri n:        H_u = n Σ (H_{i+1,j,k} − H_{i,j,k+1}) B^{n−1}_{ijk}(u, v, w)
//!               H_v = n Σ (H_{i,j+1,k} − H_{i,j,k+1}) B^{n−1}_{ijk}(u, v, w)
//! ```
//!
//! (`w = 1 − u − v`, so `∂/∂u` of the tri patch is the directional
//! derivative along `(1, 0, −1)`.) Ring operations only: exact for exact
//! scalars and symbolic for `Poly`.
//!
//! Reference: source 001 (lecture), derivatives of Bézier curves and
//! surfaces ("导矢"), and of triangular patches (directional derivatives).

use super::{Net, Shape, Workspace};
use crate::algebra::scalar::Scalar;
use crate::hpoint::HPoint;
use crate::rect::RectPatch;
use crate::render::Jet;
use crate::tri::TriPatch;

/// The nets of `H`, `H_u`, `H_v` of a patch, with their workspaces.
///
/// # Examples
///
/// ```
/// use exact_bezier::{eval::Jets, RectPatch, ratio};
/// use num_rational::BigRational;
/// // The bilinear patch X(u, v) = (u, v, u·v).
/// let p = |x: i64, y: i64, z: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1), ratio(z, 1)];
/// let r = RectPatch::polynomial(vec![vec![p(0, 0, 0), p(0, 1, 0)], vec![p(1, 0, 0), p(1, 1, 1)]]).unwrap();
/// let j = Jets::rect(&r).jet(&ratio(1, 2), &ratio(1, 4));
/// assert_eq!(j.du.coords, vec![ratio(1, 1), ratio(0, 1), ratio(1, 4), ratio(0, 1)]);
/// assert_eq!(j.dv.coords, vec![ratio(0, 1), ratio(1, 1), ratio(1, 2), ratio(0, 1)]);
/// ```
#[derive(Clone, Debug)]
pub struct Jets<T> {
    nets: [Net<T>; 3],
    workspaces: [Workspace<T>; 3],
}

impl<T: Scalar> Jets<T> {
    /// The jets of a rect patch.
    pub fn rect(r: &RectPatch<T>) -> Self {
        let (m, n) = r.degree();
        let ctrl = r.ctrl();
        let du = difference_net(Shape::Rect(m.saturating_sub(1), n), m, r.dim(), |i, j| {
            (m > 0).then(|| (&ctrl[i + 1][j], &ctrl[i][j]))
        });
        let dv = difference_net(Shape::Rect(m, n.saturating_sub(1)), n, r.dim(), |i, j| {
            (n > 0).then(|| (&ctrl[i][j + 1], &ctrl[i][j]))
        });
        Self::from_nets([Net::from_rect(r), du, dv])
    }

    /// The jets of a tri patch.
    pub fn tri(t: &TriPatch<T>) -> Self {
        let n = t.degree();
        let rows = t.rows();
        let lower = Shape::Tri(n.saturating_sub(1));
        let du = difference_net(lower, n, t.dim(), |i, j| {
            (n > 0).then(|| (&rows[j][i + 1], &rows[j][i]))
        });
        let dv = difference_net(lower, n, t.dim(), |i, j| {
            (n > 0).then(|| (&rows[j + 1][i], &rows[j][i]))
        });
        Self::from_nets([Net::from_tri(t), du, dv])
    }

    fn from_nets(nets: [Net<T>; 3]) -> Self {
        let workspaces = [
            nets[0].workspace(),
            nets[1].workspace(),
            nets[2].workspace(),
        ];
        Jets { nets, workspaces }
    }

    /// `H`, `H_u`, `H_v` at `(u, v)` (`w = 1 − u − v` for a tri patch).
    pub fn jet(&mut self, u: &T, v: &T) -> Jet<T> {
        let one = T::one();
        let hom = match self.nets[0].shape() {
            Shape::Tri(_) => vec![u.clone(), v.clone(), one - u - v],
            _ => vec![one.clone() - u, u.clone(), one - v, v.clone()],
        };
        let [value, du, dv] = std::array::from_fn(|k| {
            let mut out = vec![T::zero(); self.nets[k].stride()];
            self.nets[k].eval_hom_into(&hom, &mut out, &mut self.workspaces[k]);
            HPoint { coords: out }
        });
        Jet { value, du, dv }
    }
}

/// The net of `shape` whose point `(i, j)` (row `i`, position `j` for a
/// rect; row `j`, position `i` for a tri, as [`Shape`] orders them) is
/// `k·(a − b)` for `pair(i, j) = Some((a, b))`, or the zero net when the
/// degree `k` is 0.
fn difference_net<'a, T: Scalar + 'a>(
    shape: Shape,
    k: usize,
    dim: usize,
    pair: impl Fn(usize, usize) -> Option<(&'a HPoint<T>, &'a HPoint<T>)>,
) -> Net<T> {
    let factor = T::from_i64(k as i64);
    let mut coords = Vec::with_capacity(shape.points() * (dim + 1));
    let mut push = |i: usize, j: usize| match pair(i, j) {
        Some((a, b)) => coords.extend(
            a.coords
                .iter()
                .zip(&b.coords)
                .map(|(x, y)| (x.clone() - y) * &factor),
        ),
        None => coords.extend((0..=dim).map(|_| T::zero())),
    };
    match shape {
        Shape::Rect(m, n) => (0..=m).for_each(|i| (0..=n).for_each(|j| push(i, j))),
        Shape::Tri(n) => (0..=n).for_each(|j| (0..=n - j).for_each(|i| push(i, j))),
        Shape::Curve(n) => (0..=n).for_each(|i| push(i, 0)),
    }
    Net::new(coords, dim + 1, shape).expect("a difference net has its shape")
}
