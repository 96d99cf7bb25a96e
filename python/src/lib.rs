//! Python bindings of `exact-bezier`: the extension module
//! `exact_bezier._native`, which the pure-Python package `exact_bezier`
//! (python/exact_bezier/) re-exports.
//!
//! The bindings stand on the library's public API only:
//!
//! - curves and patches are built through the JSON reader
//!   ([`exact_bezier::io::patch_from_value`]), so a Python constructor
//!   validates exactly as a JSON file does and raises the same messages;
//! - exact evaluation is the library's `eval` on `BigRational`, float batch
//!   evaluation its [`Evaluator`](exact_bezier::eval::Evaluator) on `f64`, with the GIL released;
//! - keys are [`canonical_text`] and its SHA-256 digest, as
//!   `exact-bezier key` prints them; coincidence is
//!   [`exact_bezier::coincide::coincide`] (called in `decide` only).
//!
//! Every call into the library runs under `guarded`: a library
//! [`Error`] becomes `ExactBezierError` (or `LimitError`) with the message
//! the command line prints, and a Rust panic becomes `ExactBezierError`
//! instead of crossing into Python.

#![warn(missing_docs)]

mod algebraic;
mod batch;
mod poly;
mod run;

use exact_bezier::coincide::{canonical_text, KeyDigest};
use exact_bezier::io::{parse_rational, patch_from_value, patch_to_json, read_patches};
use exact_bezier::limits;
use exact_bezier::{Error, Patch};
use num_bigint::BigInt;
use num_rational::BigRational;
use pyo3::create_exception;
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::sync::PyOnceLock;
use pyo3::types::{PyBool, PyFloat, PyInt, PyList, PyString, PyTuple, PyType};
use serde_json::{Map, Value};
use std::hash::{DefaultHasher, Hash, Hasher};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::OnceLock;

create_exception!(
    exact_bezier,
    ExactBezierError,
    PyValueError,
    "An input or request that exact-bezier refuses: the message is the one the command line prints."
);
create_exception!(
    exact_bezier,
    ParseError,
    ExactBezierError,
    "Text that is not the documented format: malformed JSON or STEP, a number that is not exact text."
);
create_exception!(
    exact_bezier,
    DomainError,
    ExactBezierError,
    "A parameter outside the domain, or a point at infinity (a zero weight where it is evaluated)."
);
create_exception!(
    exact_bezier,
    LimitError,
    ExactBezierError,
    "An input or computation over a documented resource limit (docs/limits.md): digits, dimension, degree, work."
);

/// The Python exception for a library error: [`LimitError`] for a limit
/// (including the degree limit), [`ParseError`] for malformed text,
/// [`DomainError`] for a parameter out of the domain or a point at
/// infinity, [`ExactBezierError`] for the rest; the message is the error's
/// `Display`, as `exact-bezier` prints it after `error: `.
fn to_py_err(e: Error) -> PyErr {
    let message = e.to_string();
    match e {
        Error::Limit(_) | Error::DegreeTooHigh { .. } => LimitError::new_err(message),
        Error::Format(_) | Error::BadNumber(_) | Error::NotFinite(_) => {
            ParseError::new_err(message)
        }
        Error::Domain(_) | Error::PointAtInfinity => DomainError::new_err(message),
        _ => ExactBezierError::new_err(message),
    }
}

/// The text of a panic payload.
fn panic_text(payload: &(dyn std::any::Any + Send)) -> String {
    if let Some(s) = payload.downcast_ref::<&str>() {
        (*s).to_string()
    } else if let Some(s) = payload.downcast_ref::<String>() {
        s.clone()
    } else {
        "a panic".to_string()
    }
}

/// Why a guarded call failed: the library said no, or it panicked (a bug).
enum Failure {
    /// A library error, raised with its own message.
    Lib(Error),
    /// A caught panic's message.
    Panic(String),
}

impl From<Failure> for PyErr {
    fn from(f: Failure) -> PyErr {
        match f {
            Failure::Lib(e) => to_py_err(e),
            Failure::Panic(m) => ExactBezierError::new_err(format!(
                "internal error (a bug in exact-bezier, please report it): {m}"
            )),
        }
    }
}

