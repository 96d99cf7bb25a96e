//! The text form of [`RealAlgebraic`]: a small expression grammar that
//! SymPy's `sympify` reads as the same number (documented in
//! `docs/algebraic_numbers.md`).
//!
//! ```text
//! expr    := term (("+" | "-") term)*
//! term    := unary (("*" | "/") unary)*
//! unary   := ("-" | "+") unary | power
//! power   := atom ("**" unary)?                 right-associative, exponent rational
//! atom    := integer | decimal | "(" expr ")" | call
//! call    := "sqrt(" expr ")" | "cbrt(" expr ")" | "root(" expr "," integer ")"
//!          | "Rational(" expr "," expr ")" | "CRootOf(" poly "," integer ")"
//! poly    := the same grammar in the one variable x, integer powers ≥ 0 only
//! ```
//!
//! SymPy takes `x**(1/n)`, `sqrt`, `cbrt` and `root` of a negative number to
//! be the principal *complex* root, so they are rejected here for negative
//! arguments (write `-cbrt(2)`, not `cbrt(-2)`). Decimals (`0.5`) are read
//! exactly here but as floats by SymPy; the writer never emits them.
//!
//! Output: rationals as `p/q` or integers; radical sums as `c*root` terms
//! (`sqrt(6)/6`, `1 - 2*cbrt(12)/3`, `root(72, 4)`); other numbers as
//! `CRootOf(<primitive integer polynomial in x>, k)` with `k` the index of
//! the real root in increasing order.
//!
//! Bounds on hostile input: at most [`crate::limits::max_algebraic_text`]
//! characters (64 per digit of `--max-digits`, at least 10 000), nesting
//! depth 64 (brackets, calls and power exponents each count a level), root
//! indices and exponents at most 64 in absolute value, `CRootOf` degree at
//! most [`crate::limits::MAX_DEGREE`]. The writer stays inside them: a
//! radical of index over 64 is written as nested roots (`root(sqrt(2), 64)`
//! for `2^(1/128)`), and a command checks every number it writes
//! ([`crate::limits::check_written_number`]).

use super::polys::{primitive_integer, QPoly};
use super::radical::RadicalSum;
use super::RealAlgebraic;
use crate::algebra::scalar::{Field, Roots};
use crate::algebra::upoly::UPoly;
use crate::error::Error;
use crate::limits::{
    MAX_ALGEBRAIC_DEPTH as MAX_DEPTH, MAX_ALGEBRAIC_EXPONENT as MAX_EXPONENT, MAX_DEGREE,
};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};

/// A parsed expression.
#[derive(Clone, Debug)]
enum Ast {
    Num(BigRational),
    X,
    Neg(Box<Ast>),
    /// `a op b op c …` of one precedence level, kept flat (a long sum is
    /// one node, not a deep tree): the first operand and `(op, operand)`s.
    Chain(Box<Ast>, Vec<(char, Ast)>),
    Pow(Box<Ast>, Box<Ast>),
    Call(String, Vec<Ast>),
}

/// Read a number in the text grammar (module docs).
///
/// # Errors
///
/// [`Error::BadNumber`] for text outside the grammar, a negative radicand, a
/// division by zero, a root index out of range, or input over the bounds.
///
/// ```
/// use exact_bezier::{algebra::parse_algebraic, algebra::RealAlgebraic, Scalar};
/// let x = parse_algebraic("sqrt(2) + sqrt(3) - sqrt(5 + 2*sqrt(6))").unwrap();
/// assert_eq!(x, RealAlgebraic::from_i64(0));
/// assert_eq!(parse_algebraic("(3/2)**(1/3)").unwrap().to_string(), "cbrt(12)/2");
/// ```
pub fn parse_algebraic(text: &str) -> Result<RealAlgebraic, Error> {
    parse(text)
}

pub(crate) fn parse(text: &str) -> Result<RealAlgebraic, Error> {
    let max_len = crate::limits::max_algebraic_text();
    if text.len() > max_len {
        return Err(bad(
            text,
            &format!("longer than {max_len} characters (the bound grows with --max-digits)"),
        ));
    }
    let tokens = tokenize(text)?;
    let mut p = Parser {
        tokens: &tokens,
        pos: 0,
        depth: 0,
        text,
    };
    let ast = p.expr()?;
    if p.pos != tokens.len() {
        return Err(bad(text, "unexpected text after the expression"));
    }
    eval(&ast, text)
}

fn bad(text: &str, why: &str) -> Error {
    Error::BadNumber(format!("{text:?}: {why}"))
}

