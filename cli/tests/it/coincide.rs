//! Coincidence, minimal degree, canonical keys and the filtered predicate on
//! random exact patches: copies made by the maps (1)–(6) coincide, and the
//! witness reproduces them; perturbed copies do not.

use crate::common::cli_json as cli;
use exact_bezier::strategy::*;
use exact_bezier::{
    coincide::canonical_key, coincide::coincide, coincide::dedup, coincide::minimal_curve,
    coincide::minimal_rect, coincide::multiply_components, coincide::shared_boundaries,
    coincide::Edge, coincide::MobiusParam, coincide::Options, coincide::Symmetry, io::read_patches,
    ratio, Patch, RationalCurve, RectPatch, Tolerance,
};
use num_rational::BigRational;
use proptest::prelude::*;
use proptest::strategy::ValueTree;

type Q = BigRational;

/// The maps (1)–(6) with their parameters.
#[derive(Clone, Debug)]
struct Maps {
    sym: Symmetry,
    alpha: Q,
    beta: Q,
    k: Q,
    elevate: (usize, usize),
    /// A positive bilinear factor multiplied into every component.
    factor: Option<Vec<Vec<Q>>>,
}

fn maps() -> impl Strategy<Value = Maps> {
    maps_with(open_unit_parameter, positive_weight())
}

/// The maps with Möbius parameters in `[1/20, 19/20]` and `k` in
/// `[1/10, 10]`: the f64 path's round-off then stays well below its
/// tolerance (α = 1/744 with weights from 1/3 to 868 loses 5 digits).
fn moderate_maps() -> impl Strategy<Value = Maps> {
    maps_with(|| rational_in(1, 19, 20), moderate_weight())
}

fn maps_with<P: Strategy<Value = Q>>(
    parameter: impl Fn() -> P,
    weight: impl Strategy<Value = Q>,
) -> impl Strategy<Value = Maps> {
    (
        0u8..8,
        parameter(),
        parameter(),
        weight,
        (0usize..=1, 0usize..=1),
        proptest::option::of(proptest::collection::vec(
            proptest::collection::vec(1i64..=5, 2),
            2,
        )),
    )
        .prop_map(|(s, alpha, beta, k, elevate, f)| Maps {
            sym: Symmetry::all().nth(s as usize).unwrap(),
            alpha,
            beta,
            k,
            elevate,
            factor: f.map(|g| {
                g.iter()
                    .map(|r| r.iter().map(|&x| ratio(x, 1)).collect())
                    .collect()
            }),
        })
}

/// Factor, then elevate, then Möbius (so Möbius adds linear common factors
/// too), then scale, then the symmetry.
fn apply(a: &RectPatch<Q>, t: &Maps) -> RectPatch<Q> {
    let base = match &t.factor {
        Some(f) => multiply_components(a, f),
        None => a.clone(),
    };
    let moved = base
        .elevate(t.elevate.0, t.elevate.1)
        .mobius_u(&t.alpha)
        .mobius_v(&t.beta)
        .scale_weights(&t.k);
    t.sym.apply_rect(&moved)
}

fn bidegree() -> impl Strategy<Value = RectPatch<Q>> {
    (1usize..=3, 1usize..=2).prop_flat_map(|(m, n)| rect(m, n, 3))
}

/// Weights `p/q` with `1 ≤ p, q ≤ 10`.
fn moderate_weight() -> impl Strategy<Value = Q> + Clone {
    (1i64..=10, 1i64..=10).prop_map(|(p, q)| ratio(p, q))
}

/// A patch like [`bidegree`] with weights in `[1/10, 10]`, for the f64 path.
fn moderate_bidegree() -> impl Strategy<Value = RectPatch<Q>> {
    (1usize..=3, 1usize..=2).prop_flat_map(|(m, n)| rect_weighted(m, n, 3, moderate_weight()))
}

