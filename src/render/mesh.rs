//! [`Mesh`]: triangulated surfaces with normals, for 3D viewers (OBJ, STL,
//! PLY), and the exact first partial derivatives they are built from.
//!
//! Conventions: a rect patch is sampled on the grid `(u, v) = (i/N, j/N)`,
//! `0 ≤ i, j ≤ N`, giving `(N+1)²` vertices and `2N²` triangles; a tri
//! patch on `(u, v) = (i/N, j/N)`, `i + j ≤ N`, giving `(N+1)(N+2)/2`
//! vertices and `N²` triangles. Triangles are oriented so that their face
//! normal points along `X_u × X_v`.
//!
//! Normals come from exact derivative formulas on the homogeneous form, not
//! from finite differences. With `X = P/w` (`P` the weighted coordinates):
//!
//! ```text
//! X_u = (w·P_u − w_u·P) / w²,   X_v = (w·P_v − w_v·P) / w²
//! N ∥ (w·P_u − w_u·P) × (w·P_v − w_v·P)      (w² > 0 drops out)
//! ```
//!
//! and the homogeneous partials come from the difference nets of
//! [`Jets`] (`H_u = m Σ (H_{i+1,j} − H_{i,j}) B_{i,m−1} B_{j,n}`, and the
//! tri analogue), evaluated by the batch kernel of [`crate::eval`] with one
//! set of nets per patch; a curve's `H'(t) = n·(b₁ⁿ⁻¹ − b₀ⁿ⁻¹)` comes from
//! the last de Casteljau level ([`curve_jet`]). Only ring operations are used, so
//! [`rect_jet`], [`tri_jet`] and [`normal_direction`] are exact for exact
//! scalars (and symbolic for `Poly`).
//!
//! Where the normal vanishes (a collapsed edge of a degenerate patch, where
//! `X_u × X_v = 0`), the vertex takes the exact normal at the parameter
//! moved 10⁻⁶ (then 10⁻³) of the way toward the domain centre: the limit
//! normal along that path. A patch degenerate on a whole neighbourhood
//! (collapsed to a curve) keeps the zero vector there.
//!
//! Reference: source 001 (lecture), derivatives of Bézier curves and
//! "三角域Bézier曲面" (directional derivatives from the de Casteljau levels).

use crate::algebra::scalar::{ratio, Ordered, Scalar};
use crate::error::Error;
use crate::eval::Jets;
use crate::hpoint::HPoint;
use crate::limits::MAX_DENSITY;
use crate::patch::Patch;
use crate::rect::RectPatch;
use crate::tri::TriPatch;
use std::fmt::Write;

pub use crate::eval::Jet;

/// The homogeneous point of a curve at `t` and its derivative:
/// `(b₀ⁿ, n·(b₁ⁿ⁻¹ − b₀ⁿ⁻¹))` from de Casteljau stopped one level early.
///
/// **Panics if `points` is empty.**
///
/// # Examples
///
/// ```
/// use exact_bezier::{render::curve_jet, hpoint::HPoint, ratio};
/// use exact_bezier::BigRational;
/// // H(t) = (t², 1) from the control points 0, 0, 1 (weights 1).
/// let pts: Vec<HPoint<BigRational>> =
///     [0, 0, 1].iter().map(|&x| HPoint::from_cartesian(&[ratio(x, 1)])).collect();
/// let (h, d) = curve_jet(&pts, &ratio(1, 3));
/// assert_eq!(h.coords, vec![ratio(1, 9), ratio(1, 1)]);
/// assert_eq!(d.coords, vec![ratio(2, 3), ratio(0, 1)]); // 2t, and w' = 0
/// ```
pub fn curve_jet<T: Scalar>(points: &[HPoint<T>], t: &T) -> (HPoint<T>, HPoint<T>) {
    let n = points.len() - 1;
    if n == 0 {
        let p = points[0].clone();
        let zero = HPoint::zero(p.dim());
        return (p, zero);
    }
    let s = T::one() - t;
    let mut row: Vec<HPoint<T>> = points.to_vec();
    for k in (2..row.len()).rev() {
        for i in 0..k {
            crate::hpoint::step_in_place(&mut row, i, &s, t);
        }
    }
    let value = row[0].combine(&s, &row[1], t);
    let deriv = row[1].sub(&row[0]).scale(&ratio(n as i64, 1));
    (value, deriv)
}

