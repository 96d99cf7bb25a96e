//! [`surface_knot_lines`] on hand-derived cases, and against the
//! Bézier-piece method `pieces::knot_lines` on random and planted surfaces.

use super::pieces::knot_lines;
use super::*;
use crate::nurbs::Nurbs;
use proptest::prelude::*;

fn q(n: i64, d: i64) -> Q {
    Q::new(n.into(), d.into())
}

/// The knots `0^{p+1}, inner…, 2^{p+1}` (integers).
fn clamped(p: usize, inner: &[i64]) -> Vec<Q> {
    let mut k = vec![q(0, 1); p + 1];
    k.extend(inner.iter().map(|&x| q(x, 1)));
    k.extend(vec![q(2, 1); p + 1]);
    k
}

/// A surface cubic in u with knots `clamped(3, inner)`, linear in v with
/// two columns; row `i` is `(j, heights[i])` with weight `weights[i]`. Its
/// homogeneous u-continuity is that of `Σ_i w_i N_i(u) (heights_i, 1)`
/// (the `y = j` coordinate only adds `Σ w_i N_i(u)`).
fn cubic_in_u(inner: &[i64], heights: &[i64], weights: &[i64]) -> NurbsSurface<Q> {
    let u = Knots::new(3, clamped(3, inner), heights.len()).unwrap();
    let v = Knots::new(1, vec![q(0, 1), q(0, 1), q(1, 1), q(1, 1)], 2).unwrap();
    let net = heights
        .iter()
        .zip(weights)
        .map(|(&h, &w)| {
            (0..2)
                .map(|j| HPoint::from_point(&[q(j, 1), q(h, 1)], &q(w, 1)))
                .collect()
        })
        .collect();
    NurbsSurface::new(u, v, net).unwrap()
}

/// The one u-line of `s`, checked to be at u = 1 of degree 3.
fn only_line(s: &NurbsSurface<Q>) -> Option<usize> {
    let lines = surface_knot_lines(s);
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert_eq!(
        (lines[0].direction, &lines[0].knot),
        (Direction::U, &q(1, 1))
    );
    assert_eq!(lines[0].degree, 3);
    lines[0].continuity
}

/// `N_2` on the knots `0, 0, 1, 2, 2` (heights δ_{i2}) is `C²` at the
/// simple knot 1 (multiplicity rule). It is not `C³`: one cubic on [0, 2]
/// with double zeros at 0 and 2 (the end knots are double in `N_2`'s own
/// knots, so value and slope vanish there) would be `c·u²(u − 2)²`, of
/// degree 4 unless c = 0, and `N_2` is not 0.
#[test]
fn a_bump_over_a_simple_knot_is_c2_not_c3() {
    assert_eq!(
        only_line(&cubic_in_u(&[1], &[0, 0, 1, 0, 0], &[1; 5])),
        Some(2)
    );
}

/// The Greville abscissae of `0⁴ 1 2⁴` are 0, 1/3, 1, 5/3, 2; as heights
/// (times 3) they reproduce z = 3u (linear precision): one polynomial.
#[test]
fn a_linear_function_has_a_removable_knot() {
    assert_eq!(
        only_line(&cubic_in_u(&[1], &[0, 1, 3, 5, 6], &[1; 5])),
        None
    );
}

/// `N_2` on `0, 0, 1, 1, 2` is `C¹` at the double knot. `C²` would make it
/// `u²(a u + b)` on [0, 1] and `c(2 − u)³` on [1, 2] with equal value, slope
/// and second derivative at 1: `a + b = c`, `3a + 2b = −3c`, `6a + 2b = 6c`,
/// whose only solution is 0.
#[test]
fn a_bump_over_a_double_knot_is_c1() {
    let s = cubic_in_u(&[1, 1], &[0, 0, 1, 0, 0, 0], &[1; 6]);
    assert_eq!(only_line(&s), Some(1));
}

/// At a knot of multiplicity 4 in a cubic, rows 3 and 4 end one part and
/// begin the other. Different rows: the parts do not meet, no line.
#[test]
fn a_broken_net_at_a_full_knot_is_not_listed() {
    let s = cubic_in_u(&[1; 4], &[0, 0, 0, 1, 2, 0, 0, 0], &[1; 8]);
    assert_eq!(surface_knot_lines(&s), vec![]);
}

/// Equal rows 3 and 4 meet; the end slopes `3(P₃ − P₂)` = 3 and
/// `3(P₅ − P₄)` = −3 (both spans of length 1) differ: `C⁰`.
#[test]
fn a_shared_row_at_a_full_knot_is_c0() {
    let s = cubic_in_u(&[1; 4], &[0, 0, 0, 1, 1, 0, 0, 0], &[1; 8]);
    assert_eq!(only_line(&s), Some(0));
}

