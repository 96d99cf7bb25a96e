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

use crate::algebra::gcd::{gcd_u128, gcd_u64};
use crate::algebra::limbs::push_word;
use crate::algebra::modp::Fp;
use crate::coincide::certificate::FpGrids;
use crate::coincide::minimal::Net;
use crate::coincide::Symmetry;
use crate::curve::RationalCurve;
use crate::error::Error;
use crate::limits::Size;
use crate::rect::RectPatch;
use crate::Patch;
use num_rational::BigRational;
use num_traits::ToPrimitive;
use std::borrow::Cow;
use std::cmp::Ordering;

/// A rational `p/q` in lowest terms with `q > 0`, in machine integers.
///
/// Its products and reductions are `#[inline(always)]`: called, they
/// returned their `Option<Small>` through the stack, and the wider load of
/// its tag stalled on store forwarding (most of the reader's time in
/// `SmallPatch::new`, issue 31).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Small {
    p: i128,
    q: i128,
}

/// `v` as a 64-bit word, if it fits one.
#[inline(always)]
fn word(v: i128) -> Option<i64> {
    i64::try_from(v).ok()
}

/// `a · b`, on one 64-bit product when both fit words (then it cannot
/// overflow `i128`); `None` on overflow.
#[inline(always)]
fn checked_mul(a: i128, b: i128) -> Option<i128> {
    match (word(a), word(b)) {
        (Some(x), Some(y)) => Some(i128::from(x) * i128::from(y)),
        _ => a.checked_mul(b),
    }
}

/// `a / g` for a divisor `g > 0` of `a`, on 64-bit words when `a` fits.
#[inline(always)]
fn div_exact(a: i128, g: i128) -> i128 {
    match (g, i64::try_from(a), i64::try_from(g)) {
        (1, _, _) => a,
        (_, Ok(a), Ok(g)) => i128::from(a / g),
        _ => a / g,
    }
}

impl Small {
    const ONE: Small = Small { p: 1, q: 1 };

    /// `p/q` in lowest terms, for `q > 0`.
    #[inline(always)]
    fn reduced((p, q): (i128, i128)) -> Option<Small> {
        if q <= 0 {
            return None;
        }
        if q == 1 {
            return Some(Small { p, q });
        }
        let g = gcd_u128(p.unsigned_abs(), q.unsigned_abs()) as i128;
        Some(Small {
            p: div_exact(p, g),
            q: div_exact(q, g),
        })
    }

    fn of(x: &BigRational) -> Option<Small> {
        Some(Small {
            p: x.numer().to_i128()?,
            q: x.denom().to_i128()?,
        })
    }

    /// The product, reduced by cross gcds; `None` on overflow. Integers
    /// (`q = 1`, the common case) need no gcd, or one when only one is.
    #[inline(always)]
    fn mul(self, o: Small) -> Option<Small> {
        match (self.q, o.q) {
            (1, 1) => {
                return Some(Small {
                    p: checked_mul(self.p, o.p)?,
                    q: 1,
                })
            }
            (1, _) => return o.mul_integer(self.p),
            (_, 1) => return self.mul_integer(o.p),
            _ => {}
        }
        if let Some(product) = self.mul_words(o) {
            return Some(product);
        }
        let g1 = gcd_u128(self.p.unsigned_abs(), o.q.unsigned_abs()) as i128;
        let g2 = gcd_u128(o.p.unsigned_abs(), self.q.unsigned_abs()) as i128;
        Some(Small {
            p: div_exact(self.p, g1).checked_mul(div_exact(o.p, g2))?,
            q: div_exact(self.q, g2).checked_mul(div_exact(o.q, g1))?,
        })
    }

    /// `self · a` for an integer `a`: `(p/q)·a = p(a/g) / (q/g)` with
    /// `g = gcd(a, q)`, in lowest terms; `None` on overflow.
    #[inline(always)]
    fn mul_integer(self, a: i128) -> Option<Small> {
        let g = gcd_u128(a.unsigned_abs(), self.q.unsigned_abs()) as i128;
        Some(Small {
            p: checked_mul(self.p, div_exact(a, g))?,
            q: div_exact(self.q, g),
        })
    }

