//! `Display` for curves and patches: a short human form that names the
//! kind, degree and dimension and lists the control points with their
//! weights, eliding the middle of a long net.
//!
//! ```text
//! rational curve of degree 2 in 2D: (1, 0) w 1, (1, 4/3) w 3/5, (-7/25, 24/25) w 1
//! rect patch of bidegree (3, 3) in 3D, 16 control points: (0, 0, 0) w 1, (0, 1, 0) w 1, …, (3, 3, 0) w 1
//! ```
//!
//! The exact interchange form is the JSON of docs/FORMAT.md (`FromStr` and,
//! with the `serde` feature, `serde`); `Display` is for people.

use crate::algebra::scalar::Field;
use crate::hpoint::HPoint;
use crate::{RationalCurve, RectPatch, TriPatch};
use std::fmt;

/// Control points shown in full up to this count; longer nets show the
/// first `SHOWN_HEAD` and the last one.
const SHOWN_ALL: usize = 6;
const SHOWN_HEAD: usize = 3;

/// `(x, y, …) w ω` for one homogeneous control point, or its homogeneous
/// coordinates at a zero weight.
fn write_point<T: Field + fmt::Display>(f: &mut fmt::Formatter<'_>, h: &HPoint<T>) -> fmt::Result {
    let coords: Vec<String> = match h.project() {
        Ok(p) => p.iter().map(ToString::to_string).collect(),
        Err(_) => h.weighted().iter().map(ToString::to_string).collect(),
    };
    write!(f, "({}) w {}", coords.join(", "), h.weight())
}

/// The points of a net in order, eliding the middle of a long one.
fn write_net<'a, T: Field + fmt::Display + 'a>(
    f: &mut fmt::Formatter<'_>,
    net: impl ExactSizeIterator<Item = &'a HPoint<T>>,
) -> fmt::Result {
    let len = net.len();
    for (k, h) in net.enumerate() {
        let shown = len <= SHOWN_ALL || k < SHOWN_HEAD || k + 1 == len;
        if shown {
            if k > 0 {
                write!(f, ", ")?;
            }
            write_point(f, h)?;
        } else if k == SHOWN_HEAD {
            write!(f, ", …")?;
        }
    }
    Ok(())
}

/// ```
/// use exact_bezier::{ratio, RationalCurve};
/// use exact_bezier::BigRational;
/// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
/// let c = RationalCurve::new(vec![p(0, 0), p(1, 2), p(2, 0)], vec![ratio(1, 1), ratio(1, 3), ratio(1, 1)]).unwrap();
/// assert_eq!(c.to_string(), "rational curve of degree 2 in 2D: (0, 0) w 1, (1, 2) w 1/3, (2, 0) w 1");
/// ```
impl<T: Field + fmt::Display> fmt::Display for RationalCurve<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "rational curve of degree {} in {}D: ",
            self.degree(),
            self.dim()
        )?;
        write_net(f, self.ctrl().iter())
    }
}

impl<T: Field + fmt::Display> fmt::Display for RectPatch<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (m, n) = self.degree();
        write!(
            f,
            "rect patch of bidegree ({m}, {n}) in {}D, {} control points: ",
            self.dim(),
            (m + 1) * (n + 1)
        )?;
        write_net(
            f,
            self.ctrl().iter().flatten().collect::<Vec<_>>().into_iter(),
        )
    }
}

impl<T: Field + fmt::Display> fmt::Display for TriPatch<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let n = self.degree();
        write!(
            f,
            "tri patch of degree {n} in {}D, {} control points: ",
            self.dim(),
            (n + 1) * (n + 2) / 2
        )?;
        write_net(
            f,
            self.rows().iter().flatten().collect::<Vec<_>>().into_iter(),
        )
    }
}
