//! The bowl of source 002 §5: four trigonometric surfaces joined u–u in a
//! ring, built from the printed 16 points of `S₁` and 12 points of `S₂`.
//!
//! The paper prints only `S₁` and `S₂`. Our documented completion uses the
//! half-turn `H(x, y, z) = (−x, −y, z)` about the bowl's axis:
//!
//! ```text
//! G⁰ bowl:  S₁ = P (printed);  S₂: Qᵢ₀ = Pᵢ₃, Qᵢⱼ printed (j = 1, 2, 3);
//!           S₃: Rᵢ₀ = Qᵢ₃, Rᵢⱼ = H(Pᵢⱼ) (j = 1, 2, 3);
//!           S₄: Tᵢ₀ = H(Pᵢ₃), Tᵢⱼ = H(Qᵢⱼ) (j = 1, 2), Tᵢ₃ = Pᵢ₀;
//! G¹ bowl:  the same, but every second row is rebuilt by `trig_stitch`
//!           with the factors μ₁…μ₄ (S₄'s rows 1 and 2 from its joins with
//!           S₃ and, reversed in v, with S₁).
//! ```
//!
//! All four surfaces share α₁ (u direction), as the u–u joins require; each
//! has its own α₂. Reference: source 002 §5, Figs. 4–6.

use super::stitch::trig_stitch;
use super::surface::TrigRect;
use crate::algebra::scalar::{ratio, Ordered};
use crate::error::Error;

/// Printed coordinates in hundredths.
type Printed = [[[i64; 3]; 4]; 4];

/// `P_{ij}` of §5, `[i][j]`, in hundredths.
const P: Printed = [
    [
        [-218, 252, 85],
        [-450, -103, 98],
        [-398, -192, 95],
        [-147, -327, 89],
    ],
    [
        [-398, 87, 75],
        [-282, 79, 41],
        [-340, -154, 65],
        [-79, -382, 75],
    ],
    [
        [-288, 55, 40],
        [-165, 6, 36],
        [-201, -129, 50],
        [34, -236, 31],
    ],
    [[-19, 22, 26], [-3, 24, 2], [-88, -25, 13], [37, 80, 2]],
];

/// `Q_{ij}` of §5 for `j = 1, 2, 3` (index 0 unused: `Qᵢ₀ = Pᵢ₃`).
const Q: Printed = [
    [[0; 3], [-151, -301, 95], [-52, -411, 90], [-151, -382, 88]],
    [[0; 3], [-146, -368, 83], [-62, -345, 71], [18, -309, 65]],
    [[0; 3], [-74, -186, 45], [-134, -286, 36], [91, -250, 45]],
    [[0; 3], [-113, -137, 12], [-93, -137, 2], [115, -34, 15]],
];

fn point<T: Ordered>(h: [i64; 3], turn: bool) -> Vec<T> {
    let sign = if turn { -1 } else { 1 };
    vec![
        ratio(sign * h[0], 100),
        ratio(sign * h[1], 100),
        ratio(h[2], 100),
    ]
}

/// Column `j` of a printed net (the 4 points `·ᵢⱼ`), optionally half-turned.
fn column<T: Ordered>(net: &Printed, j: usize, turn: bool) -> Vec<Vec<T>> {
    (0..4).map(|i| point(net[i][j], turn)).collect()
}

/// A surface from its four columns `cols[j][i] = ·ᵢⱼ`.
fn from_columns<T: Ordered>(cols: [Vec<Vec<T>>; 4], alpha: [T; 2]) -> Result<TrigRect<T>, Error> {
    let points = (0..4)
        .map(|i| cols.iter().map(|c| c[i].clone()).collect())
        .collect();
    TrigRect::new(points, alpha)
}

/// Column `j` of a surface.
fn column_of<T: Ordered>(s: &TrigRect<T>, j: usize) -> Vec<Vec<T>> {
    s.points().iter().map(|row| row[j].clone()).collect()
}

/// The four surfaces of the bowl, `S₁…S₄`, with shape parameters
/// `(α₁, alpha2[k])`; G⁰ as printed (Fig. 4) when `mu` is `None`, G¹ with
/// the factors `μ₁…μ₄` of the joins `S₁S₂, S₂S₃, S₃S₄, S₄S₁` otherwise
/// (Fig. 5). The completion is documented in the module text.
///
/// # Errors
///
/// [`Error::Domain`] if a `μ` is not positive or an α₂ is zero (G¹ only).
///
/// # Examples
///
/// ```
/// use exact_bezier::{ratio, trig::trig_bowl, trig::trig_g0, Tolerance, trig::TrigJoin};
/// use exact_bezier::BigRational;
/// let a2: [BigRational; 4] = [13, 11, 11, 13].map(|k| ratio(k, 10));
/// let bowl = trig_bowl(&ratio(6, 5), &a2, None).unwrap();
/// for k in 0..4 {
///     assert!(trig_g0(&bowl[k], &bowl[(k + 1) % 4], TrigJoin::UU, Tolerance::EXACT));
/// }
/// ```
pub fn trig_bowl<T: Ordered>(
    alpha1: &T,
    alpha2: &[T; 4],
    mu: Option<&[T; 4]>,
) -> Result<Vec<TrigRect<T>>, Error> {
    let al = |k: usize| [alpha1.clone(), alpha2[k].clone()];
    let p = |j| column::<T>(&P, j, false);
    let hp = |j| column::<T>(&P, j, true);
    let q = |j| column::<T>(&Q, j, false);
    let hq = |j| column::<T>(&Q, j, true);
    let s1 = from_columns([p(0), p(1), p(2), p(3)], al(0))?;
    let Some(mu) = mu else {
        return Ok(vec![
            s1,
            from_columns([p(3), q(1), q(2), q(3)], al(1))?,
            from_columns([q(3), hp(1), hp(2), hp(3)], al(2))?,
            from_columns([hp(3), hq(1), hq(2), p(0)], al(3))?,
        ]);
    };
    if mu
        .iter()
        .any(|m| !m.is_positive_within(crate::Tolerance::EXACT))
    {
        return Err(Error::Domain("the factors μ must be positive".into()));
    }
    let s2 = trig_stitch(&s1, alpha2[1].clone(), mu[0].clone(), [q(2), q(3)])?;
    let s3 = trig_stitch(&s2, alpha2[2].clone(), mu[1].clone(), [hp(2), hp(3)])?;
    // The join S₄S₁ seen backwards: S₁ reversed in v, factor 1/μ₄.
    let back = trig_stitch(
        &s1.reverse_v(),
        alpha2[3].clone(),
        mu[3].recip(),
        [hq(2), hq(3)],
    )?;
    let s4 = trig_stitch(
        &s3,
        alpha2[3].clone(),
        mu[2].clone(),
        [column_of(&back, 1), column_of(&back, 0)],
    )?;
    Ok(vec![s1, s2, s3, s4])
}
