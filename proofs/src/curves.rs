//! Curve algorithms and the lecture's curve formulas, proved on symbols:
//! symbolic control points, weights and parameters ([`Poly`]), so each
//! identity holds for all values. Homogeneous control points
//! `c_i = (q_i, w_i)` are independent symbols (`q_i` stands for `w_i P_i`);
//! one spatial coordinate suffices where coordinates do not interact, since
//! every algorithm treats them alike.
//!
//! Degree bounds: each claim's text states the degrees it was checked for
//! (`prove --json` reports them as `degree_bound`).

use super::calculus::nth_derivative;
use super::{Claim, Verdict};
use exact_bezier::algebra::Poly;
use exact_bezier::algebra::{binomial_scalar, Scalar};
use exact_bezier::bernstein::bernstein;
use exact_bezier::curve::geometry::{cross_norm_sq, CurveEnd};
use exact_bezier::curve::RationalCurve;
use exact_bezier::hpoint::{de_casteljau, HPoint};
use num_traits::{One, Zero};

fn v(name: &str) -> Poly {
    Poly::var(name)
}

/// A rational curve of degree `n` with symbolic homogeneous control points
/// `(q{i}_{k}…, w{i})` in `dim` coordinates.
fn sym_rational(n: usize, dim: usize) -> RationalCurve<Poly> {
    let ctrl = (0..=n)
        .map(|i| {
            let mut coords: Vec<Poly> = (0..dim).map(|k| v(&format!("q{i}_{k}"))).collect();
            coords.push(v(&format!("w{i}")));
            HPoint { coords }
        })
        .collect();
    RationalCurve::from_hom(ctrl).expect("well-formed symbols")
}

/// A polynomial curve of degree `n` with symbolic points `p{i}_{k}`.
fn sym_polynomial(n: usize, dim: usize) -> RationalCurve<Poly> {
    let pts = (0..=n)
        .map(|i| (0..dim).map(|k| v(&format!("p{i}_{k}"))).collect())
        .collect();
    RationalCurve::polynomial(pts).expect("well-formed symbols")
}

/// Run `check(n)` for each degree; `Proved` (for those degrees, which the
/// claim's text and bound state) iff all hold, else the first failure is
/// the detail.
fn over_degrees(
    claim: &str,
    source: &str,
    degrees: impl IntoIterator<Item = usize>,
    how: &str,
    check: impl Fn(usize) -> Result<(), String>,
) -> Claim {
    let degrees: Vec<usize> = degrees.into_iter().collect();
    let failure = degrees
        .iter()
        .find_map(|&n| check(n).err().map(|e| format!("n = {n}: {e}")));
    let range = format!(
        "{} ≤ n ≤ {}",
        degrees.first().unwrap_or(&0),
        degrees.last().unwrap_or(&0)
    );
    let detail = failure
        .clone()
        .unwrap_or_else(|| format!("{how}; each n an identity"));
    let claim = format!("{claim} — checked for every {range}");
    Claim::check(&claim, source, Verdict::Proved, failure.is_none(), detail).with_bound(range)
}

fn same(a: &HPoint<Poly>, b: &HPoint<Poly>) -> Result<(), String> {
    if a == b {
        Ok(())
    } else {
        let diff = a.sub(b);
        Err(format!(
            "difference {:?}",
            diff.coords
                .iter()
                .map(|x| super::abbreviate(&x.to_string()))
                .collect::<Vec<_>>()
        ))
    }
}

fn same_frac(a: &(Poly, Poly), b: &(Poly, Poly)) -> Result<(), String> {
    let d = a.0.clone() * &b.1 - &(b.0.clone() * &a.1);
    if d.is_zero() {
        Ok(())
    } else {
        Err(format!(
            "cross-multiplied difference {}",
            super::abbreviate(&d.to_string())
        ))
    }
}

/// `Σ_i c_i B_{i,n}(t)`, the defining Bernstein sum.
fn bernstein_sum(c: &RationalCurve<Poly>, t: &Poly) -> HPoint<Poly> {
    let n = c.degree();
    c.ctrl()
        .iter()
        .enumerate()
        .fold(HPoint::zero(c.dim()), |acc, (i, p)| {
            acc.add(&p.scale(&bernstein(i, n, t)))
        })
}