    /// [`mul`](Small::mul) when all four integers fit 64-bit words (the
    /// common case): gcds and quotients on words, and products of two words
    /// cannot overflow `i128`. `None` when they do not fit.
    #[inline(always)]
    fn mul_words(self, o: Small) -> Option<Small> {
        let (a, b, c, d) = (word(self.p)?, word(self.q)?, word(o.p)?, word(o.q)?);
        let gcd = |x: i64, y: i64| gcd_u64(x.unsigned_abs(), y.unsigned_abs()) as i64;
        let (g1, g2) = (gcd(a, d), gcd(c, b));
        // A gcd of 2⁶³ (both i64::MIN) does not fit: the general path.
        if g1 <= 0 || g2 <= 0 {
            return None;
        }
        Some(Small {
            p: i128::from(a / g1) * i128::from(c / g2),
            q: i128::from(b / g2) * i128::from(d / g1),
        })
    }

    /// Whether the product fits `i128` ([`mul`](Small::mul) is not
    /// `None`), decided without a gcd when the unreduced one fits.
    #[inline(always)]
    fn product_fits(self, o: Small) -> bool {
        let unreduced = checked_mul(self.p, o.p).is_some() && checked_mul(self.q, o.q).is_some();
        unreduced || self.mul(o).is_some()
    }

    /// `1/self` for `self > 0`.
    fn recip_positive(self) -> Small {
        Small {
            p: self.q,
            q: self.p,
        }
    }

    /// Exact order by cross products; `None` on overflow.
    #[inline(always)]
    fn cmp(self, o: Small) -> Option<Ordering> {
        if self.q == o.q {
            // One denominator (q > 0): the numerators decide.
            return Some(self.p.cmp(&o.p));
        }
        Some(self.p.checked_mul(o.q)?.cmp(&o.p.checked_mul(self.q)?))
    }

    /// `p` or `p/q` in decimal, as `BigRational`'s text.
    fn write(self, out: &mut String) {
        push_int(out, self.p);
        if self.q != 1 {
            out.push('/');
            push_int(out, self.q);
        }
    }
}

/// `v` in decimal, on 64-bit words when it fits one (the common case: the
/// formatter's 128-bit path divides in software); one or two digits (the
/// coordinates and invariants of small nets) written where it is called.
#[inline(always)]
fn push_int(out: &mut String, v: i128) {
    let Ok(u) = u64::try_from(v.unsigned_abs()) else {
        use std::fmt::Write;
        let _ = write!(out, "{v}");
        return;
    };
    if v < 0 {
        out.push('-');
    }
    if u < 100 {
        if u >= 10 {
            out.push(char::from(b'0' + (u / 10) as u8));
        }
        out.push(char::from(b'0' + (u % 10) as u8));
        return;
    }
    push_word(out, u);
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

/// The net split into Cartesian points (row-major, `dim` numbers each;
/// the normalized point `Ĥ` is the point and a trailing 1) and weights, in
/// its own orientation; borrowed from a [`SmallPatch`], owned from a net.
struct Split<'a> {
    m: usize,
    n: usize,
    dim: usize,
    coords: Cow<'a, [Small]>,
    weight: Cow<'a, [Small]>,
}

