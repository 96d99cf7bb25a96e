//! The coincidence key against GMP: exact-bezier's
//! [`canonical_text`] next to the same canonical form computed on rug's
//! `Rational` (GMP 6), results checked identical as text.
//!
//! The canonical form (`src/coincide/canonical.rs`, `docs/bulk_dedup.md`),
//! for a net of positive weights that is already of minimal degree: the
//! normalized points `Ĥ_{i,j} = H_{i,j} / ω_{i,j}` (the Cartesian point and
//! a trailing 1) read row by row under each admissible symmetry (the two
//! reversals of a curve; the 8 symmetries of the unit square that give
//! bidegree `(min, max)`), the lexicographically smallest kept; among the
//! symmetries that tie on points, the smallest row of weight invariants
//! `I_{i,j} = ω_{i,j} ω_{0,0}^{i+j−1} / (ω_{1,0}^i ω_{0,1}^j)`; then the
//! key text `eb1;KIND;M,N;P=…;I=+:…`.
//!
//! Both sides start from the homogeneous net in memory (`(ω x, ω y, ω z, ω)`
//! per control point, as our patches hold it) and end with the key text.
//! The GMP side is told that the nets are minimal and their weights
//! positive (true of these inputs: a wrong assumption would show as a
//! differing text), so it skips the minimal-degree certificate ours runs.
//! Half of the nets are copies of the other half under a symmetry, Möbius
//! maps and weight scaling (made by our library): on both sides a copy must
//! get its original's key.

use crate::{interleaved, record, Case, Lcg, Shape};
use exact_bezier::coincide::{canonical_text, Symmetry};
use exact_bezier::io::read_patches;
use exact_bezier::{Patch, RationalCurve, RectPatch};
use num_rational::BigRational;
use rug::Rational;
use serde_json::{Map, Value};
use std::cmp::Ordering;

/// A net as the GMP side holds it: row-major homogeneous control points
/// `[ω x, ω y, ω z]` and weights `ω`, `(m + 1) × (n + 1)` of them (`n = 0`
/// for a curve).
struct GmpNet {
    curve: bool,
    m: usize,
    n: usize,
    coords: Vec<[Rational; 3]>,
    weights: Vec<Rational>,
}

/// A symmetry of the unit square: swap u and v, then reverse u, then v.
#[derive(Clone, Copy)]
struct Sym {
    swap: bool,
    reverse_u: bool,
    reverse_v: bool,
}

/// The normalized points and weights of a net, seen through a symmetry.
struct View<'a> {
    hat: &'a [[Rational; 3]],
    weights: &'a [Rational],
    cols: usize,
    m: usize,
    n: usize,
    sym: Sym,
}

impl View<'_> {
    /// The row-major index of the original position of position (i, j).
    fn src(&self, i: usize, j: usize) -> usize {
        let i1 = if self.sym.reverse_u { self.m - i } else { i };
        let j1 = if self.sym.reverse_v { self.n - j } else { j };
        let (a, b) = if self.sym.swap { (j1, i1) } else { (i1, j1) };
        a * self.cols + b
    }

    fn positions(&self) -> impl Iterator<Item = (usize, usize)> + '_ {
        (0..=self.m).flat_map(move |i| (0..=self.n).map(move |j| (i, j)))
    }

    /// Row-major comparison of the normalized points.
    fn cmp_points(&self, other: &View<'_>) -> Ordering {
        self.positions()
            .map(|(i, j)| self.hat[self.src(i, j)].cmp(&other.hat[other.src(i, j)]))
            .find(|o| o.is_ne())
            .unwrap_or(Ordering::Equal)
    }

    /// `I_{i,j} = (ω_{i,j}/ω_{0,0}) A^i B^j` with `A = ω_{0,0}/ω_{1,0}`,
    /// `B = ω_{0,0}/ω_{0,1}`, row by row.
    fn invariants(&self) -> Vec<Rational> {
        let w = |i: usize, j: usize| &self.weights[self.src(i, j)];
        let powers = |base: Option<Rational>, deg: usize| {
            let mut out = vec![Rational::from(1)];
            if let Some(base) = base {
                for k in 0..deg {
                    out.push(Rational::from(&out[k] * &base));
                }
            }
            out
        };
        let a = powers(
            (self.m > 0).then(|| Rational::from(w(0, 0) / w(1, 0))),
            self.m,
        );
        let b = powers(
            (self.n > 0).then(|| Rational::from(w(0, 0) / w(0, 1))),
            self.n,
        );
        let inv00 = Rational::from(w(0, 0).recip_ref());
        self.positions()
            .map(|(i, j)| Rational::from(w(i, j) * &inv00) * &a[i] * &b[j])
            .collect()
    }
}

impl GmpNet {
    fn new(patch: &Patch<BigRational>) -> GmpNet {
        let q = |x: &BigRational| Rational::from(Rational::parse(x.to_string()).expect("exact"));
        let (curve, points, weights): (bool, Vec<Vec<BigRational>>, Vec<Vec<BigRational>>) =
            match patch {
                Patch::Curve(c) => (
                    true,
                    c.points().expect("finite"),
                    c.weights().into_iter().map(|w| vec![w]).collect(),
                ),
                Patch::Rect(r) => (false, r.points().expect("finite").concat(), r.weights()),
                Patch::Tri(_) => unreachable!("keys are of curves and rect patches"),
            };
        let (m, n) = (weights.len() - 1, weights[0].len() - 1);
        let weights: Vec<Rational> = weights.iter().flatten().map(q).collect();
        let coords = points
            .iter()
            .zip(&weights)
            .map(|(p, w)| std::array::from_fn(|k| q(&p[k]) * w))
            .collect();
        GmpNet {
            curve,
            m,
            n,
            coords,
            weights,
        }
    }