/// Rows 4…7 of weight 2 are the same points scaled apart: with heights
/// 0, 0, 0, 1 | 1, 2, 3, … the first differences agree (1 and 1) and the
/// second do not (`P₁ − 2P₂ + P₃` = 1, `P₄ − 2P₅ + P₆` = 0): `C¹`.
#[test]
fn parts_scaled_apart_meet() {
    let heights = [0, 0, 0, 1, 1, 2, 3, 4];
    for right in [1, 2] {
        let weights = [1, 1, 1, 1, right, right, right, right];
        assert_eq!(only_line(&cubic_in_u(&[1; 4], &heights, &weights)), Some(1));
    }
}

/// The same bump with u and v exchanged is a v-line.
#[test]
fn v_knots_are_read_from_the_rows() {
    let s = cubic_in_u(&[1], &[0, 0, 1, 0, 0], &[1; 5]);
    let (u, v) = s.knots();
    let swapped = NurbsSurface::new(v.clone(), u.clone(), transpose(s.control_points())).unwrap();
    let lines = surface_knot_lines(&swapped);
    assert_eq!(lines.len(), 1);
    assert_eq!(
        (lines[0].direction, lines[0].continuity),
        (Direction::V, Some(2))
    );
}

fn transpose(net: &[Vec<HPoint<Q>>]) -> Vec<Vec<HPoint<Q>>> {
    (0..net[0].len())
        .map(|j| net.iter().map(|row| row[j].clone()).collect())
        .collect()
}

/// Boehm's knot insertion of `t` (strictly inside the domain) into a
/// degree-`p` curve: with `u_k ≤ t < u_{k+1}`,
/// `P'_i = (1 − a_i) P_{i−1} + a_i P_i`, `a_i = (t − u_i)/(u_{i+p} − u_i)`
/// for `k − p < i ≤ k`; the points before are kept, those after shift by
/// one. The curve is unchanged (Piegl & Tiller §5.2).
fn insert(knots: &[Q], p: usize, points: &[HPoint<Q>], t: &Q) -> (Vec<Q>, Vec<HPoint<Q>>) {
    let k = knots.iter().rposition(|x| x <= t).unwrap();
    let new = (0..=points.len())
        .map(|i| match i {
            _ if i + p <= k => points[i].clone(),
            _ if i > k => points[i - 1].clone(),
            _ => {
                let a = (t - &knots[i]) / (&knots[i + p] - &knots[i]);
                points[i - 1].lerp(&points[i], &a)
            }
        })
        .collect();
    let mut knots = knots.to_vec();
    knots.insert(k + 1, t.clone());
    (knots, new)
}

/// A surface under construction: degrees, knots, net (`net[i][j]`, i along u).
#[derive(Clone, Debug)]
struct Raw {
    p: usize,
    u: Vec<Q>,
    q: usize,
    v: Vec<Q>,
    net: Vec<Vec<HPoint<Q>>>,
}

impl Raw {
    /// `t` inserted `times` times in u.
    fn insert_u(mut self, t: &Q, times: usize) -> Raw {
        for _ in 0..times {
            let columns: Vec<(Vec<Q>, Vec<HPoint<Q>>)> = transpose(&self.net)
                .iter()
                .map(|c| insert(&self.u, self.p, c, t))
                .collect();
            self.u = columns[0].0.clone();
            let cols: Vec<Vec<HPoint<Q>>> = columns.into_iter().map(|c| c.1).collect();
            self.net = transpose(&cols);
        }
        self
    }

    fn swapped(self) -> Raw {
        Raw {
            p: self.q,
            u: self.v,
            q: self.p,
            v: self.u,
            net: transpose(&self.net),
        }
    }

    fn build(&self) -> NurbsSurface<Q> {
        let u = Knots::new(self.p, self.u.clone(), self.net.len()).unwrap();
        let v = Knots::new(self.q, self.v.clone(), self.net[0].len()).unwrap();
        NurbsSurface::new(u, v, self.net.clone()).unwrap()
    }
}

/// Knot values shared by the random knots and the insertions, so that
/// insertions raise existing multiplicities.
const POOL: [(i64, i64); 4] = [(1, 5), (1, 3), (1, 2), (3, 4)];

