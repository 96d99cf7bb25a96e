//! Packed exponent vectors: the product and power kernels of
//! [`Poly`](crate::Poly) on monomials that are one `u64` each.
//!
//! For one operation the variables that occur are numbered by increasing id
//! and each gets a bit field wide enough for its largest exponent in the
//! result, variable 0 in the most significant field. A monomial
//! `x_0^{e_0}⋯x_k^{e_k}` is then the integer `Σ e_i·2^{shift_i}`, and
//!
//! - comparing two packed monomials as integers is the lexicographic order
//!   with the smallest id most significant — the order of [`Monomial`], so a
//!   packed sorted list unpacks to a sorted list;
//! - the product of two monomials is the sum of their keys (no field
//!   overflows, by the choice of widths), one machine addition.
//!
//! This is the layout of Monagan & Pearce (*Sparse polynomial division using
//! a heap*, 2011; *Parallel sparse polynomial multiplication using heaps*,
//! 2009). Products run Johnson's heap merge (1974) over these keys, with the
//! coefficients in `i128` without overflow checks when a bound on every
//! partial sum fits (`|c| ≤ max|a|·max|b|·min(#a, #b)`), in [`Int`]
//! otherwise.

use super::monomial::Monomial;
use super::terms::Terms;
use crate::algebra::int::Int;
use std::cmp::Reverse;
use std::collections::BinaryHeap;

/// The bit fields of one packing: variable ids (increasing) and the shift
/// of each one's field.
pub(crate) struct Packing {
    vars: Vec<u32>,
    shifts: Vec<u32>,
}

/// A term list with packed monomials, sorted by increasing key.
pub(crate) struct Packed {
    pub(super) keys: Vec<u64>,
    pub(super) coeffs: Vec<Int>,
}

/// Bits needed for the value `n` (at least 1).
fn width(n: u64) -> u32 {
    (64 - n.leading_zeros()).max(1)
}

impl Packing {
    /// A packing for results whose exponent of `vars[i]` is at most
    /// `max[i]`; `None` if the fields do not fit 63 bits (so `u64::MAX`
    /// is never a key: the merge kernel uses it as "stream exhausted").
    pub(crate) fn new(vars: Vec<u32>, max: &[u64]) -> Option<Packing> {
        let widths: Vec<u32> = max.iter().map(|&m| width(m)).collect();
        let total: u32 = widths.iter().sum();
        if total > 63 {
            return None;
        }
        let mut shift = total;
        let shifts = widths
            .iter()
            .map(|w| {
                shift -= w;
                shift
            })
            .collect();
        Some(Packing { vars, shifts })
    }

    /// The variables of `lists` (sorted ids) and, per variable, the
    /// largest exponent in each list summed over the lists, times `k`.
    pub(crate) fn for_product(lists: &[&Terms], k: u64) -> Option<Packing> {
        // The few distinct ids, kept sorted as they come (sorting every
        // factor of every term first cost more than the product itself).
        let mut vars: Vec<u32> = Vec::new();
        for (m, _) in lists.iter().flat_map(|t| t.iter()) {
            for (v, _) in m.factors() {
                if let Err(at) = vars.binary_search(&v) {
                    vars.insert(at, v);
                }
            }
        }
        let mut max = vec![0u64; vars.len()];
        for t in lists {
            let mut top = vec![0u64; vars.len()];
            for (m, _) in t.iter() {
                for (v, e) in m.factors() {
                    let i = vars.binary_search(&v).unwrap_or(0);
                    top[i] = top[i].max(u64::from(e));
                }
            }
            for (mx, t) in max.iter_mut().zip(top) {
                *mx += t;
            }
        }
        for mx in &mut max {
            *mx = mx.checked_mul(k)?;
        }
        Packing::new(vars, &max)
    }

    /// The packed key of `m` (every variable of `m` is in the packing).
    fn key(&self, m: &Monomial) -> u64 {
        m.factors().fold(0, |key, (v, e)| {
            let i = self.vars.binary_search(&v).unwrap_or(0);
            key | (u64::from(e) << self.shifts[i])
        })
    }

    /// Pack a sorted term list.
    pub(crate) fn pack(&self, t: &Terms) -> Packed {
        Packed {
            keys: t.iter().map(|(m, _)| self.key(m)).collect(),
            coeffs: t.iter().map(|(_, c)| c.clone()).collect(),
        }
    }

