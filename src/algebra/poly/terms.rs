//! Sorted term lists over Z: the arithmetic kernel behind [`Poly`](crate::Poly).
//!
//! A term list is a `Vec<(Monomial, Int)>` sorted by increasing monomial
//! (a monomial order, see [`Monomial`]), with distinct monomials and
//! non-zero integer coefficients. Coefficients are [`Int`]: `i128` while they
//! fit, a big integer otherwise, so the usual small coefficients of a proof
//! never allocate and never take a gcd.
//!
//! - sum: one linear merge (`a·fa + b·fb`, the scale factors bring two
//!   polynomials to a common denominator); a sum of many: one k-way heap
//!   merge of all the lists;
//! - product: Johnson's heap merge of the `|b|` sorted streams `a·b_j`
//!   (each stream is sorted because the order is multiplicative), so equal
//!   monomials meet in the heap and are summed at once — no map, no sort.

use super::monomial::Monomial;
use crate::algebra::int::Int;
use num_traits::{Signed, Zero};
use std::cmp::{Ordering, Reverse};
use std::collections::BinaryHeap;

/// A sorted term list.
pub(crate) type Terms = Vec<(Monomial, Int)>;

/// Is `a < 0`?
pub(crate) fn is_negative(a: &Int) -> bool {
    match a {
        Int::Small(x) => *x < 0,
        Int::Big(x) => x.is_negative(),
    }
}

/// Is `a = 1`?
pub(crate) fn is_one(a: &Int) -> bool {
    matches!(a, Int::Small(1))
}

/// `a·b` without consuming `a`.
pub(crate) fn mul(a: &Int, b: &Int) -> Int {
    a.clone() * b
}

/// The gcd of `start` and every coefficient, stopping as soon as it is 1
/// (so a primitive list costs one or two gcds, not one per term).
pub(crate) fn content_with(terms: &Terms, start: &Int) -> Int {
    let mut g = start.clone();
    for (_, c) in terms {
        if is_one(&g) {
            break;
        }
        g = g.gcd(c);
    }
    g
}

/// Multiply every coefficient by `f`.
pub(crate) fn scale(terms: &mut Terms, f: &Int) {
    if !is_one(f) {
        for (_, c) in terms.iter_mut() {
            *c = mul(c, f);
        }
    }
}

/// Divide every coefficient by `g` (which divides each).
pub(crate) fn divide(terms: &mut Terms, g: &Int) {
    if !is_one(g) {
        for (_, c) in terms.iter_mut() {
            *c = c.div_exact(g);
        }
    }
}

/// `fa·a + fb·b` by one merge (`fa`, `fb` non-zero).
pub(crate) fn add(a: &Terms, fa: &Int, b: &Terms, fb: &Int) -> Terms {
    let times = |c: &Int, f: &Int| if is_one(f) { c.clone() } else { mul(c, f) };
    let mut out = Vec::with_capacity(a.len() + b.len());
    let (mut i, mut j) = (0, 0);
    while i < a.len() && j < b.len() {
        match a[i].0.cmp(&b[j].0) {
            Ordering::Less => {
                out.push((a[i].0.clone(), times(&a[i].1, fa)));
                i += 1;
            }
            Ordering::Greater => {
                out.push((b[j].0.clone(), times(&b[j].1, fb)));
                j += 1;
            }
            Ordering::Equal => {
                let c = times(&a[i].1, fa) + &times(&b[j].1, fb);
                if !c.is_zero() {
                    out.push((a[i].0.clone(), c));
                }
                i += 1;
                j += 1;
            }
        }
    }
    out.extend(a[i..].iter().map(|(m, c)| (m.clone(), times(c, fa))));
    out.extend(b[j..].iter().map(|(m, c)| (m.clone(), times(c, fb))));
    out
}

/// `Σ f_k·t_k` (every `f_k` non-zero) by one k-way heap merge of the
/// sorted lists `t_k`: each input term moves once, where a balanced tree of
/// two-way merges moves it `log₂ k` times and normalizes every partial sum.
pub(crate) fn sum_scaled(parts: &[(&Terms, Int)]) -> Terms {
    // Heap of (next monomial of list k, k, index i into list k), min first.
    let mut heap: BinaryHeap<Reverse<(&Monomial, usize, usize)>> = parts
        .iter()
        .enumerate()
        .filter_map(|(k, (t, _))| t.first().map(|(m, _)| Reverse((m, k, 0))))
        .collect();
    let mut out: Terms = Vec::with_capacity(parts.iter().map(|(t, _)| t.len()).sum());
    while let Some(mut top) = heap.peek_mut() {
        let Reverse((m, k, i)) = &mut *top;
        let (m0, k, i0) = (*m, *k, *i);
        let (t, f) = &parts[k];
        let c = if is_one(f) {
            t[i0].1.clone()
        } else {
            mul(&t[i0].1, f)
        };
        if let Some((next, _)) = t.get(i0 + 1) {
            (*m, *i) = (next, i0 + 1);
            drop(top);
        } else {
            std::collections::binary_heap::PeekMut::pop(top);
        }
        match out.last_mut() {
            Some((last, acc)) if last == m0 => *acc = std::mem::replace(acc, Int::Small(0)) + &c,
            _ => {
                drop_zero_last(&mut out);
                out.push((m0.clone(), c));
            }
        }
    }
    drop_zero_last(&mut out);
    out
}

