//! [`Error`]: one typed error for malformed input and impossible requests.

use std::fmt;

/// Everything that can be wrong with an input or a request.
///
/// `Display` names the numbers involved, so a command-line user sees what to
/// fix ("a degree 3 curve needs 4 control points, not 3").
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum Error {
    /// The input is not valid JSON or not of the interchange format.
    Format(String),
    /// A number could not be read exactly from its text.
    BadNumber(String),
    /// A NaN or infinite `f64` where a finite number is needed.
    NotFinite(String),
    /// Counts of points, weights or coordinates do not match.
    Shape(String),
    /// A weight is zero, or negative where positive weights are required.
    Weight {
        /// Which weight, e.g. `w_2` or `w_{1,0}`.
        index: String,
        /// Its value as text.
        value: String,
    },
    /// A degree beyond the documented limit (`limits::MAX_DEGREE`).
    DegreeTooHigh {
        /// The degree asked for.
        degree: usize,
        /// The limit it was checked against.
        limit: usize,
    },
    /// A parameter outside the allowed domain (e.g. a Möbius α of 0 or 1).
    Domain(String),
    /// A homogeneous point of weight zero cannot be projected.
    PointAtInfinity,
    /// The request has no exact answer over Q (e.g. an irrational root).
    NotRational(String),
    /// The input or the work it asks for is over a documented resource
    /// limit (see [`crate::limits`] and `docs/limits.md`); the message names
    /// the limit and how to raise it.
    Limit(String),
    /// A file or stream could not be read (a missing file, no permission,
    /// an I/O failure); the message names the file and the reason.
    Io(String),
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Format(m) => write!(f, "malformed input: {m}"),
            Error::BadNumber(m) => write!(f, "not an exact number: {m}"),
            Error::NotFinite(m) => write!(f, "not a finite number: {m}"),
            Error::Shape(m) => write!(f, "{m}"),
            Error::Weight { index, value } => write!(
                f,
                "weight {index} is {value}: weights must be positive (zero or negative weights are not allowed)"
            ),
            Error::DegreeTooHigh { degree, limit } => {
                write!(f, "degree {degree} is over the limit of {limit}")
            }
            Error::Domain(m) => write!(f, "parameter out of domain: {m}"),
            Error::PointAtInfinity => write!(f, "point at infinity: the weight is zero"),
            Error::NotRational(m) => write!(f, "no exact rational answer: {m}"),
            Error::Limit(m) => write!(f, "over a limit: {m}"),
            Error::Io(m) => write!(f, "{m}"),
        }
    }
}

impl std::error::Error for Error {}