impl Split<'_> {
    fn new(net: &Net<BigRational>) -> Option<Split<'static>> {
        let (m, n) = (net.len() - 1, net[0].len() - 1);
        let dim = net[0][0].coords.len() - 1;
        let mut coords = Vec::with_capacity((m + 1) * (n + 1) * dim);
        let mut weight = Vec::with_capacity((m + 1) * (n + 1));
        for h in net.iter().flatten() {
            let w = Small::of(h.weight())?;
            let inv = w.recip_positive();
            for c in &h.coords[..dim] {
                coords.push(Small::of(c)?.mul(inv)?);
            }
            weight.push(w);
        }
        Some(Split {
            m,
            n,
            dim,
            coords: Cow::Owned(coords),
            weight: Cow::Owned(weight),
        })
    }

    /// The Cartesian coordinates of the point of row-major index `k`.
    fn point(&self, k: usize) -> &[Small] {
        &self.coords[k * self.dim..(k + 1) * self.dim]
    }

    /// Row-major index, in this net, of position (i, j) of its view under
    /// `sym` (of bidegree `(vm, vn)`): as `View::src` of the general path.
    fn source(&self, sym: Symmetry, (vm, vn): (usize, usize), i: usize, j: usize) -> usize {
        let i1 = if sym.reverse_u { vm - i } else { i };
        let j1 = if sym.reverse_v { vn - j } else { j };
        let (a, b) = if sym.swap { (j1, i1) } else { (i1, j1) };
        a * (self.n + 1) + b
    }

    /// The lexicographic order of the normalized points of the views under
    /// `a` and `b`, row by row; `None` on overflow. Each normalized point
    /// ends in the same 1, so the Cartesian coordinates decide.
    fn cmp_views(&self, a: Symmetry, b: Symmetry, dims: (usize, usize)) -> Option<Ordering> {
        for (i, j) in positions(dims) {
            let x = self.point(self.source(a, dims, i, j)).iter().copied();
            let y = self.point(self.source(b, dims, i, j)).iter().copied();
            match cmp_seq(x, y)? {
                Ordering::Equal => {}
                o => return Some(o),
            }
        }
        Some(Ordering::Equal)
    }

    /// The weight invariants of the view, `I_{i,j} = (ω_{i,j}/ω_{0,0}) A^i B^j`
    /// with `A = ω_{0,0}/ω_{1,0}`, `B = ω_{0,0}/ω_{0,1}` (positive weights),
    /// in machine fractions or over Q; `None` when a machine number
    /// overflows.
    fn invariants<N: InvariantNumber>(
        &self,
        sym: Symmetry,
        (vm, vn): (usize, usize),
    ) -> Option<Vec<N>> {
        let w = |i, j| N::from_small(self.weight[self.source(sym, (vm, vn), i, j)]);
        let w00 = w(0, 0);
        let powers = |deg: usize, pivot: N| -> Option<Vec<N>> {
            let base = w00.times(&pivot.recip_positive())?;
            let mut out = vec![N::from_small(Small::ONE)];
            for k in 0..deg {
                out.push(out[k].times(&base)?);
            }
            Some(out)
        };
        let a = powers(vm, if vm > 0 { w(1, 0) } else { w00.clone() })?;
        let b = powers(vn, if vn > 0 { w(0, 1) } else { w00.clone() })?;
        let inv00 = w00.recip_positive();
        let rows = try_collect(a.len(), a.iter().map(|ai| inv00.times(ai)))?;
        try_collect(
            (vm + 1) * (vn + 1),
            positions((vm, vn)).map(|(i, j)| w(i, j).times(&rows[i])?.times(&b[j])),
        )
    }
}

/// The numbers the weight invariants are computed in: machine fractions
/// (products `None` on overflow) or `BigRational` (products reduced by
/// Lehmer's gcd, [`product`](crate::algebra::gcd::product)).
trait InvariantNumber: Sized + Clone {
    fn from_small(x: Small) -> Self;
    fn times(&self, o: &Self) -> Option<Self>;
    /// `1/self` for `self > 0`.
    fn recip_positive(&self) -> Self;
}

impl InvariantNumber for Small {
    fn from_small(x: Small) -> Self {
        x
    }
    fn times(&self, o: &Self) -> Option<Self> {
        self.mul(*o)
    }
    fn recip_positive(&self) -> Self {
        Small::recip_positive(*self)
    }
}

impl InvariantNumber for BigRational {
    fn from_small(x: Small) -> Self {
        BigRational::new_raw(x.p.into(), x.q.into())
    }
    fn times(&self, o: &Self) -> Option<Self> {
        Some(crate::algebra::gcd::product(self, o))
    }
    fn recip_positive(&self) -> Self {
        self.recip()
    }
}

/// The values of `items` (`len` of them) if none is `None`: one allocation
/// of `len` (collecting into `Option<Vec>` cannot size its vector ahead and
/// grows it step by step).
fn try_collect<T>(len: usize, items: impl Iterator<Item = Option<T>>) -> Option<Vec<T>> {
    let mut out = Vec::with_capacity(len);
    for x in items {
        out.push(x?);
    }
    Some(out)
}