/// `H`, `H_u`, `H_v` of a rect patch at `(u, v)`, by [`Jets`] (the
/// Horner–Bernstein kernel on the patch's net and its two difference
/// nets). Exact for exact `T`. For many points build one [`Jets`].
///
/// # Examples
///
/// ```
/// use exact_bezier::{render::rect_jet, RectPatch, ratio};
/// use exact_bezier::BigRational;
/// // The bilinear patch X(u, v) = (u, v, u·v).
/// let p = |x: i64, y: i64, z: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1), ratio(z, 1)];
/// let r = RectPatch::polynomial(vec![vec![p(0, 0, 0), p(0, 1, 0)], vec![p(1, 0, 0), p(1, 1, 1)]]).unwrap();
/// let j = rect_jet(&r, &ratio(1, 2), &ratio(1, 4));
/// assert_eq!(j.du.coords, vec![ratio(1, 1), ratio(0, 1), ratio(1, 4), ratio(0, 1)]);
/// assert_eq!(j.dv.coords, vec![ratio(0, 1), ratio(1, 1), ratio(1, 2), ratio(0, 1)]);
/// ```
pub fn rect_jet<T: Scalar>(patch: &RectPatch<T>, u: &T, v: &T) -> Jet<T> {
    Jets::rect(patch).jet(u, v)
}

/// `H`, `H_u`, `H_v` of a tri patch at `(u, v)` (`w = 1 − u − v`), by
/// [`Jets`]: `H_u = n Σ (H_{i+1,j,k} − H_{i,j,k+1}) B^{n−1}_{ijk}` and
/// likewise `H_v`. Exact for exact `T`.
///
/// # Examples
///
/// ```
/// use exact_bezier::{render::tri_jet, TriPatch, ratio};
/// use exact_bezier::BigRational;
/// // Quadratic tri patch with scalar values: X = u² (only P_{2,0,0} = 1).
/// let c = |x: i64| vec![ratio::<BigRational>(x, 1)];
/// let t = TriPatch::polynomial(vec![vec![c(0), c(0), c(1)], vec![c(0), c(0)], vec![c(0)]]).unwrap();
/// let j = tri_jet(&t, &ratio(1, 3), &ratio(1, 2));
/// assert_eq!(j.value.coords[0], ratio(1, 9));
/// assert_eq!(j.du.coords[0], ratio(2, 3)); // ∂(u²)/∂u
/// assert_eq!(j.dv.coords[0], ratio(0, 1));
/// ```
pub fn tri_jet<T: Scalar>(patch: &TriPatch<T>, u: &T, v: &T) -> Jet<T> {
    Jets::tri(patch).jet(u, v)
}

/// A vector along the surface normal at a jet, in 3D (2D patches get
/// `z = 0`): `(w·P_u − w_u·P) × (w·P_v − w_v·P)`, i.e. `w⁴·(X_u × X_v)`.
/// Ring operations only: exact for exact `T`.
///
/// # Errors
///
/// [`Error::Shape`] unless the patch is 2- or 3-dimensional.
///
/// # Examples
///
/// ```
/// use exact_bezier::{render::normal_direction, render::rect_jet, RectPatch, ratio};
/// use exact_bezier::BigRational;
/// let p = |x: i64, y: i64, z: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1), ratio(z, 1)];
/// let r = RectPatch::polynomial(vec![vec![p(0, 0, 0), p(0, 1, 0)], vec![p(1, 0, 0), p(1, 1, 1)]]).unwrap();
/// // X = (u, v, uv): X_u × X_v = (−v, −u, 1).
/// let n = normal_direction(&rect_jet(&r, &ratio(1, 2), &ratio(1, 4))).unwrap();
/// assert_eq!(n, vec![ratio(-1, 4), ratio(-1, 2), ratio(1, 1)]);
/// ```
pub fn normal_direction<T: Scalar>(jet: &Jet<T>) -> Result<Vec<T>, Error> {
    let tu = tangent3(&jet.value.coords, &jet.du.coords)?;
    let tv = tangent3(&jet.value.coords, &jet.dv.coords)?;
    Ok(cross(&tu, &tv))
}