/// Run `f` with a fresh work counter under this thread's limits
/// ([`run::current`], set by `exact_bezier.limits`), catching panics.
fn guarded<T>(f: impl FnOnce() -> Result<T, Error>) -> Result<T, Failure> {
    match catch_unwind(AssertUnwindSafe(|| limits::with_limits(run::current(), f))) {
        Ok(r) => r.map_err(Failure::Lib),
        Err(p) => Err(Failure::Panic(panic_text(p.as_ref()))),
    }
}

/// [`guarded`] with the GIL released: for work that may take long (exact
/// arithmetic, batches), so other Python threads run meanwhile.
fn detached<T: Send>(py: Python<'_>, f: impl FnOnce() -> Result<T, Error> + Send) -> PyResult<T> {
    Ok(py.detach(|| guarded(f))?)
}

/// `fractions.Fraction`, `numbers.Rational`, `numbers.Real` and
/// `decimal.Decimal`, imported once.
static FRACTION: PyOnceLock<Py<PyType>> = PyOnceLock::new();
static RATIONAL: PyOnceLock<Py<PyType>> = PyOnceLock::new();
static REAL: PyOnceLock<Py<PyType>> = PyOnceLock::new();
static DECIMAL: PyOnceLock<Py<PyType>> = PyOnceLock::new();

/// The exact text of a Python number, for the JSON reader: an `int`, a
/// `numbers.Rational` (`fractions.Fraction`, NumPy integers), a
/// `decimal.Decimal` or a `str` as it is written ("1/3", "0.885", checked
/// by the reader), and a `float` (any `numbers.Real`) only when
/// `from_float`, as the exact binary value it holds.
fn number_text(x: &Bound<'_, PyAny>, from_float: bool) -> PyResult<String> {
    let py = x.py();
    if x.is_instance_of::<PyBool>() {
        return Err(PyTypeError::new_err(format!(
            "{} is a bool, not a number: pass an int, a fractions.Fraction or an exact string",
            x.repr()?
        )));
    }
    if x.is_instance_of::<PyString>() {
        return x.extract::<String>();
    }
    if x.is_instance_of::<PyInt>() {
        return Ok(x.extract::<BigInt>()?.to_string());
    }
    if x.is_instance(RATIONAL.import(py, "numbers", "Rational")?)? {
        let int = py.get_type::<PyInt>();
        let n: BigInt = int.call1((x.getattr("numerator")?,))?.extract()?;
        let d: BigInt = int.call1((x.getattr("denominator")?,))?.extract()?;
        return Ok(format!("{n}/{d}"));
    }
    if x.is_instance(DECIMAL.import(py, "decimal", "Decimal")?)? {
        return x.str()?.extract::<String>();
    }
    if x.is_instance_of::<PyFloat>() || x.is_instance(REAL.import(py, "numbers", "Real")?)? {
        let f: f64 = x.extract()?;
        if !from_float {
            return Err(PyTypeError::new_err(format!(
                "the float {f:?} is not an exact number: pass an int, a fractions.Fraction or an exact string such as \"{f:?}\" (its decimal text), or exact_from_float=True to take the float's exact binary value"
            )));
        }
        if !f.is_finite() {
            return Err(to_py_err(Error::NotFinite(format!("{f}"))));
        }
        let pair = PyFloat::new(py, f).call_method0("as_integer_ratio")?;
        let (n, d): (BigInt, BigInt) = pair.extract()?;
        return Ok(format!("{n}/{d}"));
    }
    Err(PyTypeError::new_err(format!(
        "expected a number (int, fractions.Fraction, decimal.Decimal or an exact string such as \"1/3\"), found {}",
        x.get_type().name()?
    )))
}

/// A nested list or tuple of Python numbers as a JSON tree whose leaves are
/// exact number strings (NumPy arrays through `tolist()`). The JSON reader
/// checks the nesting.
fn json_tree(x: &Bound<'_, PyAny>, from_float: bool, depth: usize) -> PyResult<Value> {
    if depth > 4 {
        return Err(PyTypeError::new_err(
            "points are nested too deeply: a curve takes a list of points, a patch a list of rows of points",
        ));
    }
    let items: Option<Vec<Bound<'_, PyAny>>> = if x.is_instance_of::<PyList>() {
        Some(x.cast::<PyList>()?.iter().collect())
    } else if x.is_instance_of::<PyTuple>() {
        Some(x.cast::<PyTuple>()?.iter().collect())
    } else if !x.is_instance_of::<PyString>() && x.hasattr("tolist")? && x.hasattr("shape")? {
        return json_tree(&x.call_method0("tolist")?, from_float, depth);
    } else {
        None
    };
    match items {
        Some(items) => Ok(Value::Array(
            items
                .iter()
                .map(|i| json_tree(i, from_float, depth + 1))
                .collect::<PyResult<_>>()?,
        )),
        None => Ok(Value::String(number_text(x, from_float)?)),
    }
}