/// Append `p_k · Π_{j≠k} q_j mod p` for the fractions `x(k) = p_k/q_k`,
/// `k < n`: their images times the product of their denominators, by
/// products of the denominators before `k` and after it (no inverse);
/// `None` when `p` divides a denominator.
fn push_cleared(out: &mut Vec<Fp>, n: usize, x: impl Fn(usize) -> Small) -> Option<()> {
    let start = out.len();
    let mut before = Fp::new(1);
    let mut fractions = false;
    for k in 0..n {
        let xk = x(k);
        let image = Fp::from_i128(xk.p);
        out.push(if fractions { image * before } else { image });
        if xk.q != 1 {
            before = before * Fp::from_i128(xk.q);
            fractions = true;
        }
    }
    if before == Fp::new(0) {
        return None;
    }
    if fractions {
        let mut after = Fp::new(1);
        for (k, y) in out[start..].iter_mut().enumerate().rev() {
            *y = *y * after;
            let q = x(k).q;
            if q != 1 {
                after = after * Fp::from_i128(q);
            }
        }
    }
    Some(())
}

fn positions((m, n): (usize, usize)) -> impl Iterator<Item = (usize, usize)> {
    (0..=m).flat_map(move |i| (0..=n).map(move |j| (i, j)))
}

/// The key text of a net with positive weights that is already of minimal
/// (bi)degree, or `None` when a number leaves `i128`.
pub(super) fn key_text(net: &Net<BigRational>, curve: bool) -> Option<String> {
    split_key_text(&Split::new(net)?, curve, false)
}

/// [`key_text`], with the weight invariants over Q when they leave `i128`
/// (the points still in machine integers): `None` only when a point or a
/// comparison of points does.
pub(super) fn key_text_rational_invariants(net: &Net<BigRational>, curve: bool) -> Option<String> {
    split_key_text(&Split::new(net)?, curve, true)
}

/// The key text of a split net already of minimal (bi)degree, or `None`
/// when a number leaves `i128` (the weight invariants only if not
/// `rational_invariants`).
fn split_key_text(s: &Split, curve: bool, rational_invariants: bool) -> Option<String> {
    let target = if curve {
        (s.m, s.n)
    } else {
        (s.m.min(s.n), s.m.max(s.n))
    };
    let mut best: Vec<Symmetry> = Vec::new();
    for sym in Symmetry::admissible(curve, (s.m, s.n), target) {
        let order = match best.first() {
            None => Ordering::Equal,
            Some(&b) => s.cmp_views(sym, b, target)?,
        };
        match order {
            Ordering::Equal => best.push(sym),
            Ordering::Less => best = vec![sym],
            Ordering::Greater => {}
        }
    }
    if let Some((sym, inv)) = least_machine_invariants(s, &best, target) {
        return Some(text(curve, target, s, sym, inv.len(), |out, k| {
            inv[k].write(out)
        }));
    }
    if !rational_invariants {
        return None;
    }
    let (sym, inv) = best
        .iter()
        .map(|&sym| (sym, s.invariants::<BigRational>(sym, target)))
        .min_by(|a, b| a.1.cmp(&b.1))?;
    let inv = inv?;
    Some(text(curve, target, s, sym, inv.len(), |out, k| {
        super::push_rational(out, &inv[k])
    }))
}

/// The view among `best` with the least invariants in machine fractions,
/// or `None` when one of them overflows.
fn least_machine_invariants(
    s: &Split,
    best: &[Symmetry],
    target: (usize, usize),
) -> Option<(Symmetry, Vec<Small>)> {
    let mut chosen: Option<(Symmetry, Vec<Small>)> = None;
    for &sym in best {
        let inv = s.invariants::<Small>(sym, target)?;
        let better = match &chosen {
            None => true,
            Some((_, c)) => cmp_seq(inv.iter().copied(), c.iter().copied())? == Ordering::Less,
        };
        if better {
            chosen = Some((sym, inv));
        }
    }
    chosen
}

/// The text of [`CanonicalKey::text`](super::CanonicalKey::text) from the
/// chosen view; `invariant(out, k)` writes the `k`-th of `count` invariants.
fn text(
    curve: bool,
    dims: (usize, usize),
    s: &Split,
    sym: Symmetry,
    count: usize,
    invariant: impl Fn(&mut String, usize),
) -> String {
    let mut out = super::text_head(curve, dims);
    // Room for the usual short numbers: one growth, not several.
    out.reserve(8 * (s.coords.len() + s.weight.len()) + 4 * count);
    for (k, (i, j)) in positions(dims).enumerate() {
        if k > 0 {
            out.push(';');
        }
        for x in s.point(s.source(sym, dims, i, j)) {
            x.write(&mut out);
            out.push(',');
        }
        out.push('1');
    }
    out.push_str(";I=");
    for k in 0..count {
        if k > 0 {
            out.push(';');
        }
        out.push_str("+:");
        invariant(&mut out, k);
    }
    out
}

