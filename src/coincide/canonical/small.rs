//! The fast path of the key text: the same [`CanonicalKey::text`](super::CanonicalKey::text)
//! computed in machine integers for the common case — positive weights, a
//! net certified minimal modulo p (so no reduction is needed), and every
//! number and intermediate within `i128`. Any overflow returns `None` and
//! the caller takes the general `BigRational` path; the two agree
//! (property-tested in the parent module).
//!
//! Why it is faster: `BigRational` allocates and runs a multi-limb binary
//! gcd on every product; here a product of reduced fractions is reduced by
//! two single-word gcds of its cross terms (`(a/b)(c/d) = (a/g₁)(c/g₂) /
//! ((b/g₂)(d/g₁))` with `g₁ = gcd(a, d)`, `g₂ = gcd(c, b)`).

use crate::coincide::minimal::Net;
use crate::coincide::Symmetry;
use num_rational::BigRational;
use num_traits::ToPrimitive;
use std::cmp::Ordering;

/// A rational `p/q` in lowest terms with `q > 0`, in machine integers.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Small {
    p: i128,
    q: i128,
}

/// Binary gcd of machine words (`gcd(0, b) = b`).
fn gcd(mut a: u128, mut b: u128) -> u128 {
    if a == 0 || b == 0 {
        return a | b;
    }
    let shift = (a | b).trailing_zeros();
    a >>= a.trailing_zeros();
    loop {
        b >>= b.trailing_zeros();
        if a > b {
            std::mem::swap(&mut a, &mut b);
        }
        b -= a;
        if b == 0 {
            return a << shift;
        }
    }
}

impl Small {
    const ONE: Small = Small { p: 1, q: 1 };

    fn of(x: &BigRational) -> Option<Small> {
        Some(Small {
            p: x.numer().to_i128()?,
            q: x.denom().to_i128()?,
        })
    }

    /// The product, reduced by cross gcds; `None` on overflow.
    fn mul(self, o: Small) -> Option<Small> {
        let g1 = gcd(self.p.unsigned_abs(), o.q.unsigned_abs()) as i128;
        let g2 = gcd(o.p.unsigned_abs(), self.q.unsigned_abs()) as i128;
        Some(Small {
            p: (self.p / g1).checked_mul(o.p / g2)?,
            q: (self.q / g2).checked_mul(o.q / g1)?,
        })
    }

    /// `1/self` for `self > 0`.
    fn recip_positive(self) -> Small {
        Small {
            p: self.q,
            q: self.p,
        }
    }

    /// Exact order by cross products; `None` on overflow.
    fn cmp(self, o: Small) -> Option<Ordering> {
        Some(self.p.checked_mul(o.q)?.cmp(&o.p.checked_mul(self.q)?))
    }

    fn write(self, out: &mut String) {
        use std::fmt::Write;
        let _ = if self.q == 1 {
            write!(out, "{}", self.p)
        } else {
            write!(out, "{}/{}", self.p, self.q)
        };
    }
}

/// Lexicographic order of two equally long sequences; `None` on overflow.
fn cmp_seq(a: impl Iterator<Item = Small>, b: impl Iterator<Item = Small>) -> Option<Ordering> {
    for (x, y) in a.zip(b) {
        match x.cmp(y)? {
            Ordering::Equal => {}
            o => return Some(o),
        }
    }
    Some(Ordering::Equal)
}

/// The net split into normalized points (row-major, each with its trailing
/// 1) and weights, in its own orientation.
struct Split {
    m: usize,
    n: usize,
    hat: Vec<Vec<Small>>,
    weight: Vec<Small>,
}

impl Split {
    fn new(net: &Net<BigRational>) -> Option<Split> {
        let (m, n) = (net.len() - 1, net[0].len() - 1);
        let mut hat = Vec::with_capacity((m + 1) * (n + 1));
        let mut weight = Vec::with_capacity(hat.capacity());
        for h in net.iter().flatten() {
            let w = Small::of(h.weight())?;
            let inv = w.recip_positive();
            let coords = h.coords[..h.coords.len() - 1]
                .iter()
                .map(|c| Small::of(c)?.mul(inv))
                .chain(std::iter::once(Some(Small::ONE)))
                .collect::<Option<Vec<Small>>>()?;
            hat.push(coords);
            weight.push(w);
        }
        Some(Split { m, n, hat, weight })
    }