    /// Per variable (by increasing id) its id, the shift of its field and
    /// the field's mask: the exponent of `vars[i]` in `key` is
    /// `(key >> shift) & mask`.
    pub(crate) fn fields(&self) -> Vec<(u32, u32, u64)> {
        self.vars
            .iter()
            .zip(&self.shifts)
            .map(|(&v, &s)| {
                let next = self.shifts.iter().filter(|&&t| t > s).min().copied();
                let mask = next.map_or(u64::MAX >> s, |n| (1u64 << (n - s)) - 1);
                (v, s, mask)
            })
            .collect()
    }

    /// Unpack to a sorted term list.
    pub(crate) fn unpack(&self, p: Packed) -> Terms {
        // Field masks once, not per term.
        let fields = self.fields();
        p.keys
            .into_iter()
            .zip(p.coeffs)
            .map(|(key, c)| {
                let m = Monomial::from_factors(fields.iter().filter_map(|&(v, s, mask)| {
                    let e = (key >> s) & mask;
                    (e > 0).then_some((v, e as u32))
                }));
                (m, c)
            })
            .collect()
    }
}

impl Packed {
    /// Number of terms.
    pub(crate) fn len(&self) -> usize {
        self.keys.len()
    }

    /// The product by Johnson's heap merge of the streams `self·b_j` over
    /// the terms `b_j` of the shorter operand.
    pub(crate) fn mul(&self, other: &Packed) -> Packed {
        let (a, b) = if self.len() >= other.len() {
            (self, other)
        } else {
            (other, self)
        };
        if b.len() == 0 {
            return Packed {
                keys: Vec::new(),
                coeffs: Vec::new(),
            };
        }
        match (small_bound(a), small_bound(b)) {
            (Some(x), Some(y)) if x + y + width(b.len() as u64) <= 126 => {
                let small = |c: &[Int]| -> Vec<i128> {
                    c.iter()
                        .map(|c| match c {
                            Int::Small(x) => *x,
                            Int::Big(_) => unreachable!("bounded by small_bound"),
                        })
                        .collect()
                };
                let (keys, coeffs) = product(
                    (&a.keys, &small(&a.coeffs)),
                    (&b.keys, &small(&b.coeffs)),
                    |x, y| x * y,
                    |acc, x| *acc += x,
                    |c| *c == 0,
                );
                Packed {
                    keys,
                    coeffs: coeffs.into_iter().map(Int::Small).collect(),
                }
            }
            _ => {
                let (keys, coeffs) = product(
                    (&a.keys, &a.coeffs),
                    (&b.keys, &b.coeffs),
                    |x, y| x.clone() * y,
                    |acc, x| *acc = std::mem::replace(acc, Int::Small(0)) + &x,
                    |c| matches!(c, Int::Small(0)),
                );
                Packed { keys, coeffs }
            }
        }
    }
}

/// The bit length of the largest coefficient if every one is small.
fn small_bound(p: &Packed) -> Option<u32> {
    p.coeffs.iter().try_fold(0, |acc, c| match c {
        Int::Small(x) => Some(acc.max(128 - x.unsigned_abs().leading_zeros())),
        Int::Big(_) => None,
    })
}

/// The product of two sorted packed lists (`b` the shorter, not empty):
/// by [`scan_product`] when `b` has at most [`SCAN_MAX`] terms, else by
/// [`heap_product`].
fn product<C>(
    a: (&[u64], &[C]),
    b: (&[u64], &[C]),
    mul: impl Fn(&C, &C) -> C,
    add: impl Fn(&mut C, C),
    is_zero: impl Fn(&C) -> bool,
) -> (Vec<u64>, Vec<C>) {
    if b.0.len() <= SCAN_MAX {
        scan_product(a, b, mul, add, is_zero)
    } else {
        heap_product(a, b, mul, add, is_zero)
    }
}

/// Up to this many streams a linear scan of their heads beats a heap.
const SCAN_MAX: usize = 8;

/// The product as a merge of the few streams `a·b_j` by scanning their
/// heads: each step takes the least head key and sums the products of every
/// stream at that key at once (in a dense product, every stream), with no
/// heap to maintain. An exhausted stream's head is `u64::MAX`, never a key.
fn scan_product<C>(
    (ak, ac): (&[u64], &[C]),
    (bk, bc): (&[u64], &[C]),
    mul: impl Fn(&C, &C) -> C,
    add: impl Fn(&mut C, C),
    is_zero: impl Fn(&C) -> bool,
) -> (Vec<u64>, Vec<C>) {
    let mut keys: Vec<u64> = Vec::with_capacity(ak.len() + bk.len());
    let mut coeffs: Vec<C> = Vec::with_capacity(ak.len() + bk.len());
    let mut head: Vec<u64> = bk.iter().map(|&kb| ak[0] + kb).collect();
    let mut next = vec![0usize; bk.len()];
    loop {
        let key = head.iter().copied().min().unwrap_or(u64::MAX);
        if key == u64::MAX {
            break;
        }
        let mut sum: Option<C> = None;
        for j in 0..bk.len() {
            if head[j] == key {
                let i = next[j];
                let c = mul(&ac[i], &bc[j]);
                match &mut sum {
                    Some(acc) => add(acc, c),
                    None => sum = Some(c),
                }
                next[j] = i + 1;
                head[j] = ak.get(i + 1).map_or(u64::MAX, |&k| k + bk[j]);
            }
        }
        if let Some(c) = sum.filter(|c| !is_zero(c)) {
            keys.push(key);
            coeffs.push(c);
        }
    }
    (keys, coeffs)
}

