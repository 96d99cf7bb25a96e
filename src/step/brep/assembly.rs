//! Assembly placements: where each body of a STEP model sits, exactly.
//!
//! A part's shape is a representation in its own coordinates; an assembly
//! places it by a relationship between the part's representation (the
//! child) and the assembly's (the parent), ISO 10303-43 §4:
//!
//! ```text
//! (REPRESENTATION_RELATIONSHIP('','',#child,#parent)
//!  REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION(#t) SHAPE_REPRESENTATION_RELATIONSHIP())
//! #t = ITEM_DEFINED_TRANSFORMATION('','',#placement_in_child,#placement_in_parent)
//! #m = MAPPED_ITEM('',#map,#placement_in_parent)     (an item of the parent)
//! #map = REPRESENTATION_MAP(#placement_in_child,#child)
//! SHAPE_REPRESENTATION_RELATIONSHIP('','',#a,#b)      (one shape, two representations)
//! ```
//!
//! The transformation takes the child's placement onto the parent's: with
//! frames `F₁ = (o₁; x̂₁, ŷ₁, ẑ₁)` in the child and `F₂` in the parent, a
//! child point `x` goes to `o₂ + s·R·(x − o₁)` with `R = [x̂₂ ŷ₂ ẑ₂]·[x̂₁ ŷ₁ ẑ₁]ᵀ`
//! and `s` the child's length unit in the parent's (1 when both are
//! millimetres). The frames' unit vectors are exact radicals
//! ([`Frame::from_placement`]), so placements are exact over
//! [`RealAlgebraic`]. A relationship without a transformation joins two
//! representations of one shape (the identity). When the
//! `CONTEXT_DEPENDENT_SHAPE_REPRESENTATION` of a relationship names its
//! `NEXT_ASSEMBLY_USAGE_OCCURRENCE` and the product structure says the
//! parent is `rep_1`, the relationship is read the other way round (some
//! writers swap the two).
//!
//! Every path from a body's representation up to a representation that
//! is placed nowhere (a root) is one [`Occurrence`] of the body: a part used
//! twice in an assembly is two occurrences, with one body read once.

use super::{context, record, reference, references, type_name, Body, Store};
use crate::algebra::RealAlgebraic;
use crate::algebra::Scalar;
use crate::analytic::{dot, Frame};
use crate::limits::MAX_STEP_DEPTH;
use crate::step::geometry::placement;
use num_rational::BigRational;
use num_traits::{One, Zero};
use std::collections::{BTreeSet, HashMap, HashSet};

/// At most this many occurrences are listed (over all bodies); a model with
/// more (or a hostile file whose placements multiply) is cut there, and
/// says so in the summary's invalid entities.
pub const MAX_OCCURRENCES: usize = 100_000;

/// A similarity `x ↦ A·x + t` of 3-space, exact: a rotation times the
/// ratio of two length units, then a translation.
#[derive(Clone, Debug, PartialEq)]
pub struct Placement {
    /// `A`, row by row.
    pub linear: [[RealAlgebraic; 3]; 3],
    /// `t`.
    pub translation: [RealAlgebraic; 3],
}

impl Placement {
    /// `x ↦ x`.
    ///
    /// ```
    /// use exact_bezier::step::brep::Placement;
    /// use exact_bezier::algebra::{RealAlgebraic, Scalar};
    /// let p: Vec<RealAlgebraic> = [1, 2, 3].map(RealAlgebraic::from_i64).to_vec();
    /// assert_eq!(Placement::identity().apply(&p), p);
    /// ```
    pub fn identity() -> Placement {
        let e = |i: usize, j: usize| RealAlgebraic::from_i64(i64::from(i == j));
        Placement {
            linear: [0, 1, 2].map(|i| [0, 1, 2].map(|j| e(i, j))),
            translation: [0, 1, 2].map(|_| RealAlgebraic::zero()),
        }
    }

