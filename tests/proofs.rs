//! Every family in `proofs/` has the verdicts it is expected to have.
//! One test per family, so they run in parallel and fail by name.

use exact_bezier::proofs::FAMILIES;

fn check(name: &str) {
    let family = FAMILIES
        .iter()
        .find(|f| f.name == name)
        .unwrap_or_else(|| panic!("no proof family {name}"));
    let claims = (family.run)();
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
);