/// An exact parameter value from Python (the rules of [`number_text`]).
fn exact_param(x: &Bound<'_, PyAny>, from_float: bool) -> PyResult<BigRational> {
    let text = number_text(x, from_float)?;
    Ok(guarded(|| parse_rational(&text))?)
}

/// An exact parameter in `[0, 1]` ([`Error::Domain`] outside).
fn unit_param(x: &Bound<'_, PyAny>, from_float: bool) -> PyResult<BigRational> {
    let t = exact_param(x, from_float)?;
    if t < BigRational::from_integer(0.into()) || t > BigRational::from_integer(1.into()) {
        return Err(to_py_err(Error::Domain(format!(
            "t = {t} is outside [0, 1]"
        ))));
    }
    Ok(t)
}

/// A rational as a `fractions.Fraction`.
fn fraction<'py>(py: Python<'py>, q: &BigRational) -> PyResult<Bound<'py, PyAny>> {
    FRACTION
        .import(py, "fractions", "Fraction")?
        .call1((q.numer().clone(), q.denom().clone()))
}

/// A list of rationals as a list of `Fraction`s.
fn fractions<'py>(py: Python<'py>, xs: &[BigRational]) -> PyResult<Bound<'py, PyList>> {
    let items = xs
        .iter()
        .map(|q| fraction(py, q))
        .collect::<PyResult<Vec<_>>>()?;
    PyList::new(py, items)
}

/// The patch's JSON text (the library's writer, compact).
fn json_text(p: &Patch<BigRational>) -> PyResult<String> {
    Ok(guarded(|| patch_to_json(p).map(|v| v.to_string()))?)
}

/// Read exactly one patch of `kind` from JSON text.
fn read_one(text: &str, kind: &str, class: &str) -> PyResult<Patch<BigRational>> {
    let mut patches = guarded(|| {
        limits::check_input_bytes(text.len() as u64)?;
        read_patches(text)
    })?;
    if patches.len() != 1 {
        return Err(to_py_err(Error::Shape(format!(
            "the JSON text holds {} patches; {class}.from_json reads exactly one (exact_bezier.read_json reads several)",
            patches.len()
        ))));
    }
    let p = patches.remove(0);
    if p.kind() != kind {
        return Err(to_py_err(Error::Shape(format!(
            "the JSON text holds a {}, not a {kind} (exact_bezier.read_json reads any kind)",
            p.kind()
        ))));
    }
    Ok(p)
}

/// Build a patch of `kind` from Python points and optional weights, through
/// the JSON reader (same checks and messages as a JSON file).
fn build(
    kind: &str,
    points: &Bound<'_, PyAny>,
    weights: Option<&Bound<'_, PyAny>>,
    from_float: bool,
) -> PyResult<Patch<BigRational>> {
    let mut obj = Map::new();
    obj.insert("kind".into(), kind.into());
    obj.insert("points".into(), json_tree(points, from_float, 0)?);
    if let Some(w) = weights {
        obj.insert("weights".into(), json_tree(w, from_float, 0)?);
    }
    let v = Value::Object(obj);
    Ok(guarded(|| patch_from_value(&v))?)
}

/// The work of `count` exact evaluations of `p` at parameters of
/// `param_bits` bits, charged against the work limit first (the model of
/// `exact-bezier eval`, docs/limits.md).
fn charge_eval(p: &Patch<BigRational>, count: u64, param_bits: u64) -> Result<(), Error> {
    let size = p.size();
    let ops = size.eval_ops().saturating_mul(count);
    let bits = size.grown_bits(size.total_degree(), param_bits);
    limits::charge("eval", limits::exact_work(ops, bits))
}

/// The exact point of `p` at `params` (`[t]` or `[u, v]`), after charging
/// its work.
fn eval_exact(p: &Patch<BigRational>, params: &[BigRational]) -> Result<Vec<BigRational>, Error> {
    charge_eval(p, 1, limits::max_bits(params))?;
    match (p, params) {
        (Patch::Curve(c), [t]) => c.eval(t),
        (Patch::Rect(r), [u, v]) => r.eval(u, v),
        (Patch::Tri(tri), [u, v]) => tri.eval(u, v),
        _ => Err(Error::Shape(format!(
            "a {} takes {} parameter(s), not {}",
            p.kind(),
            if matches!(p, Patch::Curve(_)) { 1 } else { 2 },
            params.len()
        ))),
    }
}

