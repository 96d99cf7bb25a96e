//! Trigonometric curves and surfaces (source 002): exact laws over random
//! rational τ and α, G¹ of constructed joins, f64/exact agreement, the bowl
//! fixtures and the `eval` command line.

use crate::common::cli;
use exact_bezier::strategy::{point, positive_weight, rational_in, small_rational, unit_parameter};
use exact_bezier::{
    io::read_trig_patches, io::trig_patch_to_json, io::TrigPatch, ratio, trig::trig_basis_values,
    trig::trig_bowl, trig::trig_g0, trig::trig_g1_factor, trig::trig_stitch,
    trig::trig_tangent_continuous, trig::TrigCurve, trig::TrigJoin, trig::TrigParam,
    trig::TrigRect, Error, Ordered, Tolerance,
};
use num_rational::BigRational;
use num_traits::{One, Zero};
use proptest::collection::vec;
use proptest::prelude::*;

type Q = BigRational;

/// A shape parameter in (0, 2] with denominator 100.
fn shape() -> impl Strategy<Value = Q> {
    rational_in(1, 200, 100)
}

fn rect() -> impl Strategy<Value = TrigRect<Q>> {
    (vec(vec(point(3), 4), 4), shape(), shape())
        .prop_map(|(p, a1, a2)| TrigRect::new(p, [a1, a2]).expect("4 × 4"))
}