    /// The key text, for positive weights and a minimal net.
    fn key_text(&self) -> String {
        let hat: Vec<[Rational; 3]> = self
            .coords
            .iter()
            .zip(&self.weights)
            .map(|(c, w)| {
                let inv = Rational::from(w.recip_ref());
                std::array::from_fn(|k| Rational::from(&c[k] * &inv))
            })
            .collect();
        let (m, n) = (self.m, self.n);
        let target = if self.curve {
            (m, n)
        } else {
            (m.min(n), m.max(n))
        };
        let mut best: Vec<View<'_>> = Vec::new();
        for bits in 0..8u8 {
            let sym = Sym {
                swap: bits & 1 != 0,
                reverse_u: bits & 2 != 0,
                reverse_v: bits & 4 != 0,
            };
            let shape = if sym.swap { (n, m) } else { (m, n) };
            if shape != target || (self.curve && (sym.swap || sym.reverse_v)) {
                continue;
            }
            let v = View {
                hat: &hat,
                weights: &self.weights,
                cols: n + 1,
                m: target.0,
                n: target.1,
                sym,
            };
            match best.first().map(|b| v.cmp_points(b)) {
                None | Some(Ordering::Equal) => best.push(v),
                Some(Ordering::Less) => best = vec![v],
                Some(Ordering::Greater) => {}
            }
        }
        let (view, invariants) = best
            .iter()
            .map(|v| (v, v.invariants()))
            .min_by(|a, b| a.1.cmp(&b.1))
            .expect("the identity is admissible");
        let kind = if self.curve { "curve" } else { "rect" };
        let points: Vec<String> = view
            .positions()
            .map(|(i, j)| {
                let [x, y, z] = &hat[view.src(i, j)];
                format!("{x},{y},{z},1")
            })
            .collect();
        let invariants: Vec<String> = invariants.iter().map(|q| format!("+:{q}")).collect();
        format!(
            "eb1;{kind};{},{};P={};I={}",
            target.0,
            target.1,
            points.join(";"),
            invariants.join(";")
        )
    }
}

/// A copy of `p` under a symmetry, Möbius maps and weight scaling drawn
/// from `rng` (for a curve: reversed or not).
fn copy_of(p: &Patch<BigRational>, rng: &mut Lcg) -> Patch<BigRational> {
    let mut small = |lo: u64| {
        let d = 5 + rng.next() % 20;
        BigRational::new((lo + rng.next() % (d - lo)).into(), d.into())
    };
    let (alpha, beta, k) = (small(1), small(1), small(1));
    let bits = rng.next();
    match p {
        Patch::Curve(c) => {
            let c: RationalCurve<BigRational> = c.mobius(&alpha).scale_weights(&k);
            Patch::Curve(if bits & 1 == 0 { c } else { c.reverse() })
        }
        Patch::Rect(r) => {
            let sym = Symmetry {
                swap: bits & 1 != 0,
                reverse_u: bits & 2 != 0,
                reverse_v: bits & 4 != 0,
            };
            let r: RectPatch<BigRational> = r.mobius_u(&alpha).mobius_v(&beta).scale_weights(&k);
            Patch::Rect(sym.apply_rect(&r))
        }
        Patch::Tri(_) => unreachable!("keys are of curves and rect patches"),
    }
}

/// The key rows: cubic curves and bicubics in space with 10-, 30- and
/// 60-digit coordinates (the last beyond our machine-integer path), `nets`
/// nets each (half of them copies): ns per key.
pub fn key_cases(
    nets: usize,
    repeat: usize,
    only: Option<&str>,
    rng: &mut Lcg,
) -> Map<String, Value> {
    let mut out = Map::new();
    for shape in [Shape::Curve, Shape::Rect] {
        for digits in [10, 30, 60] {
            let kind = if matches!(shape, Shape::Curve) {
                "curve"
            } else {
                "bicubic"
            };
            let name = format!("key, {kind}, {digits}-digit points");
            if only.is_some_and(|o| !name.contains(o)) {
                continue;
            }
            let originals: Vec<Patch<BigRational>> = (0..nets / 2)
                .map(|_| {
                    let case = Case::new(shape, digits, false, 0, rng);
                    read_patches(&case.json()).expect("a valid patch").remove(0)
                })
                .collect();
            let copies: Vec<Patch<BigRational>> =
                originals.iter().map(|p| copy_of(p, rng)).collect();
            let patches = [originals, copies].concat();
            let theirs_in: Vec<GmpNet> = patches.iter().map(GmpNet::new).collect();
            let (mut ours, mut theirs) = (Vec::new(), Vec::new());
            let (a, b) = interleaved(
                repeat,
                patches.len(),
                || {
                    ours = patches
                        .iter()
                        .map(|p| canonical_text(p).expect("a key"))
                        .collect()
                },
                || theirs = theirs_in.iter().map(GmpNet::key_text).collect(),
            );
            assert_eq!(ours, theirs, "{name}: key texts differ");
            let half = patches.len() / 2;
            assert_eq!(ours[..half], ours[half..], "{name}: a copy's key differs");
            record(&mut out, name, (a, b));
        }
    }
    out
}
