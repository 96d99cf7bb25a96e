//! `Poly`: the library's symbolic polynomials over Q ([`Poly`]) in Python.
//! Its representation is canonical, so `==` decides equality of
//! polynomials; the package turns SymPy expressions into `Poly` values
//! (`Poly.from_sympy`, `prove_identity`) with the kernel's arithmetic doing
//! every expansion.

use crate::fraction;
use exact_bezier::Poly as KPoly;
use num_rational::BigRational;
use num_traits::{One, Zero};
use pyo3::basic::CompareOp;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyTuple};

/// The largest exponent `Poly.__pow__` and `Poly.from_terms` accept.
const MAX_EXPONENT: u32 = 10_000;

/// A polynomial over Q in named variables, exact and canonical.
///
/// ```text
/// >>> from exact_bezier import Poly
/// >>> a, b = Poly.var("a"), Poly.var("b")
/// >>> (a + b) ** 2 == a * a + 2 * a * b + b * b
/// True
/// >>> str((a - 1) * (a + 1))
/// 'a^2 - 1'
///
/// ```
#[pyclass(frozen, module = "exact_bezier", name = "Poly")]
pub struct Poly {
    /// The polynomial.
    pub poly: KPoly,
}

/// A Python value as a polynomial: a `Poly`, an `int` or a `Fraction`.
fn poly_of(x: &Bound<'_, PyAny>) -> Option<KPoly> {
    if let Ok(p) = x.cast::<Poly>() {
        return Some(p.get().poly.clone());
    }
    let text = crate::number_text(x, false).ok()?;
    crate::guarded(|| exact_bezier::io::parse_rational(&text))
        .ok()
        .map(KPoly::constant)
}

/// `v` as a Python `Poly`, or `NotImplemented` when the operand was not a
/// polynomial or number.
fn binary(
    py: Python<'_>,
    other: &Bound<'_, PyAny>,
    f: impl FnOnce(KPoly) -> KPoly,
) -> PyResult<Py<PyAny>> {
    match poly_of(other) {
        Some(o) => Ok(Bound::new(py, Poly { poly: f(o) })?.into_any().unbind()),
        None => Ok(py.NotImplemented()),
    }
}

#[pymethods]
impl Poly {
    /// The variable `name`.
    #[staticmethod]
    fn var(name: &str) -> PyResult<Self> {
        if name.is_empty() || !name.chars().all(|c| c.is_alphanumeric() || c == '_') {
            return Err(PyValueError::new_err(format!(
                "a variable name is letters, digits and _, not {name:?}"
            )));
        }
        Ok(Poly {
            poly: KPoly::var(name),
        })
    }

    /// The constant `x` (an `int` or `Fraction`).
    #[staticmethod]
    fn constant(x: &Bound<'_, PyAny>) -> PyResult<Self> {
        let text = crate::number_text(x, false)?;
        let q = crate::guarded(|| exact_bezier::io::parse_rational(&text))?;
        Ok(Poly {
            poly: KPoly::constant(q),
        })
    }

    /// The polynomial `Σ c·Π name^e` of `terms`: pairs of a list of
    /// `(name, exponent)` and a coefficient (`int` or `Fraction`).
    #[staticmethod]
    fn from_terms(terms: &Bound<'_, PyAny>) -> PyResult<Self> {
        let mut sum = KPoly::zero();
        for t in terms.try_iter()? {
            let (monomial, c): (Vec<(String, u32)>, Bound<'_, PyAny>) = t?.extract()?;
            let mut term = Poly::constant(&c)?.poly;
            for (name, e) in monomial {
                if e > MAX_EXPONENT {
                    return Err(PyValueError::new_err(format!(
                        "exponent {e} is over the limit of {MAX_EXPONENT}"
                    )));
                }
                term = term * &Poly::var(&name)?.poly.pow(e);
            }
            sum = sum + &term;
        }
        Ok(Poly { poly: sum })
    }

    /// The terms: a list of `(monomial, coefficient)` with the monomial a
    /// dict `{name: exponent}` and the coefficient a `Fraction`.
    fn terms<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        let items = self
            .poly
            .terms()
            .map(|(m, c)| {
                let d = PyDict::new(py);
                for (name, e) in m {
                    d.set_item(name, e)?;
                }
                PyTuple::new(py, [d.into_any(), fraction(py, &c)?])
            })
            .collect::<PyResult<Vec<_>>>()?;
        PyList::new(py, items)
    }

