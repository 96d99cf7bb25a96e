//! Blossoms (source 003 §1–3): Properties 1.4–1.6, Lemmas 2.1, 2.2, 3.1 and
//! the blossoming algorithm (26).
//!
//! Method: two independent constructions of each polar form — from
//! power-form coefficients by elementary symmetric sums
//! ([`polar_univariate`], [`polar_bivariate`], [`polar_tensor`]) and from
//! Bézier control points by de Casteljau with one argument per level
//! (curve blossom, algorithm (26), tensor blossom) — run on [`Poly`] with
//! symbolic coefficients and symbolic arguments. Degree bounds are stated in
//! each claim.

use super::triangles::symbolic_tri;
use super::{Claim, Verdict};
use exact_bezier::algebra::Poly;
use exact_bezier::algebra::{binomial, recip_int};
use exact_bezier::bernstein::bernstein;
use exact_bezier::blossom::{
    polar_bivariate, polar_tensor, polar_univariate, rect_blossom, ShiftOp,
};
use exact_bezier::curve::RationalCurve;
use exact_bezier::hpoint::HPoint;
use exact_bezier::rect::RectPatch;
use exact_bezier::tri::Bary;
use num_bigint::BigInt;
use num_traits::{One, Zero};

fn holds(claim: &str, source: &str, ok: bool, how: &str) -> Claim {
    Claim::check(claim, source, Verdict::Proved, ok, how.to_string())
}

fn v(name: &str) -> Poly {
    Poly::var(name)
}

fn vars(prefix: &str, n: usize) -> Vec<Poly> {
    (0..n).map(|k| v(&format!("{prefix}{k}"))).collect()
}

/// Symbolic power-form coefficients `c[a][b]`, `a + b ≤ n`.
fn coef2(prefix: &str, n: usize) -> Vec<Vec<Poly>> {
    (0..=n)
        .map(|a| {
            (0..=n - a)
                .map(|b| v(&format!("{prefix}{a}_{b}")))
                .collect()
        })
        .collect()
}

/// The power-form coefficients of a polynomial in `x` (and `y`), `c[a][b]`.
fn power_coefficients(p: &Poly, x: &str, y: &str, da: usize, db: usize) -> Vec<Vec<Poly>> {
    (0..=da)
        .map(|a| {
            let pa = p.coeff_of(x, a as u32);
            (0..=db).map(|b| pa.coeff_of(y, b as u32)).collect()
        })
        .collect()
}

/// Property 1.4 (existence): symmetric, affine in one argument, diagonal.
fn existence_claims() -> Vec<Claim> {
    let mut out = Vec::new();
    let lam = v("lambda");
    let mix = |y: &Poly, z: &Poly| (Poly::one() - &lam) * y + &(lam.clone() * z);
    for n in 1..=5usize {
        let c = vars("c", n + 1);
        let args = vars("t", n);
        let f = |a: &[Poly]| polar_univariate(&c, n, a).expect("n arguments");
        let mut swapped = args.clone();
        swapped.swap(0, n - 1);
        let mut rotated = args.clone();
        rotated.rotate_left(1);
        let (y, z) = (v("y"), v("z"));
        let with = |first: Poly| {
            let mut a = args.clone();
            a[0] = first;
            f(&a)
        };
        let affine = with(mix(&y, &z))
            == (Poly::one() - &lam) * with(y.clone()) + &(lam.clone() * with(z.clone()));
        let x = v("x");
        let diag = f(&vec![x.clone(); n]);
        let p = c.iter().enumerate().fold(Poly::zero(), |acc, (a, ca)| {
            acc + ca.clone() * x.pow(a as u32)
        });
        out.push(holds(
            &format!("Property 1.4, univariate n = {n}: B_n[p] is symmetric, affine in each argument, and B_n[p](x, …, x) = p(x)"),
            "003 Definition 1.1, Property 1.4",
            f(&swapped) == f(&args) && f(&rotated) == f(&args) && affine && diag == p,
            "symbolic coefficients and arguments; symmetry by a transposition and an n-cycle (they generate S_n)",
        ));
    }
    for n in 1..=4usize {
        let c = coef2("c", n);
        let args: Vec<[Poly; 2]> = (0..n)
            .map(|k| [v(&format!("x{k}")), v(&format!("y{k}"))])
            .collect();
        let f = |a: &[[Poly; 2]]| polar_bivariate(&c, n, a).expect("n arguments");
        let mut swapped = args.clone();
        swapped.swap(0, n - 1);
        let mut rotated = args.clone();
        rotated.rotate_left(1);
        let (y, z) = ([v("ya"), v("yb")], [v("za"), v("zb")]);
        let with = |first: [Poly; 2]| {
            let mut a = args.clone();
            a[0] = first;
            f(&a)
        };
        let m = [mix(&y[0], &z[0]), mix(&y[1], &z[1])];
        let affine =
            with(m) == (Poly::one() - &lam) * with(y.clone()) + &(lam.clone() * with(z.clone()));
        let (xx, yy) = (v("X"), v("Y"));
        let diag = f(&vec![[xx.clone(), yy.clone()]; n]);
        let p = c.iter().enumerate().fold(Poly::zero(), |acc, (a, row)| {
            row.iter().enumerate().fold(acc, |acc, (b, cab)| {
                acc + cab.clone() * xx.pow(a as u32) * yy.pow(b as u32)
            })
        });
        out.push(holds(
            &format!("Property 1.4, bivariate total degree n = {n}: B_n[p] is symmetric, n-affine and diagonal"),
            "003 Definition 1.2, Property 1.4",
            f(&swapped) == f(&args) && f(&rotated) == f(&args) && affine && diag == p,
            "symbolic coefficients and arguments",
        ));
    }
    out
}

