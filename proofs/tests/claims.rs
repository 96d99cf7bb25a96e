//! Every family in `proofs/` has the verdicts it is expected to have.
//! One test per family, so they run in parallel and fail by name.

use exact_bezier_proofs::{family, run_family, Verdict, FAMILIES};

fn check(name: &str) {
    let family = family(name).unwrap_or_else(|| panic!("no proof family {name}"));
    let claims = run_family(family);
    assert!(!claims.is_empty(), "family {name} has no claims");
    let off: Vec<String> = claims
        .iter()
        .filter(|c| !c.as_expected())
        .map(|c| {
            format!(
                "{} — {} (expected {}): {}",
                c.claim, c.verdict, c.expected, c.detail
            )
        })
        .collect();
    assert!(
        off.is_empty(),
        "claims off their expected verdict:\n{}",
        off.join("\n")
    );
    for c in &claims {
        assert_ne!(
            c.expected,
            Verdict::Broken,
            "{}: broken is never expected",
            c.claim
        );
        // A claim with a degree bound states it in its text.
        if let Some(bound) = &c.bound {
            assert!(
                c.claim.contains(bound.as_str()),
                "{}: text lacks its bound {bound}",
                c.claim
            );
        }
    }
}

/// `prove --json` objects carry the family, the degree bound and the time.
#[test]
fn json_has_bound_and_time() {
    let claims = run_family(family("reduction").expect("family"));
    let json = claims[0].to_json("reduction");
    assert_eq!(json["family"], "reduction");
    assert!(json["elapsed_ms"].as_f64().is_some_and(|t| t >= 0.0));
    assert!(json["degree_bound"]
        .as_str()
        .is_some_and(|b| b.contains('n')));
}

macro_rules! families {
    ($($name:ident),* $(,)?) => {
        $( #[test] fn $name() { check(stringify!($name)); } )*

        #[test]
        fn every_family_is_tested() {
            let tested = [$(stringify!($name)),*];
            for f in FAMILIES {
                assert!(tested.contains(&f.name), "family {} has no test in tests/proofs.rs", f.name);
            }
        }
    };
}

families!(
    quiz,
    bernstein,
    general_degree,
    curves,
    lecture_joins,
    reduction,
    trig_basis,
    trig_stitching,
    trig_rational,
    hang_li,
    hang_li_tables,
    surfaces,
    yang_yong,
    yang_yong_examples,
    zhang_chen_feng,
    triangles,
    blossoms,
    nurbs,
    conversions,
    coincide,
    analytic,
);