/// The control points as nested lists of `Fraction`s.
fn points_py<'py>(py: Python<'py>, p: &Patch<BigRational>) -> PyResult<Bound<'py, PyList>> {
    let grid = |rows: Vec<Vec<Vec<BigRational>>>| -> PyResult<Bound<'py, PyList>> {
        let rows = rows
            .iter()
            .map(|r| {
                PyList::new(
                    py,
                    r.iter()
                        .map(|q| fractions(py, q))
                        .collect::<PyResult<Vec<_>>>()?,
                )
            })
            .collect::<PyResult<Vec<_>>>()?;
        PyList::new(py, rows)
    };
    match p {
        Patch::Curve(c) => {
            let pts = guarded(|| c.points())?;
            PyList::new(
                py,
                pts.iter()
                    .map(|q| fractions(py, q))
                    .collect::<PyResult<Vec<_>>>()?,
            )
        }
        Patch::Rect(r) => grid(guarded(|| r.points())?),
        Patch::Tri(t) => grid(guarded(|| {
            t.rows()
                .iter()
                .map(|r| r.iter().map(|h| h.project()).collect::<Result<_, _>>())
                .collect::<Result<_, _>>()
        })?),
    }
}

/// The weights as (nested) lists of `Fraction`s.
fn weights_py<'py>(py: Python<'py>, p: &Patch<BigRational>) -> PyResult<Bound<'py, PyList>> {
    let grid = |rows: Vec<Vec<BigRational>>| -> PyResult<Bound<'py, PyList>> {
        PyList::new(
            py,
            rows.iter()
                .map(|r| fractions(py, r))
                .collect::<PyResult<Vec<_>>>()?,
        )
    };
    match p {
        Patch::Curve(c) => fractions(py, &c.weights()),
        Patch::Rect(r) => grid(r.weights()),
        Patch::Tri(t) => grid(t.weights()),
    }
}

/// The degree: an `int` for a curve or tri patch, `(m, n)` for a rect.
fn degree_py(py: Python<'_>, p: &Patch<BigRational>) -> PyResult<Py<PyAny>> {
    Ok(match p {
        Patch::Curve(c) => c.degree().into_pyobject(py)?.into_any().unbind(),
        Patch::Rect(r) => r.degree().into_pyobject(py)?.into_any().unbind(),
        Patch::Tri(t) => t.degree().into_pyobject(py)?.into_any().unbind(),
    })
}

/// Coordinates per point.
fn dim_of<T: exact_bezier::Scalar>(p: &Patch<T>) -> usize {
    match p {
        Patch::Curve(c) => c.dim(),
        Patch::Rect(r) => r.dim(),
        Patch::Tri(t) => t.dim(),
    }
}

