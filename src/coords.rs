//! Control points from the point types users already have: fixed-size
//! arrays, `Vec`s and slices, and (feature `mint`) `mint` points and
//! vectors, the interchange types of the Rust graphics ecosystem
//! (nalgebra, cgmath, glam and kurbo convert to and from them).
//!
//! ```
//! use exact_bezier::{coords::Coords, RationalCurve};
//! let c = RationalCurve::polynomial([[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]].map(Coords::into_coords).to_vec()).unwrap();
//! assert_eq!(c.eval(&0.5).unwrap(), vec![1.0, 1.0]);
//! let p: [f64; 2] = exact_bezier::coords::to_array(&c.eval(&0.5).unwrap()).unwrap();
//! assert_eq!(p, [1.0, 1.0]);
//! ```

/// A point that can give its coordinates as a `Vec`.
pub trait Coords<T> {
    /// The coordinates, in order.
    fn into_coords(self) -> Vec<T>;
}

impl<T, const N: usize> Coords<T> for [T; N] {
    fn into_coords(self) -> Vec<T> {
        self.into()
    }
}

impl<T> Coords<T> for Vec<T> {
    fn into_coords(self) -> Vec<T> {
        self
    }
}

impl<T: Clone> Coords<T> for &[T] {
    fn into_coords(self) -> Vec<T> {
        self.to_vec()
    }
}

/// `Coords` for mint's 2D and 3D points and vectors.
#[cfg(feature = "mint")]
macro_rules! mint_coords {
    ($($ty:ident { $($field:ident),+ }),+) => {$(
        impl<T> Coords<T> for mint::$ty<T> {
            fn into_coords(self) -> Vec<T> {
                vec![$(self.$field),+]
            }
        }
    )+};
}

#[cfg(feature = "mint")]
mint_coords!(
    Point2 { x, y },
    Point3 { x, y, z },
    Vector2 { x, y },
    Vector3 { x, y, z }
);

/// The point `p` as a fixed-size array, or `None` if it has another
/// dimension.
pub fn to_array<T: Clone, const N: usize>(p: &[T]) -> Option<[T; N]> {
    <[T; N]>::try_from(p.to_vec()).ok()
}

/// The 3D point `p` as a `mint::Point3`, or `None` if it is not 3D.
#[cfg(feature = "mint")]
pub fn to_mint3<T: Clone>(p: &[T]) -> Option<mint::Point3<T>> {
    to_array::<T, 3>(p).map(mint::Point3::from)
}

#[cfg(all(test, feature = "mint"))]
mod tests {
    use super::*;
    use crate::{ratio, RationalCurve};
    use num_rational::BigRational;

    #[test]
    fn mint_points_build_an_exact_curve_and_come_back() {
        let q = |n: i64| ratio::<BigRational>(n, 1);
        let pts = [
            mint::Point3 {
                x: q(0),
                y: q(0),
                z: q(0),
            },
            mint::Point3 {
                x: q(2),
                y: q(4),
                z: q(2),
            },
            mint::Point3 {
                x: q(4),
                y: q(0),
                z: q(0),
            },
        ];
        let c = RationalCurve::polynomial(pts.map(Coords::into_coords).to_vec()).unwrap();
        let mid = to_mint3(&c.eval(&ratio(1, 2)).unwrap()).unwrap();
        assert_eq!(
            mid,
            mint::Point3 {
                x: q(2),
                y: q(2),
                z: q(1)
            }
        );
        assert!(to_mint3(&[q(1), q(2)]).is_none());
    }
}