    /// Row-major index, in this net, of position (i, j) of its view under
    /// `sym` (of bidegree `(vm, vn)`): as `View::src` of the general path.
    fn source(&self, sym: Symmetry, (vm, vn): (usize, usize), i: usize, j: usize) -> usize {
        let i1 = if sym.reverse_u { vm - i } else { i };
        let j1 = if sym.reverse_v { vn - j } else { j };
        let (a, b) = if sym.swap { (j1, i1) } else { (i1, j1) };
        a * (self.n + 1) + b
    }

    /// The normalized points of the view, row by row.
    fn points(&self, sym: Symmetry, dims: (usize, usize)) -> impl Iterator<Item = Small> + '_ {
        positions(dims)
            .flat_map(move |(i, j)| self.hat[self.source(sym, dims, i, j)].iter().copied())
    }

    /// The weight invariants of the view, `I_{i,j} = (ω_{i,j}/ω_{0,0}) A^i B^j`
    /// with `A = ω_{0,0}/ω_{1,0}`, `B = ω_{0,0}/ω_{0,1}` (positive weights).
    fn invariants(&self, sym: Symmetry, (vm, vn): (usize, usize)) -> Option<Vec<Small>> {
        let w = |i, j| self.weight[self.source(sym, (vm, vn), i, j)];
        let w00 = w(0, 0);
        let powers = |deg: usize, pivot: Small| -> Option<Vec<Small>> {
            let base = w00.mul(pivot.recip_positive())?;
            let mut out = vec![Small::ONE];
            for k in 0..deg {
                out.push(out[k].mul(base)?);
            }
            Some(out)
        };
        let a = powers(vm, if vm > 0 { w(1, 0) } else { w00 })?;
        let b = powers(vn, if vn > 0 { w(0, 1) } else { w00 })?;
        let inv00 = w00.recip_positive();
        let rows = a
            .iter()
            .map(|ai| inv00.mul(*ai))
            .collect::<Option<Vec<Small>>>()?;
        positions((vm, vn))
            .map(|(i, j)| w(i, j).mul(rows[i])?.mul(b[j]))
            .collect()
    }
}

fn positions((m, n): (usize, usize)) -> impl Iterator<Item = (usize, usize)> {
    (0..=m).flat_map(move |i| (0..=n).map(move |j| (i, j)))
}

/// The key text of a net with positive weights that is already of minimal
/// (bi)degree, or `None` when a number leaves `i128`.
pub(super) fn key_text(net: &Net<BigRational>, curve: bool) -> Option<String> {
    let s = Split::new(net)?;
    let target = if curve {
        (s.m, s.n)
    } else {
        (s.m.min(s.n), s.m.max(s.n))
    };
    let mut best: Vec<Symmetry> = Vec::new();
    for sym in Symmetry::admissible(curve, (s.m, s.n), target) {
        let order = match best.first() {
            None => Ordering::Equal,
            Some(&b) => cmp_seq(s.points(sym, target), s.points(b, target))?,
        };
        match order {
            Ordering::Equal => best.push(sym),
            Ordering::Less => best = vec![sym],
            Ordering::Greater => {}
        }
    }
    let mut chosen: Option<(Symmetry, Vec<Small>)> = None;
    for sym in best {
        let inv = s.invariants(sym, target)?;
        let better = match &chosen {
            None => true,
            Some((_, c)) => cmp_seq(inv.iter().copied(), c.iter().copied())? == Ordering::Less,
        };
        if better {
            chosen = Some((sym, inv));
        }
    }
    let (sym, inv) = chosen?;
    Some(text(curve, target, &s, sym, &inv))
}

/// The text of [`CanonicalKey::text`](super::CanonicalKey::text) from the chosen view.
fn text(curve: bool, dims: (usize, usize), s: &Split, sym: Symmetry, inv: &[Small]) -> String {
    let mut out = super::text_head(curve, dims);
    for (k, (i, j)) in positions(dims).enumerate() {
        if k > 0 {
            out.push(';');
        }
        for (c, x) in s.hat[s.source(sym, dims, i, j)].iter().enumerate() {
            if c > 0 {
                out.push(',');
            }
            x.write(&mut out);
        }
    }
    out.push_str(";I=");
    for (k, x) in inv.iter().enumerate() {
        if k > 0 {
            out.push(';');
        }
        out.push_str("+:");
        x.write(&mut out);
    }
    out
}