fn algorithm_claims() -> Vec<Claim> {
    let t = v("t");
    vec![
        over_degrees(
            "de Casteljau's algorithm equals the Bernstein sum Σ c_i B_{i,n}(t)",
            "001 lecture, de Casteljau算法",
            1..=10,
            "symbolic t and homogeneous control points (q_i, w_i)",
            |n| {
                let c = sym_rational(n, 1);
                same(&c.eval_hom(&t), &bernstein_sum(&c, &t))
            },
        ),
        over_degrees(
            "de Casteljau step: P(t) = Σ_{i=0}^{n−1} [(1−t)P_i + tP_{i+1}] B_{i,n−1}(t) (printed with upper limit n; the extra term is 0·P_{n+1} since B_{n,n−1} = 0)",
            "001 lecture, de Casteljau算法",
            1..=10,
            "symbolic t and P_i; the printed upper limit n names a non-existent P_{n+1} with the zero coefficient B_{n,n−1}",
            |n| {
                let c = sym_rational(n, 1);
                let cc = c.ctrl();
                let step = (0..n).fold(HPoint::zero(1), |acc, i| {
                    acc.add(&cc[i].lerp(&cc[i + 1], &t).scale(&bernstein(i, n - 1, &t)))
                });
                same(&step, &bernstein_sum(&c, &t))
            },
        ),
        over_degrees(
            "linear Möbius reparameterization keeps every point: X̃(s) = X(u(s)), u = (α−1)s/(2αs−s−α), w̃_i = w_i(1−α)ⁱα^{n−i}",
            "000 Yang & Yong eqs (2), (4), curve case",
            1..=10,
            "symbolic α, s, c_i: with N = (α−1)s, D = 2αs−s−α, the old curve at the homogeneous parameter (D−N : N) (= Dⁿ·H(N/D)) equals (−1)ⁿ H̃(s) identically, so the projected points agree wherever D ≠ 0",
            |n| {
                let (alpha, s) = (v("alpha"), v("s"));
                let c = sym_rational(n, 1);
                let num = (alpha.clone() - Poly::one()) * &s;
                let den = Poly::from_int(2) * &alpha * &s - &s - &alpha;
                let old = c.eval_hom_param(&(den - &num), &num);
                let sign = Poly::from_int(if n % 2 == 0 { 1 } else { -1 });
                same(&c.mobius(&alpha).eval_hom(&s).scale(&sign), &old)
            },
        ),
        over_degrees(
            "degree elevation P*_i = (i/(n+1))P_{i−1} + (1 − i/(n+1))P_i, applied r = 1, 2, 3 times, keeps every point (homogeneous curve unchanged)",
            "001 lecture, 升阶",
            1..=10,
            "symbolic t and c_i",
            |n| {
                let c = sym_rational(n, 1);
                let h = c.eval_hom(&t);
                (1..=3).try_for_each(|r| same(&c.elevate(r).eval_hom(&t), &h))
            },
        ),
        over_degrees(
            "subdivision at τ keeps every point: left(s) = H(τs), right(s) = H(τ + s(1−τ))",
            "001 lecture, de Casteljau算法 (ours: subdivision)",
            1..=10,
            "symbolic τ, s and c_i",
            |n| {
                let (tau, s) = (v("tau"), v("s"));
                let c = sym_rational(n, 1);
                let (l, r) = c.subdivide(&tau);
                same(&l.eval_hom(&s), &c.eval_hom(&(tau.clone() * &s)))?;
                let u = tau.clone() + s.clone() * (Poly::one() - &tau);
                same(&r.eval_hom(&s), &c.eval_hom(&u))
            },
        ),
        over_degrees(
            "sub-segment [a, b] keeps every point: seg(s) = H(a + s(b − a))",
            "ours",
            1..=10,
            "symbolic a, b, s and c_i",
            |n| {
                let (a, b, s) = (v("a"), v("b"), v("s"));
                let c = sym_rational(n, 1);
                let u = a.clone() + s.clone() * (b.clone() - &a);
                same(&c.subsegment(&a, &b).eval_hom(&s), &c.eval_hom(&u))
            },
        ),
        over_degrees(
            "symmetry: the reversed control polygon P*_i = P_{n−i} traces C*(t) = C(1 − t)",
            "001 lecture, 对称",
            1..=10,
            "symbolic t and c_i",
            |n| {
                let c = sym_rational(n, 1);
                same(&c.reverse().eval_hom(&t), &c.eval_hom(&(Poly::one() - &t)))
            },
        ),
        over_degrees(
            "affine invariance: the curve of the mapped control points is the mapped curve, A X(t) + b",
            "001 lecture, 几何不变性",
            1..=10,
            "symbolic 2×2 matrix A, translation b, t and homogeneous c_i (map applied as (A q + w b, w))",
            |n| {
                let c = sym_rational(n, 2);
                let a = vec![vec![v("a11"), v("a12")], vec![v("a21"), v("a22")]];
                let b = vec![v("b1"), v("b2")];
                let h = c.eval_hom(&t);
                let w = h.weight().clone();
                let mut mapped: Vec<Poly> = (0..2)
                    .map(|r| a[r][0].clone() * &h.coords[0] + &(a[r][1].clone() * &h.coords[1]) + &(b[r].clone() * &w))
                    .collect();
                mapped.push(w);
                let m = c.affine(&a, &b).map_err(|e| e.to_string())?;
                same(&m.eval_hom(&t), &HPoint { coords: mapped })
            },
        ),
        over_degrees(
            "blossom: symmetric, affine in each argument, diagonal b[t,…,t] = H(t), dual functional b[0^{n−i}, 1^i] = c_i",
            "001 lecture (de Casteljau's multilinear form); ours",
            1..=10,
            "symbolic arguments u_1…u_n, t and c_i; symmetry by swapping adjacent arguments; affinity as degree ≤ 1 in each u_j",
            |n| {
                let c = sym_rational(n, 1);
                let u = Poly::vars("u", n);
                let bl = c.blossom(&u).map_err(|e| e.to_string())?;
                for j in 0..n.saturating_sub(1) {
                    let mut sw = u.clone();
                    sw.swap(j, j + 1);
                    same(&c.blossom(&sw).map_err(|e| e.to_string())?, &bl)?;
                }
                if bl.coords.iter().any(|x| (0..n).any(|j| x.degree_in(&format!("u{j}")) > 1)) {
                    return Err("not affine in an argument".into());
                }
                same(&c.blossom(&vec![t.clone(); n]).map_err(|e| e.to_string())?, &c.eval_hom(&t))?;
                (0..=n).try_for_each(|i| {
                    let mut args = vec![Poly::zero(); n - i];
                    args.extend(vec![Poly::one(); i]);
                    same(&c.blossom(&args).map_err(|e| e.to_string())?, &c.ctrl()[i])
                })
            },
        ),
    ]
}