fn near(a: &[f64], b: &[f64], tol: f64) -> bool {
    a.iter().zip(b).all(|(x, y)| (x - y).abs() <= tol)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn partition_of_unity(tau in unit_parameter(), alpha in small_rational(), k in 1usize..4) {
        let at = TrigParam::from_tau(&tau);
        let sum = |k| trig_basis_values(&alpha, k, &at).into_iter().fold(Q::zero(), |a, x| a + x);
        prop_assert_eq!(sum(0), Q::one());
        prop_assert_eq!(sum(k), Q::zero());
    }

    #[test]
    fn non_negative_for_alpha_in_0_2(tau in unit_parameter(), alpha in rational_in(0, 200, 100)) {
        let x = trig_basis_values(&alpha, 0, &TrigParam::from_tau(&tau));
        prop_assert!(x.iter().all(|v| *v >= Q::zero()));
    }

    #[test]
    fn corrected_g0_condition(s1 in rect(), l1 in shape(), rest in vec(vec(point(3), 4), 4)) {
        // λ₁(Q₁₀ − Q₀₀) = α₁(P₁₃ − P₀₃), λ₁(Q₂₀ − Q₃₀) = α₁(P₂₃ − P₃₃), shared ends.
        let a1 = s1.alpha()[0].clone();
        let p = |i: usize| s1.points()[i][3].clone();
        let toward = |from: Vec<Q>, to: Vec<Q>| -> Vec<Q> {
            from.iter().zip(&to).map(|(a, b)| a.clone() + &((b.clone() - a) * &a1 / &l1)).collect()
        };
        let edge = [p(0), toward(p(0), p(1)), toward(p(3), p(2)), p(3)];
        let mut q = rest.clone();
        for i in 0..4 {
            q[i][0] = edge[i].clone();
        }
        let s2 = TrigRect::new(q, [l1.clone(), ratio(1, 1)]).unwrap();
        prop_assert!(trig_g0(&s1, &s2, TrigJoin::UU, Tolerance::EXACT));
    }

    #[test]
    fn theorem_1_monotonicity(tau in unit_parameter(), a in shape(), b in shape()) {
        // Larger α: X₁, X₂ grow, X₀, X₃ shrink (Theorem 1).
        let at = TrigParam::from_tau(&tau);
        let (lo, hi) = if a <= b { (a, b) } else { (b, a) };
        let (x, y) = (trig_basis_values(&lo, 0, &at), trig_basis_values(&hi, 0, &at));
        prop_assert!(y[1] >= x[1] && y[2] >= x[2] && y[0] <= x[0] && y[3] <= x[3]);
    }

    #[test]
    fn constructed_joins_are_g1(s1 in rect(), l2 in shape(), mu in positive_weight(),
                                far in vec(vec(point(3), 4), 2), tau in unit_parameter()) {
        let s2 = trig_stitch(&s1, l2, mu.clone(), [far[0].clone(), far[1].clone()]).unwrap();
        prop_assert!(trig_g0(&s1, &s2, TrigJoin::UU, Tolerance::EXACT));
        prop_assert_eq!(trig_g1_factor(&s1, &s2, TrigJoin::UU, Tolerance::EXACT), Some(mu.clone()));
        // Second method: the derivatives at one exact point.
        let u = TrigParam::from_tau(&tau);
        let d1 = s1.partial(0, 1, &u, &TrigParam::end());
        let d2 = s2.partial(0, 1, &u, &TrigParam::start());
        prop_assert_eq!(d1, d2.iter().map(|x| x.clone() * &mu).collect::<Vec<_>>());
        prop_assert_eq!(s1.eval(&u, &TrigParam::end()), s2.eval(&u, &TrigParam::start()));
        prop_assert_eq!(trig_tangent_continuous(&s1, &s2, TrigJoin::UU, Tolerance::EXACT), Ok(true));
        // Folding the neighbour back (Qᵢ₁ ↦ 2Qᵢ₀ − Qᵢ₁) turns its normals round.
        let mut folded = s2.points().to_vec();
        for row in folded.iter_mut() {
            row[1] = row[0].iter().zip(&row[1]).map(|(a, b)| a.clone() + a - b).collect();
        }
        let folded = TrigRect::new(folded, s2.alpha().clone()).unwrap();
        prop_assert_eq!(trig_g1_factor(&s1, &folded, TrigJoin::UU, Tolerance::EXACT), None);
        prop_assert_eq!(trig_tangent_continuous(&s1, &folded, TrigJoin::UU, Tolerance::EXACT), Ok(false));
    }

    #[test]
    fn swapped_joins_are_g1(s1 in rect(), l in shape(), mu in positive_weight(),
                            far in vec(vec(point(3), 4), 2)) {
        // v–v: stitch the transpose and transpose back.
        let s2 = trig_stitch(&s1.swap_uv(), l, mu.clone(), [far[0].clone(), far[1].clone()]).unwrap();
        prop_assert_eq!(trig_g1_factor(&s1, &s2.swap_uv(), TrigJoin::VV, Tolerance::EXACT), Some(mu.clone()));
        // u–v: the u–u neighbour with u and v exchanged.
        let n = trig_stitch(&s1, s1.alpha()[1].clone(), mu.clone(), [far[0].clone(), far[1].clone()]).unwrap();
        prop_assert_eq!(trig_g1_factor(&s1, &n.swap_uv(), TrigJoin::UV, Tolerance::EXACT), Some(mu));
    }

    #[test]
    fn exact_and_f64_agree(s in rect(), tu in unit_parameter(), tv in unit_parameter()) {
        let (u, v) = (TrigParam::from_tau(&tu), TrigParam::from_tau(&tv));
        let exact: Vec<f64> = s.partial(1, 1, &u, &v).iter().map(Ordered::to_f64).collect();
        let angle = |t: &Q| 2.0 * t.to_f64().atan();
        let (fu, fv) = (TrigParam::from_angle(angle(&tu)), TrigParam::from_angle(angle(&tv)));
        let float = s.map(Ordered::to_f64).partial(1, 1, &fu, &fv);
        prop_assert!(near(&exact, &float, 1e-9 * (1.0 + exact.iter().fold(0.0f64, |m, x| m.max(x.abs())))));
    }

    #[test]
    fn reversal_reverses_the_parameter(p in vec(point(2), 4), alpha in shape(), tau in unit_parameter()) {
        let c = TrigCurve::new(p, alpha).unwrap();
        let at = TrigParam::from_tau(&tau);
        prop_assert_eq!(c.reverse().eval(&at.reflect()), c.eval(&at));
    }
}