#[derive(Clone, Debug, PartialEq)]
enum Tok {
    Num(BigRational),
    Ident(String),
    Op(&'static str),
}

fn tokenize(text: &str) -> Result<Vec<Tok>, Error> {
    let chars: Vec<char> = text.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        if c.is_whitespace() {
            i += 1;
        } else if c.is_ascii_digit() || c == '.' {
            let start = i;
            while i < chars.len() && (chars[i].is_ascii_digit() || chars[i] == '.') {
                i += 1;
            }
            let s: String = chars[start..i].iter().collect();
            let q = crate::algebra::parse_rational(&s).map_err(|_| bad(text, "bad number"))?;
            out.push(Tok::Num(q));
        } else if c.is_ascii_alphabetic() {
            let start = i;
            while i < chars.len() && chars[i].is_ascii_alphanumeric() {
                i += 1;
            }
            out.push(Tok::Ident(chars[start..i].iter().collect()));
        } else {
            let two: String = chars[i..(i + 2).min(chars.len())].iter().collect();
            let op = if two == "**" {
                "**"
            } else {
                match c {
                    '+' => "+",
                    '-' => "-",
                    '*' => "*",
                    '/' => "/",
                    '(' => "(",
                    ')' => ")",
                    ',' => ",",
                    _ => return Err(bad(text, &format!("unexpected character {c:?}"))),
                }
            };
            i += op.len();
            out.push(Tok::Op(op));
        }
    }
    Ok(out)
}

struct Parser<'a> {
    tokens: &'a [Tok],
    pos: usize,
    depth: usize,
    text: &'a str,
}

impl Parser<'_> {
    fn peek_op(&self, op: &str) -> bool {
        matches!(self.tokens.get(self.pos), Some(Tok::Op(o)) if *o == op)
    }

    fn expect(&mut self, op: &str) -> Result<(), Error> {
        if self.peek_op(op) {
            self.pos += 1;
            Ok(())
        } else {
            Err(bad(self.text, &format!("expected {op:?}")))
        }
    }

    /// One more level of nesting (a bracket, a call's arguments or a
    /// power's exponent), refused past [`MAX_DEPTH`]; [`Parser::leave`]
    /// ends it.
    fn enter(&mut self) -> Result<(), Error> {
        self.depth += 1;
        if self.depth > MAX_DEPTH {
            return Err(bad(
                self.text,
                &format!("nested more than {MAX_DEPTH} deep"),
            ));
        }
        Ok(())
    }

    fn leave(&mut self) {
        self.depth -= 1;
    }

    /// `first (op next)*` for the operators `ops`, as one flat node.
    fn chain(
        &mut self,
        ops: [&'static str; 2],
        next: fn(&mut Self) -> Result<Ast, Error>,
    ) -> Result<Ast, Error> {
        let first = next(self)?;
        let mut rest = Vec::new();
        while let Some(op) = ops.into_iter().find(|o| self.peek_op(o)) {
            self.pos += 1;
            rest.push((op.chars().next().expect("op"), next(self)?));
        }
        Ok(if rest.is_empty() {
            first
        } else {
            Ast::Chain(Box::new(first), rest)
        })
    }

    fn expr(&mut self) -> Result<Ast, Error> {
        self.chain(["+", "-"], Self::term)
    }

    fn term(&mut self) -> Result<Ast, Error> {
        self.chain(["*", "/"], Self::unary)
    }

    /// Signs (any number, read in a loop), then a power.
    fn unary(&mut self) -> Result<Ast, Error> {
        let mut negative = false;
        while let Some(op) = ["-", "+"].into_iter().find(|o| self.peek_op(o)) {
            self.pos += 1;
            negative ^= op == "-";
        }
        let base = self.atom()?;
        let power = if self.peek_op("**") {
            self.pos += 1;
            self.enter()?;
            let e = self.unary()?;
            self.leave();
            Ast::Pow(Box::new(base), Box::new(e))
        } else {
            base
        };
        Ok(if negative {
            Ast::Neg(Box::new(power))
        } else {
            power
        })
    }

    fn atom(&mut self) -> Result<Ast, Error> {
        match self.tokens.get(self.pos).cloned() {
            Some(Tok::Num(q)) => {
                self.pos += 1;
                Ok(Ast::Num(q))
            }
            Some(Tok::Op("(")) => {
                self.pos += 1;
                self.enter()?;
                let e = self.expr()?;
                self.expect(")")?;
                self.leave();
                Ok(e)
            }
            Some(Tok::Ident(name)) => {
                self.pos += 1;
                if name == "x" {
                    return Ok(Ast::X);
                }
                self.expect("(")?;
                self.enter()?;
                let mut args = vec![self.expr()?];
                while self.peek_op(",") {
                    self.pos += 1;
                    args.push(self.expr()?);
                }
                self.expect(")")?;
                self.leave();
                Ok(Ast::Call(name, args))
            }
            _ => Err(bad(self.text, "expected a number, a bracket or a function")),
        }
    }
}