/// Johnson's heap product of two sorted packed lists (`b` the shorter):
/// one heap entry per stream `a·b_j`, keyed by its next monomial; equal
/// monomials leave the heap consecutively and are summed at once.
fn heap_product<C>(
    (ak, ac): (&[u64], &[C]),
    (bk, bc): (&[u64], &[C]),
    mul: impl Fn(&C, &C) -> C,
    add: impl Fn(&mut C, C),
    is_zero: impl Fn(&C) -> bool,
) -> (Vec<u64>, Vec<C>) {
    let mut keys: Vec<u64> = Vec::with_capacity(ak.len() + bk.len());
    let mut coeffs: Vec<C> = Vec::with_capacity(ak.len() + bk.len());
    let mut heap: BinaryHeap<Reverse<(u64, u32)>> = bk
        .iter()
        .enumerate()
        .map(|(j, &kb)| Reverse((ak[0] + kb, j as u32)))
        .collect();
    // The next index into `a` of each stream.
    let mut next = vec![0usize; bk.len()];
    while let Some(mut top) = heap.peek_mut() {
        let Reverse((key, j)) = *top;
        let j = j as usize;
        let i = next[j];
        let c = mul(&ac[i], &bc[j]);
        if i + 1 < ak.len() {
            next[j] = i + 1;
            top.0 .0 = ak[i + 1] + bk[j];
            drop(top);
        } else {
            std::collections::binary_heap::PeekMut::pop(top);
        }
        match keys.last() {
            Some(&last) if last == key => {
                if let Some(acc) = coeffs.last_mut() {
                    add(acc, c);
                }
            }
            _ => {
                if coeffs.last().is_some_and(&is_zero) {
                    keys.pop();
                    coeffs.pop();
                }
                keys.push(key);
                coeffs.push(c);
            }
        }
    }
    if coeffs.last().is_some_and(&is_zero) {
        keys.pop();
        coeffs.pop();
    }
    (keys, coeffs)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn m(f: &[(u32, u32)]) -> Monomial {
        Monomial::from_factors(f.iter().copied())
    }

    #[test]
    fn keys_order_like_monomials_and_add_under_products() {
        // Monomials in variables 2, 5, 9 with exponents < 4, in every
        // combination: the packed order is the monomial order, and the key
        // of a product is the sum of the keys.
        let all: Vec<Monomial> = (0..64u32)
            .map(|n| {
                let f: Vec<(u32, u32)> = [(2, n % 4), (5, (n / 4) % 4), (9, n / 16)]
                    .into_iter()
                    .filter(|&(_, e)| e > 0)
                    .collect();
                m(&f)
            })
            .collect();
        let packing = Packing::new(vec![2, 5, 9], &[6, 6, 6]).expect("9 bits");
        for a in &all {
            for b in &all {
                assert_eq!(a.cmp(b), packing.key(a).cmp(&packing.key(b)));
                assert_eq!(packing.key(&a.mul(b)), packing.key(a) + packing.key(b));
            }
        }
    }

    #[test]
    fn round_trip_and_overflowing_layouts() {
        let packing = Packing::new(vec![0, 3], &[1, 1_000_000]).expect("21 bits");
        let t: Terms = vec![
            (m(&[(3, 7)]), Int::Small(-2)),
            (m(&[(0, 1), (3, 999_999)]), Int::Small(5)),
        ];
        assert_eq!(packing.unpack(packing.pack(&t)), t);
        // 5 variables of 2^13 need 70 bits: no packing.
        assert!(Packing::new(vec![0, 1, 2], &[(1 << 21) - 1; 3]).is_some());
        assert!(Packing::new(vec![0, 1, 2], &[(1 << 21) - 1, (1 << 21) - 1, 1 << 21]).is_none());
        assert!(Packing::new(vec![0, 1, 2, 3, 4], &[8191; 5]).is_none());
    }
}