/// `v` (row-major) as rows of `cols` entries.
fn rows<T: Clone>(v: &[T], cols: usize) -> Vec<Vec<T>> {
    v.chunks(cols).map(<[T]>::to_vec).collect()
}

/// Bits of a machine fraction as [`limits::bits`](crate::limits::bits)
/// counts them: the numerator's and the denominator's bit lengths.
fn bit_len(x: Small) -> u64 {
    let len = |v: u128| u64::from(128 - v.leading_zeros());
    len(x.p.unsigned_abs()) + len(x.q.unsigned_abs())
}

/// A curve or rect patch over Q whose numbers are machine fractions: what
/// the bulk commands read straight from a JSON line
/// ([`io::read_small_patch`](crate::io::read_small_patch)), keyed without a
/// `BigRational` when its net is certified minimal (the common case).
///
/// It is the same patch as [`to_patch`](SmallPatch::to_patch), and
/// [`key_text`](SmallPatch::key_text) is the same text as
/// [`canonical_text`](super::canonical_text) of that patch.
///
/// ```
/// use exact_bezier::coincide::canonical::{canonical_text, SmallPatch};
/// // The curve (0) (1/2) (3) with weights 1, 2, 1.
/// let mut c = SmallPatch::new(true, (2, 0), 1, &[(0, 1), (1, 2), (3, 1)], &[(1, 1), (2, 1), (1, 1)]).unwrap();
/// assert!(c.certify());
/// assert_eq!(c.key_text().unwrap(), canonical_text(&c.to_patch().unwrap()).unwrap());
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SmallPatch {
    curve: bool,
    shape: (usize, usize),
    dim: usize,
    /// Cartesian coordinates, row-major, `dim` per point.
    coords: Vec<Small>,
    /// Weights, row-major.
    weights: Vec<Small>,
    /// The key text in machine integers, once [`certify`](SmallPatch::certify)
    /// has proved the net minimal and no number of the key left `i128`.
    text: Option<String>,
}

impl SmallPatch {
    /// The curve (`curve`, `shape = (n, 0)`: `n + 1` points) or rect patch
    /// of bidegree `shape` in dimension `dim`, from its Cartesian
    /// coordinates (row-major, `dim` per point) and weights, each `(p, q)`
    /// standing for `p/q`. `None` unless every `q > 0`, every weight is
    /// positive, `dim ≥ 1` and the counts fit the shape.
    pub fn new(
        curve: bool,
        shape: (usize, usize),
        dim: usize,
        coords: &[(i128, i128)],
        weights: &[(i128, i128)],
    ) -> Option<SmallPatch> {
        let count = (shape.0 + 1) * (shape.1 + 1);
        let fits = dim >= 1
            && (!curve || shape.1 == 0)
            && weights.len() == count
            && coords.len() == count * dim;
        if !fits {
            return None;
        }
        let coords = try_collect(coords.len(), coords.iter().map(|&x| Small::reduced(x)))?;
        let weights = try_collect(
            weights.len(),
            weights
                .iter()
                .map(|&w| Small::reduced(w).filter(|w| w.p > 0)),
        )?;
        Some(SmallPatch {
            curve,
            shape,
            dim,
            coords,
            weights,
            text: None,
        })
    }

    /// The (bi)degree: `(n, 0)` for a curve.
    pub fn degree(&self) -> (usize, usize) {
        self.shape
    }

    /// Coordinates per point (Cartesian).
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// Whether every homogeneous number `x·ω` of the net fits `i128`
    /// ([`size`](SmallPatch::size) is not `None`), decided without the
    /// gcds of the bit count: an unreduced product that fits decides, and
    /// when every integer of the net fits a 64-bit word, every product does.
    pub fn homogeneous_fits(&self) -> bool {
        let words = |x: &Small| word(x.p).is_some() && word(x.q).is_some();
        if self.coords.iter().chain(&self.weights).all(words) {
            return true;
        }
        let points = self.coords.chunks_exact(self.dim);
        self.weights
            .iter()
            .zip(points)
            .all(|(&w, x)| x.iter().all(|&c| c.product_fits(w)))
    }

