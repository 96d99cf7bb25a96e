//! The NumPy path: points and derivatives of a patch's `f64` copy at
//! arrays of parameters, into `float64` arrays, with no Python object per
//! point and the GIL released during the work.
//!
//! The parameters are read in place from the caller's array once NumPy has
//! made it C-contiguous, aligned `float64` (`numpy.require`: no copy when it
//! already is), and the results are written into arrays made here with
//! `numpy.empty`, through their data pointers (`__array_interface__`). As
//! with NumPy's own GIL-free loops, another thread must not resize or write
//! the parameter array during the call.

use crate::{detached, dim_of, to_py_err};
use exact_bezier::eval::{Evaluator, Jets};
use exact_bezier::{Error, Patch};
use pyo3::prelude::*;
use pyo3::types::PyTuple;

/// Points per chunk of a derivative batch (the scratch buffer's size).
const CHUNK: usize = 1024;

/// Parameters per point: 1 for a curve, 2 for a patch.
fn params_per_point(p: &Patch<f64>) -> usize {
    if matches!(p, Patch::Curve(_)) {
        1
    } else {
        2
    }
}

/// The address of a NumPy array's data.
fn data_address(arr: &Bound<'_, PyAny>) -> PyResult<usize> {
    let (address, _read_only): (usize, bool) = arr
        .getattr("__array_interface__")?
        .get_item("data")?
        .extract()?;
    Ok(address)
}

/// The parameters as a C-contiguous aligned `float64` array (kept alive by
/// the caller while its data is read), its data address and the number of
/// points; checks the shape: `(N,)` or `(N, 1)` for a curve, `(N, 2)` for
/// a patch.
fn param_array<'py>(
    py: Python<'py>,
    p: &Patch<f64>,
    params: &Bound<'py, PyAny>,
) -> PyResult<(Bound<'py, PyAny>, usize, usize)> {
    let np = py.import("numpy")?;
    let arr = np.call_method1("require", (params, "float64", ["C", "A"]))?;
    let shape: Vec<usize> = arr.getattr("shape")?.extract()?;
    let k = params_per_point(p);
    let ok = match shape.as_slice() {
        [_] => k == 1,
        [_, c] => *c == k,
        _ => false,
    };
    if !ok {
        let want = if k == 1 { "(N,) or (N, 1)" } else { "(N, 2)" };
        return Err(to_py_err(Error::Shape(format!(
            "a {} takes parameters of shape {want}, not {shape:?}",
            p.kind()
        ))));
    }
    let address = data_address(&arr)?;
    Ok((arr, address, shape[0]))
}

/// A new `float64` array of shape `(n, dim)` and its data address.
fn output<'py>(py: Python<'py>, n: usize, dim: usize) -> PyResult<(Bound<'py, PyAny>, usize)> {
    let arr = py
        .import("numpy")?
        .call_method1("empty", ((n, dim), "float64"))?;
    let address = data_address(&arr)?;
    Ok((arr, address))
}

/// The `len` values at `address`, read-only.
///
/// # Safety
///
/// `address` is the data of a live, aligned, C-contiguous `float64` array
/// of at least `len` elements (or `len` is 0).
unsafe fn slice<'a>(address: usize, len: usize) -> &'a [f64] {
    if len == 0 {
        return &[];
    }
    // SAFETY: the caller's contract.
    unsafe { std::slice::from_raw_parts(address as *const f64, len) }
}

/// The `len` values at `address`, writable.
///
/// # Safety
///
/// As [`slice`], and the array was made by [`output`] in this call, so
/// nothing else refers to its data.
unsafe fn slice_mut<'a>(address: usize, len: usize) -> &'a mut [f64] {
    if len == 0 {
        return &mut [];
    }
    // SAFETY: the caller's contract.
    unsafe { std::slice::from_raw_parts_mut(address as *mut f64, len) }
}