/// `Δᵏ P_i` written out as `Σ_j (−1)^{k−j} C(k, j) P_{i+j}` (independent
/// of the crate's difference code).
fn delta(p: &[Poly], k: usize, i: usize) -> Poly {
    (0..=k).fold(Poly::zero(), |acc, j| {
        let c = binomial_scalar::<Poly>(k, j);
        let term = c * &p[i + j];
        if (k - j) % 2 == 1 {
            acc - term
        } else {
            acc + term
        }
    })
}

fn derivative_claims() -> Vec<Claim> {
    let t = v("t");
    let coords = |n: usize| -> Vec<Poly> { (0..=n).map(|i| v(&format!("p{i}_0"))).collect() };
    let curve_poly = |n: usize| bernstein_sum(&sym_polynomial(n, 1), &t).coords[0].clone();
    vec![
        over_degrees(
            "k-th derivative: P⁽ᵏ⁾(t) = n!/(n−k)! Σ_{i=0}^{n−k} Δᵏ P_i B_{i,n−k}(t), Δᵏ P_i = Δᵏ⁻¹ P_{i+1} − Δᵏ⁻¹ P_i",
            "001 lecture, k 阶导数的差分形式",
            1..=10,
            "symbolic t and P_i, every k = 0…n: the printed formula (Δᵏ written out with binomials) equals the k-th t-derivative of Σ P_i B_{i,n}(t)",
            |n| {
                let p = coords(n);
                let x = curve_poly(n);
                (0..=n).try_for_each(|k| {
                    let ff: Poly = (n - k + 1..=n).fold(Poly::one(), |a, m| a * Poly::from_int(m as i64));
                    let printed = (0..=n - k).fold(Poly::zero(), |a, i| {
                        a + delta(&p, k, i) * bernstein(i, n - k, &t)
                    }) * ff;
                    let truth = nth_derivative(&x, "t", k);
                    if printed == truth { Ok(()) } else { Err(format!("k = {k}")) }
                })
            },
        ),
        over_degrees(
            "hodograph(k) computes the k-th derivative of the homogeneous curve (and 0 for k > n)",
            "ours",
            1..=10,
            "symbolic t and rational c_i, k = 0…n+1: de Casteljau on hodograph(k) equals the k-th t-derivative of H(t)",
            |n| {
                let c = sym_rational(n, 1);
                let h = c.eval_hom(&t);
                (0..=n + 1).try_for_each(|k| {
                    let truth = HPoint { coords: h.coords.iter().map(|x| nth_derivative(x, "t", k)).collect() };
                    let hod = c.hodograph(k);
                    let ours = if hod.is_empty() { HPoint::zero(1) } else { de_casteljau(&hod, &t) };
                    same(&ours, &truth)
                })
            },
        ),
        over_degrees(
            "end derivatives: P'(0) = n(P1 − P0), P'(1) = n(Pn − Pn−1), P''(0) = n(n−1)(P2 − 2P1 + P0), P''(1) = n(n−1)(Pn − 2Pn−1 + Pn−2)",
            "001 lecture, 切向量 and 二阶导数",
            2..=10,
            "symbolic P_i: derivatives of Σ P_i B_{i,n}(t) at t = 0 and t = 1",
            |n| {
                let p = coords(n);
                let x = curve_poly(n);
                let at = |q: &Poly, val: i64| q.subst("t", &Poly::from_int(val));
                let (d1, d2) = (x.derivative("t"), nth_derivative(&x, "t", 2));
                let nn = Poly::from_int(n as i64);
                let nn1 = Poly::from_int((n * (n - 1)) as i64);
                let two = Poly::from_int(2);
                let checks = [
                    (at(&d1, 0), nn.clone() * (p[1].clone() - &p[0])),
                    (at(&d1, 1), nn * (p[n].clone() - &p[n - 1])),
                    (at(&d2, 0), nn1.clone() * (p[2].clone() - two.clone() * &p[1] + &p[0])),
                    (at(&d2, 1), nn1 * (p[n].clone() - two * &p[n - 1] + &p[n - 2])),
                ];
                match checks.iter().position(|(a, b)| a != b) {
                    None => Ok(()),
                    Some(j) => Err(format!("formula {j} fails")),
                }
            },
        ),
        over_degrees(
            "derivs_hom (Leibniz rule, fraction-free) gives the derivatives of X = H/w: X⁽ᵏ⁾ = M_k/w^{k+1}",
            "ours",
            1..=8,
            "symbolic t, q_i, w_i; M_0 = H and the quotient rule M_{k+1} = M_k' w − (k+1) w' M_k checked for k = 0…2, weight entries w^{k+1}",
            |n| {
                let c = sym_rational(n, 1);
                let d = c.derivs_hom(&t, 3);
                let h = c.eval_hom(&t);
                let w = h.weight().clone();
                let dw = w.derivative("t");
                if d[0].coords[0] != h.coords[0] {
                    return Err("M_0 ≠ H".into());
                }
                (0..3).try_for_each(|k| {
                    let mk = &d[k].coords[0];
                    let quotient = mk.derivative("t") * &w - &(Poly::from_int(k as i64 + 1) * &dw * mk);
                    if d[k + 1].coords[0] != quotient {
                        return Err(format!("k = {k}: quotient rule fails"));
                    }
                    if *d[k].weight() != w.pow_u32(k as u32 + 1) {
                        return Err(format!("k = {k}: weight entry"));
                    }
                    Ok(())
                })
            },
        ),
    ]
}