/// The methods every kind shares, and the kind-specific ones in `$extra`.
macro_rules! patch_class {
    ($name:ident, $kind:literal, $doc:literal, { $($extra:tt)* }) => {
        #[doc = $doc]
        #[pyclass(frozen, module = "exact_bezier")]
        pub struct $name {
            /// The exact patch (always of kind `$kind`).
            patch: Patch<BigRational>,
            /// Its nearest `f64` copy, made on the first float evaluation.
            nearest: OnceLock<Patch<f64>>,
        }

        impl $name {
            /// Wrap an exact patch of this kind.
            fn wrap(patch: Patch<BigRational>) -> Self {
                $name { patch, nearest: OnceLock::new() }
            }

            /// The `f64` copy, made once.
            fn nearest(&self) -> &Patch<f64> {
                self.nearest.get_or_init(|| self.patch.to_f64())
            }
        }

        #[pymethods]
        impl $name {
            /// Build from control points and optional weights (all 1 if
            /// omitted). Numbers are `int`, `fractions.Fraction`,
            /// `decimal.Decimal` or exact strings ("1/3", "0.885");
            /// `float` only with `exact_from_float=True`.
            ///
            /// ```text
            /// >>> from exact_bezier import Curve
            /// >>> Curve([[0, 0], ["1/2", 1], [1, 0]], weights=[1, 2, 1]).degree
            /// 2
            ///
            /// ```
            #[new]
            #[pyo3(signature = (points, weights = None, *, exact_from_float = false))]
            fn new(
                points: &Bound<'_, PyAny>,
                weights: Option<&Bound<'_, PyAny>>,
                exact_from_float: bool,
            ) -> PyResult<Self> {
                Ok(Self::wrap(build($kind, points, weights, exact_from_float)?))
            }

            /// Read one patch of this kind from JSON text (docs/FORMAT.md).
            ///
            /// ```text
            /// >>> from exact_bezier import Curve
            /// >>> Curve.from_json('{"kind": "curve", "points": [[0], [0.5]]}').points
            /// [[Fraction(0, 1)], [Fraction(1, 2)]]
            ///
            /// ```
            #[staticmethod]
            fn from_json(text: &str) -> PyResult<Self> {
                Ok(Self::wrap(read_one(text, $kind, stringify!($name))?))
            }

            /// The JSON text of the patch (docs/FORMAT.md).
            ///
            /// ```text
            /// >>> from exact_bezier import Curve
            /// >>> Curve([[0], [1]], weights=[1, "1/3"]).to_json()
            /// '{"kind":"curve","degree":1,"points":[[0],[1]],"weights":[1,"1/3"]}'
            ///
            /// ```
            fn to_json(&self) -> PyResult<String> {
                json_text(&self.patch)
            }

            /// `"curve"`, `"rect"` or `"tri"`.
            #[getter]
            fn kind(&self) -> &'static str {
                $kind
            }

            /// The degree: `int`, or `(m, n)` for a rect patch.
            #[getter]
            fn degree(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
                degree_py(py, &self.patch)
            }

            /// Coordinates per point.
            #[getter]
            fn dim(&self) -> usize {
                dim_of(&self.patch)
            }

            /// The Cartesian control points, as `Fraction`s.
            #[getter]
            fn points<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
                points_py(py, &self.patch)
            }

            /// The weights, as `Fraction`s.
            #[getter]
            fn weights<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
                weights_py(py, &self.patch)
            }

            /// Points at many parameters in `float64`, as an array of
            /// shape `(N, dim)` (the GIL is released meanwhile). Parameters
            /// have shape `(N,)` or `(N, 1)` for a curve, `(N, 2)` for a patch.
            ///
            /// ```text
            /// >>> from exact_bezier import Curve
            /// >>> Curve([[0, 0], [2, 4], [4, 0]]).eval_many([0, 0.5, 1]).tolist()
            /// [[0.0, 0.0], [2.0, 2.0], [4.0, 0.0]]
            ///
            /// ```
            fn eval_many<'py>(
                &self,
                py: Python<'py>,
                params: &Bound<'py, PyAny>,
            ) -> PyResult<Bound<'py, PyAny>> {
                batch::eval_many(py, self.nearest(), params)
            }

            /// Points and first derivatives at many parameters in
            /// `float64`: `(X, dX)` for a curve, `(X, X_u, X_v)` for a patch,
            /// each of shape `(N, dim)` (the GIL is released meanwhile).
            ///
            /// ```text
            /// >>> from exact_bezier import Curve
            /// >>> x, dx = Curve([[0, 0], [2, 4], [4, 0]]).derivatives_many([0.5])
            /// >>> dx.tolist()
            /// [[4.0, 0.0]]
            ///
            /// ```
            fn derivatives_many<'py>(
                &self,
                py: Python<'py>,
                params: &Bound<'py, PyAny>,
            ) -> PyResult<Bound<'py, PyTuple>> {
                batch::derivatives_many(py, self.nearest(), params)
            }

            fn __repr__(&self) -> PyResult<String> {
                let text = json_text(&self.patch)?;
                let quoted = serde_json::Value::String(text).to_string();
                Ok(format!("{}.from_json({})", stringify!($name), quoted))
            }

            fn __eq__(&self, py: Python<'_>, other: &Bound<'_, PyAny>) -> Py<PyAny> {
                match other.cast::<$name>() {
                    Ok(o) => (self.patch == o.get().patch)
                        .into_pyobject(py)
                        .map(|b| b.to_owned().into_any().unbind())
                        .unwrap_or_else(|_| py.NotImplemented()),
                    Err(_) => py.NotImplemented(),
                }
            }

            fn __hash__(&self) -> PyResult<u64> {
                let mut h = DefaultHasher::new();
                json_text(&self.patch)?.hash(&mut h);
                Ok(h.finish())
            }

            fn __reduce__<'py>(
                &self,
                py: Python<'py>,
            ) -> PyResult<(Bound<'py, PyAny>, (String,))> {
                let load = py.get_type::<$name>().getattr("from_json")?;
                Ok((load, (json_text(&self.patch)?,)))
            }

            $($extra)*
        }
    };
}

