//! Exact standard forms over the real algebraic numbers (source 000,
//! Examples 1 and 2), checked against values derived by hand.

use exact_bezier::{algebra::*, coincide, io::*, prelude::*, reparam::*};
use num_rational::BigRational;

type A = RealAlgebraic;

fn fixture(name: &str) -> RectPatch<BigRational> {
    let text = crate::common::read_to_string(format!("tests/fixtures/{name}")).unwrap();
    match &read_patches(&text).unwrap()[0] {
        Patch::Rect(r) => r.clone(),
        _ => panic!("a rect patch"),
    }
}

fn a(s: &str) -> A {
    parse_algebraic(s).unwrap()
}

#[test]
fn example1_standard_weights_are_radicals() {
    let p = fixture("yang_yong_example1.json");
    let s = standardize(&p.map(RealAlgebraic::from_rational), Options::default()).unwrap();
    // By hand: a Möbius map multiplies ω_ij by λ^i μ^j up to a common factor,
    // with λ² = ω00/ω20 = 8/3 and μ² = ω00/ω02 = 4, so the standard weights
    // are λ^i μ^j ω_ij / ω00 (ω10 = √(8/3)·2/8 = √6/6, the source's 1/√6).
    let (lambda, mu) = (a("sqrt(8/3)"), a("2"));
    let w = p.weights();
    for (i, row) in s.patch.weights().iter().enumerate() {
        for (j, got) in row.iter().enumerate() {
            let want = lambda.pow_u32(i as u32)
                * &mu.pow_u32(j as u32)
                * &A::from_rational(&(w[i][j].clone() / &w[0][0]));
            assert_eq!(*got, want, "ω{i}{j}");
        }
    }
    assert_eq!(s.patch.weights()[1][0].to_string(), "sqrt(6)/6");
    // A Möbius map never moves control points.
    assert_eq!(
        s.patch.points().unwrap(),
        p.map(A::from_rational).points().unwrap()
    );
    let StandardMap::Mobius { alpha, beta, .. } = &s.map else {
        panic!("linear")
    };
    assert_eq!(*alpha, a("1/(1 + sqrt(8/3))"));
    assert_eq!(beta.clone(), Some(a("1/3")));
}

#[test]
fn example2_compact_standard_form_is_exact() {
    let p = fixture("yang_yong_example2.json");
    let s = standardize(
        &p.map(RealAlgebraic::from_rational),
        Options {
            compact: true,
            ..Options::default()
        },
    )
    .unwrap();
    let one = A::from_i64(1);
    assert_eq!(
        corner_weights(&s.patch),
        [one.clone(), one.clone(), one.clone(), one]
    );
    let StandardMap::Quadratic { map, .. } = &s.map else {
        panic!("quadratic")
    };
    // The roots the source's (19) needs: α2 = 1/(1 + ∛(3/2)), α1 = 1/(1 + ∛(5/8)).
    assert_eq!(map.alpha2, a("1/(1 + cbrt(3/2))"));
    assert_eq!(map.alpha1, a("1/(1 + cbrt(5/8))"));
    // The standard form passes through the original surface's points at the
    // mapped parameters, exactly.
    let orig = p.map(A::from_rational);
    for (s_, t_) in [("1/3", "1/2"), ("3/4", "1/5")] {
        let (u, v) = map.param_hom(&a(s_), &a(t_));
        let want = orig.eval_hom_projective(&u, &v).project().unwrap();
        assert_eq!(s.patch.eval(&a(s_), &a(t_)).unwrap(), want);
    }
}

