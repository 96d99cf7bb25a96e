use super::*;
use crate::algebra::scalar::ratio;
use proptest::prelude::*;

fn r(n: i64) -> RealAlgebraic {
    RealAlgebraic::from_i64(n)
}

fn q(p: i64, d: i64) -> RealAlgebraic {
    Scalar::from_rational(&ratio::<BigRational>(p, d))
}

fn sqrt(x: &RealAlgebraic) -> RealAlgebraic {
    x.nth_root(2).unwrap()
}

fn parse(s: &str) -> RealAlgebraic {
    s.parse().unwrap()
}

#[test]
fn sqrt2_plus_sqrt3_identities() {
    let s = sqrt(&r(2)) + &sqrt(&r(3));
    assert_eq!(s.clone() * &s, r(5) + r(2) * sqrt(&r(6)));
    // √(5 + 2√6) is a root of a sum: the general representation.
    let t = sqrt(&(r(5) + r(2) * sqrt(&r(6))));
    assert!((s.clone() - &t).is_zero() || (s.clone() - &t).signum() == 0);
    assert_eq!(s, t);
    assert_eq!((s - &t).as_rational(), Some(BigRational::zero()));
}

#[test]
fn rational_results_come_back_rational() {
    let c = r(2).nth_root(3).unwrap();
    assert_eq!((c.clone() * &c * &c).as_rational(), Some(ratio(2, 1)));
    let x = sqrt(&(r(3) + sqrt(&r(2))));
    assert_eq!(
        (x.clone() * &x - &sqrt(&r(2))).as_rational(),
        Some(ratio(3, 1))
    );
    assert_eq!((x.clone() / &x).as_rational(), Some(ratio(1, 1)));
}

#[test]
fn tiny_differences_have_the_right_sign() {
    // √(10⁸⁰ + 1) − 10⁴⁰ ≈ 5·10⁻⁴¹ > 0; 10⁴⁰ − √(10⁸⁰ − 1) > 0.
    let big = BigRational::from_integer(num_traits::pow(BigInt::from(10), 80));
    let ten40 = RealAlgebraic::rat(BigRational::from_integer(num_traits::pow(
        BigInt::from(10),
        40,
    )));
    let up = sqrt(&RealAlgebraic::rat(big.clone() + BigRational::one()));
    let down = sqrt(&RealAlgebraic::rat(big - BigRational::one()));
    assert_eq!((up.clone() - &ten40).signum(), 1);
    assert_eq!((ten40.clone() - &down).signum(), 1);
    assert!(down < ten40 && ten40 < up);
    // The same through the general representation: ∛(1 + √2) perturbed by 10⁻⁴⁰.
    let c = (r(1) + sqrt(&r(2))).nth_root(3).unwrap();
    let eps = RealAlgebraic::rat(BigRational::new(
        1.into(),
        num_traits::pow(BigInt::from(10), 40),
    ));
    assert!(c.clone() + &eps > c);
    assert!(c.clone() - &eps < c);
}

#[test]
fn text_round_trips() {
    for s in [
        "sqrt(6)/6",
        "1 - 2*cbrt(12)/3",
        "-sqrt(2)",
        "3/7",
        "-5",
        "root(72, 4)",
        "sqrt(2) + sqrt(3)",
        "CRootOf(x**5 - x - 1, 0)",
    ] {
        assert_eq!(parse(s).to_string(), s, "{s}");
    }
    assert_eq!(parse("1/sqrt(6)").to_string(), "sqrt(6)/6");
    assert_eq!(parse("(8/3)**(1/2)").to_string(), "2*sqrt(6)/3");
    assert_eq!(parse("2**(-1/2)*2").to_string(), "sqrt(2)");
    assert_eq!(parse("CRootOf(x**2 - 2, 0)"), -sqrt(&r(2)));
    assert_eq!(parse("Rational(3, 4)"), q(3, 4));
    for bad in [
        "cbrt(-2)",
        "sqrt(",
        "x + 1",
        "1/0",
        "root(2, 0)",
        "2**100",
        "foo(1)",
        "CRootOf(x**2 + 1, 0)",
    ] {
        assert!(bad.parse::<RealAlgebraic>().is_err(), "{bad}");
    }
}

#[test]
fn general_roots_print_as_crootof() {
    let c = (r(1) + sqrt(&r(2))).nth_root(3).unwrap();
    let text = c.to_string();
    assert!(text.starts_with("CRootOf("), "{text}");
    assert_eq!(parse(&text), c);
    assert_eq!(c.to_decimal(20), "1.34150376263057771968");
}

#[test]
fn to_f64_and_decimals() {
    assert_eq!(sqrt(&r(2)).to_f64(), std::f64::consts::SQRT_2);
    assert_eq!(q(-1, 3).to_decimal(3), "-0.333");
    assert_eq!(q(1, 8).to_decimal(2), "0.13");
    assert_eq!((-sqrt(&r(2))).to_decimal(5), "-1.41421");
}

#[test]
fn real_roots_in_an_interval() {
    let p = UPoly::new(vec![
        ratio::<BigRational>(2, 1),
        ratio(0, 1),
        ratio(-3, 1),
        ratio(0, 1),
        ratio(1, 1),
    ]); // (x² − 1)(x² − 2)
    let all = RealAlgebraic::real_roots_in(&p, &ratio(-10, 1), &ratio(10, 1));
    assert_eq!(all, vec![-sqrt(&r(2)), r(-1), r(1), sqrt(&r(2))]);
    let some = RealAlgebraic::real_roots_in(&p, &ratio(-1, 1), &ratio(2, 1));
    assert_eq!(some, vec![r(1), sqrt(&r(2))]);
}