/// Property 1.4 (uniqueness, as agreement of independent constructions)
/// and the blossoming algorithm (26).
fn uniqueness_claims() -> Vec<Claim> {
    let mut out = Vec::new();
    for n in 1..=4usize {
        let t = symbolic_tri(n, "");
        let (u, w) = (v("u"), v("v"));
        let poly = t.eval_hom_bary(&u, &w, &(Poly::one() - &u - &w));
        let args: Vec<Bary<Poly>> = (0..n)
            .map(|k| {
                let (a, b) = (v(&format!("a{k}")), v(&format!("b{k}")));
                let c = Poly::one() - &a - &b;
                [a, b, c]
            })
            .collect();
        let by26 = t.blossom(&args).expect("n arguments");
        let flat: Vec<[Poly; 2]> = args.iter().map(|b| [b[0].clone(), b[1].clone()]).collect();
        let by_power = HPoint {
            coords: poly
                .coords
                .iter()
                .map(|p| {
                    polar_bivariate(&power_coefficients(p, "u", "v", n, n), n, &flat)
                        .expect("degree n")
                })
                .collect(),
        };
        out.push(holds(
            &format!("Property 1.4 / algorithm (26), n = {n}: the blossoming algorithm equals the power-form polar form of T̂(u, v)"),
            "003 eq. (26), Property 1.4",
            by26 == by_power,
            "symbolic control net and barycentric arguments (u⁽ᵏ⁾, v⁽ᵏ⁾, 1 − u⁽ᵏ⁾ − v⁽ᵏ⁾)",
        ));
        let by2 = ShiftOp::product(&args).apply(&t).expect("degree n");
        out.push(holds(
            &format!("Property 1.5 eq. (2), n = {n}: B_n[T̂](x⁽¹⁾…x⁽ⁿ⁾) = Π_k (u⁽ᵏ⁾E₁ + v⁽ᵏ⁾E₂ + w⁽ᵏ⁾E₃) Q̂_000 equals algorithm (26)"),
            "003 eqs. (2), (3), (26)",
            by2 == by26,
            "symbolic control net and arguments",
        ));
    }
    for n in 1..=5usize {
        let c = RationalCurve::from_hom(
            (0..=n)
                .map(|i| HPoint {
                    coords: vec![v(&format!("p{i}")), v(&format!("q{i}"))],
                })
                .collect(),
        )
        .expect("a curve");
        let t = v("t");
        let poly = c.eval_hom(&t);
        let args = vars("s", n);
        let by_casteljau = c.blossom(&args).expect("n arguments");
        let by_power = poly.map(&|p: &Poly| {
            let coef: Vec<Poly> = (0..=n).map(|a| p.coeff_of("t", a as u32)).collect();
            polar_univariate(&coef, n, &args).expect("degree n")
        });
        out.push(holds(
            &format!("Property 1.4, curve n = {n}: the de Casteljau blossom equals the power-form polar form"),
            "003 Definition 1.1, Property 1.4",
            by_casteljau == by_power,
            "symbolic control points, weights and arguments",
        ));
    }
    for (m, n) in [(1, 1), (1, 2), (2, 1), (2, 2), (2, 3), (3, 3)] {
        let r = symbolic_rect(m, n);
        let (s, t) = (v("s"), v("t"));
        let poly = r.eval_hom(&s, &t);
        let (us, vs) = (vars("g", m), vars("h", n));
        let by_casteljau = rect_blossom(&r, &us, &vs).expect("(m, n) arguments");
        let by_power = poly.map(&|p: &Poly| {
            polar_tensor(&power_coefficients(p, "s", "t", m, n), (m, n), &us, &vs)
                .expect("bidegree")
        });
        out.push(holds(
            &format!("Property 1.4, tensor ({m}, {n}): the de Casteljau blossom equals the power-form polar form"),
            "003 Definition 1.3, Property 1.4",
            by_casteljau == by_power,
            "symbolic control net and arguments",
        ));
    }
    out
}

