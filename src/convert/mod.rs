//! Exact conversions between rectangular (tensor-product) and triangular
//! rational Bézier patches, all in homogeneous form (ring operations only):
//!
//! | function | from → to | source |
//! | --- | --- | --- |
//! | [`rect_to_tri`], [`rect_to_tris`] | rect (m, n) → two tris of degree m + n on Δ1, Δ2 | 003 Theorem 2.3, eqs. (14), (16) |
//! | [`tri_to_rect_on_quad`] | tri → rect (n, n) on any bilinear quadrilateral | 003 eq. (22) with the blossoming algorithm (26) |
//! | [`tri_to_rects`] | tri → three rects (n, n) over the split D1, D2, D3 | 003 Theorem 3.2 |
//! | [`tri_to_rects_operators`] | the same by the printed operator formulas | 003 eqs. (23), (24), (25) |
//! | [`tri_to_rect_hu`] | tri → the rect on D1 by shift operators | 001 (Hu 1996 eqs. 5, 6) |
//! | [`tri_to_degenerate_rect`] | tri → one degenerate rect (n, n) | 001 (Hu 2001, operators A_k, corrected) |
//!
//! Parameter maps (each conversion is exact: the new patch at the mapped
//! parameters equals the old one homogeneously, proved in
//! `proofs/src/conversions.rs`):
//!
//! ```text
//! rect → tri on Δ1:   tri(u, v, w) = rect(u, v)
//! rect → tri on Δ2:   tri(u, v, w) = rect(1 − u, 1 − v)
//! tri → rect on quad: rect(s, t) = tri(L(s, t)),  L(s,t) = (1−s)(1−t)c₀₀ + s(1−t)c₁₀ + st c₁₁ + (1−s)t c₀₁
//! tri → degenerate:   rect(s, t) = tri(s, (1 − s)t, (1 − s)(1 − t))   (edge s = 1 collapses to T1)
//! ```

mod degenerate;
mod rect_to_tri;
mod tri_to_rect;

pub use degenerate::{degree_raising_matrix, tri_to_degenerate_rect};
pub use rect_to_tri::{rect_to_tri, rect_to_tris, square_corners, Half};
pub use tri_to_rect::{
    bilinear, tri_to_rect_hu, tri_to_rect_on_quad, tri_to_rects, tri_to_rects_operators, Split,
};

use crate::algebra::scalar::Scalar;

/// `1 / C(n, k)` as a scalar.
fn recip_binomial<T: Scalar>(n: usize, k: usize) -> T {
    T::from_rational(&num_rational::BigRational::new(
        1.into(),
        crate::algebra::scalar::binomial(n, k),
    ))
}