#[test]
fn curve_value_by_hand() {
    // α = 1, τ = 1/2 (s = 4/5, c = 3/5): X = (1/5, 4/25, 6/25, 2/5) from the factorized
    // forms (1−s), s(1−s), c(1−c), 1−c; P = (0,0), (1,2), (3,2), (4,0).
    let p = |x: i64, y: i64| vec![ratio::<Q>(x, 1), ratio(y, 1)];
    let c = TrigCurve::new(vec![p(0, 0), p(1, 2), p(3, 2), p(4, 0)], ratio(1, 1)).unwrap();
    let at = TrigParam::from_tau(&ratio(1, 2));
    assert_eq!(c.eval(&at), vec![ratio(62, 25), ratio(4, 5)]);
}

#[test]
fn surface_partials_match_finite_differences() {
    let net: Vec<Vec<Vec<f64>>> = (0..4)
        .map(|i| {
            (0..4)
                .map(|j| vec![i as f64, j as f64, ((i * j) % 5) as f64])
                .collect()
        })
        .collect();
    let s = TrigRect::new(net, [1.2, 0.7]).unwrap();
    let (u, v, h) = (0.4, 0.9, 1e-4);
    let at = |u: f64, v: f64| (TrigParam::from_angle(u), TrigParam::from_angle(v));
    let f = |ku, kv, u, v| {
        let (a, b) = at(u, v);
        s.partial(ku, kv, &a, &b)
    };
    let fd_uv: Vec<f64> = (0..3)
        .map(|k| {
            (f(0, 0, u + h, v + h)[k] - f(0, 0, u + h, v - h)[k] - f(0, 0, u - h, v + h)[k]
                + f(0, 0, u - h, v - h)[k])
                / (4.0 * h * h)
        })
        .collect();
    assert!(near(&f(1, 1, u, v), &fd_uv, 1e-5));
    let fd_uu: Vec<f64> = (0..3)
        .map(|k| (f(1, 0, u + h, v)[k] - f(1, 0, u - h, v)[k]) / (2.0 * h))
        .collect();
    assert!(near(&f(2, 0, u, v), &fd_uu, 1e-6));
}

#[test]
fn stitch_rejects_bad_parameters() {
    let net: Vec<Vec<Vec<Q>>> = (0..4)
        .map(|i| (0..4).map(|j| vec![ratio(i, 1), ratio(j, 1)]).collect())
        .collect();
    let s1 = TrigRect::new(net, [ratio(1, 1), ratio(1, 1)]).unwrap();
    let far = || [s1.points()[0].clone(), s1.points()[1].clone()];
    assert!(matches!(
        trig_stitch(&s1, ratio(1, 1), ratio(0, 1), far()),
        Err(Error::Domain(_))
    ));
    assert!(matches!(
        trig_stitch(&s1, ratio(0, 1), ratio(1, 1), far()),
        Err(Error::Domain(_))
    ));
    assert!(matches!(
        trig_stitch(&s1, ratio(1, 1), ratio(1, 1), [vec![], vec![]]),
        Err(Error::Shape(_))
    ));
    assert!(matches!(
        TrigRect::new(
            vec![vec![vec![ratio::<Q>(1, 1)]]],
            [ratio(1, 1), ratio(1, 1)]
        ),
        Err(Error::Shape(_))
    ));
}

/// Fig. 6(a) shapes and Fig. 5(a) factors.
fn bowl_parameters() -> (Q, [Q; 4], [Q; 4]) {
    let r = |k: i64| ratio::<Q>(k, 100);
    (
        r(120),
        [r(130), r(110), r(110), r(130)],
        [r(100), r(80), r(80), r(70)],
    )
}

fn fixture(name: &str) -> String {
    format!(
        "{}/tests/fixtures/{name}",
        concat!(env!("CARGO_MANIFEST_DIR"), "/..")
    )
}