fn small_int(q: &BigRational, text: &str, what: &str) -> Result<i64, Error> {
    q.is_integer()
        .then(|| q.to_integer().to_i64())
        .flatten()
        .filter(|n| n.abs() <= MAX_EXPONENT)
        .ok_or_else(|| {
            bad(
                text,
                &format!("{what} must be an integer of size at most 64"),
            )
        })
}

fn eval(ast: &Ast, text: &str) -> Result<RealAlgebraic, Error> {
    let rat = |a: &Ast| -> Result<BigRational, Error> {
        eval(a, text)?
            .as_rational()
            .ok_or_else(|| bad(text, "this argument must be rational"))
    };
    Ok(match ast {
        Ast::Num(q) => RealAlgebraic::rat(q.clone()),
        Ast::X => return Err(bad(text, "x may appear only inside CRootOf")),
        Ast::Neg(a) => -eval(a, text)?,
        Ast::Chain(first, rest) => {
            let mut acc = eval(first, text)?;
            for (op, b) in rest {
                let b = eval(b, text)?;
                acc.check_pair_degree(&b, &format!("the number {text:?}"))?;
                acc = match op {
                    '+' => acc + b,
                    '-' => acc - b,
                    '*' => acc * b,
                    _ if b.is_zero() => return Err(bad(text, "division by zero")),
                    _ => acc / b,
                };
            }
            acc
        }
        Ast::Pow(base, e) => {
            let e = rat(e)?;
            let p = small_int(
                &BigRational::from_integer(e.numer().clone()),
                text,
                "an exponent",
            )?;
            let q = small_int(
                &BigRational::from_integer(e.denom().clone()),
                text,
                "a root index",
            )?;
            let b = eval(base, text)?;
            let r = real_root(&b, q as u32, text)?;
            integer_power(&r, p, text)?
        }
        Ast::Call(name, args) => match (name.as_str(), args.as_slice()) {
            ("sqrt", [a]) => real_root(&eval(a, text)?, 2, text)?,
            ("cbrt", [a]) => real_root(&eval(a, text)?, 3, text)?,
            ("root", [a, n]) => {
                let n = small_int(&rat(n)?, text, "a root index")?;
                if n < 1 {
                    return Err(bad(text, "a root index must be positive"));
                }
                real_root(&eval(a, text)?, n as u32, text)?
            }
            ("Rational", [a, b]) => {
                let (a, b) = (rat(a)?, rat(b)?);
                if b.is_zero() {
                    return Err(bad(text, "division by zero"));
                }
                RealAlgebraic::rat(a / b)
            }
            ("CRootOf", [p, k]) => {
                let p = eval_poly(p, text)?;
                let k = small_int(&rat(k)?, text, "a root index")?;
                if p.degree().unwrap_or(0) > MAX_DEGREE {
                    return Err(bad(text, "CRootOf degree over 64"));
                }
                let k = usize::try_from(k).map_err(|_| bad(text, "negative root index"))?;
                RealAlgebraic::root_of(&p, k).map_err(|e| bad(text, &e.to_string()))?
            }
            _ => {
                return Err(bad(
                    text,
                    &format!("unknown function {name} or wrong arguments"),
                ))
            }
        },
    })
}

/// The principal real root (SymPy's for non-negative radicands).
fn real_root(x: &RealAlgebraic, n: u32, text: &str) -> Result<RealAlgebraic, Error> {
    if n == 1 {
        return Ok(x.clone());
    }
    x.check_root_degree(n, &format!("the number {text:?}"))?;
    if x.signum() < 0 {
        return Err(bad(
            text,
            "SymPy reads roots of negative numbers as complex; write -cbrt(2) for the real cube root of -2",
        ));
    }
    x.nth_root(n).ok_or_else(|| bad(text, "no real root"))
}

fn integer_power(x: &RealAlgebraic, p: i64, text: &str) -> Result<RealAlgebraic, Error> {
    use crate::algebra::scalar::Scalar;
    if p < 0 && x.is_zero() {
        return Err(bad(text, "division by zero"));
    }
    let r = x.pow_u32(p.unsigned_abs() as u32);
    Ok(if p < 0 { r.recip() } else { r })
}