/// A rectangle of bidegree (m, n) with symbolic homogeneous points.
pub fn symbolic_rect(m: usize, n: usize) -> RectPatch<Poly> {
    let ctrl = (0..=m)
        .map(|i| {
            (0..=n)
                .map(|j| HPoint {
                    coords: vec![v(&format!("P{i}_{j}")), v(&format!("W{i}_{j}"))],
                })
                .collect()
        })
        .collect();
    RectPatch::from_hom(ctrl).expect("a rectangular net")
}

/// Properties 1.5 (eq. 4) and 1.6 (eqs. 5, 6): dual functionals.
fn dual_functional_claims() -> Vec<Claim> {
    let mut out = Vec::new();
    let vertex = |k: usize| -> Bary<Poly> {
        let mut b = [Poly::zero(), Poly::zero(), Poly::zero()];
        b[k] = Poly::one();
        b
    };
    for n in 1..=6usize {
        let t = symbolic_tri(n, "");
        let ok = (0..=n).all(|s| {
            (0..=n - s).all(|r| {
                let mut args = vec![vertex(0); r];
                args.extend(vec![vertex(1); s]);
                args.extend(vec![vertex(2); n - r - s]);
                t.blossom(&args).expect("n arguments") == *t.get(r, s)
            })
        });
        out.push(holds(
            &format!("Property 1.5 eq. (4), n = {n}: Q̂_rst = B_n[T̂](T1^r, T2^s, T3^t)"),
            "003 eq. (4)",
            ok,
            "symbolic control net",
        ));
    }
    for (m, n) in [(1, 1), (2, 2), (2, 3), (4, 4)] {
        let r = symbolic_rect(m, n);
        let ok = (0..=m).all(|i| {
            (0..=n).all(|j| {
                let mut us = vec![Poly::zero(); m - i];
                us.extend(vec![Poly::one(); i]);
                let mut vs = vec![Poly::zero(); n - j];
                vs.extend(vec![Poly::one(); j]);
                rect_blossom(&r, &us, &vs).expect("arguments") == r.ctrl()[i][j]
            })
        });
        out.push(holds(
            &format!(
                "Property 1.6 eq. (5), ({m}, {n}): B_(m,n)[Ĝ](0^(m−i), 1^i; 0^(n−j), 1^j) = P̂_ij"
            ),
            "003 eq. (5)",
            ok,
            "symbolic control net",
        ));
    }
    for n in 1..=6usize {
        let t = v("t");
        let ok = (0..=n).all(|i| {
            let b = bernstein(i, n, &t);
            let coef: Vec<Poly> = (0..=n).map(|a| b.coeff_of("t", a as u32)).collect();
            (0..=n).all(|k| {
                let mut args = vec![Poly::one(); k];
                args.extend(vec![Poly::zero(); n - k]);
                let want = if k == i { Poly::one() } else { Poly::zero() };
                polar_univariate(&coef, n, &args).expect("degree n") == want
            })
        });
        out.push(holds(
            &format!("Property 1.6 eq. (6), n = {n}: B_n[B_i^n](1^k, 0^(n−k)) = δ_ki"),
            "003 eq. (6)",
            ok,
            "power-form polar form of the expanded Bernstein polynomials",
        ));
    }
    out
}