/// The fixture file holds exactly these surfaces; `EXACT_BEZIER_BLESS=1`
/// rewrites it.
fn check_fixture(name: &str, surfaces: &[TrigRect<Q>]) {
    let patches: Vec<TrigPatch<Q>> = surfaces.iter().cloned().map(TrigPatch::Rect).collect();
    if std::env::var_os("EXACT_BEZIER_BLESS").is_some() {
        let json: Vec<_> = patches.iter().map(trig_patch_to_json).collect();
        std::fs::write(
            fixture(name),
            serde_json::to_string_pretty(&json).unwrap() + "\n",
        )
        .unwrap();
    }
    let text = crate::common::read_to_string(fixture(name)).unwrap();
    assert_eq!(read_trig_patches(&text).unwrap().unwrap(), patches);
}

#[test]
fn bowl_fixtures() {
    let (a1, a2, mu) = bowl_parameters();
    let g0 = trig_bowl(&a1, &a2, None).unwrap();
    let g1 = trig_bowl(&a1, &a2, Some(&mu)).unwrap();
    for k in 0..4 {
        let next = (k + 1) % 4;
        assert!(trig_g0(&g0[k], &g0[next], TrigJoin::UU, Tolerance::EXACT));
        assert_eq!(
            trig_g1_factor(&g1[k], &g1[next], TrigJoin::UU, Tolerance::EXACT),
            Some(mu[k].clone())
        );
    }
    // The printed S₁ is kept: P₀₀ = (−2.18, 2.52, 0.85), P₃₃ = (0.37, 0.80, 0.02).
    assert_eq!(
        g1[0].points()[0][0],
        vec![ratio(-218, 100), ratio(252, 100), ratio(85, 100)]
    );
    assert_eq!(
        g1[0].points()[3][3],
        vec![ratio(37, 100), ratio(80, 100), ratio(2, 100)]
    );
    // The f64 instantiation decides the same joins within a tolerance.
    let tol = Tolerance(1e-9);
    let f: Vec<TrigRect<f64>> = g1.iter().map(|s| s.map(Ordered::to_f64)).collect();
    for k in 0..4 {
        let mu_f = trig_g1_factor(&f[k], &f[(k + 1) % 4], TrigJoin::UU, tol).unwrap();
        assert!((mu_f - mu[k].to_f64()).abs() < 1e-9);
        assert_eq!(
            trig_tangent_continuous(&f[k], &f[(k + 1) % 4], TrigJoin::UU, tol),
            Ok(true)
        );
    }
    check_fixture("bowl.json", &g1);
    check_fixture("bowl_g0.json", &g0);
}