/// `|a × b|²` with the explicit 3D cross product (independent of
/// [`cross_norm_sq`]'s Lagrange identity).
fn cross3_sq(a: &[Poly], b: &[Poly]) -> Poly {
    let c = [
        a[1].clone() * &b[2] - &(a[2].clone() * &b[1]),
        a[2].clone() * &b[0] - &(a[0].clone() * &b[2]),
        a[0].clone() * &b[1] - &(a[1].clone() * &b[0]),
    ];
    c.iter().fold(Poly::zero(), |acc, x| acc + x.clone() * x)
}

fn curvature_claims() -> Vec<Claim> {
    let sub = |a: &[Poly], b: &[Poly]| -> Vec<Poly> {
        a.iter().zip(b).map(|(x, y)| x.clone() - y).collect()
    };
    let norm_sq = |a: &[Poly]| a.iter().fold(Poly::zero(), |acc, x| acc + x.clone() * x);
    vec![
        over_degrees(
            "end curvature: k(0) = (n−1)/n · |(P1−P0) × (P2−P1)| / |P1−P0|³ and k(1) = (n−1)/n · |(Pn−1−Pn−2) × (Pn−Pn−1)| / |Pn−Pn−1|³",
            "001 lecture, 二阶导数 (曲率公式)",
            2..=10,
            "symbolic 3D P_i: the squared printed formula (explicit cross product) cross-multiplied with κ² = |X'×X''|²/|X'|⁶ from the exact derivatives at t = 0 and t = 1",
            |n| {
                let c = sym_polynomial(n, 3);
                let p: Vec<Vec<Poly>> = c.ctrl().iter().map(|h| h.weighted().to_vec()).collect();
                let nm1 = Poly::from_int(n as i64 - 1);
                let nn = Poly::from_int(n as i64);
                // (n−1)²|a × b|² / (n²|leg|⁶), leg the end leg of the polygon.
                let printed = |a: Vec<Poly>, b: Vec<Poly>, leg: &[Poly]| {
                    (nm1.clone() * &nm1 * cross3_sq(&a, &b), nn.clone() * &nn * norm_sq(leg).pow_u32(3))
                };
                let first = sub(&p[1], &p[0]);
                let last = sub(&p[n], &p[n - 1]);
                let k0 = printed(first.clone(), sub(&p[2], &p[1]), &first);
                let k1 = printed(sub(&p[n - 1], &p[n - 2]), last.clone(), &last);
                same_frac(&c.curvature_sq_frac(&Poly::zero()), &k0)?;
                same_frac(&c.curvature_sq_frac(&Poly::one()), &k1)
            },
        ),
        over_degrees(
            "rational end curvature: κ(0) = (n−1)/n · (w0 w2/w1²) · |(P1−P0) × (P2−P1)| / |P1−P0|³ (and at t = 1 with the indices mirrored)",
            "ours (extends 001 lecture's k(0), k(1))",
            2..=10,
            "symbolic 2D q_i and w_i: end_curvature_sq_frac cross-multiplied with κ² from the exact rational derivatives at t = 0 and t = 1",
            |n| {
                let c = sym_rational(n, 2);
                same_frac(&c.end_curvature_sq_frac(CurveEnd::Start), &c.curvature_sq_frac(&Poly::zero()))?;
                same_frac(&c.end_curvature_sq_frac(CurveEnd::Finish), &c.curvature_sq_frac(&Poly::one()))
            },
        ),
        Claim::identity(
            "Lagrange's identity |a × b|² = |a|²|b|² − (a·b)² (used for curvature in any dimension)",
            "ours",
            Verdict::Proved,
            &cross_norm_sq(&Poly::vars("a", 3), &Poly::vars("b", 3)),
            &cross3_sq(&Poly::vars("a", 3), &Poly::vars("b", 3)),
            "symbolic 3D vectors a, b",
        ),
    ]
}