    /// The size the cost model charges ([`Patch::size`](crate::Patch::size)
    /// of [`to_patch`](SmallPatch::to_patch)); `None` when a homogeneous
    /// number leaves `i128`.
    pub fn size(&self) -> Option<Size> {
        let mut bits = 0;
        for (&w, x) in self.weights.iter().zip(self.coords.chunks_exact(self.dim)) {
            bits = bits.max(bit_len(w));
            for &c in x {
                bits = bits.max(bit_len(c.mul(w)?));
            }
        }
        Some(Size {
            degree: self.shape,
            tri: false,
            dim: self.dim,
            bits,
            field_degree: 1,
            field: false,
        })
    }

    /// Prove the net minimal modulo `p` as
    /// [`KeyPlan::Minimal`](super::KeyPlan::Minimal) does (the same
    /// certificate on the same image, each component times a non-zero
    /// constant: the same answer); `false` when it is not proved (or a
    /// denominator is divisible by `p`). When it is proved, the key text is
    /// computed at once in machine integers (work linear in the net, like
    /// reading it) and kept for [`key_text`](SmallPatch::key_text), unless a
    /// number leaves `i128` ([`machine_keyed`](SmallPatch::machine_keyed)
    /// tells which, as [`KeyPlan::Machine`](super::KeyPlan::Machine) does).
    pub fn certify(&mut self) -> bool {
        let shape = (self.shape.0, self.shape.1);
        let certified = self
            .homogeneous_mod_p()
            .is_some_and(|image| FpGrids::new(image, self.dim + 1, shape).bernstein_certified());
        if certified {
            self.text = split_key_text(&self.split(), self.curve, false);
        }
        certified
    }

    /// Whether [`certify`](SmallPatch::certify) computed the key text in
    /// machine integers (else [`key_text`](SmallPatch::key_text) takes the
    /// general `BigRational` path).
    pub fn machine_keyed(&self) -> bool {
        self.text.is_some()
    }