    /// The map taking frame `from` (in the child) onto frame `to` (in the
    /// parent), lengths scaled by `scale`: `x ↦ o₂ + s·Σₖ ((x − o₁)·ê₁ₖ)·ê₂ₖ`,
    /// i.e. `A = s·[x̂₂ ŷ₂ ẑ₂]·[x̂₁ ŷ₁ ẑ₁]ᵀ` and `t = o₂ − A·o₁`
    /// (ISO 10303-43 `item_defined_transformation`).
    ///
    /// ```
    /// use exact_bezier::analytic::Frame;
    /// use exact_bezier::step::brep::Placement;
    /// use exact_bezier::algebra::{RealAlgebraic, Scalar};
    /// use exact_bezier::BigRational;
    /// let r = |v: [i64; 3]| v.map(RealAlgebraic::from_i64).to_vec();
    /// let child = Frame::from_axes(r([1, 0, 0]), r([1, 0, 0]), r([0, 0, 1]));
    /// // the parent frame at (0, 0, 5), turned a quarter about z
    /// let parent = Frame::from_axes(r([0, 0, 5]), r([0, 1, 0]), r([0, 0, 1]));
    /// let p = Placement::between(&child, &parent, &BigRational::from_integer(1.into()));
    /// assert_eq!(p.apply(&r([1, 0, 0])), r([0, 0, 5]));
    /// assert_eq!(p.apply(&r([2, 0, 0])), r([0, 1, 5]));
    /// ```
    pub fn between(
        from: &Frame<RealAlgebraic>,
        to: &Frame<RealAlgebraic>,
        scale: &BigRational,
    ) -> Placement {
        let s = RealAlgebraic::from_rational(scale);
        let axes = |f: &Frame<RealAlgebraic>| [f.x.clone(), f.y.clone(), f.z.clone()];
        let (a1, a2) = (axes(from), axes(to));
        let linear = [0, 1, 2].map(|i| {
            [0, 1, 2].map(|j| {
                let r = (0..3).fold(RealAlgebraic::zero(), |acc, k| {
                    acc + &(a2[k][i].clone() * &a1[k][j])
                });
                r * &s
            })
        });
        let moved = mat_vec(&linear, &from.origin);
        let translation = [0, 1, 2].map(|i| to.origin[i].clone() - &moved[i]);
        Placement {
            linear,
            translation,
        }
    }

    /// `self ∘ inner`: first `inner`, then `self`.
    pub fn after(&self, inner: &Placement) -> Placement {
        let linear = [0, 1, 2].map(|i| {
            [0, 1, 2].map(|j| {
                (0..3).fold(RealAlgebraic::zero(), |acc, k| {
                    acc + &(self.linear[i][k].clone() * &inner.linear[k][j])
                })
            })
        });
        Placement {
            linear,
            translation: self.apply_array(&inner.translation),
        }
    }

    /// `A·p + t` for a 3D point `p`.
    pub fn apply(&self, p: &[RealAlgebraic]) -> Vec<RealAlgebraic> {
        let moved = mat_vec(&self.linear, p);
        (0..3)
            .map(|i| moved[i].clone() + &self.translation[i])
            .collect()
    }

    fn apply_array(&self, p: &[RealAlgebraic; 3]) -> [RealAlgebraic; 3] {
        let v = self.apply(p);
        [v[0].clone(), v[1].clone(), v[2].clone()]
    }
}

/// `A·p`.
fn mat_vec(a: &[[RealAlgebraic; 3]; 3], p: &[RealAlgebraic]) -> Vec<RealAlgebraic> {
    a.iter().map(|row| dot(row, p)).collect()
}

/// One placed occurrence of a body in the model.
#[derive(Clone, Debug, PartialEq)]
pub struct Occurrence {
    /// The body's representation id ([`Body::id`]).
    pub body: u64,
    /// The representation the path ends at (placed nowhere): the
    /// model's top assembly, or the body itself when it is not placed.
    pub root: u64,
    /// The root's representation context (its length unit is the
    /// placement's).
    pub context: Option<u64>,
    /// The relationships (`REPRESENTATION_RELATIONSHIP…` or
    /// `MAPPED_ITEM` ids) that carry the body up to the root, the body's
    /// own first; empty when the body is its own root.
    pub path: Vec<u64>,
    /// From the body's coordinates to the root's.
    pub placement: Placement,
}

/// A placing relationship, read.
#[derive(Clone, Debug)]
struct Link {
    /// The relationship or `MAPPED_ITEM`.
    id: u64,
    /// The `ITEM_DEFINED_TRANSFORMATION` or `MAPPED_ITEM` applied.
    transform: u64,
    child: u64,
    parent: u64,
    placement: Placement,
}