/// `eval` reads algebraic control points and weights (issue 14): the exact
/// standard form of Example 1 at (s, t) = (1/3, 1/2), evaluated by the
/// CLI, equals Example 1 evaluated (in the library, over RealAlgebraic) at
/// the Möbius images u(s), v(t) of source 000 eq. (2) with the printed
/// map's α = (2√6 − 3)/5 and β = 1/3: a second route to the same point.
#[test]
fn eval_reads_algebraic_patches() {
    let p = fixture("yang_yong_example1.json");
    let s = standardize(&p.map(RealAlgebraic::from_rational), Options::default()).unwrap();
    let StandardMap::Mobius { alpha, beta, .. } = &s.map else {
        panic!("linear")
    };
    let dir = std::env::temp_dir().join(format!("exact-bezier-alg-eval-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("standard.json");
    let text = patch_to_json(&Patch::Rect(s.patch.clone()))
        .unwrap()
        .to_string();
    std::fs::write(&file, text).unwrap();
    let (code, v) = crate::common::cli_json(&["eval", file.to_str().unwrap(), "--at", "1/3,1/2"]);
    assert_eq!(code, 0, "{v}");
    let got: Vec<A> = v["point"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| match x {
            serde_json::Value::String(s) => a(s),
            n => a(&n.to_string()),
        })
        .collect();
    let u = RationalCurve::<A>::mobius_param(alpha, &a("1/3")).unwrap();
    let beta = beta.as_ref().expect("Example 1's map moves v too");
    let w = RationalCurve::<A>::mobius_param(beta, &a("1/2")).unwrap();
    let want = p.map(A::from_rational).eval(&u, &w).unwrap();
    assert_eq!(got, want);
    let _ = std::fs::remove_dir_all(&dir);
}

/// `coincide` over the real algebraic numbers (issue 14): Example 1 and its
/// exact standard form are the same patch, and the witness's Möbius ratios
/// are the hand-derived λ = √(8/3), μ = 2 of the test above (from Example
/// 1's weights ω00/ω20 = 8/3, ω00/ω02 = 4), not read from the
/// standardization's output.
#[test]
fn example1_coincides_with_its_exact_standard_form() {
    let p = fixture("yang_yong_example1.json");
    let s = standardize(&p.map(RealAlgebraic::from_rational), Options::default()).unwrap();
    let ex1 = Patch::Rect(p.map(A::from_rational));
    let c = coincide::coincide(
        &ex1,
        &Patch::Rect(s.patch.clone()),
        coincide::Options::default(),
    )
    .unwrap();
    assert!(c.coincident, "{}", c.reason);
    let w = c.witness.unwrap();
    assert_eq!(w.symmetry.to_string(), "identity");
    let rho = |p: &coincide::MobiusParam<A>| match p {
        coincide::MobiusParam::Value { rho, .. } => rho.clone(),
        other => panic!("an exact ratio, not {other:?}"),
    };
    assert_eq!(rho(&w.u), a("sqrt(8/3)"));
    assert_eq!(rho(&w.v), a("2"));
}

/// The algebraic decision has no tolerance: the standard form with one
/// weight moved by a relative 10⁻⁴⁰ is a different patch, and the reason
/// names that weight's invariant.
#[test]
fn a_weight_moved_by_1e_minus_40_is_not_coincident() {
    let p = fixture("yang_yong_example1.json");
    let s = standardize(&p.map(RealAlgebraic::from_rational), Options::default())
        .unwrap()
        .patch;
    let mut w = s.weights();
    w[1][1] = w[1][1].clone() * &a("1 + 1/10**40");
    let moved = RectPatch::new(s.points().unwrap(), w).unwrap();
    let c = coincide::coincide(
        &Patch::Rect(s),
        &Patch::Rect(moved),
        coincide::Options::default(),
    )
    .unwrap();
    assert!(!c.coincident);
    assert!(c.reason.contains("I_{1,1}"), "{}", c.reason);
}

const EX1: &str = "tests/fixtures/yang_yong_example1.json";
const EX1_STANDARD: &str = "tests/fixtures/yang_yong_example1_standard.json";
const QUARTER: &str = "tests/fixtures/quarter_circle.json";

/// Read one patch over the real algebraic numbers.
fn algebraic_fixture(path: &str) -> Patch<A> {
    let text = crate::common::read_to_string(path).unwrap();
    read_patches_as::<A>(&text).unwrap().remove(0)
}

/// A number of the CLI's output (a JSON number or a string in the grammar).
fn number(v: &serde_json::Value) -> A {
    match v {
        serde_json::Value::String(s) => a(s),
        n => a(&n.to_string()),
    }
}

/// Write `patches` as JSON Lines to a fresh temporary file.
fn jsonl(name: &str, patches: &[Patch<A>]) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("exact-bezier-alg-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("in.jsonl");
    let text: Vec<String> = patches
        .iter()
        .map(|p| patch_to_json(p).unwrap().to_string())
        .collect();
    std::fs::write(&file, text.join("\n")).unwrap();
    file
}

/// The standard-form fixture is what the library computes (so the CLI
/// tests below read the numbers the hand-checked test above verified).
#[test]
fn the_standard_form_fixture_is_the_librarys() {
    let s = standardize(
        &fixture("yang_yong_example1.json").map(RealAlgebraic::from_rational),
        Options::default(),
    )
    .unwrap();
    assert_eq!(algebraic_fixture(EX1_STANDARD), Patch::Rect(s.patch));
}

/// `coincide` on files: Example 1 against its standard form, with the
/// hand-derived ratio λ = √(8/3) of the test above as the witness.
#[test]
fn cli_coincide_reads_algebraic_files() {
    let (code, v) = crate::common::cli_json(&["coincide", EX1, EX1_STANDARD]);
    assert_eq!(code, 0, "{v}");
    assert_eq!(v["coincident"], true, "{v}");
    assert_eq!(number(&v["witness"]["u"]["rho"]), a("sqrt(8/3)"));
    assert_eq!(number(&v["witness"]["v"]["sigma"]), a("2"));
    let (_, f) = crate::common::cli_json(&["coincide", EX1_STANDARD, EX1, "--filtered"]);
    assert_eq!(
        (f["coincident"].clone(), f["decided_by"].clone()),
        (true.into(), "exact".into())
    );
}

/// `reparam` with an algebraic α: the result coincides with the input and
/// the witness recovers that α (a second route: the decision does not
/// know how the copy was made).
#[test]
fn cli_reparam_takes_algebraic_parameters() {
    let (code, out, err) = crate::common::cli(&["reparam", QUARTER, "--mobius", "sqrt(2)/2"]);
    assert_eq!(code, 0, "{err}");
    let dir = std::env::temp_dir().join(format!("exact-bezier-alg-reparam-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let moved = dir.join("moved.json");
    std::fs::write(&moved, out).unwrap();
    let (_, v) = crate::common::cli_json(&["coincide", QUARTER, moved.to_str().unwrap()]);
    assert_eq!(v["coincident"], true, "{v}");
    assert_eq!(number(&v["witness"]["u"]["alpha"]), a("sqrt(2)/2"));
    let (code, _, err) = crate::common::cli(&["reparam", QUARTER, "--mobius", "sqrt(2)"]);
    assert_eq!(code, 2);
    assert!(err.contains("strictly between 0 and 1"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// `curvature` of the algebraic quarter circle: exactly 1 (the unit circle),
/// at a parameter where nothing about it is special.
#[test]
fn cli_curvature_of_the_algebraic_quarter_circle_is_one() {
    let (code, v) = crate::common::cli_json(&["curvature", QUARTER, "--at", "2/7"]);
    assert_eq!(code, 0, "{v}");
    assert_eq!(number(&v["curvature"]), a("1"));
    assert_eq!(number(&v["curvature_squared"]), a("1"));
}

/// `elevate` and `deriv` on algebraic input agree with the library's own
/// evaluation of the input (elevation keeps the curve; the derivative of
/// the circle x² + y² = 1 is orthogonal to the point).
#[test]
fn cli_elevate_and_deriv_read_algebraic_files() {
    let (code, out, err) = crate::common::cli(&["elevate", QUARTER, "--by", "2"]);
    assert_eq!(code, 0, "{err}");
    let raised = read_patches_as::<A>(&out).unwrap().remove(0);
    let (Patch::Curve(c), Patch::Curve(q)) = (algebraic_fixture(QUARTER), raised) else {
        panic!("curves")
    };
    assert_eq!(q.degree(), 4);
    let t = a("3/11");
    assert_eq!(q.eval(&t).unwrap(), c.eval(&t).unwrap());
    let (code, v) = crate::common::cli_json(&["deriv", QUARTER, "--at", "3/11"]);
    assert_eq!(code, 0, "{v}");
    let d: Vec<A> = v["derivative"]
        .as_array()
        .unwrap()
        .iter()
        .map(number)
        .collect();
    let p = c.eval(&t).unwrap();
    assert_eq!(
        d[0].clone() * &p[0] + &(d[1].clone() * &p[1]),
        A::from_i64(0)
    );
}

/// `dedup` and `key` on a stream mixing rational and algebraic patches:
/// classes as constructed — Example 1, its standard form and a Möbius copy
/// of that with an algebraic β (one class, keyed by the rational digest);
/// Example 3 alone; a patch with an irrational weight invariant and its
/// Möbius copy (one class, compared exactly).
#[test]
fn cli_dedup_groups_algebraic_patches() {
    let ex1 = algebraic_fixture(EX1);
    let Patch::Rect(std1) = algebraic_fixture(EX1_STANDARD) else {
        panic!("a rect")
    };
    let Patch::Rect(r1) = ex1.clone() else {
        panic!("a rect")
    };
    let mut w = r1.weights();
    w[1][1] = a("sqrt(2)");
    let irr = RectPatch::new(r1.points().unwrap(), w).unwrap();
    let stream = [
        ex1,
        Patch::Rect(std1.clone()),
        Patch::Rect(std1.mobius_u(&a("1/3")).mobius_v(&a("sqrt(2)/2"))),
        algebraic_fixture("tests/fixtures/yang_yong_example3.json"),
        Patch::Rect(irr.clone()),
        Patch::Rect(
            irr.mobius_u(&a("1/5"))
                .mobius_v(&a("sqrt(3)/3"))
                .reverse_u(),
        ),
    ];
    let file = jsonl("dedup", &stream);
    let (code, out, err) = crate::common::cli(&["dedup", file.to_str().unwrap(), "--witness"]);
    assert_eq!(code, 0, "{err}");
    let classes: Vec<Vec<u64>> = out
        .lines()
        .map(|l| {
            let v: serde_json::Value = serde_json::from_str(l).unwrap();
            v["members"]
                .as_array()
                .unwrap()
                .iter()
                .map(|m| m.as_u64().unwrap())
                .collect()
        })
        .collect();
    assert_eq!(classes, vec![vec![0, 1, 2], vec![3], vec![4, 5]]);
    let (code, out, _) = crate::common::cli(&["key", EX1]);
    let (code2, out2, _) = crate::common::cli(&["key", EX1_STANDARD]);
    assert_eq!((code, code2), (0, 0));
    assert_eq!(out, out2, "a rational key is the key of the copy over Q");
    let irr_file = jsonl("key", &stream[4..5]);
    let (code, _, err) = crate::common::cli(&["key", irr_file.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(err.contains("no canonical text"), "{err}");
    let _ = std::fs::remove_dir_all(file.parent().unwrap());
    let _ = std::fs::remove_dir_all(irr_file.parent().unwrap());
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(12))]

    /// Laws over the real algebraic numbers: a rect Möbius-mapped by the
    /// irrational α = 1/(1 + √k) in u (and a rational β in v) coincides with
    /// its rational original, the witness recovers ρ = √k, and its
    /// canonical key is rational and equal to the original's key over Q.
    #[test]
    fn algebraic_mobius_copies_share_the_rational_key(
        r in exact_bezier::strategy::rect(2, 1, 2),
        k in exact_bezier::strategy::rational_in(1, 9, 7),
        beta in exact_bezier::strategy::open_unit_parameter(),
    ) {
        let sqrt_k = A::from_rational(&k).nth_root(2).unwrap();
        let alpha = (A::from_i64(1) + &sqrt_k).recip();
        let lifted = r.map(A::from_rational);
        let copy = Patch::Rect(lifted.mobius_u(&alpha).mobius_v(&A::from_rational(&beta)));
        let c = coincide::coincide(&Patch::Rect(lifted), &copy, coincide::Options::default()).unwrap();
        proptest::prop_assert!(c.coincident, "{}", c.reason);
        let w = c.witness.unwrap();
        if w.symmetry.to_string() == "identity" {
            proptest::prop_assert_eq!(w.u, coincide::MobiusParam::Value { rho: sqrt_k, alpha });
        }
        let key = coincide::canonical_key(&copy).unwrap().to_rational();
        proptest::prop_assert_eq!(key, Some(coincide::canonical_key(&Patch::Rect(r)).unwrap()));
    }
}

/// A bicubic whose weights `k + √p` span the degree-16 field Q(√2, √3, √5,
/// √7): its copy under Möbius maps with an algebraic α coincides, and so
/// does its elevated copy (minimality certified by interval resultants,
/// elevation undone exactly; the exact gcd over this field took minutes),
/// while a copy with one point moved does not.
#[test]
fn algebraic_bicubics_over_a_degree_16_field() {
    let primes = [2, 3, 5, 7];
    let pts: Vec<Vec<Vec<A>>> = (0..4)
        .map(|i| {
            (0..4)
                .map(|j| vec![A::from_i64(i), A::from_i64(j), A::from_i64((i * j + i) % 5)])
                .collect()
        })
        .collect();
    let w: Vec<Vec<A>> = (0..4)
        .map(|i| {
            (0..4)
                .map(|j| {
                    a(&format!(
                        "{} + sqrt({})",
                        1 + (i + 2 * j) % 4,
                        primes[(i + j) % 4]
                    ))
                })
                .collect()
        })
        .collect();
    let r = RectPatch::new(pts.clone(), w.clone()).unwrap();
    let moved = r.mobius_u(&a("sqrt(2)/2")).mobius_v(&a("1/3"));
    let c = coincide::coincide(
        &Patch::Rect(r.clone()),
        &Patch::Rect(moved),
        coincide::Options::default(),
    )
    .unwrap();
    assert!(c.coincident, "{}", c.reason);
    let raised = coincide::coincide(
        &Patch::Rect(r.clone()),
        &Patch::Rect(r.elevate(1, 2)),
        coincide::Options::default(),
    )
    .unwrap();
    assert!(raised.coincident, "{}", raised.reason);
    assert_eq!(raised.reductions[1].to, (3, 3));
    let mut bent = pts;
    bent[2][1][2] = A::from_i64(9);
    let other = RectPatch::new(bent, w).unwrap();
    assert!(
        !coincide::coincide(
            &Patch::Rect(r),
            &Patch::Rect(other),
            coincide::Options::default()
        )
        .unwrap()
        .coincident
    );
}

/// A Möbius map whose α is a root of a degree-7 polynomial (its powers
/// went through resultants of growing degree for minutes) runs in the
/// field of α and the curve's numbers (degree 7, under a second), charged
/// from that degree: refused under a budget of 10⁶ units, answered under
/// the default; a cubic root on a rational quadratic arc runs too; commas
/// inside `CRootOf(…, k)` belong to the number.
#[test]
fn general_roots_are_charged_before_they_run() {
    const ARC: &str = "docs/figures/inputs/circle_arc_quadratic.json";
    let alpha = "CRootOf(x**7 - 3*x - 1, 2)/3";
    let (code, _, err) = crate::common::cli(&[
        "--max-work",
        "1000000",
        "reparam",
        QUARTER,
        "--mobius",
        alpha,
    ]);
    assert_eq!(code, 2);
    assert!(err.contains("--max-work"), "{err}");
    let (code, out, err) = crate::common::cli(&["reparam", QUARTER, "--mobius", alpha]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(
        read_patches_as::<A>(&out).map(|p| p.len()).ok(),
        Some(1),
        "{out:.200}"
    );
    let (code, out, err) =
        crate::common::cli(&["reparam", ARC, "--mobius", "CRootOf(x**3 - x - 1, 0)/2"]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("CRootOf"), "{out}");
}

/// An input whose numbers span a number field over the limit is refused
/// as it is read, naming the limit: a root of a quintic and one of a
/// degree-13 polynomial need a field of degree 5·13 = 65 > 32. With the
/// quintic alone (degree 5) the same command answers.
#[test]
fn inputs_over_the_field_degree_limit_are_refused_at_once() {
    let dir = std::env::temp_dir().join(format!("exact-bezier-alg-field-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let over = dir.join("over.json");
    std::fs::write(
        &over,
        r#"{"kind":"curve","degree":1,"points":[[0,"CRootOf(x**5 - x - 1, 0)"],[1,"CRootOf(x**13 - x - 1, 0)"]]}"#,
    )
    .unwrap();
    let (code, _, err) = crate::common::cli(&["eval", over.to_str().unwrap(), "--at", "1/2"]);
    assert_ne!(code, 0);
    assert!(
        err.contains("degree 65") && err.contains("field degree limit of 32"),
        "{err}"
    );
    let under = dir.join("under.json");
    std::fs::write(
        &under,
        r#"{"kind":"curve","degree":1,"points":[[0,"CRootOf(x**5 - x - 1, 0)"],[1,2]]}"#,
    )
    .unwrap();
    let (code, _, err) = crate::common::cli(&["eval", under.to_str().unwrap(), "--at", "1/2"]);
    assert_eq!(code, 0, "{err}");
}

/// The issue's `arc` cases with algebraic arguments (they ran for 5–10
/// minutes): each now answers, and the curve it writes is read back as an
/// algebraic curve.
#[test]
fn arcs_with_algebraic_arguments_answer() {
    for args in [
        [
            "arc",
            "--cos-half=1/2",
            "--lambda=sqrt(2)/10",
            "--points=1,0,0;0,1,0;0,0,1",
        ],
        [
            "arc",
            "--cos-half=sqrt(2)/2",
            "--lambda=1/10",
            "--points=1,0;1,1;0,1",
        ],
    ] {
        let (code, v) = crate::common::cli_json(&args);
        assert_eq!(code, 0, "{args:?}: {v}");
        let text = v.to_string();
        assert_eq!(
            read_patches_as::<A>(&text).map(|p| p.len()).ok(),
            Some(1),
            "{text}"
        );
    }
}