fn value(p: &MobiusParam<Q>) -> Q {
    match p {
        MobiusParam::Value { alpha, .. } => alpha.clone(),
        other => panic!("expected a rational Möbius parameter, got {other:?}"),
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    #[test]
    fn transformed_copies_coincide_and_the_witness_reproduces_them(a in bidegree(), t in maps()) {
        // Mixed (bivariate) factors run the slow pseudo-remainder gcd: they
        // have their own test with fewer cases.
        let b = apply(&a, &Maps { factor: None, ..t });
        let (pa, pb) = (Patch::Rect(a.clone()), Patch::Rect(b.clone()));
        let c = coincide(&pa, &pb, Options::default()).unwrap();
        prop_assert!(c.coincident, "{}", c.reason);
        let w = c.witness.unwrap();
        let (ra, rb) = (minimal_rect(&a).unwrap().patch, minimal_rect(&b).unwrap().patch);
        prop_assert_eq!(ra.degree(), a.degree());
        let rebuilt = w
            .symmetry
            .apply_rect(&ra)
            .mobius_u(&value(&w.u))
            .mobius_v(&value(&w.v))
            .scale_weights(w.k.as_ref().unwrap());
        prop_assert_eq!(rebuilt, rb);
        prop_assert_eq!(canonical_key(&pa).unwrap(), canonical_key(&pb).unwrap());
        prop_assert!(coincide(&pa, &pb, Options::filtered()).unwrap().coincident);
    }

    #[test]
    fn mixed_common_factors_are_removed(a in rect(2, 1, 2), t in maps(), f in proptest::collection::vec(1i64..=5, 4)) {
        let f = vec![vec![ratio(f[0], 1), ratio(f[1], 1)], vec![ratio(f[2], 1), ratio(f[3], 1)]];
        let b = apply(&a, &Maps { factor: Some(f), elevate: (0, 0), ..t });
        let c = coincide(&Patch::Rect(a.clone()), &Patch::Rect(b.clone()), Options::default()).unwrap();
        prop_assert!(c.coincident, "{}", c.reason);
        let ((m, n), to) = (a.degree(), c.reductions[1].to);
        prop_assert!(to == (m, n) || to == (n, m), "{:?}", to);
    }

    #[test]
    fn a_perturbed_weight_or_point_is_detected(
        a in bidegree(), t in maps(), at in (0usize..4, 0usize..3), point in any::<bool>()
    ) {
        let (m, n) = a.degree();
        let (i, j) = (at.0.min(m), at.1.min(n));
        let mut pts = a.points().unwrap();
        let mut ws = a.weights();
        if point {
            pts[i][j][0] = pts[i][j][0].clone() + ratio::<Q>(1, 7);
        } else {
            ws[i][j] = ws[i][j].clone() * ratio::<Q>(8, 7);
        }
        let bent = RectPatch::new(pts, ws).unwrap();
        let t = Maps { factor: None, ..t };
        let (pa, pb) = (Patch::Rect(a), Patch::Rect(apply(&bent, &t)));
        let c = coincide(&pa, &pb, Options::default()).unwrap();
        prop_assert!(!c.coincident);
        prop_assert!(c.reason.contains("differs") || c.reason.contains("invariant"), "{}", c.reason);
        prop_assert_ne!(canonical_key(&pa).unwrap(), canonical_key(&pb).unwrap());
        prop_assert!(!coincide(&pa, &pb, Options::filtered()).unwrap().coincident);
    }

    #[test]
    fn f64_path_agrees_on_copies_and_perturbations(a in moderate_bidegree(), t in moderate_maps()) {
        // Möbius before elevation: the f64 path undoes elevation but removes
        // no common factors.
        let moved = |r: &RectPatch<Q>| {
            let m = r.mobius_u(&t.alpha).mobius_v(&t.beta).scale_weights(&t.k);
            t.sym.apply_rect(&m.elevate(t.elevate.0, t.elevate.1))
        };
        let b = moved(&a);
        let (fa, fb) = (Patch::Rect(a.clone()).to_f64(), Patch::Rect(b).to_f64());
        let c = coincide(&fa, &fb, Options::within(Tolerance(1e-6))).unwrap();
        prop_assert!(c.coincident, "{}", c.reason);
        let mut ws = a.weights();
        ws[0][0] = ws[0][0].clone() * ratio::<Q>(3, 2);
        let bent = RectPatch::new(a.points().unwrap(), ws).unwrap();
        let (qa, qbent) = (Patch::Rect(a.clone()), Patch::Rect(moved(&bent)));
        let exact = coincide(&qa, &qbent, Options::default()).unwrap();
        let float = coincide(&fa, &qbent.to_f64(), Options::within(Tolerance(1e-6))).unwrap();
        prop_assert_eq!(float.coincident, exact.coincident, "{} / {}", float.reason, exact.reason);
    }

    #[test]
    fn curves_elevated_then_moved_reduce_and_coincide(
        c in curve(3, 2), alpha in open_unit_parameter(), k in positive_weight(), r in 1usize..=2, rev in any::<bool>()
    ) {
        let mut b = c.elevate(r).mobius(&alpha).scale_weights(&k);
        if rev {
            b = b.reverse();
        }
        let red = minimal_curve(&b).unwrap();
        prop_assert_eq!(red.degree_after, (3, 0));
        // α = 1/2 is the identity map up to scaling: then there is no factor.
        prop_assert_eq!(red.common_factor == "1", alpha == ratio(1, 2));
        let res = coincide(&Patch::Curve(c), &Patch::Curve(b), Options::default()).unwrap();
        prop_assert!(res.coincident, "{}", res.reason);
        prop_assert_eq!(res.witness.unwrap().symmetry.reverse_u, rev);
    }
}

fn fixture(name: &str) -> Patch<Q> {
    let text = crate::common::read_to_string(format!("tests/fixtures/{name}.json")).unwrap();
    read_patches(&text).unwrap().remove(0)
}

#[test]
fn example3_is_not_example1() {
    let (ex1, ex3) = (fixture("yang_yong_example1"), fixture("yang_yong_example3"));
    let c = coincide(&ex1, &ex3, Options::default()).unwrap();
    assert!(!c.coincident);
    // By hand: I_{0,2} = ω02·ω00/ω01² = 2·8/25 = 16/25 for Example 1, and
    // 7.84·1.44/4.22² = 112896/178084 = 28224/44521 for Example 3.
    assert!(
        c.reason
            .starts_with("weight invariant I_{0,2} is 16/25 vs 28224/44521"),
        "{}",
        c.reason
    );
}

#[test]
fn example1_against_a_standardizing_map_of_itself() {
    let ex1 = fixture("yang_yong_example1");
    let Patch::Rect(r) = &ex1 else { panic!() };
    // α = 3/5, β = 7/10 (Example 3's printed parameters, applied exactly).
    let moved = Patch::Rect(
        r.mobius_u(&ratio(3, 5))
            .mobius_v(&ratio(7, 10))
            .scale_weights(&ratio(4, 1)),
    );
    let c = coincide(&ex1, &moved, Options::default()).unwrap();
    assert!(c.coincident);
    let w = c.witness.unwrap();
    assert_eq!(w.symmetry, Symmetry::IDENTITY);
    assert_eq!(value(&w.u), ratio(3, 5));
    assert_eq!(value(&w.v), ratio(7, 10));
    assert_eq!(w.k, Some(ratio(4, 1)));
}

#[test]
fn shared_boundary_between_two_patches() {
    let p = |x: i64, y: i64, z: i64| vec![ratio::<Q>(x, 1), ratio(y, 1), ratio(z, 1)];
    let w = |x: i64| ratio::<Q>(x, 1);
    let a = RectPatch::new(
        vec![
            vec![p(0, 0, 0), p(0, 1, 1), p(0, 2, 0)],
            vec![p(1, 0, 2), p(1, 1, 3), p(1, 2, 1)],
        ],
        vec![vec![w(1), w(2), w(3)], vec![w(2), w(5), w(1)]],
    )
    .unwrap();
    // b's v = 0 column is a's u = 1 row reversed, Möbius-moved and elevated.
    let edge = exact_bezier::coincide::boundary_curve(&a, Edge::U1)
        .reverse()
        .mobius(&ratio(1, 3))
        .elevate(1);
    let ctrl: Vec<Vec<_>> = edge
        .ctrl()
        .iter()
        .enumerate()
        .map(|(i, h)| {
            let other = exact_bezier::hpoint::HPoint::from_point(&p(5, i as i64, 7), &w(1));
            vec![h.clone(), other]
        })
        .collect();
    let b = RectPatch::from_hom(ctrl).unwrap();
    let shared = shared_boundaries(&a, &b).unwrap();
    let pairs: Vec<(Edge, Edge)> = shared.iter().map(|(x, y, _)| (*x, *y)).collect();
    assert_eq!(pairs, vec![(Edge::U1, Edge::V0)]);
    assert!(shared[0].2.witness.as_ref().unwrap().symmetry.reverse_u);
}

#[test]
fn dedup_finds_planted_duplicates() {
    let mut runner = proptest::test_runner::TestRunner::deterministic();
    let base: Vec<RectPatch<Q>> = (0..6)
        .map(|_| rect(2, 3, 3).new_tree(&mut runner).unwrap().current())
        .collect();
    let t = maps();
    let mut all: Vec<Patch<Q>> = base.iter().cloned().map(Patch::Rect).collect();
    for k in [1, 4, 1] {
        let m = t.new_tree(&mut runner).unwrap().current();
        all.push(Patch::Rect(apply(&base[k], &Maps { factor: None, ..m })));
    }
    let classes = dedup(&all).unwrap();
    assert_eq!(
        classes,
        vec![
            vec![0],
            vec![1, 6, 8],
            vec![2],
            vec![3],
            vec![4, 7],
            vec![5]
        ]
    );
}

#[test]
fn minimal_degree_of_elevated_then_moved_patch() {
    let p = |x: i64, y: i64| vec![ratio::<Q>(x, 1), ratio(y, 1)];
    let a = RectPatch::new(
        vec![vec![p(0, 0), p(0, 1)], vec![p(1, 0), p(2, 3)]],
        vec![
            vec![ratio(1, 1), ratio(2, 1)],
            vec![ratio(3, 1), ratio(1, 2)],
        ],
    )
    .unwrap();
    // Möbius after elevation: the factors (α(1−u) + (1−α)u)² (u: elevated twice)
    // and β(1−v) + (1−β)v, found by the gcd.
    let big = a
        .elevate(2, 1)
        .mobius_u(&ratio(1, 3))
        .mobius_v(&ratio(1, 4));
    let red = minimal_rect(&big).unwrap();
    assert!(!red.certified);
    assert_eq!(red.degree_after, (1, 1));
    // Expected factor up to normalization: (1 + u)²·(1 + 2v)/2, with leading coefficient 1:
    // α = 1/3: (1/3)(1−u) + (2/3)u ∝ 1 + u; β = 1/4: (1/4)(1−v) + (3/4)v ∝ 1 + 2v.
    assert_eq!(red.common_factor, "u^2*v + 1/2*u^2 + 2*u*v + u + v + 1/2");
    // Möbius before elevation: pure elevation, no factor.
    let plain = a.mobius_u(&ratio(1, 3)).elevate(2, 1);
    assert_eq!(minimal_rect(&plain).unwrap().common_factor, "1");
    assert_eq!(
        minimal_rect(&plain).unwrap().patch,
        a.mobius_u(&ratio(1, 3))
    );
}

#[test]
fn degree_zero_direction_and_curve_patch_mismatch_are_handled() {
    let p = |x: i64| vec![ratio::<Q>(x, 1)];
    let c = RationalCurve::polynomial(vec![p(0), p(1)]).unwrap();
    let r = RectPatch::polynomial(vec![vec![p(0), p(1)]]).unwrap();
    let res = coincide(
        &Patch::Curve(c),
        &Patch::Rect(r.clone()),
        Options::default(),
    )
    .unwrap();
    assert!(!res.coincident);
    let copy = r.mobius_v(&ratio(2, 9)).swap_uv();
    assert!(
        coincide(&Patch::Rect(r), &Patch::Rect(copy), Options::default())
            .unwrap()
            .coincident
    );
}

#[test]
fn cli_coincide() {
    let (ex1, ex3) = (
        "tests/fixtures/yang_yong_example1.json",
        "tests/fixtures/yang_yong_example3.json",
    );
    let (code, v) = cli(&["coincide", ex1, ex3]);
    assert_eq!(code, 0);
    assert_eq!(v["coincident"], false);
    assert!(v["reason"].as_str().unwrap().contains("I_{0,2}"));
    let (code, v) = cli(&["coincide", ex1, ex1, "--filtered"]);
    assert_eq!((code, v["coincident"].clone()), (0, true.into()));
    assert_eq!(v["decided_by"], "exact");
    let (code, v) = cli(&["coincide", ex1, ex3, "--scalar", "f64", "--tol", "0.05"]);
    assert_eq!((code, v["coincident"].clone()), (0, true.into()));
    assert_eq!(cli(&["coincide", ex1, "tests/fixtures/README.md"]).0, 2);
    assert_eq!(cli(&["coincide", ex1, ex3, "--tol", "1e-3"]).0, 2);
}

/// `x · (1 + 10⁻¹²)`, or `10⁻¹²` for zero: a perturbation far below f64
/// tolerances of typical CAD data, which exact keys must still see.
fn nudge(x: &Q) -> Q {
    let eps = Q::new(1.into(), num_bigint::BigInt::from(10).pow(12));
    if *x == ratio(0, 1) {
        eps
    } else {
        x.clone() * (Q::from_integer(1.into()) + eps)
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    #[test]
    fn key_digests_agree_with_pairwise_coincide(
        a in bidegree(), t in maps(), at in (0usize..4, 0usize..3), point in any::<bool>(), other in bidegree()
    ) {
        use exact_bezier::coincide::key_digest;
        let t = Maps { factor: None, ..t };
        let (m, n) = a.degree();
        let (i, j) = (at.0.min(m), at.1.min(n));
        let (mut pts, mut ws) = (a.points().unwrap(), a.weights());
        if point {
            pts[i][j][1] = nudge(&pts[i][j][1]);
        } else {
            ws[i][j] = nudge(&ws[i][j]);
        }
        let bent = RectPatch::new(pts, ws).unwrap();
        let pa = Patch::Rect(a.clone());
        for b in [apply(&a, &t), apply(&bent, &t), other] {
            let pb = Patch::Rect(b);
            let same = coincide(&pa, &pb, Options::default()).unwrap().coincident;
            prop_assert_eq!(key_digest(&pa).unwrap() == key_digest(&pb).unwrap(), same);
        }
    }

    #[test]
    fn curve_key_digests_agree_with_pairwise_coincide(
        c in curve(3, 2), alpha in open_unit_parameter(), k in positive_weight(), at in 0usize..4, rev in any::<bool>()
    ) {
        use exact_bezier::coincide::key_digest;
        let moved = |c: &RationalCurve<Q>| {
            let b = c.elevate(1).mobius(&alpha).scale_weights(&k);
            if rev { b.reverse() } else { b }
        };
        let mut ws = c.weights();
        ws[at] = nudge(&ws[at]);
        let bent = RationalCurve::new(c.points().unwrap(), ws).unwrap();
        let pa = Patch::Curve(c.clone());
        for (b, expected) in [(moved(&c), true), (moved(&bent), false)] {
            let pb = Patch::Curve(b);
            prop_assert_eq!(coincide(&pa, &pb, Options::default()).unwrap().coincident, expected);
            prop_assert_eq!(key_digest(&pa).unwrap() == key_digest(&pb).unwrap(), expected);
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// The machine-integer fast path of the key text agrees with the
    /// general `BigRational` one: on ties between symmetries (mirrored
    /// points), on copies, and on weights too big for `i128` (fallback).
    #[test]
    fn fast_key_text_is_the_general_one(
        a in bidegree(), t in maps(), mirror in any::<bool>(), big in 0u32..3, c in curve(3, 2)
    ) {
        use exact_bezier::coincide::canonical_text;
        let (m, _) = a.degree();
        let (mut pts, mut ws) = (a.points().unwrap(), a.weights());
        if mirror {
            for i in 0..=m / 2 {
                pts[m - i] = pts[i].clone();
            }
        }
        let scale = Q::new(num_bigint::BigInt::from(10).pow(12 * big), 7.into());
        ws[0][0] = ws[0][0].clone() * scale;
        let r = RectPatch::new(pts, ws).unwrap();
        let moved = apply(&r, &Maps { factor: None, elevate: (0, 0), ..t.clone() });
        let curves = [c.clone(), c.mobius(&t.alpha).reverse()];
        let all = [Patch::Rect(r), Patch::Rect(moved)].into_iter().chain(curves.into_iter().map(Patch::Curve));
        for p in all {
            prop_assert_eq!(canonical_text(&p).unwrap(), canonical_key(&p).unwrap().text());
        }
    }
}