/// `w·P' − w'·P` padded to three coordinates, from the homogeneous point
/// `h = (P, w)` and its derivative `d = (P', w')`.
fn tangent3<T: Scalar>(h: &[T], d: &[T]) -> Result<[T; 3], Error> {
    let dim = h.len() - 1;
    if !(2..=3).contains(&dim) {
        return Err(Error::Shape(format!(
            "a mesh needs 2D or 3D points, not {dim}D"
        )));
    }
    let (w, dw) = (&h[dim], &d[dim]);
    let c = |k: usize| {
        if k < dim {
            d[k].clone() * w - &(h[k].clone() * dw)
        } else {
            T::zero()
        }
    };
    Ok([c(0), c(1), c(2)])
}

fn cross<T: Scalar>(a: &[T; 3], b: &[T; 3]) -> Vec<T> {
    let c = |i: usize, j: usize| a[i].clone() * &b[j] - &(a[j].clone() * &b[i]);
    vec![c(1, 2), c(2, 0), c(0, 1)]
}

/// A triangle mesh with one unit normal per vertex.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Mesh {
    /// Vertex positions (2D patches get `z = 0`).
    pub positions: Vec<[f64; 3]>,
    /// Unit normals, one per vertex.
    pub normals: Vec<[f64; 3]>,
    /// Vertex indices (0-based), counter-clockwise about the normal.
    pub triangles: Vec<[usize; 3]>,
}

/// # Construction
impl Mesh {
    /// Mesh every rect and tri patch of `patches` at `density` steps per
    /// parameter, in one mesh (patches are not welded: a shared boundary
    /// appears once per patch).
    ///
    /// # Errors
    ///
    /// [`Error::Shape`] for a curve (no surface) or points that are not 2D or
    /// 3D; [`Error::Domain`] for a density of 0 or over [`MAX_DENSITY`];
    /// [`Error::PointAtInfinity`] / [`Error::NotFinite`] if a sample cannot
    /// be projected.
    ///
    /// # Examples
    ///
    /// ```
    /// use exact_bezier::{io::read_patches, render::Mesh};
    /// let p = read_patches(r#"{"kind": "tri", "degree": 1, "points": [[[0,0,0],[1,0,0]],[[0,1,0]]]}"#).unwrap();
    /// let m = Mesh::from_patches(&p, 4).unwrap();
    /// assert_eq!((m.positions.len(), m.triangles.len()), (15, 16));
    /// assert_eq!(m.normals[0], [0.0, 0.0, 1.0]);
    /// ```
    pub fn from_patches<T: Ordered>(patches: &[Patch<T>], density: usize) -> Result<Mesh, Error> {
        let mut mesh = Mesh::default();
        for p in patches {
            let part = match p {
                Patch::Rect(r) => Mesh::from_rect(r, density)?,
                Patch::Tri(t) => Mesh::from_tri(t, density)?,
                Patch::Curve(_) => {
                    return Err(Error::Shape(
                        "a curve has no surface to mesh: give rect or tri patches".into(),
                    ))
                }
            };
            mesh.append(part);
        }
        Ok(mesh)
    }

    /// Mesh a rect patch on the `(N+1) × (N+1)` parameter grid.
    ///
    /// # Errors
    ///
    /// As [`Mesh::from_patches`].
    pub fn from_rect<T: Ordered>(patch: &RectPatch<T>, density: usize) -> Result<Mesh, Error> {
        let n = check_density(density)?;
        let grid: Vec<(usize, usize)> =
            (0..=n).flat_map(|i| (0..=n).map(move |j| (i, j))).collect();
        let mut mesh = Mesh::default();
        mesh.push_vertices(
            &mut Jets::rect(patch),
            &grid,
            n,
            &(ratio(1, 2), ratio(1, 2)),
        )?;
        let id = |i: usize, j: usize| i * (n + 1) + j;
        for i in 0..n {
            for j in 0..n {
                let (a, b, c, d) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
                mesh.triangles.push([a, b, c]);
                mesh.triangles.push([a, c, d]);
            }
        }
        Ok(mesh)
    }

