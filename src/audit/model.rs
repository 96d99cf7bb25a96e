//! A model: the Bézier pieces of a file with where each came from (read by
//! [`crate::io::read_model`] from our JSON — patches, `nurbs-*` objects,
//! geomdl — or from STEP).

use crate::algebra::RealAlgebraic;
use crate::nurbs::Nurbs;
use crate::patch::Patch;
use crate::step::StepModel;
use num_rational::BigRational;
use rayon::prelude::*;
use std::collections::BTreeMap;

/// Where a piece came from.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Origin {
    /// Position of its object in a JSON input (array index), if JSON.
    pub element: Option<usize>,
    /// The STEP entity id, if STEP.
    pub entity: Option<u64>,
    /// The faces whose surface it is (STEP).
    pub faces: Vec<u64>,
    /// The knot span in u (along a curve), for NURBS.
    pub u: Option<[BigRational; 2]>,
    /// The knot span in v, for NURBS surfaces.
    pub v: Option<[BigRational; 2]>,
}

impl Origin {
    /// The source object (entity or element) this piece belongs to.
    pub fn source(&self) -> (Option<u64>, Option<usize>) {
        (self.entity, self.element)
    }
}

/// One Bézier piece of a model, over the exact scalar `T` (rational, or
/// real algebraic where a coordinate or weight is a radical).
#[derive(Clone, Debug, PartialEq)]
pub struct Piece<T = BigRational> {
    /// The piece.
    pub patch: Patch<T>,
    /// Where it came from.
    pub origin: Origin,
}

/// The pieces of a file, and what was skipped reading it.
#[derive(Clone, Debug)]
pub struct Model<T = BigRational> {
    /// Every piece, in file order.
    pub pieces: Vec<Piece<T>>,
    /// STEP entity types skipped, with counts.
    pub skipped: BTreeMap<String, usize>,
    /// STEP entities of a supported type that could not be read.
    pub invalid: Vec<(u64, String)>,
    /// STEP faces on surfaces that are not B-splines: `(face, surface)`.
    pub other_faces: Vec<(u64, u64)>,
}

impl<T> Default for Model<T> {
    fn default() -> Self {
        Model {
            pieces: Vec::new(),
            skipped: BTreeMap::new(),
            invalid: Vec::new(),
            other_faces: Vec::new(),
        }
    }
}

/// A model as read: over Q when every number is rational, else over the
/// real algebraic numbers ([`crate::io::read_exact_model`]).
#[derive(Clone, Debug)]
pub enum ExactModel {
    /// Every number rational (every STEP and NURBS input).
    Rational(Model),
    /// Some number algebraic and irrational.
    Algebraic(Model<RealAlgebraic>),
}

/// The Bézier pieces of `n`, each with `base` and its knot spans as origin.
pub fn nurbs_pieces(n: &Nurbs, base: Origin) -> impl Iterator<Item = Piece> + '_ {
    n.pieces().into_iter().map(move |p| Piece {
        patch: p.patch,
        origin: Origin {
            u: Some(p.u),
            v: p.v,
            ..base.clone()
        },
    })
}

impl Model {
    /// The model of a STEP file: the Bézier pieces of every B-spline surface
    /// entity, with the entity and its faces as origin (converted on all
    /// cores, in the file's order).
    pub fn from_step(step: StepModel) -> Model {
        let pieces = step
            .entities
            .par_iter()
            .map(|e| {
                let base = Origin {
                    entity: Some(e.id),
                    faces: e.faces.clone(),
                    ..Origin::default()
                };
                nurbs_pieces(&e.nurbs, base).collect::<Vec<_>>()
            })
            .collect::<Vec<_>>()
            .into_iter()
            .flatten()
            .collect();
        Model {
            pieces,
            skipped: step.skipped,
            invalid: step.invalid,
            other_faces: step.other_faces,
        }
    }
}