fn invariant_claims() -> Vec<Claim> {
    let check = |moved: &RationalCurve<Poly>, orig: &RationalCurve<Poly>| -> Result<(), String> {
        let pairs = moved
            .mobius_invariants_frac()
            .into_iter()
            .zip(orig.mobius_invariants_frac())
            .chain(
                moved
                    .local_invariants_frac()
                    .into_iter()
                    .zip(orig.local_invariants_frac()),
            );
        for (a, b) in pairs {
            same_frac(&a, &b)?;
        }
        Ok(())
    };
    vec![over_degrees(
        "the weight invariants w_iⁿ/(w_0^{n−i} w_nⁱ) and w_{i−1}w_{i+1}/w_i² are unchanged by Möbius reparameterization and by uniform weight scaling (so is the conic type of a quadratic, decided by w0w2/w1²)",
        "ours (from 000 eqs (4), (5))",
        2..=10,
        "symbolic weights w_i, α and scale k; each invariant cross-multiplied",
        |n| {
            let c = sym_rational(n, 1);
            check(&c.mobius(&v("alpha")), &c)?;
            check(&c.scale_weights(&v("k")), &c)
        },
    )]
}

/// `p(t)/t` for a polynomial with `p(0) = 0` (shift of coefficients).
fn div_by_t(p: &Poly) -> Poly {
    let t = v("t");
    (1..=p.degree_in("t")).fold(Poly::zero(), |acc, k| {
        acc + p.coeff_of("t", k) * t.pow(k - 1)
    })
}