fn eval_poly(ast: &Ast, text: &str) -> Result<QPoly, Error> {
    Ok(match ast {
        Ast::X => UPoly::new(vec![BigRational::zero(), BigRational::one()]),
        Ast::Neg(a) => eval_poly(a, text)?.scale(&-BigRational::one()),
        Ast::Chain(first, rest) => {
            let mut acc = eval_poly(first, text)?;
            for (op, b) in rest {
                let b = eval_poly(b, text)?;
                acc = match op {
                    '+' => acc.add(&b),
                    '-' => acc.sub(&b),
                    '*' => acc.mul(&b),
                    _ => match b.degree() {
                        Some(0) => acc.scale(&b.coeffs()[0].recip()),
                        _ => {
                            return Err(bad(
                                text,
                                "a polynomial may be divided only by a non-zero number",
                            ))
                        }
                    },
                };
            }
            acc
        }
        Ast::Pow(base, e) => {
            let base = eval_poly(base, text)?;
            let e = eval(e, text)?
                .as_rational()
                .ok_or_else(|| bad(text, "exponent must be rational"))?;
            let k = small_int(&e, text, "a polynomial exponent")?;
            if k < 0 {
                return Err(bad(text, "negative power in a polynomial"));
            }
            (0..k).fold(UPoly::constant(BigRational::one()), |acc, _| acc.mul(&base))
        }
        _ => {
            let v = eval(ast, text)?
                .as_rational()
                .ok_or_else(|| bad(text, "polynomial coefficients must be rational"))?;
            UPoly::new(vec![v])
        }
    })
}

/// `sqrt(R)`, `cbrt(R)` or `root(R, n)`; an index over the reader's
/// bound [`MAX_EXPONENT`] is written as nested roots whose indices are at
/// most that bound and multiply to `n` (`root(2, 128)` is
/// `root(sqrt(2), 64)`), so that the reader takes back what is written. The
/// index of a radical has no prime factor over 64: every index comes from
/// a root index or exponent the reader took (≤ 64) or divides the degree of
/// a field built from numbers of degree ≤ 64.
fn root_word(n: u32, r: &BigInt) -> String {
    let bound = MAX_EXPONENT as u32;
    let outer = (2..=bound.min(n))
        .rev()
        .find(|f| n.is_multiple_of(*f) && n / f <= bound)
        .or_else(|| (2..=bound.min(n)).rev().find(|f| n.is_multiple_of(*f)))
        .filter(|_| n > bound);
    let (index, inner) = match outer {
        Some(f) => (f, root_word(n / f, r)),
        None => (n, r.to_string()),
    };
    match index {
        2 => format!("sqrt({inner})"),
        3 => format!("cbrt({inner})"),
        _ => format!("root({inner}, {index})"),
    }
}

/// The text of a radical sum: rational term first, then `±[p*]root[/q]`.
pub(crate) fn radical_text(s: &RadicalSum) -> String {
    if s.is_zero() {
        return "0".into();
    }
    let mut out = String::new();
    for (m, c) in s.terms().iter() {
        let neg = c.is_negative();
        let a = c.abs();
        let body = if m.0.is_empty() {
            a.to_string()
        } else {
            let (n, r) = m.as_single_root();
            let root = root_word(n, &r);
            let num = if a.numer().is_one() {
                root
            } else {
                format!("{}*{root}", a.numer())
            };
            if a.denom().is_one() {
                num
            } else {
                format!("{num}/{}", a.denom())
            }
        };
        match (out.is_empty(), neg) {
            (true, true) => out.push('-'),
            (true, false) => {}
            (false, true) => out.push_str(" - "),
            (false, false) => out.push_str(" + "),
        }
        out.push_str(&body);
    }
    out
}