    /// The variables, sorted by name.
    #[getter]
    fn variables(&self) -> Vec<String> {
        let mut v = self.poly.variables();
        v.sort();
        v
    }

    /// The total degree (0 for a constant, including 0).
    #[getter]
    fn total_degree(&self) -> u32 {
        self.poly.total_degree()
    }

    /// The value when the polynomial is a constant (a `Fraction`), else
    /// `None`.
    fn as_constant<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyAny>>> {
        self.poly
            .as_constant()
            .map(|q: BigRational| fraction(py, &q))
            .transpose()
    }

    fn __bool__(&self) -> bool {
        !self.poly.is_zero()
    }

    fn __str__(&self) -> String {
        self.poly.to_string()
    }

    fn __repr__(&self) -> String {
        format!("Poly({:?})", self.poly.to_string())
    }

    fn __hash__(&self) -> u64 {
        use std::hash::{DefaultHasher, Hash, Hasher};
        let mut h = DefaultHasher::new();
        self.poly.hash(&mut h);
        h.finish()
    }

    fn __richcmp__(
        &self,
        py: Python<'_>,
        other: &Bound<'_, PyAny>,
        op: CompareOp,
    ) -> PyResult<Py<PyAny>> {
        let Some(o) = poly_of(other) else {
            return Ok(py.NotImplemented());
        };
        let r = match op {
            CompareOp::Eq => self.poly == o,
            CompareOp::Ne => self.poly != o,
            _ => return Ok(py.NotImplemented()),
        };
        Ok(pyo3::types::PyBool::new(py, r)
            .to_owned()
            .into_any()
            .unbind())
    }

    fn __neg__(&self) -> Self {
        Poly {
            poly: -self.poly.clone(),
        }
    }
    fn __add__(&self, py: Python<'_>, o: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        binary(py, o, |o| self.poly.clone() + &o)
    }
    fn __radd__(&self, py: Python<'_>, o: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        binary(py, o, |o| o + &self.poly)
    }
    fn __sub__(&self, py: Python<'_>, o: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        binary(py, o, |o| self.poly.clone() - &o)
    }
    fn __rsub__(&self, py: Python<'_>, o: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        binary(py, o, |o| o - &self.poly)
    }
    fn __mul__(&self, py: Python<'_>, o: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        binary(py, o, |o| self.poly.clone() * &o)
    }
    fn __rmul__(&self, py: Python<'_>, o: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        binary(py, o, |o| o * &self.poly)
    }

    fn __pow__(&self, e: u32, modulo: Option<&Bound<'_, PyAny>>) -> PyResult<Self> {
        if modulo.is_some() {
            return Err(PyValueError::new_err("Poly ** e takes no modulus"));
        }
        if e > MAX_EXPONENT {
            return Err(PyValueError::new_err(format!(
                "exponent {e} is over the limit of {MAX_EXPONENT}"
            )));
        }
        Ok(Poly {
            poly: if e == 0 {
                KPoly::one()
            } else {
                self.poly.pow(e)
            },
        })
    }

    /// Substitute the rational `value` (`int` or `Fraction`) for `name`.
    fn subs(&self, name: &str, value: &Bound<'_, PyAny>) -> PyResult<Self> {
        let text = crate::number_text(value, false)?;
        let q = crate::guarded(|| exact_bezier::io::parse_rational(&text))?;
        Ok(Poly {
            poly: self.poly.subst_rational(name, &q),
        })
    }

    /// The partial derivative in `name`.
    fn diff(&self, name: &str) -> Self {
        Poly {
            poly: self.poly.derivative(name),
        }
    }

    fn __reduce__<'py>(
        &self,
        py: Python<'py>,
    ) -> PyResult<(Bound<'py, PyAny>, (Bound<'py, PyList>,))> {
        let rebuild = py.get_type::<Poly>().getattr("from_terms")?;
        let terms = self
            .poly
            .terms()
            .map(|(m, c)| PyTuple::new(py, [m.into_pyobject(py)?.into_any(), fraction(py, &c)?]))
            .collect::<PyResult<Vec<_>>>()?;
        Ok((rebuild, (PyList::new(py, terms)?,)))
    }
}