    /// Mesh a tri patch on the points `(i/N, j/N)`, `i + j ≤ N`.
    ///
    /// # Errors
    ///
    /// As [`Mesh::from_patches`].
    pub fn from_tri<T: Ordered>(patch: &TriPatch<T>, density: usize) -> Result<Mesh, Error> {
        let n = check_density(density)?;
        let grid: Vec<(usize, usize)> = (0..=n)
            .flat_map(|j| (0..=n - j).map(move |i| (i, j)))
            .collect();
        let mut mesh = Mesh::default();
        mesh.push_vertices(&mut Jets::tri(patch), &grid, n, &(ratio(1, 3), ratio(1, 3)))?;
        let mut start = Vec::with_capacity(n + 1);
        for j in 0..=n {
            start.push(if j == 0 { 0 } else { start[j - 1] + n + 2 - j });
        }
        let id = |i: usize, j: usize| start[j] + i;
        for j in 0..n {
            for i in 0..n - j {
                mesh.triangles.push([id(i, j), id(i + 1, j), id(i, j + 1)]);
                if i + j + 1 < n {
                    mesh.triangles
                        .push([id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)]);
                }
            }
        }
        Ok(mesh)
    }

    /// Append `other`, renumbering its triangles.
    pub fn append(&mut self, other: Mesh) {
        let base = self.positions.len();
        self.positions.extend(other.positions);
        self.normals.extend(other.normals);
        self.triangles
            .extend(other.triangles.iter().map(|t| t.map(|k| k + base)));
    }

    /// Add the vertices at the grid points `(i/N, j/N)` with their unit
    /// normals, from one batch of jets (see the module docs for collapsed
    /// points, which take a second evaluation nearer `centre`).
    fn push_vertices<T: Ordered>(
        &mut self,
        jets: &mut Jets<T>,
        grid: &[(usize, usize)],
        n: usize,
        centre: &(T, T),
    ) -> Result<(), Error> {
        let params: Vec<T> = grid
            .iter()
            .flat_map(|&(i, j)| [ratio(i as i64, n as i64), ratio(j as i64, n as i64)])
            .collect();
        let per_point = 3 * jets.stride();
        let mut out = vec![T::zero(); grid.len() * per_point];
        jets.eval_batch(&params, &mut out)?;
        let mut nearby = vec![T::zero(); per_point];
        for (uv, jet) in params.chunks_exact(2).zip(out.chunks_exact(per_point)) {
            let h = &jet[..jets.stride()];
            let x = HPoint { coords: h.to_vec() }.project()?;
            let mut p = [0.0; 3];
            for (slot, c) in p.iter_mut().zip(&x) {
                *slot = c.to_f64();
            }
            let mut normal = unit_normal(jet)?;
            for eps in [ratio::<T>(1, 1_000_000), ratio(1, 1000)] {
                if normal != [0.0; 3] {
                    break;
                }
                let toward = |a: &T, c: &T| a.clone() + &((c.clone() - a) * &eps);
                jets.eval_into(
                    &[toward(&uv[0], &centre.0), toward(&uv[1], &centre.1)],
                    &mut nearby,
                );
                normal = unit_normal(&nearby)?;
            }
            if p.iter().any(|c| !c.is_finite()) {
                return Err(Error::NotFinite(format!("mesh vertex {p:?} is not finite")));
            }
            self.positions.push(p);
            self.normals.push(normal);
        }
        Ok(())
    }

    /// The (unnormalized) face normal `(b − a) × (c − a)`.
    fn face_normal(&self, t: &[usize; 3]) -> [f64; 3] {
        let [a, b, c] = t.map(|k| self.positions[k]);
        let e1 = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
        let e2 = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
        let v = cross(&e1, &e2);
        [v[0], v[1], v[2]]
    }
}