/// The product `a·b` by Johnson's heap merge over the streams `a·b_j`.
pub(crate) fn mul_terms(a: &Terms, b: &Terms) -> Terms {
    let (a, b) = if a.len() >= b.len() { (a, b) } else { (b, a) };
    if b.is_empty() {
        return Vec::new();
    }
    match b.as_slice() {
        [t] => return stream(a, t).collect(),
        [t, u] => return merge(stream(a, t), stream(a, u), a.len() * 2),
        _ => {}
    }
    // Heap of (next monomial of stream j, j, index i into a), min first.
    let mut heap: BinaryHeap<Reverse<(Monomial, usize, usize)>> = b
        .iter()
        .enumerate()
        .map(|(j, (mb, _))| Reverse((a[0].0.mul(mb), j, 0)))
        .collect();
    let mut out: Terms = Vec::with_capacity(a.len() + b.len());
    while let Some(mut top) = heap.peek_mut() {
        let Reverse((m, j, i)) = &mut *top;
        let (j, i0) = (*j, *i);
        let c = mul(&a[i0].1, &b[j].1);
        if i0 + 1 < a.len() {
            // Replace the top by the stream's next monomial: one sift.
            let next = a[i0 + 1].0.mul(&b[j].0);
            *i = i0 + 1;
            let m = std::mem::replace(m, next);
            drop(top);
            accumulate(&mut out, m, c);
        } else {
            let Reverse((m, _, _)) = std::collections::binary_heap::PeekMut::pop(top);
            accumulate(&mut out, m, c);
        }
    }
    drop_zero_last(&mut out);
    out
}

/// The sorted stream `a·t` of a term list times one term.
fn stream<'a>(a: &'a Terms, t: &'a (Monomial, Int)) -> impl Iterator<Item = (Monomial, Int)> + 'a {
    a.iter().map(move |(m, c)| (m.mul(&t.0), mul(c, &t.1)))
}

/// The sum of two sorted term streams (a two-way merge: multiplying by a
/// binomial such as `1 − s`, the commonest product in de Casteljau).
fn merge(
    x: impl Iterator<Item = (Monomial, Int)>,
    y: impl Iterator<Item = (Monomial, Int)>,
    capacity: usize,
) -> Terms {
    let mut out = Vec::with_capacity(capacity);
    let (mut x, mut y) = (x.peekable(), y.peekable());
    loop {
        let next = match (x.peek(), y.peek()) {
            (Some(p), Some(q)) if p.0 <= q.0 => x.next(),
            (Some(_), Some(_)) => y.next(),
            (Some(_), None) => x.next(),
            (None, _) => y.next(),
        };
        let Some((m, c)) = next else { break };
        accumulate(&mut out, m, c);
    }
    drop_zero_last(&mut out);
    out
}

/// Append the term `c·m` to a list sorted up to `m`: add it to the last
/// term if that has the same monomial, else push it (first dropping a last
/// term that cancelled to zero).
fn accumulate(out: &mut Terms, m: Monomial, c: Int) {
    if let Some((last, acc)) = out.last_mut()
        && *last == m
    {
        *acc = std::mem::replace(acc, Int::Small(0)) + &c;
        return;
    }
    drop_zero_last(out);
    out.push((m, c));
}

fn drop_zero_last(out: &mut Terms) {
    if out.last().is_some_and(|(_, c)| c.is_zero()) {
        out.pop();
    }
}

/// `Σ_k f_k·m_k·t_k`: the sum of the sorted term lists `t_k`, each times
/// one monomial `m_k` and one integer `f_k ≠ 0`, in one merge of the
/// streams `m_k·t_k` (each sorted, the order being multiplicative) by
/// scanning their few heads — no intermediate product list and no second
/// merge to add them. This is the de Casteljau step `a·P + b·Q` with
/// binomials `a`, `b` (four streams), written once to its output.
pub(crate) fn sum_of_shifted(parts: &[(&Terms, &Monomial, Int)]) -> Terms {
    let head = |k: usize, i: usize| {
        let (t, m, _) = &parts[k];
        t.get(i).map(|(tm, _)| tm.mul(m))
    };
    let mut heads: Vec<Option<Monomial>> = (0..parts.len()).map(|k| head(k, 0)).collect();
    let mut next = vec![0usize; parts.len()];
    let mut out: Terms = Vec::with_capacity(parts.iter().map(|(t, _, _)| t.len()).sum());
    // The streams whose head is the least monomial.
    let mut least: Vec<usize> = Vec::with_capacity(parts.len());
    loop {
        least.clear();
        for k in 0..heads.len() {
            let Some(h) = &heads[k] else { continue };
            let order = least
                .first()
                .and_then(|&l| heads[l].as_ref())
                .map_or(Ordering::Less, |min| h.cmp(min));
            match order {
                Ordering::Less => {
                    least.clear();
                    least.push(k);
                }
                Ordering::Equal => least.push(k),
                Ordering::Greater => {}
            }
        }
        let Some(&first) = least.first() else { break };
        let m = heads[first].take().unwrap_or_default();
        let mut sum: Option<Int> = None;
        for &k in &least {
            let (t, _, f) = &parts[k];
            let i = next[k];
            let c = if is_one(f) {
                t[i].1.clone()
            } else {
                mul(&t[i].1, f)
            };
            sum = Some(match sum {
                Some(s) => s + &c,
                None => c,
            });
            next[k] = i + 1;
            heads[k] = head(k, i + 1);
        }
        if let Some(sum) = sum.filter(|s| !s.is_zero()) {
            out.push((m, sum));
        }
    }
    out
}
