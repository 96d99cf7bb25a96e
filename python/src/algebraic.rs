//! `Algebraic`: an exact real algebraic number ([`RealAlgebraic`]) as a
//! Python number — exact `==` and `<` (also against `int` and `Fraction`),
//! `+ − × ÷`, `float()`, the text form of docs/algebraic_numbers.md (which
//! SymPy's `sympify` reads as the same number) and `to_sympy()`.

use crate::{fraction, guarded, number_text, to_py_err};
use exact_bezier::algebra::{parse_algebraic, RealAlgebraic};
use exact_bezier::Error;
use num_rational::BigRational;
use pyo3::basic::CompareOp;
use pyo3::exceptions::PyImportError;
use pyo3::prelude::*;
use pyo3::types::PyString;

/// An exact real algebraic number: a rational, a sum of radicals
/// (`sqrt(6)/6`, `1 - 2*cbrt(12)/3`) or a real root of an integer
/// polynomial (`CRootOf(x**5 - x - 1, 0)`).
///
/// ```text
/// >>> from exact_bezier import Algebraic
/// >>> a = Algebraic("sqrt(2) + sqrt(3)")
/// >>> a * a == Algebraic("5 + 2*sqrt(6)")
/// True
/// >>> Algebraic("sqrt(2)") < Algebraic("3/2"), round(float(a), 6)
/// (True, 3.146264)
///
/// ```
#[pyclass(frozen, module = "exact_bezier", name = "Algebraic")]
pub struct Algebraic {
    /// The number.
    pub value: RealAlgebraic,
}

/// A Python value as an algebraic number: an `Algebraic`, an `int`, a
/// `Fraction` (any `numbers.Rational`), `decimal.Decimal`, or text in the
/// grammar of docs/algebraic_numbers.md.
pub fn algebraic_of(x: &Bound<'_, PyAny>) -> PyResult<RealAlgebraic> {
    if let Ok(a) = x.cast::<Algebraic>() {
        return Ok(a.get().value.clone());
    }
    let text = if x.is_instance_of::<PyString>() {
        x.extract::<String>()?
    } else {
        number_text(x, false)?
    };
    Ok(guarded(|| parse_algebraic(&text))?)
}

impl Algebraic {
    /// Wrap a number.
    pub fn wrap(value: RealAlgebraic) -> Self {
        Algebraic { value }
    }

    /// The number as a Python value: a `Fraction` when rational, else an
    /// `Algebraic`.
    pub fn to_python(py: Python<'_>, value: RealAlgebraic) -> PyResult<Bound<'_, PyAny>> {
        match value.as_rational() {
            Some(q) => fraction(py, &q),
            None => Ok(Bound::new(py, Algebraic::wrap(value))?.into_any()),
        }
    }

    /// `self op other` for an arithmetic operator, `NotImplemented` for an
    /// operand that is not a number.
    fn arith(
        &self,
        py: Python<'_>,
        other: &Bound<'_, PyAny>,
        f: impl FnOnce(RealAlgebraic, RealAlgebraic) -> Result<RealAlgebraic, Error>,
        reflected: bool,
    ) -> PyResult<Py<PyAny>> {
        let Ok(o) = algebraic_of(other) else {
            return Ok(py.NotImplemented());
        };
        let (a, b) = if reflected {
            (o, self.value.clone())
        } else {
            (self.value.clone(), o)
        };
        let r = guarded(|| {
            a.check_pair_degree(&b, "the operands")?;
            f(a, b)
        })?;
        Ok(Bound::new(py, Algebraic::wrap(r))?.into_any().unbind())
    }
}

/// `a / b`, refusing a zero divisor.
fn divide(a: RealAlgebraic, b: RealAlgebraic) -> Result<RealAlgebraic, Error> {
    if b.signum() == 0 {
        return Err(Error::Domain("division by zero".into()));
    }
    Ok(a / &b)
}

#[pymethods]
impl Algebraic {
    /// The number given as text (`"sqrt(2)/2"`, `"CRootOf(x**3 - 2, 0)"`,
    /// `"1/3"`), an `int`, a `Fraction` or a `decimal.Decimal`.
    #[new]
    fn new(x: &Bound<'_, PyAny>) -> PyResult<Self> {
        Ok(Algebraic::wrap(algebraic_of(x)?))
    }