/// The subsets of `0..len` of size `k`, as bit masks.
fn subsets(len: usize, k: usize) -> Vec<u32> {
    (0u32..1 << len)
        .filter(|m| m.count_ones() as usize == k)
        .collect()
}

fn pick<T: Clone>(items: &[T], mask: u32) -> Vec<T> {
    items
        .iter()
        .enumerate()
        .filter(|(i, _)| mask >> i & 1 == 1)
        .map(|(_, x)| x.clone())
        .collect()
}

/// Lemmas 2.1 and 2.2.
fn product_claims() -> Vec<Claim> {
    let mut out = Vec::new();
    for (m, n) in [(1, 1), (1, 2), (2, 2), (1, 3), (2, 3), (1, 4)] {
        let (f, g) = (vars("f", m + 1), vars("g", n + 1));
        let x = v("x");
        let power = |c: &[Poly]| {
            c.iter().enumerate().fold(Poly::zero(), |acc, (a, ca)| {
                acc + ca.clone() * x.pow(a as u32)
            })
        };
        let fg = power(&f) * power(&g);
        let fg_coef: Vec<Poly> = (0..=m + n).map(|a| fg.coeff_of("x", a as u32)).collect();
        let args = vars("u", m + n);
        let lhs = polar_univariate(&fg_coef, m + n, &args).expect("degree m + n");
        let rhs = subsets(m + n, m).iter().fold(Poly::zero(), |acc, &mask| {
            let bf = polar_univariate(&f, m, &pick(&args, mask)).expect("m");
            let bg = polar_univariate(&g, n, &pick(&args, !mask)).expect("n");
            acc + bf * bg
        }) * recip_int::<Poly>(&binomial(m + n, m));
        out.push(Claim::identity(
            &format!("Lemma 2.1, (m, n) = ({m}, {n}): B_(m+n)[f·g] = Σ_σ1 B_m[f](u_I) B_n[g](u_J) / C(m+n, m)"),
            "003 Lemma 2.1",
            Verdict::Proved,
            &lhs,
            &rhs,
            "symbolic coefficients and arguments",
        ));
    }
    for (m, n) in [(1, 1), (2, 1), (2, 2), (1, 3)] {
        for (r, s) in (0..=m).flat_map(|r| (0..=n).map(move |s| (r, s))) {
            let (f, g) = (vars("f", r + 1), vars("g", s + 1));
            let (x, y) = (v("x"), v("y"));
            let fx = f.iter().enumerate().fold(Poly::zero(), |acc, (a, c)| {
                acc + c.clone() * x.pow(a as u32)
            });
            let gy = g.iter().enumerate().fold(Poly::zero(), |acc, (b, c)| {
                acc + c.clone() * y.pow(b as u32)
            });
            let coef = power_coefficients(&(fx * gy), "x", "y", r, s);
            let big = m + n;
            let args: Vec<[Poly; 2]> = (0..big)
                .map(|k| [v(&format!("u{k}")), v(&format!("v{k}"))])
                .collect();
            let us: Vec<Poly> = args.iter().map(|a| a[0].clone()).collect();
            let vs: Vec<Poly> = args.iter().map(|a| a[1].clone()).collect();
            let lhs = polar_bivariate(&coef, big, &args).expect("total degree m + n");
            let mut rhs = Poly::zero();
            for i_mask in subsets(big, r) {
                for j_mask in subsets(big, s).into_iter().filter(|j| j & i_mask == 0) {
                    rhs = rhs
                        + polar_univariate(&f, r, &pick(&us, i_mask)).expect("r")
                            * polar_univariate(&g, s, &pick(&vs, j_mask)).expect("s");
                }
            }
            let rhs = rhs * recip_int::<Poly>(&(binomial(big, r) * binomial(big - r, s)));
            out.push(Claim::identity(
                &format!("Lemma 2.2 eq. (11), (m, n) = ({m}, {n}), deg f = {r}, deg g = {s}: B_(m+n)[f·g] = Σ_σ2 B_r[f](u_I) B_s[g](v_J) / (C(m+n, r) C(m+n−r, s))"),
                "003 Lemma 2.2 (eq. 12 is r = m, s = n)",
                Verdict::Proved,
                &lhs,
                &rhs,
                "symbolic coefficients and arguments",
            ));
        }
    }
    out
}