/// Degree `p` knots on the domain [0, 1]: clamped or not at each end, and
/// up to three interior values of [`POOL`] with multiplicities `1..=p+2`
/// (over p + 1 the surface falls apart and some control points are unused).
fn knots(p: usize) -> impl Strategy<Value = Vec<Q>> {
    let inner = prop::collection::btree_map(0..POOL.len(), 1..=p + 2, 0..=3);
    (any::<bool>(), any::<bool>(), inner).prop_map(move |(clamp_lo, clamp_hi, inner)| {
        let end = |clamp: bool, base: i64, step: i64| {
            (0..=p as i64).map(move |i| q(if clamp { base } else { base + step * i }, 1))
        };
        let mut k: Vec<Q> = end(clamp_lo, 0, -1)
            .collect::<Vec<_>>()
            .into_iter()
            .rev()
            .collect();
        for (i, m) in inner {
            k.extend(std::iter::repeat_n(q(POOL[i].0, POOL[i].1), m));
        }
        k.extend(end(clamp_hi, 1, 1));
        k
    })
}

/// A homogeneous point of the plane with small integer coordinates and a
/// positive weight (few values, so that equalities happen).
fn point() -> impl Strategy<Value = HPoint<Q>> {
    let weight = prop::sample::select(vec![q(1, 1), q(2, 1), q(1, 2), q(3, 1)]);
    (-3i64..=3, -3i64..=3, weight).prop_map(|(x, y, w)| HPoint::from_point(&[q(x, 1), q(y, 1)], &w))
}

/// A random surface of degrees 1–3.
fn raw() -> impl Strategy<Value = Raw> {
    (1usize..=3, 1usize..=3)
        .prop_flat_map(|(p, q)| (Just(p), knots(p), Just(q), knots(q)))
        .prop_flat_map(|(p, u, q, v)| {
            let (rows, cols) = (u.len() - p - 1, v.len() - q - 1);
            let net = prop::collection::vec(prop::collection::vec(point(), cols), rows);
            net.prop_map(move |net| Raw {
                p,
                u: u.clone(),
                q,
                v: v.clone(),
                net,
            })
        })
}

/// Changes planted in a random surface: knot insertions (direction,
/// value of [`POOL`], times), the block of control points from a row and a
/// column on scaled by a factor (whole rows when the column is `None`),
/// and one control point moved.
type Plant = (
    Vec<(bool, usize, usize)>,
    Option<(bool, usize, Option<usize>, i64)>,
    Option<(usize, usize, HPoint<Q>)>,
);

fn plant() -> impl Strategy<Value = Plant> {
    let insertions = prop::collection::vec((any::<bool>(), 0..POOL.len(), 1usize..=4), 0..=2);
    let scale = prop::option::of((
        any::<bool>(),
        0usize..20,
        prop::option::of(0usize..20),
        2i64..=3,
    ));
    let moved = prop::option::of((0usize..20, 0usize..20, point()));
    (insertions, scale, moved)
}

/// `raw` with the changes of `plant` (indices taken modulo the net's size).
fn planted(raw: Raw, (insertions, scale, moved): Plant) -> Raw {
    let mut s = raw;
    for (in_v, value, times) in insertions {
        let t = q(POOL[value].0, POOL[value].1);
        s = if in_v {
            s.swapped().insert_u(&t, times).swapped()
        } else {
            s.insert_u(&t, times)
        };
    }
    if let Some((in_v, from, column, factor)) = scale {
        let mut t = if in_v { s.swapped() } else { s };
        let from = from % t.net.len();
        let column = column.map_or(0, |j| j % t.net[0].len());
        for row in &mut t.net[from..] {
            for x in &mut row[column..] {
                *x = x.scale(&q(factor, 1));
            }
        }
        s = if in_v { t.swapped() } else { t };
    }
    if let Some((i, j, x)) = moved {
        let i = i % s.net.len();
        let j = j % s.net[i].len();
        s.net[i][j] = x;
    }
    s
}

proptest! {
    // Parts scaled apart by different factors within one span need a full
    // knot, a scaled block starting right after it and a partial column
    // range: about one case in a hundred, so 1 000 cases (3 s).
    #![proptest_config(ProptestConfig::with_cases(1000))]

    /// Knot removal on the net gives the lines the Bézier pieces give, on
    /// random surfaces and on surfaces with planted removable knots, full
    /// knots whose parts meet (possibly scaled apart) and broken nets.
    #[test]
    fn removal_agrees_with_the_bezier_pieces(raw in raw(), plant in plant(), plain in any::<bool>()) {
        let s = if plain { raw } else { planted(raw, plant) }.build();
        let want = knot_lines(&Nurbs::Surface(s.clone()).pieces());
        prop_assert_eq!(surface_knot_lines(&s), want);
    }
}
