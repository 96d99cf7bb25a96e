//! `serde` for curves, patches and coincidence results (feature `serde`),
//! and `FromStr` from the JSON text.
//!
//! Serialization goes through the interchange code of the command line
//! (`patch_to_json` and `patch_from_value`). So the serde form is, by
//! construction, the JSON format of docs/FORMAT.md. Exact numbers are
//! written as integers or `"p/q"` strings, which read back to the same
//! value. `f64` patches are written as JSON numbers.
//!
//! ```
//! use exact_bezier::{ratio, RationalCurve};
//! use num_rational::BigRational;
//! let c: RationalCurve<BigRational> =
//!     r#"{"kind": "curve", "points": [[0, 0], [1, 2], [2, 0]], "weights": [1, "1/3", 1]}"#.parse().unwrap();
//! assert_eq!(c.weights()[1], ratio(1, 3));
//! let text = serde_json::to_string(&c).unwrap();
//! assert_eq!(text, r#"{"kind":"curve","degree":2,"points":[[0,0],[1,2],[2,0]],"weights":[1,"1/3",1]}"#);
//! assert_eq!(text.parse::<RationalCurve<BigRational>>().unwrap(), c);
//! ```

use crate::algebra::scalar::Field;
use crate::coincide::Coincidence;
use crate::error::Error;
use crate::io::{patch_from_value, patch_to_json, read_patches, JsonScalar, Patch};
use crate::{RationalCurve, RectPatch, TriPatch};
use num_rational::BigRational;
use serde::de::Error as _;
use serde::ser::Error as _;
use serde::{Deserialize, Deserializer, Serialize, Serializer};
use serde_json::Value;
use std::str::FromStr;

impl<T: JsonScalar + Field> Serialize for Patch<T> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        patch_to_json(self).map_err(S::Error::custom)?.serialize(s)
    }
}

impl<'de> Deserialize<'de> for Patch<BigRational> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        patch_from_value(&Value::deserialize(d)?).map_err(D::Error::custom)
    }
}

/// The one patch of a JSON text: an object, or an array of exactly one.
impl FromStr for Patch<BigRational> {
    type Err = Error;

    fn from_str(text: &str) -> Result<Self, Error> {
        let mut patches = read_patches(text)?;
        if patches.len() != 1 {
            return Err(Error::Shape(format!(
                "expected one curve or patch, found {}",
                patches.len()
            )));
        }
        Ok(patches.swap_remove(0))
    }
}

/// `Serialize`, `Deserialize` and `FromStr` for one kind of patch, through
/// [`Patch`] and its `kind` field.
macro_rules! patch_kind_serde {
    ($ty:ident, $variant:ident, $kind:literal) => {
        impl<T: JsonScalar + Field> Serialize for $ty<T> {
            fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
                Patch::$variant(self.clone()).serialize(s)
            }
        }

        impl<'de> Deserialize<'de> for $ty<BigRational> {
            fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
                match Patch::deserialize(d)? {
                    Patch::$variant(p) => Ok(p),
                    other => Err(D::Error::custom(format!(
                        "expected kind \"{}\", found \"{}\"",
                        $kind,
                        other.kind()
                    ))),
                }
            }
        }

        impl FromStr for $ty<BigRational> {
            type Err = Error;

            fn from_str(text: &str) -> Result<Self, Error> {
                match text.parse::<Patch<BigRational>>()? {
                    Patch::$variant(p) => Ok(p),
                    other => Err(Error::Format(format!(
                        "expected kind \"{}\", found \"{}\"",
                        $kind,
                        other.kind()
                    ))),
                }
            }
        }
    };
}

patch_kind_serde!(RationalCurve, Curve, "curve");
patch_kind_serde!(RectPatch, Rect, "rect");
patch_kind_serde!(TriPatch, Tri, "tri");

/// The `coincide` command's object: `coincident`, `reason`, `witness`.
impl<T: JsonScalar> Serialize for Coincidence<T> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        self.to_json().serialize(s)
    }
}