patch_class!(
    Curve,
    "curve",
    "A rational Bézier curve with exact rational control points and weights.\n\n```text\n>>> from exact_bezier import Curve\n>>> c = Curve([[0, 0], [1, 2], [2, 0]], weights=[1, \"1/3\", 1])\n>>> (c.degree, c.dim, c.weights[1])\n(2, 2, Fraction(1, 3))\n\n```",
    {
        /// The exact point at `t`, as a list of `Fraction`s.
        ///
        /// ```text
        /// >>> from exact_bezier import Curve
        /// >>> Curve([[0, 0], [1, 2], [2, 0]]).eval("1/3")
        /// [Fraction(2, 3), Fraction(8, 9)]
        ///
        /// ```
        #[pyo3(signature = (t, *, exact_from_float = false))]
        fn eval<'py>(
            &self,
            py: Python<'py>,
            t: &Bound<'py, PyAny>,
            exact_from_float: bool,
        ) -> PyResult<Bound<'py, PyList>> {
            let t = exact_param(t, exact_from_float)?;
            let x = detached(py, || eval_exact(&self.patch, &[t]))?;
            fractions(py, &x)
        }

        /// The pieces over `[0, t]` and `[t, 1]`, each reparameterized to
        /// `[0, 1]` (de Casteljau), exactly; `0 ≤ t ≤ 1`.
        ///
        /// ```text
        /// >>> from exact_bezier import Curve
        /// >>> left, right = Curve([[0], [2], [4]]).subdivide("1/2")
        /// >>> left.points, right.points
        /// ([[Fraction(0, 1)], [Fraction(1, 1)], [Fraction(2, 1)]], [[Fraction(2, 1)], [Fraction(3, 1)], [Fraction(4, 1)]])
        ///
        /// ```
        #[pyo3(signature = (t, *, exact_from_float = false))]
        fn subdivide(&self, t: &Bound<'_, PyAny>, exact_from_float: bool) -> PyResult<(Curve, Curve)> {
            let t = unit_param(t, exact_from_float)?;
            let Patch::Curve(c) = &self.patch else { unreachable!("a Curve holds a curve") };
            let (a, b) = guarded(|| Ok(c.subdivide(&t)))?;
            Ok((Curve::wrap(Patch::Curve(a)), Curve::wrap(Patch::Curve(b))))
        }
    }
);

/// The exact point of a rect or tri patch at `(u, v)` as `Fraction`s: the
/// body of both classes' `eval`.
fn eval_at_uv<'py>(
    py: Python<'py>,
    patch: &Patch<BigRational>,
    u: &Bound<'py, PyAny>,
    v: &Bound<'py, PyAny>,
    exact_from_float: bool,
) -> PyResult<Bound<'py, PyList>> {
    let uv = [
        exact_param(u, exact_from_float)?,
        exact_param(v, exact_from_float)?,
    ];
    let x = detached(py, || eval_exact(patch, &uv))?;
    fractions(py, &x)
}