    /// The net as a [`Split`], borrowing the patch's numbers.
    fn split(&self) -> Split<'_> {
        Split {
            m: self.shape.0,
            n: self.shape.1,
            dim: self.dim,
            coords: Cow::Borrowed(&self.coords),
            weight: Cow::Borrowed(&self.weights),
        }
    }

    /// The image modulo `p` of the homogeneous net, each component times
    /// a non-zero constant, as flat grids of Bernstein coefficients
    /// ([`FpGrids`]: component `c` of point `k`, row-major, at
    /// `c·count + k`), or `None` when `p` divides a denominator. The
    /// constants clear the denominators without an inverse
    /// ([`push_cleared`]): the weights are multiplied by the product of
    /// their denominators, coordinate `c` by that of its own. The
    /// certificate cannot tell: a component's degree, and the gcd of the
    /// components, are those of its non-zero multiples.
    fn homogeneous_mod_p(&self) -> Option<Vec<Fp>> {
        let (count, dim) = (self.weights.len(), self.dim);
        let mut grids = Vec::with_capacity(count * (dim + 1));
        for c in 0..dim {
            push_cleared(&mut grids, count, |k| self.coords[k * dim + c])?;
        }
        push_cleared(&mut grids, count, |k| self.weights[k])?;
        let (coords, weights) = grids.split_at_mut(dim * count);
        for component in coords.chunks_exact_mut(count) {
            for (x, &w) in component.iter_mut().zip(&*weights) {
                *x = *x * w;
            }
        }
        Some(grids)
    }

    /// The same patch over `BigRational`.
    ///
    /// # Errors
    ///
    /// As [`RationalCurve::new`] and [`RectPatch::new`] (never for a patch
    /// built by [`new`](SmallPatch::new)).
    pub fn to_patch(&self) -> Result<Patch<BigRational>, Error> {
        let big = |x: &Small| BigRational::new(x.p.into(), x.q.into());
        let points: Vec<Vec<BigRational>> = self
            .coords
            .chunks_exact(self.dim)
            .map(|x| x.iter().map(big).collect())
            .collect();
        let weights: Vec<BigRational> = self.weights.iter().map(big).collect();
        if self.curve {
            return RationalCurve::new(points, weights).map(Patch::Curve);
        }
        let cols = self.shape.1 + 1;
        RectPatch::new(rows(&points, cols), rows(&weights, cols)).map(Patch::Rect)
    }

    /// The key text, [`canonical_text`](super::canonical_text) of
    /// [`to_patch`](SmallPatch::to_patch): the one
    /// [`certify`](SmallPatch::certify) computed in machine integers, else
    /// through the general path.
    ///
    /// # Errors
    ///
    /// As [`canonical_text`](super::canonical_text).
    pub fn key_text(&self) -> Result<Cow<'_, str>, Error> {
        match &self.text {
            Some(text) => Ok(Cow::Borrowed(text)),
            None => super::canonical_text(&self.to_patch()?).map(Cow::Owned),
        }
    }

    /// [`key_text`](SmallPatch::key_text), taking the patch (no copy of a
    /// machine-computed text).
    ///
    /// # Errors
    ///
    /// As [`canonical_text`](super::canonical_text).
    pub fn into_key_text(self) -> Result<String, Error> {
        match self.text {
            Some(text) => Ok(text),
            None => super::canonical_text(&self.to_patch()?),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::coincide::canonical::canonical_key;
    use proptest::prelude::*;

    fn big(x: Small) -> BigRational {
        BigRational::new(x.p.into(), x.q.into())
    }

    /// Integers of every size up to 2¹²⁶: on words, at the word limits,
    /// and beyond them.
    fn integer() -> impl Strategy<Value = i128> {
        prop_oneof![
            -1000i128..1000,
            any::<i64>().prop_map(i128::from),
            Just(i128::from(i64::MIN)),
            Just(i128::from(i64::MAX) + 1),
            (any::<i64>(), 1i128..1 << 62).prop_map(|(a, b)| i128::from(a) * b),
        ]
    }

    /// Fractions, a third of them integers (the products' shortcuts).
    fn fraction() -> impl Strategy<Value = Small> {
        let ratio = (integer(), integer()).prop_filter_map("q > 0", |(p, q)| {
            Small::reduced((p, q.checked_abs()?.max(1)))
        });
        prop_oneof![2 => ratio, 1 => integer().prop_map(|p| Small { p, q: 1 })]
    }

    /// A bicubic or curve of small machine fractions, positive weights.
    fn small_patch() -> impl Strategy<Value = SmallPatch> {
        patch_of((1i128..30, 1i128..12))
    }

    /// As [`small_patch`], with weights up to 2⁴⁰ over up to 2²⁰: the
    /// invariants of some leave `i128`.
    fn wide_patch() -> impl Strategy<Value = SmallPatch> {
        patch_of((1i128..1 << 40, 1i128..1 << 20))
    }

    /// A bicubic or curve of small machine coordinates and weights drawn
    /// from `weight`.
    fn patch_of(
        weight: impl Strategy<Value = (i128, i128)> + Clone + 'static,
    ) -> impl Strategy<Value = SmallPatch> {
        let number = (-30i128..30, 1i128..12);
        (any::<bool>(), 1usize..4, 1usize..4, 1usize..4).prop_flat_map(move |(curve, m, n, dim)| {
            let n = if curve { 0 } else { n };
            let count = (m + 1) * (n + 1);
            (
                prop::collection::vec(number.clone(), count * dim),
                prop::collection::vec(weight.clone(), count),
            )
                .prop_filter_map("a patch", move |(coords, weights)| {
                    SmallPatch::new(curve, (m, n), dim, &coords, &weights)
                })
        })
    }

    proptest! {
        #[test]
        fn products_are_exact_or_refused_when_they_leave_128_bits(a in fraction(), b in fraction()) {
            let exact = big(a) * big(b);
            match a.mul(b) {
                Some(x) => prop_assert_eq!(big(x), exact),
                None => prop_assert!(Small::of(&exact).is_none()),
            }
        }

        #[test]
        fn homogeneous_numbers_fit_when_the_size_is_known(
            coords in prop::collection::vec(fraction(), 3),
            weights in prop::collection::vec(fraction(), 3),
        ) {
            let pair = |x: &Small| (x.p, x.q);
            let coords: Vec<_> = coords.iter().map(pair).collect();
            let weights: Vec<_> = weights.iter().map(|w| (w.p.checked_abs().unwrap_or(1).max(1), w.q)).collect();
            let s = SmallPatch::new(true, (2, 0), 1, &coords, &weights).unwrap();
            prop_assert_eq!(s.homogeneous_fits(), s.size().is_some());
        }

        #[test]
        fn the_machine_certificate_is_that_of_the_net_over_q(mut s in small_patch()) {
            let patch = s.to_patch().unwrap();
            let (net, _) = crate::coincide::net_of(&patch).unwrap();
            prop_assert_eq!(s.certify(), crate::coincide::minimal::certified_minimal(&net));
        }

        #[test]
        fn the_machine_text_decides_the_plan(mut s in wide_patch()) {
            use crate::coincide::canonical::{canonical_text, key_plan, KeyPlan};
            let patch = s.to_patch().unwrap();
            let certified = s.certify();
            let plan = key_plan(&patch).unwrap();
            prop_assert_eq!(s.machine_keyed(), plan == KeyPlan::Machine);
            prop_assert_eq!(certified, matches!(plan, KeyPlan::Machine | KeyPlan::Minimal));
            prop_assert_eq!(s.key_text().unwrap(), canonical_text(&patch).unwrap());
        }

        /// Invariants over Q beside machine points (wide weights): on a
        /// net certified minimal (the function's precondition; a point
        /// repeated makes a net of too high a degree), the text of the
        /// general path, whose points are `BigRational` too.
        #[test]
        fn rational_invariants_give_the_general_text(s in wide_patch()) {
            let patch = s.to_patch().unwrap();
            let (net, curve) = crate::coincide::net_of(&patch).unwrap();
            prop_assume!(crate::coincide::minimal::certified_minimal(&net));
            if let Some(text) = key_text_rational_invariants(&net, curve) {
                prop_assert_eq!(text, canonical_key(&patch).unwrap().text());
            }
        }

        #[test]
        fn certified_key_texts_are_those_of_the_general_path(mut s in small_patch()) {
            if s.certify() {
                let patch = s.to_patch().unwrap();
                prop_assert_eq!(s.key_text().unwrap(), canonical_key(&patch).unwrap().text());
            }
        }
    }

    /// A cubic whose invariant `I_3 = ω₃ω₀²/ω₁³` leaves `i128` (`ω₁ =
    /// 1/(2⁴⁵ + 1)`): the machine text gives up, the mixed one is the
    /// general path's.
    #[test]
    fn overflowing_invariants_are_taken_over_q() {
        let big_recip = (1, (1i128 << 45) + 1);
        let s = SmallPatch::new(
            true,
            (3, 0),
            1,
            &[(0, 1), (1, 3), (2, 1), (5, 2)],
            &[(1, 1), big_recip, (3, 1), (2, 7)],
        )
        .unwrap();
        let patch = s.to_patch().unwrap();
        let (net, curve) = crate::coincide::net_of(&patch).unwrap();
        assert_eq!(key_text(&net, curve), None);
        let text = key_text_rational_invariants(&net, curve).unwrap();
        assert_eq!(text, canonical_key(&patch).unwrap().text());
        let cube = num_bigint::BigInt::from((1i128 << 45) + 1).pow(3);
        assert!(text.ends_with(&format!(";+:{}/7", cube * 2)), "{text}");
    }

    #[test]
    fn a_denominator_divisible_by_p_is_not_certified() {
        let p = i128::from(crate::algebra::modp::MODULUS);
        let plain = [(0, 1), (1, 2), (3, 1)];
        let weights = [(1, 1), (2, 1), (1, 1)];
        let certify = |coords: &[(i128, i128)], weights: &[(i128, i128)]| {
            SmallPatch::new(true, (2, 0), 1, coords, weights)
                .unwrap()
                .certify()
        };
        assert!(certify(&plain, &weights));
        // p in a coordinate's denominator, or in a weight's.
        assert!(!certify(&[(0, 1), (1, 2 * p), (3, 1)], &weights));
        assert!(!certify(&plain, &[(1, 1), (2, p), (1, 1)]));
    }

    #[test]
    fn integers_are_written_as_the_formatter_writes_them() {
        for v in [
            0,
            7,
            -7,
            10,
            -42,
            99,
            100,
            i128::from(u64::MAX),
            -i128::from(u64::MAX),
            i128::from(u64::MAX) + 1,
            i128::MIN,
            i128::MAX,
        ] {
            let mut out = String::new();
            push_int(&mut out, v);
            assert_eq!(out, v.to_string());
        }
    }
}