/// What [`occurrences`] found: the occurrences, the transformations they use,
/// and the entities that could not be read.
pub(super) struct Assembly {
    pub occurrences: Vec<Occurrence>,
    pub applied: BTreeSet<u64>,
    pub invalid: Vec<(u64, String)>,
}

/// The occurrences of `bodies` in the file `store` (see the module's text).
pub(super) fn occurrences(store: &Store, order: &[u64], bodies: &[Body]) -> Assembly {
    let mut invalid = Vec::new();
    let mut groups = Groups::default();
    let mut links = Vec::new();
    for &id in order {
        if let Some((rep_1, rep_2)) = identity(store, id) {
            groups.join(rep_1, rep_2);
        }
    }
    // Representations holding one solid are representations of one shape.
    let mut holder = HashMap::new();
    for b in bodies {
        for &solid in &b.solids {
            groups.join(*holder.entry(solid).or_insert(b.id), b.id);
        }
    }
    groups.flatten();
    let products = Products::read(store, order);
    for &id in order {
        match read_link(store, id, &products, &groups) {
            Ok(found) => links.extend(found),
            Err(why) => invalid.push((id, why)),
        }
    }
    let mut up: HashMap<u64, Vec<&Link>> = HashMap::new();
    for l in &links {
        let (c, p) = (groups.find(l.child), groups.find(l.parent));
        if c == p {
            invalid.push((l.id, "a representation placed in itself".into()));
        } else {
            up.entry(c).or_default().push(l);
        }
    }
    let mut walk = Walk {
        store,
        up: &up,
        groups: &groups,
        occurrences: Vec::new(),
        applied: BTreeSet::new(),
        cut: None,
    };
    let mut shapes = HashSet::new();
    for b in bodies {
        // A second representation of the same solids is placed through
        // the first.
        if shapes.insert((groups.find(b.id), &b.solids)) {
            walk.from(b.id, b.id, Placement::identity(), &mut Vec::new());
        }
    }
    if let Some(body) = walk.cut {
        invalid.push((
            body,
            format!("over {MAX_OCCURRENCES} occurrences: the rest are not listed"),
        ));
    }
    Assembly {
        occurrences: walk.occurrences,
        applied: walk.applied,
        invalid,
    }
}

/// The depth-first enumeration of paths to roots.
struct Walk<'a> {
    store: &'a Store,
    up: &'a HashMap<u64, Vec<&'a Link>>,
    groups: &'a Groups,
    occurrences: Vec<Occurrence>,
    applied: BTreeSet<u64>,
    /// The first body with occurrences not listed ([`MAX_OCCURRENCES`]).
    cut: Option<u64>,
}

impl<'a> Walk<'a> {
    /// Every path up from representation `rep` reached from `body` by the
    /// links in `path` and placed so far by `placed`.
    fn from(&mut self, body: u64, rep: u64, placed: Placement, path: &mut Vec<&'a Link>) {
        let parents = self
            .up
            .get(&self.groups.find(rep))
            .map_or(&[][..], Vec::as_slice);
        let on_path = |g: u64, path: &[&Link]| {
            self.groups.find(body) == g || path.iter().any(|l| self.groups.find(l.parent) == g)
        };
        let next: Vec<&'a Link> = parents
            .iter()
            .copied()
            .filter(|l| !on_path(self.groups.find(l.parent), path))
            .collect();
        if self.occurrences.len() >= MAX_OCCURRENCES {
            self.cut.get_or_insert(body);
            return;
        }
        if next.is_empty() || path.len() >= MAX_STEP_DEPTH {
            self.applied.extend(path.iter().map(|l| l.transform));
            self.occurrences.push(Occurrence {
                body,
                root: rep,
                context: context_of(self.store, rep),
                path: path.iter().map(|l| l.id).collect(),
                placement: placed,
            });
            return;
        }
        for l in next {
            path.push(l);
            self.from(body, l.parent, l.placement.after(&placed), path);
            path.pop();
        }
    }
}

/// Representations joined by relationships without a transformation
/// (one shape), as a union–find forest.
#[derive(Default)]
struct Groups {
    parent: HashMap<u64, u64>,
}

impl Groups {
    /// The group of `x`, halving the path on the way.
    fn root(&mut self, mut x: u64) -> u64 {
        while let Some(&p) = self.parent.get(&x) {
            if let Some(&grand) = self.parent.get(&p) {
                self.parent.insert(x, grand);
            }
            x = p;
        }
        x
    }