/// # Output formats
impl Mesh {
    /// Wavefront OBJ: `v x y z`, `vn x y z`, `f a//a b//b c//c` (1-based).
    pub fn to_obj(&self) -> String {
        let mut s = String::from("# exact-bezier mesh\n");
        for p in &self.positions {
            let _ = writeln!(s, "v {} {} {}", p[0], p[1], p[2]);
        }
        for n in &self.normals {
            let _ = writeln!(s, "vn {} {} {}", n[0], n[1], n[2]);
        }
        for t in &self.triangles {
            let [a, b, c] = t.map(|k| k + 1);
            let _ = writeln!(s, "f {a}//{a} {b}//{b} {c}//{c}");
        }
        s
    }

    /// ASCII STL: one facet per triangle with its unit face normal (STL has
    /// no vertex normals; a zero-area triangle gets the normal `0 0 0`).
    pub fn to_stl(&self) -> String {
        let mut s = String::from("solid exact_bezier\n");
        for t in &self.triangles {
            let n = normalize(self.face_normal(t));
            let _ = writeln!(
                s,
                "  facet normal {} {} {}\n    outer loop",
                n[0], n[1], n[2]
            );
            for &k in t {
                let p = self.positions[k];
                let _ = writeln!(s, "      vertex {} {} {}", p[0], p[1], p[2]);
            }
            s.push_str("    endloop\n  endfacet\n");
        }
        s.push_str("endsolid exact_bezier\n");
        s
    }

    /// ASCII PLY with `x y z nx ny nz` per vertex and triangle faces.
    pub fn to_ply(&self) -> String {
        let mut s = format!(
            "ply\nformat ascii 1.0\ncomment exact-bezier mesh\nelement vertex {}\n\
             property float x\nproperty float y\nproperty float z\n\
             property float nx\nproperty float ny\nproperty float nz\n\
             element face {}\nproperty list uchar int vertex_indices\nend_header\n",
            self.positions.len(),
            self.triangles.len()
        );
        for (p, n) in self.positions.iter().zip(&self.normals) {
            let _ = writeln!(s, "{} {} {} {} {} {}", p[0], p[1], p[2], n[0], n[1], n[2]);
        }
        for t in &self.triangles {
            let _ = writeln!(s, "3 {} {} {}", t[0], t[1], t[2]);
        }
        s
    }
}

/// The unit normal at a jet (`H`, `H_u`, `H_v` back to back), or zero where
/// `X_u × X_v` vanishes relative to `|X_u|·|X_v|` (f64 rounding leaves a
/// tiny, meaningless remainder).
fn unit_normal<T: Ordered>(jet: &[T]) -> Result<[f64; 3], Error> {
    let s = jet.len() / 3;
    let (h, rest) = jet.split_at(s);
    let (du, dv) = rest.split_at(s);
    let tu = tangent3(h, du)?.map(|c| c.to_f64());
    let tv = tangent3(h, dv)?.map(|c| c.to_f64());
    let c = cross(&tu, &tv);
    let n = [c[0], c[1], c[2]];
    if n.iter().any(|c| !c.is_finite()) {
        return Err(Error::NotFinite(format!("the normal {n:?} is not finite")));
    }
    if norm(n) <= DEGENERATE * norm(tu) * norm(tv) {
        return Ok([0.0; 3]);
    }
    Ok(normalize(n))
}

fn check_density(density: usize) -> Result<usize, Error> {
    if density == 0 || density > MAX_DENSITY {
        return Err(Error::Domain(format!(
            "mesh density {density} must be between 1 and {MAX_DENSITY}"
        )));
    }
    Ok(density)
}

/// Relative size of `|X_u × X_v|` below which a normal counts as zero.
const DEGENERATE: f64 = 1e-10;

fn norm(v: [f64; 3]) -> f64 {
    (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt()
}

/// `v / |v|`, or the zero vector when `|v| = 0`.
fn normalize(v: [f64; 3]) -> [f64; 3] {
    let len = norm(v);
    if len == 0.0 || !len.is_finite() {
        [0.0; 3]
    } else {
        v.map(|c| c / len)
    }
}
