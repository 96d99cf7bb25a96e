//! [`Monomial`]: a power product `x_{v₁}^{e₁} ⋯ x_{v_k}^{e_k}` packed into
//! machine words, ordered by a true monomial order.
//!
//! Each factor `x_v^e` is one `u64`: the high 32 bits hold `!v` (the bitwise
//! complement of the variable id), the low 32 bits hold `e > 0`. Factors are
//! stored by increasing variable id, so the words decrease. Comparing two
//! monomials as word slices (the derived `Ord`) is then the lexicographic
//! order with variable 0 most significant: at the first variable where the
//! exponents differ, the larger exponent wins (an absent variable has
//! exponent 0, and a shorter slice that is a prefix compares less). That is
//! a monomial order — `a < b ⇒ a·c < b·c` — so multiplying every term of a
//! sorted polynomial by one monomial keeps it sorted, which the heap
//! multiplication relies on (Johnson 1974; Monagan & Pearce, *Sparse
//! polynomial multiplication and division in Maple 14*, 2009).
//!
//! Up to six factors live inline in a fixed array whose unused words are 0
//! (never a factor: exponents are positive), so that copying, comparing and
//! hashing an inline monomial are fixed-size operations on six words, and
//! comparing the padded arrays is comparing the factor slices. The
//! identities checked in `proofs/` rarely have more than five variables per
//! monomial; longer monomials are boxed.

use std::cmp::Ordering;

/// A packed monomial; the empty monomial is `1`. Canonical: `Inline` exactly
/// when there are at most [`INLINE`] factors.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub(crate) enum Monomial {
    /// `len` factor words, then zeros.
    Inline { len: u8, words: [u64; INLINE] },
    /// More than [`INLINE`] factor words.
    Long(Box<[u64]>),
}

/// Factors stored inline.
const INLINE: usize = 6;

impl Default for Monomial {
    fn default() -> Monomial {
        Monomial::Inline {
            len: 0,
            words: [0; INLINE],
        }
    }
}

/// The order of the factor slices (see the module doc); two inline
/// monomials compare as their zero-padded arrays, which is the same.
impl Ord for Monomial {
    fn cmp(&self, other: &Monomial) -> Ordering {
        match (self, other) {
            (Monomial::Inline { words: a, .. }, Monomial::Inline { words: b, .. }) => a.cmp(b),
            _ => self.words().cmp(other.words()),
        }
    }
}

impl PartialOrd for Monomial {
    fn partial_cmp(&self, other: &Monomial) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

fn word(var: u32, exp: u32) -> u64 {
    (u64::from(!var) << 32) | u64::from(exp)
}

fn var_of(w: u64) -> u32 {
    !((w >> 32) as u32)
}

fn exp_of(w: u64) -> u32 {
    w as u32
}

/// Merge two factor lists (decreasing words) into `out`, which has room
/// for both; the number of factors written.
#[inline]
fn merge_factors(a: &[u64], b: &[u64], out: &mut [u64]) -> usize {
    let (mut i, mut j, mut n) = (0, 0, 0);
    while i < a.len() && j < b.len() {
        let (x, y) = (a[i], b[j]);
        out[n] = match (x >> 32).cmp(&(y >> 32)) {
            Ordering::Equal => {
                let e = exp_of(x)
                    .checked_add(exp_of(y))
                    .expect("monomial exponent overflows u32");
                i += 1;
                j += 1;
                (x & !u64::from(u32::MAX)) | u64::from(e)
            }
            // The larger high half is the smaller variable id: first.
            Ordering::Greater => {
                i += 1;
                x
            }
            Ordering::Less => {
                j += 1;
                y
            }
        };
        n += 1;
    }
    for &w in a[i..].iter().chain(&b[j..]) {
        out[n] = w;
        n += 1;
    }
    n
}

impl Monomial {
    /// The monomial of factor words given in decreasing order.
    fn from_words(w: &[u64]) -> Monomial {
        if w.len() > INLINE {
            return Monomial::Long(w.into());
        }
        let mut words = [0; INLINE];
        words[..w.len()].copy_from_slice(w);
        Monomial::Inline {
            len: w.len() as u8,
            words,
        }
    }

    /// The factor words, decreasing.
    fn words(&self) -> &[u64] {
        match self {
            Monomial::Inline { len, words } => &words[..usize::from(*len)],
            Monomial::Long(w) => w,
        }
    }

    /// `x_var^exp` (`1` when `exp = 0`).
    pub(crate) fn power(var: u32, exp: u32) -> Monomial {
        if exp == 0 {
            return Monomial::default();
        }
        Monomial::from_words(&[word(var, exp)])
    }

