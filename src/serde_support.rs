//! `serde` for curves, patches (Bézier, trigonometric, NURBS) and results
//! (coincidence with its witness, standard forms) (feature `serde`), and
//! `FromStr` from the JSON text.
//!
//! Serialization goes through the interchange code of the command line
//! (`patch_to_json` and `patch_from_value`). So the serde form is, by
//! construction, the JSON format of docs/FORMAT.md. Exact numbers are
//! written as integers or `"p/q"` strings, which read back to the same
//! value. `f64` patches are written as JSON numbers.
//!
//! ```
//! use exact_bezier::io::patch_to_json;
//! use exact_bezier::{ratio, BigRational, Patch, RationalCurve};
//! let c: RationalCurve<BigRational> =
//!     r#"{"kind": "curve", "points": [[0, 0], [1, 2], [2, 0]], "weights": [1, "1/3", 1]}"#.parse().unwrap();
//! assert_eq!(c.weights()[1], ratio(1, 3));
//! // The text that `serde` writes too (e.g. `serde_json::to_string(&c)`).
//! let text = patch_to_json(&Patch::Curve(c.clone())).unwrap().to_string();
//! assert_eq!(text, r#"{"kind":"curve","degree":2,"points":[[0,0],[1,2],[2,0]],"weights":[1,"1/3",1]}"#);
//! assert_eq!(text.parse::<RationalCurve<BigRational>>().unwrap(), c);
//! ```

use crate::algebra::scalar::Field;
use crate::algebra::ExactNumber;
use crate::coincide::Coincidence;
use crate::error::Error;
use crate::io::{
    coincidence_to_json, patch_from_value_as, patch_to_json, read_patches_as, standard_to_json,
    trig_patch_from_value, trig_patch_to_json, JsonScalar,
};
use crate::io::{nurbs_to_json, read_nurbs};
use crate::nurbs::Nurbs;
use crate::patch::Patch;
use crate::reparam::Standard;
use crate::trig::TrigPatch;
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

/// Exact numbers: rationals (`BigRational`) or real algebraic numbers
/// (`RealAlgebraic`, text grammar of docs/algebraic_numbers.md).
impl<'de, T: ExactNumber> Deserialize<'de> for Patch<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        patch_from_value_as(&Value::deserialize(d)?).map_err(D::Error::custom)
    }
}

/// The one patch of a JSON text: an object, or an array of exactly one.
impl<T: ExactNumber> FromStr for Patch<T> {
    type Err = Error;

    fn from_str(text: &str) -> Result<Self, Error> {
        let mut patches = read_patches_as(text)?;
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

        impl<'de, T: ExactNumber> Deserialize<'de> for $ty<T> {
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

        impl<T: ExactNumber> FromStr for $ty<T> {
            type Err = Error;

            fn from_str(text: &str) -> Result<Self, Error> {
                match text.parse::<Patch<T>>()? {
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
        coincidence_to_json(self).serialize(s)
    }
}

/// `{"kind": "trig-curve" | "trig-rect", "alpha", "points"}` (source 002).
impl<T: JsonScalar> Serialize for TrigPatch<T> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        trig_patch_to_json(self).serialize(s)
    }
}

impl<'de> Deserialize<'de> for TrigPatch<BigRational> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        trig_patch_from_value(&Value::deserialize(d)?).map_err(D::Error::custom)
    }
}

/// `{"kind": "nurbs-curve" | "nurbs-surface", "degree", "knots", "points",
/// "weights"}` ([`nurbs_to_json`]).
impl Serialize for Nurbs {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        nurbs_to_json(self).serialize(s)
    }
}

/// One NURBS object of our layout (a geomdl file may hold several: read it
/// with [`read_nurbs`]).
impl<'de> Deserialize<'de> for Nurbs {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let mut all = read_nurbs(&Value::deserialize(d)?).map_err(D::Error::custom)?;
        match all.len() {
            1 => Ok(all.swap_remove(0)),
            n => Err(D::Error::custom(format!(
                "expected one NURBS object, found {n}"
            ))),
        }
    }
}