patch_class!(
    RectPatch,
    "rect",
    "A rational tensor-product Bézier patch with exact rational control points and weights;\n`points[i][j]` is `P_{i,j}`, `i` the u index.\n\n```text\n>>> from exact_bezier import RectPatch\n>>> RectPatch([[[0, 0], [0, 1], [0, 2]], [[1, 0], [1, 1], [1, 2]]]).degree\n(1, 2)\n\n```",
    {
        /// The exact point at `(u, v)`, as a list of `Fraction`s.
        ///
        /// ```text
        /// >>> from exact_bezier import RectPatch
        /// >>> RectPatch([[[0], [1]], [[2], [4]]]).eval("1/2", "1/2")
        /// [Fraction(7, 4)]
        ///
        /// ```
        #[pyo3(signature = (u, v, *, exact_from_float = false))]
        fn eval<'py>(
            &self,
            py: Python<'py>,
            u: &Bound<'py, PyAny>,
            v: &Bound<'py, PyAny>,
            exact_from_float: bool,
        ) -> PyResult<Bound<'py, PyList>> {
            eval_at_uv(py, &self.patch, u, v, exact_from_float)
        }

        /// The two pieces of the patch split at `u = t` (`direction="u"`)
        /// or `v = t` (`direction="v"`), each reparameterized to `[0, 1]²`,
        /// exactly; `0 ≤ t ≤ 1`.
        ///
        /// ```text
        /// >>> from exact_bezier import RectPatch
        /// >>> a, b = RectPatch([[[0], [1]], [[2], [4]]]).subdivide("1/2", "v")
        /// >>> a.eval(1, 1)
        /// [Fraction(3, 1)]
        ///
        /// ```
        #[pyo3(signature = (t, direction = "u", *, exact_from_float = false))]
        fn subdivide(
            &self,
            t: &Bound<'_, PyAny>,
            direction: &str,
            exact_from_float: bool,
        ) -> PyResult<(RectPatch, RectPatch)> {
            let t = unit_param(t, exact_from_float)?;
            let Patch::Rect(r) = &self.patch else { unreachable!("a RectPatch holds a rect") };
            let (a, b) = match direction {
                "u" => guarded(|| Ok(r.subdivide_u(&t)))?,
                "v" => guarded(|| Ok(r.subdivide_v(&t)))?,
                _ => {
                    return Err(to_py_err(Error::Shape(format!(
                        "direction is \"u\" or \"v\", not {direction:?}"
                    ))))
                }
            };
            Ok((RectPatch::wrap(Patch::Rect(a)), RectPatch::wrap(Patch::Rect(b))))
        }
    }
);

patch_class!(
    TriPatch,
    "tri",
    "A rational triangular Bézier patch with exact rational control points and weights;\n`points[j][i]` is `P_{i,j,n-i-j}`.\n\n```text\n>>> from exact_bezier import TriPatch\n>>> TriPatch([[[0, 0], [1, 0]], [[0, 1]]]).degree\n1\n\n```",
    {
        /// The exact point at barycentric `(u, v, 1 − u − v)`, as a list of
        /// `Fraction`s.
        ///
        /// ```text
        /// >>> from exact_bezier import TriPatch
        /// >>> TriPatch([[[0, 0], [1, 0]], [[0, 1]]]).eval("1/5", "2/5")
        /// [Fraction(1, 5), Fraction(2, 5)]
        ///
        /// ```
        #[pyo3(signature = (u, v, *, exact_from_float = false))]
        fn eval<'py>(
            &self,
            py: Python<'py>,
            u: &Bound<'py, PyAny>,
            v: &Bound<'py, PyAny>,
            exact_from_float: bool,
        ) -> PyResult<Bound<'py, PyList>> {
            eval_at_uv(py, &self.patch, u, v, exact_from_float)
        }
    }
);

/// The Python object of an exact patch: `Curve`, `RectPatch` or `TriPatch`.
fn wrap_any(py: Python<'_>, p: Patch<BigRational>) -> PyResult<Py<PyAny>> {
    Ok(match p {
        Patch::Curve(_) => Py::new(py, Curve::wrap(p))?.into_any(),
        Patch::Rect(_) => Py::new(py, RectPatch::wrap(p))?.into_any(),
        Patch::Tri(_) => Py::new(py, TriPatch::wrap(p))?.into_any(),
    })
}

/// The exact patch inside a `Curve`, `RectPatch` or `TriPatch`.
fn patch_of(x: &Bound<'_, PyAny>) -> PyResult<Patch<BigRational>> {
    if let Ok(c) = x.cast::<Curve>() {
        return Ok(c.get().patch.clone());
    }
    if let Ok(r) = x.cast::<RectPatch>() {
        return Ok(r.get().patch.clone());
    }
    if let Ok(t) = x.cast::<TriPatch>() {
        return Ok(t.get().patch.clone());
    }
    Err(PyTypeError::new_err(format!(
        "expected a Curve, RectPatch or TriPatch, found {}",
        x.get_type().name()?
    )))
}

/// Every curve and patch of JSON text: one object or an array (NURBS
/// objects give their Bézier pieces), as [`read_patches`] reads them.
///
/// ```text
/// >>> import exact_bezier as eb
/// >>> [p.kind for p in eb.read_json('[{"kind": "curve", "points": [[0]]}, {"kind": "tri", "points": [[[0]]]}]')]
/// ['curve', 'tri']
///
/// ```
#[pyfunction]
fn read_json(py: Python<'_>, text: &str) -> PyResult<Vec<Py<PyAny>>> {
    let patches = guarded(|| {
        limits::check_input_bytes(text.len() as u64)?;
        read_patches(text)
    })?;
    patches.into_iter().map(|p| wrap_any(py, p)).collect()
}