/// The batch evaluator of a patch's `f64` copy.
fn evaluator(p: &Patch<f64>) -> Evaluator<f64> {
    match p {
        Patch::Curve(c) => Evaluator::curve(c),
        Patch::Rect(r) => Evaluator::rect(r),
        Patch::Tri(t) => Evaluator::tri(t),
    }
}

/// `eval_many`: the points at an array of parameters, shape `(N, dim)`.
pub fn eval_many<'py>(
    py: Python<'py>,
    p: &Patch<f64>,
    params: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyAny>> {
    let (_keep, input, n) = param_array(py, p, params)?;
    let (k, dim) = (params_per_point(p), dim_of(p));
    let (out, address) = output(py, n, dim)?;
    detached(py, move || {
        // SAFETY: `_keep` and `out` are alive until this function returns,
        // as made by `param_array` and `output`.
        let (ts, xs) = unsafe { (slice(input, n * k), slice_mut(address, n * dim)) };
        evaluator(p).eval_batch(ts, xs)
    })?;
    Ok(out)
}

/// The Cartesian point and first derivatives from the homogeneous jet
/// `jet` (`H`, then `∂H`…, `stride = dim + 1` each, weight last), by the
/// quotient rule `X = Hd/w`, `∂X = (∂Hd·w − Hd·∂w)/w²`, into `outs[0]`
/// (the point) and `outs[1..]`.
fn cartesian(jet: &[f64], dim: usize, outs: &mut [&mut [f64]]) -> Result<(), Error> {
    let s = dim + 1;
    let w = jet[dim];
    if w == 0.0 {
        return Err(Error::PointAtInfinity);
    }
    for c in 0..dim {
        outs[0][c] = jet[c] / w;
    }
    for (d, out) in outs.iter_mut().enumerate().skip(1) {
        let h = &jet[d * s..(d + 1) * s];
        for c in 0..dim {
            out[c] = (h[c] * w - jet[c] * h[dim]) / (w * w);
        }
    }
    Ok(())
}

/// `derivatives_many`: `(X, X')` of a curve or `(X, X_u, X_v)` of a patch
/// at an array of parameters, each of shape `(N, dim)`, from the library's
/// batch [`Jets`] in chunks of [`CHUNK`] points.
pub fn derivatives_many<'py>(
    py: Python<'py>,
    p: &Patch<f64>,
    params: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyTuple>> {
    let (_keep, input, n) = param_array(py, p, params)?;
    let (k, dim) = (params_per_point(p), dim_of(p));
    let arrays = (0..=k)
        .map(|_| output(py, n, dim))
        .collect::<PyResult<Vec<_>>>()?;
    let addresses: Vec<usize> = arrays.iter().map(|(_, a)| *a).collect();
    detached(py, move || {
        let mut jets = match p {
            Patch::Curve(c) => Jets::curve(c),
            Patch::Rect(r) => Jets::rect(r),
            Patch::Tri(t) => Jets::tri(t),
        };
        let per_point = (k + 1) * jets.stride();
        // SAFETY: as in `eval_many`; the k + 1 outputs are distinct arrays.
        let ts = unsafe { slice(input, n * k) };
        let mut outs: Vec<&mut [f64]> = addresses
            .iter()
            .map(|&a| unsafe { slice_mut(a, n * dim) })
            .collect();
        let mut scratch = vec![0.0; CHUNK * per_point];
        for (c, chunk) in ts.chunks(CHUNK * k).enumerate() {
            let m = chunk.len() / k;
            let buf = &mut scratch[..m * per_point];
            jets.eval_batch(chunk, buf)?;
            for (i, jet) in buf.chunks_exact(per_point).enumerate() {
                let at = (c * CHUNK + i) * dim;
                let mut rows: Vec<&mut [f64]> =
                    outs.iter_mut().map(|o| &mut o[at..at + dim]).collect();
                cartesian(jet, dim, &mut rows)?;
            }
        }
        Ok(())
    })?;
    PyTuple::new(py, arrays.into_iter().map(|(a, _)| a))
}
