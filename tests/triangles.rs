//! Triangular patch operations on random exact patches.

use exact_bezier::strategy::{positive_weight, tri, unit_parameter};
use exact_bezier::{tri::affine_combination, tri::Bary, tri::SYMMETRIES, TriPatch};
use num_rational::BigRational;
use num_traits::{One, Zero};
use proptest::prelude::*;

type Q = BigRational;

fn bary(u: &Q, v: &Q) -> Bary<Q> {
    [u.clone(), v.clone(), Q::one() - u - v]
}

/// (u, v) in the closed triangle.
fn in_triangle() -> impl Strategy<Value = (Q, Q)> {
    (unit_parameter(), unit_parameter()).prop_map(|(a, b)| (a.clone() * (Q::one() - &b), a * b))
}

fn vertices() -> [Bary<Q>; 3] {
    std::array::from_fn(|k| {
        let mut b = [Q::zero(), Q::zero(), Q::zero()];
        b[k] = Q::one();
        b
    })
}

fn point_at(t: &TriPatch<Q>, x: &Bary<Q>) -> Vec<Q> {
    t.eval_hom_bary(&x[0], &x[1], &x[2]).project().unwrap()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn elevation_keeps_points(t in tri(3, 3), (u, v) in in_triangle()) {
        prop_assert_eq!(t.elevate().eval(&u, &v).unwrap(), t.eval(&u, &v).unwrap());
    }

    #[test]
    fn symmetries_permute_parameters(t in tri(3, 2), (u, v) in in_triangle()) {
        let x = bary(&u, &v);
        for sigma in SYMMETRIES {
            let mut y = x.clone();
            for a in 0..3 {
                y[sigma[a]] = x[a].clone();
            }
            prop_assert_eq!(point_at(&t.permute(sigma).unwrap(), &x), point_at(&t, &y));
        }
    }

    #[test]
    fn reparam_keeps_the_point_set(t in tri(3, 2), a in positive_weight(), b in positive_weight(), c in positive_weight(), (u, v) in in_triangle()) {
        let x = bary(&u, &v);
        let sum = a.clone() * &x[0] + b.clone() * &x[1] + c.clone() * &x[2];
        let y = [a.clone() * &x[0] / &sum, b.clone() * &x[1] / &sum, c.clone() * &x[2] / &sum];
        prop_assert_eq!(point_at(&t.reparam(&a, &b, &c), &x), point_at(&t, &y));
    }

    #[test]
    fn interior_subdivision_covers_the_patch(t in tri(3, 2), (pu, pv) in in_triangle(), (u, v) in in_triangle()) {
        let p = bary(&pu, &pv);
        let x = bary(&u, &v);
        for (a, piece) in t.subdivide_at(&p).iter().enumerate() {
            let mut verts = vertices();
            verts[a] = p.clone();
            prop_assert_eq!(point_at(piece, &x), point_at(&t, &affine_combination(&x, &verts)));
        }
    }

    #[test]
    fn edge_split_covers_the_patch(t in tri(3, 2), edge in 0usize..3, s in unit_parameter(), (u, v) in in_triangle()) {
        let [first, second] = t.split_edge(edge, &s).unwrap();
        // The split point q, and the boundary curve through it.
        let curve = t.boundary(edge).unwrap();
        let q = curve.eval(&s).unwrap();
        // Piece 1 ends at q and piece 2 starts at q along the same edge.
        prop_assert_eq!(first.boundary(edge).unwrap().eval(&Q::one()).unwrap(), q.clone());
        prop_assert_eq!(second.boundary(edge).unwrap().eval(&Q::zero()).unwrap(), q);
        // Each piece is the patch on the triangle with one edge vertex moved to q.
        let (start, end) = [(2, 0), (0, 1), (1, 2)][edge];
        let mut qb = [Q::zero(), Q::zero(), Q::zero()];
        qb[start] = Q::one() - &s;
        qb[end] = s.clone();
        let x = bary(&u, &v);
        let (mut v1, mut v2) = (vertices(), vertices());
        v1[end] = qb.clone();
        v2[start] = qb;
        prop_assert_eq!(point_at(&first, &x), point_at(&t, &affine_combination(&x, &v1)));
        prop_assert_eq!(point_at(&second, &x), point_at(&t, &affine_combination(&x, &v2)));
    }

    #[test]
    fn derivative_is_linear_in_the_direction(t in tri(3, 2), (u, v) in in_triangle()) {
        let du = [Q::one(), Q::zero(), -Q::one()];
        let dv = [Q::zero(), Q::one(), -Q::one()];
        let dw: Bary<Q> = std::array::from_fn(|k| du[k].clone() - &dv[k]);
        let a = t.directional_derivative(&u, &v, &du).unwrap();
        let b = t.directional_derivative(&u, &v, &dv).unwrap();
        let c = t.directional_derivative(&u, &v, &dw).unwrap();
        for k in 0..a.len() {
            prop_assert_eq!(c[k].clone(), a[k].clone() - &b[k]);
        }
    }
}

#[test]
fn directional_derivative_of_a_quadratic() {
    // X(u, v) = (u², v) as a polynomial quadratic: P_ijk chosen from the blossom
    // of (x, y) = (u·u, v): P_200 = (1, 0), P_110 = (0, 1/2), P_020 = (0, 1),
    // P_101 = (0, 0), P_011 = (0, 1/2), P_002 = (0, 0).
    let p = |x: i64, y: (i64, i64)| {
        vec![
            exact_bezier::ratio::<Q>(x, 1),
            exact_bezier::ratio(y.0, y.1),
        ]
    };
    let t = TriPatch::polynomial(vec![
        vec![p(0, (0, 1)), p(0, (0, 1)), p(1, (0, 1))],
        vec![p(0, (1, 2)), p(0, (1, 2))],
        vec![p(0, (1, 1))],
    ])
    .unwrap();
    let (u, v) = (
        exact_bezier::ratio::<Q>(1, 3),
        exact_bezier::ratio::<Q>(1, 5),
    );
    assert_eq!(t.eval(&u, &v).unwrap(), vec![u.clone() * &u, v.clone()]);
    let du = [Q::one(), Q::zero(), -Q::one()];
    // ∂/∂u (u², v) = (2u, 0)
    assert_eq!(
        t.directional_derivative(&u, &v, &du).unwrap(),
        vec![exact_bezier::ratio(2, 3), Q::zero()]
    );
}

#[test]
fn bad_arguments_are_errors() {
    let p = |x: i64| vec![exact_bezier::ratio::<Q>(x, 1)];
    let t = TriPatch::polynomial(vec![vec![p(0), p(1)], vec![p(2)]]).unwrap();
    assert!(t.permute([0, 0, 1]).is_err());
    assert!(t.boundary(3).is_err());
    assert!(t.split_edge(5, &Q::one()).is_err());
    assert!(t.blossom(&[]).is_err());
}