/// Lemma 3.1: the tensor blossom of f∘g for bilinear g.
fn composition_claims() -> Vec<Claim> {
    let mut out = Vec::new();
    for n in 1..=3usize {
        let f = coef2("c", n);
        // g(s, t) = bilinear with symbolic corners for n ≤ 2, fixed rational corners for n = 3.
        let corner = |k: usize, c: usize| -> Poly {
            if n <= 2 {
                v(&format!("g{k}_{c}"))
            } else {
                let table = [[0, 0], [3, 1], [4, 5], [-1, 2]];
                Poly::from_int(table[k][c])
            }
        };
        let g = |s: &Poly, t: &Poly| -> [Poly; 2] {
            let w = [
                (Poly::one() - s) * (Poly::one() - t),
                s.clone() * (Poly::one() - t),
                s.clone() * t,
                (Poly::one() - s) * t,
            ];
            std::array::from_fn(|c| {
                (0..4).fold(Poly::zero(), |acc, k| acc + w[k].clone() * corner(k, c))
            })
        };
        let (s, t) = (v("s"), v("t"));
        let gx = g(&s, &t);
        let fg = f.iter().enumerate().fold(Poly::zero(), |acc, (a, row)| {
            row.iter().enumerate().fold(acc, |acc, (b, c)| {
                acc + c.clone() * gx[0].pow(a as u32) * gx[1].pow(b as u32)
            })
        });
        let (us, vs) = (vars("u", n), vars("v", n));
        let lhs = polar_tensor(&power_coefficients(&fg, "s", "t", n, n), (n, n), &us, &vs)
            .expect("bidegree (n, n)");
        let mut rhs = Poly::zero();
        let mut count = 0i64;
        for perm in permutations(n) {
            let args: Vec<[Poly; 2]> = (0..n).map(|k| g(&us[perm[k]], &vs[k])).collect();
            rhs = rhs + polar_bivariate(&f, n, &args).expect("n arguments");
            count += 1;
        }
        let rhs = rhs * recip_int::<Poly>(&BigInt::from(count));
        out.push(Claim::identity(
            &format!("Lemma 3.1, n = {n}: B_(n,n)[f∘g](u; v) = Σ_τ B_n[f](g(u_τ(1), v_1), …, g(u_τ(n), v_n)) / n!"),
            "003 Lemma 3.1",
            Verdict::Proved,
            &lhs,
            &rhs,
            if n <= 2 { "symbolic f, symbolic bilinear g, symbolic arguments" } else { "symbolic f and arguments, g with corners (0,0),(3,1),(4,5),(−1,2)" },
        ));
    }
    out
}

/// All permutations of `0..n`.
fn permutations(n: usize) -> Vec<Vec<usize>> {
    if n == 0 {
        return vec![vec![]];
    }
    permutations(n - 1)
        .into_iter()
        .flat_map(|p| {
            (0..n).map(move |pos| {
                let mut q = p.clone();
                q.insert(pos, n - 1);
                q
            })
        })
        .collect()
}

/// All claims of the family.
pub fn claims() -> Vec<Claim> {
    let mut out = existence_claims();
    out.extend(uniqueness_claims());
    out.extend(dual_functional_claims());
    out.extend(product_claims());
    out.extend(composition_claims());
    out
}