/// The canonical key text (`eb1;…`) of a curve or rect patch.
///
/// ```text
/// >>> import exact_bezier as eb
/// >>> eb.key_text(eb.Curve([[0], [1]], weights=[1, "1/3"]))
/// 'eb1;curve;1,0;P=0,1;1,1;I=+:1;+:1'
///
/// ```
#[pyfunction]
fn key_text(py: Python<'_>, patch: &Bound<'_, PyAny>) -> PyResult<String> {
    let p = patch_of(patch)?;
    detached(py, || canonical_text(&p))
}

/// The canonical key (`eb1:` and 64 hex digits), as `exact-bezier key`
/// prints it.
///
/// ```text
/// >>> import exact_bezier as eb
/// >>> eb.key(eb.Curve([[0], [1], [3]])) == eb.key(eb.Curve([[3], [1], [0]]))
/// True
///
/// ```
#[pyfunction]
fn key(py: Python<'_>, patch: &Bound<'_, PyAny>) -> PyResult<String> {
    let p = patch_of(patch)?;
    detached(py, || {
        canonical_text(&p).map(|t| KeyDigest::of_text(&t).to_string())
    })
}

/// The exact coincidence decision of two patches as the command line's
/// JSON object (`{"coincident", "reason", "witness", "reductions"}`).
///
/// The one call into the library's coincidence entry point: adapt here
/// when that API changes. The work is charged first with the model of
/// `exact-bezier coincide`.
fn decide(a: &Patch<BigRational>, b: &Patch<BigRational>) -> Result<Value, Error> {
    for p in [a, b] {
        let s = p.size();
        let n1 = s.total_degree() + 1;
        let ops = n1.pow(4).saturating_mul(s.dim as u64 + 1);
        let bits = s.bits.max(8).saturating_mul(n1);
        limits::charge("coincide", limits::exact_work(ops, bits))?;
    }
    let options = exact_bezier::coincide::Options::default();
    Ok(exact_bezier::io::coincidence_to_json(
        &exact_bezier::coincide::coincide(a, b, options)?,
    ))
}

/// `decide` as JSON text; the package wraps it in a `Coincidence`.
#[pyfunction]
fn coincide_json(py: Python<'_>, a: &Bound<'_, PyAny>, b: &Bound<'_, PyAny>) -> PyResult<String> {
    let (pa, pb) = (patch_of(a)?, patch_of(b)?);
    detached(py, || decide(&pa, &pb).map(|v| v.to_string()))
}

/// Raise a panic inside a guarded call: the test of the panic barrier.
#[pyfunction]
fn _panic_for_test(py: Python<'_>) -> PyResult<()> {
    detached(py, || -> Result<(), Error> { panic!("a test panic") })
}

/// The extension module `exact_bezier._native`.
#[pymodule]
#[pyo3(name = "_native")]
fn native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add_class::<Curve>()?;
    m.add_class::<RectPatch>()?;
    m.add_class::<TriPatch>()?;
    m.add("ExactBezierError", py.get_type::<ExactBezierError>())?;
    m.add("LimitError", py.get_type::<LimitError>())?;
    m.add("ParseError", py.get_type::<ParseError>())?;
    m.add("DomainError", py.get_type::<DomainError>())?;
    m.add_class::<algebraic::Algebraic>()?;
    m.add_class::<poly::Poly>()?;
    m.add_function(wrap_pyfunction!(run::run, m)?)?;
    m.add_function(wrap_pyfunction!(run::set_limits, m)?)?;
    m.add_function(wrap_pyfunction!(run::get_limits, m)?)?;
    m.add_function(wrap_pyfunction!(read_json, m)?)?;
    m.add_function(wrap_pyfunction!(key, m)?)?;
    m.add_function(wrap_pyfunction!(key_text, m)?)?;
    m.add_function(wrap_pyfunction!(coincide_json, m)?)?;
    m.add_function(wrap_pyfunction!(_panic_for_test, m)?)?;
    m.add("KEY_VERSION", exact_bezier::coincide::KEY_VERSION)?;
    Ok(())
}