/// Bézier's original basis `f_{i,n}(t) = (−t)ⁱ/(i−1)! · d^{i−1}/dt^{i−1} [((1−t)^e − 1)/t]`
/// (`f_{0,n} = 1`) with exponent `e` (`n` correct, `n − 1` printed).
fn bezier_f(i: usize, e: usize) -> Poly {
    if i == 0 {
        return Poly::one();
    }
    let t = v("t");
    let inner = div_by_t(&((Poly::one() - &t).pow(e as u32) - Poly::one()));
    let fact: i64 = (1..i as i64).product();
    let sign = if i % 2 == 1 {
        -Poly::one()
    } else {
        Poly::one()
    };
    sign * t.pow(i as u32)
        * nth_derivative(&inner, "t", i - 1)
        * exact_bezier::algebra::ratio::<Poly>(1, fact)
}

fn bezier_original_claims() -> Vec<Claim> {
    let t = v("t");
    let tail = |i: usize, n: usize| (i..=n).fold(Poly::zero(), |a, j| a + bernstein(j, n, &t));
    let printed_fails = (1..=8).find_map(|n| {
        (1..=n)
            .find(|&i| bezier_f(i, n - 1) != tail(i, n))
            .map(|i| (n, i))
    });
    let corrected = over_degrees(
        "Bézier's original form V(t) = Σ f_{i,n}(t) A_i (A_0 = P_0, A_i = P_i − P_{i−1}) with f_{i,n} = (−t)ⁱ/(i−1)! · d^{i−1}/dt^{i−1}[((1−t)ⁿ − 1)/t] is the Bernstein–Bézier curve",
        "ours (corrects 001 lecture, Bézier曲线: 概念及性质)",
        1..=10,
        "symbolic t and P_i: f_{i,n} = Σ_{j≥i} B_{j,n} for i ≥ 1, hence Σ f_{i,n}A_i = Σ P_i B_{i,n}",
        |n| {
            let p: Vec<Poly> = (0..=n).map(|i| v(&format!("p{i}_0"))).collect();
            if let Some(i) = (1..=n).find(|&i| bezier_f(i, n) != tail(i, n)) {
                return Err(format!("f_{{{i},{n}}} ≠ Σ_{{j≥{i}}} B_{{j,{n}}}"));
            }
            let v_t = (0..=n).fold(Poly::zero(), |a, i| {
                let a_i = if i == 0 { p[0].clone() } else { p[i].clone() - &p[i - 1] };
                a + bezier_f(i, n) * a_i
            });
            let bez = (0..=n).fold(Poly::zero(), |a, i| a + bernstein(i, n, &t) * &p[i]);
            if v_t == bez { Ok(()) } else { Err("V(t) ≠ Σ P_i B_{i,n}(t)".into()) }
        },
    );
    let printed = Claim::check(
        "Bézier's original basis as printed: f_{i,n}(t) = (−t)ⁱ/(i−1)! · d^{i−1}/dt^{i−1}[((1−t)^{n−1} − 1)/t] (i ≥ 1), so that V(t) = Σ f_{i,n}A_i is the Bézier curve",
        "001 lecture, Bézier曲线: 概念及性质",
        Verdict::Refuted,
        printed_fails.is_none(),
        match printed_fails {
            Some((n, i)) => format!(
                "n = {n}, i = {i}: printed f = {} but the curve needs Σ_{{j≥{i}}} B_{{j,{n}}} = {}; e.g. n = 1: printed f_{{1,1}} = 0, so V(t) = P_0 for every t instead of the segment. Correct exponent: (1−t)ⁿ",
                bezier_f(i, n - 1),
                tail(i, n)
            ),
            None => "printed formula agrees".into(),
        },
    );
    vec![printed, corrected]
}

/// The family's claims.
pub fn claims() -> Vec<Claim> {
    let mut all = algorithm_claims();
    all.extend(derivative_claims());
    all.extend(curvature_claims());
    all.extend(invariant_claims());
    all.extend(bezier_original_claims());
    all
}