#[test]
fn cli_evaluates_trig_patches() {
    let dir = std::env::temp_dir().join(format!("trig-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let curve = dir.join("curve.json");
    std::fs::write(
        &curve,
        r#"{"kind": "trig-curve", "alpha": 1, "points": [[0,0],[1,2],[3,2],[4,0]]}"#,
    )
    .unwrap();
    let curve = curve.to_str().unwrap();
    let (code, out, _) = cli(&["eval", curve, "--at", "tau=1/2"]);
    assert_eq!(code, 0);
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["point"], serde_json::json!(["62/25", "4/5"]));
    // An angle: t = 2·atan(1/2) gives the same point in f64.
    let t = format!("{}", 2.0 * 0.5f64.atan());
    let (code, out, _) = cli(&["eval", curve, "--at", &t]);
    assert_eq!(code, 0);
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert!((v["point"][0].as_f64().unwrap() - 62.0 / 25.0).abs() < 1e-12);
    // Exact angles: angle=pi/3 is the f64 angle π/3 to 1e-12, and
    // angle=pi/2 is tau=1 exactly.
    let (code, exact) = crate::common::cli_json(&["eval", curve, "--at", "angle=pi/3"]);
    assert_eq!(code, 0);
    let third = format!("{}", std::f64::consts::FRAC_PI_3);
    let (_, float) = crate::common::cli_json(&["eval", curve, "--at", &third]);
    for (x, f) in exact["point"]
        .as_array()
        .unwrap()
        .iter()
        .zip(float["point"].as_array().unwrap())
    {
        let x = exact_bezier::algebra::parse_algebraic(x.as_str().unwrap()).unwrap();
        assert!((exact_bezier::Ordered::to_f64(&x) - f.as_f64().unwrap()).abs() < 1e-12);
    }
    let (_, right) = crate::common::cli_json(&["eval", curve, "--at", "angle=pi/2"]);
    let (_, tau1) = crate::common::cli_json(&["eval", curve, "--at", "tau=1"]);
    assert_eq!(right, tau1);
    // The bowl: S₁ at (0, 0) is P₀₀.
    let bowl = fixture("bowl.json");
    let (code, out, _) = cli(&["eval", &bowl, "--at", "tau=0,tau=0"]);
    assert_eq!(code, 0);
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(
        v[0]["point"],
        serde_json::json!(["-109/50", "63/25", "17/20"])
    );
    for bad in [
        vec!["eval", curve, "--at", "tau=2"],
        vec!["eval", curve, "--at", "tau=1/2,0.3"],
        vec!["eval", curve, "--at", "2"],
        vec!["eval", curve, "--at", "tau=1/3,tau=1/2"],
        vec!["eval", &bowl, "--at", "tau=1/3"],
    ] {
        let (code, _, err) = cli(&bad);
        assert_eq!(code, 2, "{bad:?}");
        assert_eq!(err.lines().count(), 1, "{err}");
    }
    let bad_file = dir.join("bad.json");
    for text in [
        r#"{"kind": "trig-rect", "points": []}"#,
        r#"{"kind": "trig-curve", "alpha": 1, "points": [[0],[1],[2]]}"#,
        r#"[{"kind": "trig-curve", "alpha": 1, "points": [[0],[1],[2],[3]]}, {"kind": "curve", "points": [[0]]}]"#,
        r#"{"kind": "trig-rect", "alpha": [1, 2, 3], "points": []}"#,
        r#"{"kind": "trig-cone", "alpha": 1, "points": []}"#,
    ] {
        std::fs::write(&bad_file, text).unwrap();
        let (code, _, err) = cli(&["eval", bad_file.to_str().unwrap(), "--at", "tau=0"]);
        assert_eq!(code, 2, "{text}");
        assert!(err.starts_with("error:"), "{err}");
    }
    std::fs::remove_dir_all(&dir).ok();
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    /// The rational (4,4) form agrees with the trig surface at every rational τ.
    #[test]
    fn rational_form_matches_trig_surface(s in rect(), tu in unit_parameter(), tv in unit_parameter()) {
        let (u, v) = (TrigParam::from_tau(&tu), TrigParam::from_tau(&tv));
        prop_assert_eq!(s.to_rational().eval(&tu, &tv).unwrap(), s.eval(&u, &v));
    }
}

#[test]
fn cli_converts_the_bowl_to_rational_patches() {
    let (code, out, _) = cli(&["convert", &fixture("bowl.json"), "--to", "rational"]);
    assert_eq!(code, 0);
    let rational = exact_bezier::io::read_patches(&out).unwrap();
    let trig = read_trig_patches(&crate::common::read_to_string(fixture("bowl.json")).unwrap())
        .unwrap()
        .unwrap();
    assert_eq!(rational.len(), trig.len());
    let (tu, tv) = (ratio::<Q>(1, 3), ratio::<Q>(2, 7));
    for (r, t) in rational.iter().zip(&trig) {
        let (exact_bezier::Patch::Rect(r), TrigPatch::Rect(t)) = (r, t) else {
            panic!("the bowl is made of trig-rects");
        };
        assert_eq!(r.degree(), (4, 4));
        let expected = t.eval(&TrigParam::from_tau(&tu), &TrigParam::from_tau(&tv));
        assert_eq!(r.eval(&tu, &tv).unwrap(), expected);
    }
    let (code, _, err) = cli(&[
        "convert",
        &fixture("yang_yong_example1.json"),
        "--to",
        "rational",
    ]);
    assert_eq!(code, 2);
    assert!(err.contains("trig-curve or trig-rect"), "{err}");
}