    /// The monomial of the factors `(variable id, exponent > 0)` given by
    /// increasing id.
    pub(crate) fn from_factors(f: impl Iterator<Item = (u32, u32)>) -> Monomial {
        let mut f = f.map(|(v, e)| word(v, e));
        let mut words = [0; INLINE];
        let mut len = 0;
        for w in f.by_ref() {
            words[len] = w;
            len += 1;
            if len == INLINE {
                break;
            }
        }
        match f.next() {
            None => Monomial::Inline {
                len: len as u8,
                words,
            },
            Some(w) => {
                let mut long = words.to_vec();
                long.push(w);
                long.extend(f);
                Monomial::Long(long.into_boxed_slice())
            }
        }
    }

    /// Is this the monomial `1`?
    pub(crate) fn is_one(&self) -> bool {
        self.words().is_empty()
    }

    /// The factors `(variable id, exponent)`, by increasing id.
    pub(crate) fn factors(&self) -> impl Iterator<Item = (u32, u32)> + '_ {
        self.words().iter().map(|&w| (var_of(w), exp_of(w)))
    }

    /// The product: a merge of the two factor lists, adding exponents of a
    /// common variable. Factor words compare by their high halves (`!v`);
    /// a product of at most [`INLINE`] factors is merged straight into the
    /// inline array. **Panics** if an exponent exceeds `u32::MAX`.
    #[inline]
    pub(crate) fn mul(&self, other: &Monomial) -> Monomial {
        let (a, b) = (self.words(), other.words());
        if b.is_empty() {
            return self.clone();
        }
        if a.is_empty() {
            return other.clone();
        }
        if a.len() + b.len() <= INLINE {
            let mut words = [0; INLINE];
            let len = merge_factors(a, b, &mut words) as u8;
            return Monomial::Inline { len, words };
        }
        let mut out = vec![0; a.len() + b.len()];
        let n = merge_factors(a, b, &mut out);
        Monomial::from_words(&out[..n])
    }

    /// Exponent of variable `var` (0 if absent).
    pub(crate) fn exponent(&self, var: u32) -> u32 {
        self.factors()
            .find(|(v, _)| *v == var)
            .map_or(0, |(_, e)| e)
    }

    /// The monomial with the exponent of `var` replaced by `exp`. Among
    /// monomials with equal exponents of `var`, this keeps their order.
    pub(crate) fn with_exponent(&self, var: u32, exp: u32) -> Monomial {
        let rest = Monomial::from_factors(self.factors().filter(|&(v, _)| v != var));
        if exp == 0 {
            return rest;
        }
        rest.mul(&Monomial::power(var, exp))
    }

    /// Sum of the exponents.
    pub(crate) fn total_degree(&self) -> u64 {
        self.words().iter().map(|&w| u64::from(exp_of(w))).sum()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn m(f: &[(u32, u32)]) -> Monomial {
        f.iter().fold(Monomial::default(), |acc, &(v, e)| {
            acc.mul(&Monomial::power(v, e))
        })
    }

    #[test]
    fn product_adds_exponents() {
        let p = m(&[(0, 1), (3, 2)]).mul(&m(&[(1, 4), (3, 1)]));
        assert_eq!(
            p.factors().collect::<Vec<_>>(),
            vec![(0, 1), (1, 4), (3, 3)]
        );
        assert_eq!(p.total_degree(), 8);
        assert_eq!(p.exponent(3), 3);
        assert_eq!(p.with_exponent(3, 0), m(&[(0, 1), (1, 4)]));
        assert_eq!(p.with_exponent(2, 5), m(&[(0, 1), (1, 4), (2, 5), (3, 3)]));
    }

    #[test]
    fn long_products_match_exponent_sums() {
        // 9 and 8 factors (past the stack buffer), overlapping in 4
        // variables, against the exponents summed per variable.
        let a: Vec<(u32, u32)> = (0..9).map(|k| (2 * k, k + 1)).collect();
        let b: Vec<(u32, u32)> = (0..8).map(|k| (3 * k, 2)).collect();
        let mut want = std::collections::BTreeMap::new();
        for &(v, e) in a.iter().chain(&b) {
            *want.entry(v).or_insert(0) += e;
        }
        let got = m(&a).mul(&m(&b));
        assert_eq!(
            got.factors().collect::<Vec<_>>(),
            want.into_iter().collect::<Vec<_>>()
        );
        assert_eq!(got, m(&b).mul(&m(&a)));
    }

    #[test]
    fn order_is_lex_and_multiplicative() {
        let x = m(&[(0, 1)]);
        let y = m(&[(1, 1)]);
        let one = Monomial::default();
        assert!(one < y && y < x && x < m(&[(0, 2)]));
        assert!(m(&[(0, 1), (1, 1)]) > x && m(&[(0, 1), (1, 1)]) < m(&[(0, 2)]));
        // a < b ⇒ a·c < b·c on a few samples.
        let all = [
            one.clone(),
            x.clone(),
            y.clone(),
            x.mul(&y),
            y.mul(&y),
            x.mul(&x),
        ];
        for a in &all {
            for b in &all {
                for c in &all {
                    assert_eq!(a.cmp(b), a.mul(c).cmp(&b.mul(c)));
                }
            }
        }
    }
}