/// A high-precision reference: the value from its enclosure at 2⁻³⁰⁰.
fn reference(x: &RealAlgebraic) -> BigRational {
    let (lo, hi) = x.enclosure(300);
    (lo + hi) / BigRational::from_integer(2.into())
}

fn small_radical() -> impl Strategy<Value = RealAlgebraic> {
    (-5i64..6, 1i64..4, 1i64..12, 2u32..4)
        .prop_map(|(a, b, c, n)| q(a, b) * &r(c).nth_root(n).unwrap())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(40))]

    #[test]
    fn field_laws(a in small_radical(), b in small_radical(), c in small_radical()) {
        prop_assert_eq!((a.clone() + &b) * &c, a.clone() * &c + &(b.clone() * &c));
        prop_assert_eq!(a.clone() * &b, b.clone() * &a);
        prop_assert_eq!(a.clone() - &a, r(0));
        if !b.is_zero() {
            prop_assert_eq!((a.clone() / &b) * &b, a.clone());
        }
    }

    #[test]
    fn sums_and_products_match_high_precision(a in small_radical(), b in small_radical(), c in small_radical()) {
        let x = (a.clone() + &b) * &c + &a;
        let approx = (reference(&a) + reference(&b)) * reference(&c) + reference(&a);
        let (lo, hi) = x.enclosure(200);
        let slack = BigRational::new(1.into(), BigInt::one() << 150usize);
        prop_assert!(lo - &slack <= approx && approx <= hi + &slack);
        // Order agrees with the reference wherever the references are apart.
        let (ra, rb) = (reference(&a), reference(&b));
        if (ra.clone() - &rb).abs() > slack {
            prop_assert_eq!(a < b, ra < rb);
        }
    }

    #[test]
    fn roots_of_sums_are_exact(a in 1i64..20, b in 2i64..7, n in 2u32..4) {
        // y = (a + √b)^{1/n}: yⁿ = a + √b exactly (general representation).
        let x = r(a) + &sqrt(&r(b));
        let y = x.nth_root(n).unwrap();
        prop_assert_eq!(y.pow_u32(n), x);
    }
}

fn alpha() -> RealAlgebraic {
    parse("CRootOf(x**3 - x - 1, 0)")
}

#[test]
fn identities_across_fields() {
    // (α + √2)² − 2α√2 − α² = 2, with α the real root of x³ − x − 1.
    let (a, s2) = (alpha(), sqrt(&r(2)));
    let sum = a.clone() + &s2;
    let x = sum.clone() * &sum - &(r(2) * &a * &s2) - &(a.clone() * &a);
    assert_eq!(x.as_rational(), Some(ratio(2, 1)));
    assert_eq!(x, r(2));
    // α³ = α + 1 and 1/α = α² − 1 (from α(α² − 1) = 1).
    assert_eq!(a.clone() * &a * &a, a.clone() + &r(1));
    assert_eq!(a.recip(), a.clone() * &a - &r(1));
    // √(α² + √2)² − √2 = α².
    let y = sqrt(&(a.clone() * &a + &s2));
    assert_eq!(y.clone() * &y - &s2, a.clone() * &a);
    assert!(y.root_degree().unwrap() <= 12, "{:?}", y.root_degree());
}

#[test]
fn chains_stay_in_one_field() {
    // A rational quadratic with weights (6, α, 13/5) evaluated, differentiated
    // and squared: every number stays in Q(α), degree 3 (the resultant path
    // multiplied the degrees at every step).
    let a = alpha();
    let w = [r(6), a.clone(), q(13, 5)];
    let pts = [q(7, 2), q(-17, 2), a.clone()];
    let t = q(1, 2);
    let s = r(1) - &t;
    let basis = [s.clone() * &s, r(2) * &s * &t, t.clone() * &t];
    let num = (0..3).fold(r(0), |acc, i| acc + &(basis[i].clone() * &w[i] * &pts[i]));
    let den = (0..3).fold(r(0), |acc, i| acc + &(basis[i].clone() * &w[i]));
    let y = num.clone() / &den;
    let y4 = y.clone() * &y * &y * &y;
    let z = (y4.clone() - &a).recip() + &(y.clone() * &a);
    for v in [&y, &y4, &z] {
        assert_eq!(v.root_degree(), Some(3));
    }
    // Independent check: y at the value of α by rational enclosures.
    let (lo, hi) = y.enclosure(64);
    let (al, ah) = a.enclosure(200);
    let f = |x: &BigRational| {
        let sq = BigRational::new(1.into(), 4.into());
        let w1 = x;
        let n = sq.clone() * ratio::<BigRational>(6, 1) * ratio::<BigRational>(7, 2)
            + BigRational::new(1.into(), 2.into()) * w1 * ratio::<BigRational>(-17, 2)
            + sq.clone() * ratio::<BigRational>(13, 5) * x;
        let d = sq.clone() * ratio::<BigRational>(6, 1)
            + BigRational::new(1.into(), 2.into()) * w1
            + sq * ratio::<BigRational>(13, 5);
        n / d
    };
    let (fa, fb) = (f(&al), f(&ah));
    let (flo, fhi) = if fa < fb { (fa, fb) } else { (fb, fa) };
    assert!(
        lo <= fhi && flo <= hi,
        "{} {} {} {}",
        y.to_decimal(12),
        num.to_decimal(12),
        den.to_decimal(12),
        a.to_decimal(12)
    );
    // α with √2 and ∛3: the compositum has degree 3·2·3 = 18.
    let m = a.clone() * &sqrt(&r(2)) + &r(3).nth_root(3).unwrap();
    let m2 = m.clone() * &m - &a;
    assert_eq!(m2.root_degree(), Some(18));
    assert_eq!((m2.clone() + &a) / &m, m);
}