/// The `standardize` command's object ([`standard_to_json`]).
impl<P: Clone + Into<Patch<T>>, T: JsonScalar + Field> Serialize for Standard<P, T> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        standard_to_json(self)
            .map_err(S::Error::custom)?
            .serialize(s)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::RealAlgebraic;
    use crate::reparam::{standardize, Options};
    use crate::Scalar;

    fn round_trip<X: Serialize + for<'de> Deserialize<'de> + PartialEq + std::fmt::Debug>(x: &X) {
        let text = serde_json::to_string(x).unwrap();
        assert_eq!(&serde_json::from_str::<X>(&text).unwrap(), x, "{text}");
    }

    /// The module example's text, written by `serde` (the example writes it
    /// with `patch_to_json`, to need no JSON crate of its own).
    #[test]
    fn serde_writes_the_interchange_text() {
        let c: RationalCurve<BigRational> =
            r#"{"kind": "curve", "points": [[0, 0], [1, 2], [2, 0]], "weights": [1, "1/3", 1]}"#
                .parse()
                .unwrap();
        let text = serde_json::to_string(&c).unwrap();
        assert_eq!(
            text,
            r#"{"kind":"curve","degree":2,"points":[[0,0],[1,2],[2,0]],"weights":[1,"1/3",1]}"#
        );
        assert_eq!(text, patch_to_json(&Patch::Curve(c)).unwrap().to_string());
    }

    #[test]
    fn trig_and_nurbs_round_trip() {
        let trig = r#"{"kind": "trig-rect", "alpha": ["1/2", 2],
            "points": [[[0,0,0],[1,0,0],[2,0,0],[3,0,1]], [[0,1,0],[1,1,1],[2,1,0],[3,1,0]],
                       [[0,2,0],[1,2,0],[2,2,"1/3"],[3,2,0]], [[0,3,0],[1,3,0],[2,3,0],[3,3,0]]]}"#;
        round_trip(&serde_json::from_str::<TrigPatch<BigRational>>(trig).unwrap());
        let nurbs = r#"{"kind": "nurbs-surface", "degree": [1, 2], "knots": [[0, 0, 1, 1], [0, 0, 0, "1/3", 1, 1, 1]],
            "points": [[[0,0],[0,1],[0,2],[0,3]], [[1,0],[1,1],[1,2],[1,"7/2"]]],
            "weights": [[1,2,1,1], [1,1,"1/2",1]]}"#;
        round_trip(&serde_json::from_str::<Nurbs>(nurbs).unwrap());
        let err = serde_json::from_str::<Nurbs>(
            r#"{"kind": "nurbs-curve", "degree": 1, "knots": [0, 0, 1, 1],
            "points": [[0], [1]], "weights": [1, 0]}"#,
        )
        .unwrap_err();
        assert!(err.to_string().contains("weight"), "{err}");
    }

    #[test]
    fn algebraic_patches_and_standard_forms_serialize() {
        let c: RationalCurve<RealAlgebraic> =
            r#"{"kind": "curve", "points": [[0, 0], ["sqrt(2)", 1], [2, 0]], "weights": [1, "1/2", 2]}"#
                .parse()
                .unwrap();
        round_trip(&c);
        // End weights 1 and 2 of a quadratic: α = 1/(1 + √2), an irrational map.
        let rational: RationalCurve<BigRational> =
            r#"{"kind": "curve", "points": [[0, 0], [1, 1], [2, 0]], "weights": [1, "1/2", 2]}"#
                .parse()
                .unwrap();
        let s = standardize(
            &rational.map(RealAlgebraic::from_rational),
            Options::default(),
        )
        .unwrap();
        let v = serde_json::to_value(&s).unwrap();
        assert_eq!(v, standard_to_json(&s).unwrap());
        assert_eq!(v["exact"], true);
        let w = &v["patch"]["weights"];
        assert_eq!(
            (&w[0], &w[2]),
            (&serde_json::json!(1), &serde_json::json!(1)),
            "{v}"
        );
        assert!(
            v["reparameterization"]["alpha"]
                .as_str()
                .unwrap()
                .contains("sqrt(2)"),
            "{v}"
        );
    }
}