/// `CRootOf(<poly in x>, k)` with the primitive integer form of `p`.
pub(crate) fn root_text(p: &QPoly, k: usize) -> String {
    let ints = primitive_integer(p);
    let mut out = String::new();
    for (d, c) in ints.iter().enumerate().rev() {
        if c.is_zero() {
            continue;
        }
        let a = c.abs();
        let power = match d {
            0 => String::new(),
            1 => "x".into(),
            _ => format!("x**{d}"),
        };
        let body = match (d, a.is_one()) {
            (0, _) => a.to_string(),
            (_, true) => power,
            _ => format!("{a}*{power}"),
        };
        match (out.is_empty(), c.is_negative()) {
            (true, true) => out.push('-'),
            (true, false) => {}
            (false, true) => out.push_str(" - "),
            (false, false) => out.push_str(" + "),
        }
        out.push_str(&body);
    }
    format!("CRootOf({out}, {k})")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::scalar::Scalar;

    /// `sqrt` nested 7 times around 2 is `2^(1/128)`: written with indices
    /// of at most 64, and read back as the same number (issue 32).
    #[test]
    fn a_root_of_index_over_64_is_written_readably() {
        let text = (0..7).fold("2".to_string(), |acc, _| format!("sqrt({acc})"));
        let x = parse(&text).unwrap();
        let written = x.to_string();
        assert_eq!(written, "root(sqrt(2), 64)");
        assert_eq!(parse(&written).unwrap(), x);
        // 2^(1/128) raised to 128 is 2 (an independent check of the value).
        assert_eq!(x.pow_u32(128), RealAlgebraic::from_i64(2));
    }

    /// `sqrt` nested 30 times around 3 is `3^{1/2³⁰}` and answers at once
    /// (the index-2³⁰ root is taken as thirty square roots): its value is
    /// `exp(ln 3 / 2³⁰) = 1 + 1.02316…·10⁻⁹` (ln 3 = 1.0986122886…, the
    /// second-order term is 5·10⁻¹⁹). Nested 31 times its index is over
    /// the radical index limit, refused with the limit named.
    #[test]
    fn deeply_nested_square_roots_answer_or_are_refused_at_once() {
        let nest = |k: usize| (0..k).fold("3".to_string(), |acc, _| format!("sqrt({acc})"));
        let x = parse(&nest(30)).unwrap();
        let (lo, hi) = x.enclosure(64);
        let near =
            |num: i64| BigRational::one() + BigRational::new(num.into(), 10i64.pow(14).into());
        assert!(lo > near(102_315) && hi < near(102_317), "{lo} {hi}");
        let err = parse(&nest(31)).unwrap_err();
        assert!(
            matches!(&err, Error::Limit(m) if m.contains("radical index limit")),
            "{err}"
        );
    }

    /// `√(1 + √(1 + …))` nested `k` times around 2 lives in a field of
    /// degree `2^k` (each root of a sum extends the field): degree 16 is
    /// read, 64 is refused before the root is built, naming the field
    /// degree limit (degree 32 is read too, in about a minute of a debug
    /// build: not run here).
    #[test]
    fn towers_of_roots_of_sums_stop_at_the_field_degree_limit() {
        let nest = |k: usize| (0..k).fold("2".to_string(), |acc, _| format!("sqrt(1 + {acc})"));
        let x = parse(&nest(4)).unwrap();
        assert_eq!(x.defining_polynomial().degree(), Some(16));
        let err = parse(&nest(6)).unwrap_err();
        assert!(
            matches!(&err, Error::Limit(m) if m.contains("field degree limit of 32")),
            "{err}"
        );
    }

    /// The documented nesting depth is 64 brackets: 64 nested calls are
    /// read, 65 are refused with the bound named.
    #[test]
    fn nesting_depth_is_64_brackets() {
        let nest = |k: usize| (0..k).fold("1".to_string(), |acc, _| format!("({acc})"));
        assert_eq!(parse(&nest(64)).unwrap(), RealAlgebraic::from_i64(1));
        let err = parse(&nest(65)).unwrap_err().to_string();
        assert!(err.contains("nested more than 64 deep"), "{err}");
        let calls = (0..64).fold("4".to_string(), |acc, _| format!("Rational({acc}, 1)"));
        assert_eq!(parse(&calls).unwrap(), RealAlgebraic::from_i64(4));
        // Signs are not nesting: a long run of them is read in a loop.
        assert_eq!(
            parse(&format!("{}1", "-".repeat(1001))).unwrap(),
            RealAlgebraic::from_i64(-1)
        );
    }

    /// A long sum is one flat node: 20 000 terms (over 10 000 characters,
    /// within the default 64 000) are read without deep recursion.
    #[test]
    fn long_sums_are_flat() {
        let text = vec!["1"; 20_000].join("+");
        assert!(text.len() > 10_000);
        assert_eq!(parse(&text).unwrap(), RealAlgebraic::from_i64(20_000));
        let over = vec!["1"; 40_000].join("+");
        assert!(parse(&over)
            .unwrap_err()
            .to_string()
            .contains("longer than 64000"));
    }
}