    fn join(&mut self, a: u64, b: u64) {
        let (a, b) = (self.root(a), self.root(b));
        if a != b {
            self.parent.insert(a.max(b), a.min(b));
        }
    }

    /// Point every member at its group, so that [`Groups::find`] takes
    /// one step.
    fn flatten(&mut self) {
        let members: Vec<u64> = self.parent.keys().copied().collect();
        for m in members {
            let r = self.root(m);
            self.parent.insert(m, r);
        }
    }

    /// The group of `x` (after [`Groups::flatten`]).
    fn find(&self, x: u64) -> u64 {
        self.parent.get(&x).copied().unwrap_or(x)
    }
}

/// The product structure: the representations of each product
/// definition (`SHAPE_DEFINITION_REPRESENTATION` through its
/// `PRODUCT_DEFINITION_SHAPE`), and the usage each placing relationship
/// belongs to (`CONTEXT_DEPENDENT_SHAPE_REPRESENTATION`).
struct Products {
    reps: HashMap<u64, Vec<u64>>,
    usage: HashMap<u64, u64>,
}

impl Products {
    fn read(store: &Store, order: &[u64]) -> Products {
        let mut reps: HashMap<u64, Vec<u64>> = HashMap::new();
        let mut usage = HashMap::new();
        for &id in order {
            if let Some(c) = record(store, id, "CONTEXT_DEPENDENT_SHAPE_REPRESENTATION")
                && let (Ok(rel), Some(u)) = (
                    reference(c.params.first(), "representation_relation"),
                    reference(c.params.get(1), "represented_product_relation")
                        .ok()
                        .and_then(|pds| definition(store, pds)),
                )
            {
                usage.insert(rel, u);
            }
            let Some(sdr) = record(store, id, "SHAPE_DEFINITION_REPRESENTATION") else {
                continue;
            };
            let (Ok(pds), Ok(rep)) = (
                reference(sdr.params.first(), "definition"),
                reference(sdr.params.get(1), "used_representation"),
            ) else {
                continue;
            };
            if let Some(pd) = definition(store, pds) {
                reps.entry(pd).or_default().push(rep);
            }
        }
        Products { reps, usage }
    }

    /// Does the product structure say `rep_1` is the parent of relationship
    /// `id` (whose `CONTEXT_DEPENDENT_SHAPE_REPRESENTATION` names the usage)?
    fn swapped(&self, id: u64, store: &Store, groups: &Groups, rep_1: u64, rep_2: u64) -> bool {
        let Some(n) = self
            .usage
            .get(&id)
            .and_then(|u| store.get(u))
            .and_then(|i| i.records.first())
        else {
            return false;
        };
        match (
            reference(n.params.get(3), "relating_product_definition"),
            reference(n.params.get(4), "related_product_definition"),
        ) {
            (Ok(parent), Ok(child)) => {
                self.holds(parent, rep_1, groups) && self.holds(child, rep_2, groups)
            }
            _ => false,
        }
    }

    /// Is representation `rep` (or one of its group) a shape of product
    /// definition `pd`?
    fn holds(&self, pd: u64, rep: u64, groups: &Groups) -> bool {
        self.reps
            .get(&pd)
            .is_some_and(|rs| rs.iter().any(|&r| groups.find(r) == groups.find(rep)))
    }
}

/// The `definition` of a `PRODUCT_DEFINITION_SHAPE`.
fn definition(store: &Store, pds: u64) -> Option<u64> {
    let r = record(store, pds, "PRODUCT_DEFINITION_SHAPE")?;
    reference(r.params.get(2), "definition").ok()
}

/// The two representations of relationship `id`, when it is one.
fn relationship(store: &Store, id: u64) -> Option<Result<(u64, u64), String>> {
    let r = record(store, id, "REPRESENTATION_RELATIONSHIP")
        .or_else(|| record(store, id, "SHAPE_REPRESENTATION_RELATIONSHIP"))
        .filter(|r| r.params.len() == 4)?;
    Some(
        reference(r.params.get(2), "rep_1")
            .and_then(|a| Ok((a, reference(r.params.get(3), "rep_2")?))),
    )
}

