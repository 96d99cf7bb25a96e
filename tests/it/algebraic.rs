//! Exact standard forms over the real algebraic numbers (source 000,
//! Examples 1 and 2), checked against values derived by hand.

use exact_bezier::{algebra::*, io::*, prelude::*, reparam::*};
use num_rational::BigRational;

type A = RealAlgebraic;

fn fixture(name: &str) -> RectPatch<BigRational> {
    let text = std::fs::read_to_string(format!("tests/fixtures/{name}")).unwrap();
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
    let s = standardize_rect_algebraic(&p, false).unwrap();
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
    let s = standardize_rect_algebraic(&p, true).unwrap();
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
    let s = standardize_rect_algebraic(&p, false).unwrap();
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
