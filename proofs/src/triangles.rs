//! Triangular patches (source 001, "三角域Bézier曲面"; our operations):
//! the barycentric Bernstein basis (non-negativity, partition of unity,
//! recursion) for n ≤ 6, and de Casteljau, elevation, the six symmetries,
//! the projective reparameterization, subdivision, boundary curves and
//! directional derivatives for n ≤ 4.
//!
//! Method: the algorithms run on [`Poly`] — control points and weights are
//! symbols (`x_ij`, `w_ij`; one coordinate suffices, every coordinate is
//! treated alike), parameters are symbols — so each identity holds for all
//! patches and all parameters.

use super::{Claim, Verdict};
use exact_bezier::algebra::Poly;
use exact_bezier::hpoint::HPoint;
use exact_bezier::tri::{affine_combination, tri_bernstein, Bary, TriPatch, SYMMETRIES};
use num_traits::{One, Signed, Zero};

/// A degree-`n` triangular patch with symbolic homogeneous control points
/// `(x{tag}_{i}_{j}, w{tag}_{i}_{j})`.
pub fn symbolic_tri(n: usize, tag: &str) -> TriPatch<Poly> {
    let rows = (0..=n)
        .map(|j| {
            (0..=n - j)
                .map(|i| HPoint {
                    coords: vec![
                        Poly::var(&format!("x{tag}_{i}_{j}")),
                        Poly::var(&format!("w{tag}_{i}_{j}")),
                    ],
                })
                .collect()
        })
        .collect();
    TriPatch::from_hom(rows).expect("a triangular layout")
}

/// The symbolic barycentric point `(u, v, 1 − u − v)`.
pub fn uvw() -> Bary<Poly> {
    let (u, v) = (Poly::var("u"), Poly::var("v"));
    let w = Poly::one() - &u - &v;
    [u, v, w]
}

fn eval(t: &TriPatch<Poly>, b: &Bary<Poly>) -> HPoint<Poly> {
    t.eval_hom_bary(&b[0], &b[1], &b[2])
}

fn holds(claim: &str, source: &str, ok: bool, how: &str) -> Claim {
    Claim::check(claim, source, Verdict::Proved, ok, how.to_string())
}

const SYMBOLIC: &str = "symbolic control points, weights and parameters";

fn basis_claims() -> Vec<Claim> {
    let b = [Poly::var("u"), Poly::var("v"), Poly::var("w")];
    let mut out = Vec::new();
    for n in 0..=6usize {
        let all: Vec<(usize, usize)> = (0..=n)
            .flat_map(|j| (0..=n - j).map(move |i| (i, j)))
            .collect();
        let positive = all.iter().all(|&(i, j)| {
            tri_bernstein(n, i, j, &b)
                .terms()
                .all(|(_, c)| c.is_positive())
        });
        out.push(holds(
            &format!("B^{n}_ijk ≥ 0 on the triangle: each is a monomial in u, v, w ≥ 0 with positive coefficient"),
            "001 lecture, 非负性",
            positive,
            "every coefficient of every B^n_ijk(u, v, w) is positive",
        ));
        let sum = all.iter().fold(Poly::zero(), |acc, &(i, j)| {
            acc + tri_bernstein(n, i, j, &uvw())
        });
        out.push(holds(
            &format!("Σ_{{i+j+k={n}}} B^{n}_ijk(u, v, 1 − u − v) = 1"),
            "001 lecture, 归一性",
            sum == Poly::one(),
            "summed symbolically in u, v",
        ));
        if n > 0 {
            let rec = all.iter().all(|&(i, j)| {
                let k = n - i - j;
                let mut rhs = Poly::zero();
                if i > 0 {
                    rhs = rhs + b[0].clone() * tri_bernstein(n - 1, i - 1, j, &b);
                }
                if j > 0 {
                    rhs = rhs + b[1].clone() * tri_bernstein(n - 1, i, j - 1, &b);
                }
                if k > 0 {
                    rhs = rhs + b[2].clone() * tri_bernstein(n - 1, i, j, &b);
                }
                rhs == tri_bernstein(n, i, j, &b)
            });
            out.push(holds(
                &format!(
                    "B^{n}_ijk = u B^{}_(i−1)jk + v B^{}_i(j−1)k + w B^{}_ij(k−1)",
                    n - 1,
                    n - 1,
                    n - 1
                ),
                "001 lecture, 递归",
                rec,
                "for every (i, j, k), symbolically in u, v, w",
            ));
        }
    }
    out
}