/// The two representations of a relationship without a transformation
/// (two representations of one shape).
fn identity(store: &Store, id: u64) -> Option<(u64, u64)> {
    let without = record(store, id, "REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION").is_none();
    relationship(store, id)?.ok().filter(|_| without)
}

/// The placing links of entity `id` (none for most entities).
fn read_link(
    store: &Store,
    id: u64,
    products: &Products,
    groups: &Groups,
) -> Result<Vec<Link>, String> {
    if let Some(reps) = relationship(store, id) {
        let (rep_1, rep_2) = reps?;
        let Some(t) = record(store, id, "REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION") else {
            return Ok(Vec::new());
        };
        let transform = reference(t.params.first(), "transformation_operator")?;
        let idt = record(store, transform, "ITEM_DEFINED_TRANSFORMATION").ok_or_else(|| {
            format!(
                "the transformation #{transform} is a {}, not an ITEM_DEFINED_TRANSFORMATION",
                type_name(store, transform)
            )
        })?;
        let item_1 = reference(idt.params.get(2), "transform_item_1")?;
        let item_2 = reference(idt.params.get(3), "transform_item_2")?;
        let mut ends = [(rep_1, item_1), (rep_2, item_2)];
        if products.swapped(id, store, groups, rep_1, rep_2) {
            ends.reverse();
        }
        let [(child, from), (parent, to)] = ends;
        let placement = frames_map(store, (child, from), (parent, to))?;
        return Ok(vec![Link {
            id,
            transform,
            child,
            parent,
            placement,
        }]);
    }
    mapped_items(store, id)
}

/// The links of representation `id` through its `MAPPED_ITEM`s, when it
/// is a shape representation (a drawing's mapped items place no body).
fn mapped_items(store: &Store, id: u64) -> Result<Vec<Link>, String> {
    let Some(rep) = store.get(&id).and_then(|i| {
        i.records
            .iter()
            .find(|r| r.name.ends_with("SHAPE_REPRESENTATION") && r.params.len() == 3)
    }) else {
        return Ok(Vec::new());
    };
    let mut links = Vec::new();
    for item in references(rep.params.get(1), "items")? {
        let Some(m) = record(store, item, "MAPPED_ITEM") else {
            continue;
        };
        let source = reference(m.params.get(1), "mapping_source")?;
        let target = reference(m.params.get(2), "mapping_target")?;
        let map = record(store, source, "REPRESENTATION_MAP")
            .ok_or_else(|| format!("MAPPED_ITEM #{item}: #{source} is not a REPRESENTATION_MAP"))?;
        let origin = reference(map.params.first(), "mapping_origin")?;
        let child = reference(map.params.get(1), "mapped_representation")?;
        links.push(Link {
            id: item,
            transform: item,
            child,
            parent: id,
            placement: frames_map(store, (child, origin), (id, target))?,
        });
    }
    Ok(links)
}

/// The placement taking placement `from` of representation `child` onto
/// placement `to` of representation `parent`, with the ratio of their
/// length units.
fn frames_map(store: &Store, child: (u64, u64), parent: (u64, u64)) -> Result<Placement, String> {
    let frame = |item: u64| -> Result<Frame<RealAlgebraic>, String> {
        match record(store, item, "AXIS2_PLACEMENT_3D") {
            Some(_) => placement(store, item).map_err(|e| e.to_string()),
            None => Err(format!(
                "#{item} is a {}, not an AXIS2_PLACEMENT_3D",
                type_name(store, item)
            )),
        }
    };
    let scale = match (metres(store, child.0), metres(store, parent.0)) {
        (Some(c), Some(p)) => c / p,
        _ => BigRational::one(),
    };
    Ok(Placement::between(
        &frame(child.1)?,
        &frame(parent.1)?,
        &scale,
    ))
}

/// The context of representation `rep`.
fn context_of(store: &Store, rep: u64) -> Option<u64> {
    let r = store
        .get(&rep)?
        .records
        .iter()
        .find(|r| r.name.ends_with("REPRESENTATION") && r.params.len() == 3)?;
    reference(r.params.get(2), "context_of_items").ok()
}

/// Metres per length unit of representation `rep`'s context, when declared.
fn metres(store: &Store, rep: u64) -> Option<BigRational> {
    let m = context(store, context_of(store, rep)?).ok()?.length?.metres;
    (m > BigRational::from_integer(0.into())).then_some(m)
}

#[cfg(test)]
mod tests;