    /// The text form (docs/algebraic_numbers.md), which SymPy reads.
    fn __str__(&self) -> String {
        self.value.to_string()
    }

    fn __repr__(&self) -> String {
        format!("Algebraic({:?})", self.value.to_string())
    }

    /// The nearest `float` (from 40 correct decimal digits).
    fn __float__(&self) -> f64 {
        self.value.to_decimal(40).parse().unwrap_or(f64::NAN)
    }

    /// The value rounded to `digits` decimal places, as text.
    ///
    /// ```text
    /// >>> from exact_bezier import Algebraic
    /// >>> Algebraic("sqrt(2)").decimal(10)
    /// '1.4142135624'
    ///
    /// ```
    fn decimal(&self, digits: usize) -> PyResult<String> {
        if digits > 100_000 {
            return Err(to_py_err(Error::Limit(format!(
                "{digits} decimal digits asked for, at most 100000"
            ))));
        }
        Ok(self.value.to_decimal(digits))
    }

    /// Whether the number is rational.
    #[getter]
    fn is_rational(&self) -> bool {
        self.value.as_rational().is_some()
    }

    /// The number as a `Fraction` when rational, else `None`.
    fn as_fraction<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyAny>>> {
        self.value
            .as_rational()
            .map(|q: BigRational| fraction(py, &q))
            .transpose()
    }

    /// The same number as a SymPy expression (`sympy.sympify` of the text
    /// form); SymPy is imported on the first call.
    fn to_sympy<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let sympy = py.import("sympy").map_err(|e| {
            PyImportError::new_err(format!(
                "Algebraic.to_sympy needs SymPy (pip install sympy): {e}"
            ))
        })?;
        sympy.call_method1("sympify", (self.value.to_string(),))
    }

    fn __richcmp__(
        &self,
        py: Python<'_>,
        other: &Bound<'_, PyAny>,
        op: CompareOp,
    ) -> PyResult<Py<PyAny>> {
        let Ok(o) = algebraic_of(other) else {
            return Ok(py.NotImplemented());
        };
        let ord = guarded(|| Ok(self.value.partial_cmp(&o)))?;
        let Some(ord) = ord else {
            return Ok(py.NotImplemented());
        };
        let r = op.matches(ord);
        Ok(pyo3::types::PyBool::new(py, r)
            .to_owned()
            .into_any()
            .unbind())
    }

    /// Equal numbers hash equal; a rational one as its `Fraction`.
    fn __hash__(&self, py: Python<'_>) -> PyResult<isize> {
        match self.value.as_rational() {
            Some(q) => fraction(py, &q)?.hash(),
            None => PyString::new(py, &self.value.to_decimal(30)).hash(),
        }
    }

    fn __neg__(&self) -> Self {
        Algebraic::wrap(-self.value.clone())
    }

    fn __abs__(&self) -> Self {
        if self.value.signum() < 0 {
            self.__neg__()
        } else {
            Algebraic::wrap(self.value.clone())
        }
    }

    fn __bool__(&self) -> bool {
        self.value.signum() != 0
    }

    fn __add__(&self, py: Python<'_>, o: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        self.arith(py, o, |a, b| Ok(a + &b), false)
    }
    fn __radd__(&self, py: Python<'_>, o: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        self.arith(py, o, |a, b| Ok(a + &b), true)
    }
    fn __sub__(&self, py: Python<'_>, o: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        self.arith(py, o, |a, b| Ok(a - &b), false)
    }
    fn __rsub__(&self, py: Python<'_>, o: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        self.arith(py, o, |a, b| Ok(a - &b), true)
    }
    fn __mul__(&self, py: Python<'_>, o: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        self.arith(py, o, |a, b| Ok(a * &b), false)
    }
    fn __rmul__(&self, py: Python<'_>, o: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        self.arith(py, o, |a, b| Ok(a * &b), true)
    }
    fn __truediv__(&self, py: Python<'_>, o: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        self.arith(py, o, divide, false)
    }
    fn __rtruediv__(&self, py: Python<'_>, o: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        self.arith(py, o, divide, true)
    }

    /// Pickled as its text form.
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<(Bound<'py, PyAny>, (String,))> {
        Ok((
            py.get_type::<Algebraic>().into_any(),
            (self.value.to_string(),),
        ))
    }
}