fn operation_claims(n: usize) -> Vec<Claim> {
    let t = symbolic_tri(n, "");
    let x = uvw();
    let old = eval(&t, &x);
    let mut out = Vec::new();

    // de Casteljau against the Bernstein sum.
    let sum = (0..=n)
        .flat_map(|j| (0..=n - j).map(move |i| (i, j)))
        .fold(HPoint::zero(1), |acc, (i, j)| {
            acc.add(&t.get(i, j).scale(&tri_bernstein(n, i, j, &x)))
        });
    out.push(holds(
        &format!("degree {n}: triangular de Casteljau = Σ Q̂_ijk B^n_ijk"),
        "001 lecture, de Casteljau算法",
        sum == old,
        SYMBOLIC,
    ));

    out.push(holds(
        &format!("degree {n}: elevation P*_ijk = (iP_(i−1)jk + jP_i(j−1)k + kP_ij(k−1))/(n+1) keeps the patch"),
        "ours (triangular 升阶)",
        eval(&t.elevate(), &x) == old,
        SYMBOLIC,
    ));

    let b3 = [Poly::var("u"), Poly::var("v"), Poly::var("w")];
    let all_sym = SYMMETRIES.iter().all(|&sigma| {
        let mut y = b3.clone();
        for a in 0..3 {
            y[sigma[a]] = b3[a].clone();
        }
        let p = t.permute(sigma).expect("a permutation");
        eval(&p, &b3) == eval(&t, &y)
    });
    out.push(holds(
        &format!("degree {n}: each of the six symmetries σ gives new(x) = old(y), y[σ(a)] = x[a]"),
        "ours",
        all_sym,
        SYMBOLIC,
    ));

    let (a, b, c, lam) = (
        Poly::var("a"),
        Poly::var("b"),
        Poly::var("c"),
        Poly::var("lambda"),
    );
    let moved = t.reparam(&a, &b, &c);
    let image = [a * &b3[0], b * &b3[1], c * &b3[2]];
    let scaled: Bary<Poly> = std::array::from_fn(|k| lam.clone() * &b3[k]);
    out.push(holds(
        &format!("degree {n}: weights ω_ijk aⁱbʲcᵏ give new(u, v, w) = old(au, bv, cw) homogeneously, and old(λx) = λⁿ old(x), so new(x) is old at (au, bv, cw)/(au + bv + cw)"),
        "ours (triangle analogue of source 000 eq. 4)",
        eval(&moved, &b3) == eval(&t, &image)
            && eval(&t, &scaled) == eval(&t, &b3).scale(&lam.pow(n as u32)),
        "symbolic a, b, c, λ, u, v, w and control net",
    ));

    let tt = Poly::var("t");
    let s1 = Poly::one() - &tt;
    let z = Poly::zero;
    let edges = [
        [tt.clone(), z(), s1.clone()],
        [s1.clone(), tt.clone(), z()],
        [z(), s1, tt.clone()],
    ];
    let bound = (0..3).all(|e| t.boundary(e).expect("edge").eval_hom(&tt) == eval(&t, &edges[e]));
    out.push(holds(
        &format!("degree {n}: boundary curves 0 (v = 0), 1 (w = 0), 2 (u = 0) are the patch on its edges"),
        "ours",
        bound,
        SYMBOLIC,
    ));

    let d = [Poly::var("d0"), Poly::var("d1"), Poly::var("d2")];
    let h = Poly::var("h");
    let shifted: Bary<Poly> = std::array::from_fn(|k| x[k].clone() + &(h.clone() * &d[k]));
    let first_order = eval(&t, &shifted).map(&|p: &Poly| p.coeff_of("h", 1));
    out.push(holds(
        &format!("degree {n}: the derivative patch n Σ (d·∇)P B^(n−1) is d/dh T̂(x + h d) at h = 0"),
        "ours",
        eval(&t.deriv_hom(&d), &x) == first_order,
        "symbolic direction, parameters and control net; derivative as the h-coefficient",
    ));

    let split = t.split_edge(1, &tt).expect("edge 1");
    let base: [Bary<Poly>; 3] = std::array::from_fn(|k| {
        let mut v = [z(), z(), z()];
        v[k] = Poly::one();
        v
    });
    let q = [Poly::one() - &tt, tt.clone(), z()];
    let (mut first, mut second) = (base.clone(), base.clone());
    first[1] = q.clone();
    second[0] = q;
    out.push(holds(
        &format!("degree {n}: splitting edge 1 at t gives two patches equal to the old one on (T1, q, T3) and (q, T2, T3)"),
        "ours",
        eval(&split[0], &b3) == eval(&t, &affine_combination(&b3, &first))
            && eval(&split[1], &b3) == eval(&t, &affine_combination(&b3, &second)),
        "symbolic t, parameters and control net",
    ));
    out
}

fn subdivision_claims(n: usize) -> Claim {
    let t = symbolic_tri(n, "");
    let (p0, p1) = (Poly::var("p0"), Poly::var("p1"));
    let p = [p0.clone(), p1.clone(), Poly::one() - &p0 - &p1];
    let b3 = [Poly::var("u"), Poly::var("v"), Poly::var("w")];
    let pieces = t.subdivide_at(&p);
    let ok = (0..3).all(|a| {
        let mut verts: [Bary<Poly>; 3] = std::array::from_fn(|k| {
            let mut v = [Poly::zero(), Poly::zero(), Poly::zero()];
            v[k] = Poly::one();
            v
        });
        verts[a] = p.clone();
        eval(&pieces[a], &b3) == eval(&t, &affine_combination(&b3, &verts))
    });
    holds(
        &format!("degree {n}: subdivision at an interior point p gives three patches equal to the old one on (p,T2,T3), (T1,p,T3), (T1,T2,p)"),
        "ours (blossom, source 003 eq. 4)",
        ok,
        "symbolic p, parameters and control net",
    )
}

/// All claims of the family.
pub fn claims() -> Vec<Claim> {
    let mut out = basis_claims();
    for n in 0..=4 {
        out.extend(operation_claims(n));
    }
    for n in 1..=3 {
        out.push(subdivision_claims(n));
    }
    out
}
