//! Hand-built assemblies: the placed points worked out by hand.

use super::super::tests::{read, MM_DEG, SQUARE};
use crate::algebra::{RealAlgebraic, Scalar};
use crate::ratio;
use crate::step::BrepModel;
use num_rational::BigRational;

fn q(n: i64, d: i64) -> RealAlgebraic {
    RealAlgebraic::from_rational(&ratio::<BigRational>(n, d))
}

/// Vertex `v` of the square as placed by occurrence `k`.
fn placed(m: &BrepModel, k: usize, v: u64) -> Vec<RealAlgebraic> {
    let p: Vec<RealAlgebraic> = m.vertices[&v]
        .iter()
        .map(RealAlgebraic::from_rational)
        .collect();
    m.occurrences[k].placement.apply(&p)
}

/// An assembly in metres: the square (millimetres) placed at #101, whose
/// directions are decimals and not unit vectors.
const ASSEMBLY: &str = "\
#110=(GEOMETRIC_REPRESENTATION_CONTEXT(3) GLOBAL_UNIT_ASSIGNED_CONTEXT((#111)) REPRESENTATION_CONTEXT('',''));\n\
#111=(LENGTH_UNIT() NAMED_UNIT(*) SI_UNIT($,.METRE.));\n\
#100=SHAPE_REPRESENTATION('assembly',(#101,#102),#110);\n\
#101=AXIS2_PLACEMENT_3D('',#103,#104,#105);\n\
#103=CARTESIAN_POINT('',(1.,2.,3.));#104=DIRECTION('',(0.,0.,2.));#105=DIRECTION('',(3.,4.,0.));\n\
#102=AXIS2_PLACEMENT_3D('',#106,$,#107);\n\
#106=CARTESIAN_POINT('',(0.,0.,0.));#107=DIRECTION('',(1.,1.,0.));\n\
#120=(REPRESENTATION_RELATIONSHIP('','',#62,#100) REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION(#121) SHAPE_REPRESENTATION_RELATIONSHIP());\n\
#121=ITEM_DEFINED_TRANSFORMATION('','',#9,#101);\n";

/// A second use of the square, written parent first (`rep_1` is the
/// assembly) with the product structure that says so.
const SWAPPED_USE: &str = "\
#130=(REPRESENTATION_RELATIONSHIP('','',#100,#62) REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION(#131) SHAPE_REPRESENTATION_RELATIONSHIP());\n\
#131=ITEM_DEFINED_TRANSFORMATION('','',#102,#9);\n\
#132=CONTEXT_DEPENDENT_SHAPE_REPRESENTATION(#130,#133);\n\
#133=PRODUCT_DEFINITION_SHAPE('','',#134);\n\
#134=NEXT_ASSEMBLY_USAGE_OCCURRENCE('2','square_2','',#140,#141,$);\n\
#140=PRODUCT_DEFINITION('assembly','',$,$);#141=PRODUCT_DEFINITION('square','',$,$);\n\
#142=SHAPE_DEFINITION_REPRESENTATION(#143,#100);#143=PRODUCT_DEFINITION_SHAPE('','',#140);\n\
#144=SHAPE_DEFINITION_REPRESENTATION(#145,#62);#145=PRODUCT_DEFINITION_SHAPE('','',#141);\n";

#[test]
fn a_part_placed_in_a_frame_of_decimal_directions_and_another_unit() {
    let m = read(&format!("{SQUARE}{MM_DEG}{ASSEMBLY}"));
    assert_eq!(m.occurrences.len(), 1);
    let o = &m.occurrences[0];
    assert_eq!((o.body, o.root, &o.path[..]), (62, 100, &[120][..]));
    assert_eq!(o.context, Some(110));
    assert!(m.contexts.contains_key(&110), "the root's context is read");
    // x̂ = (3, 4, 0)/5, ŷ = ẑ × x̂ = (−4, 3, 0)/5, millimetres to metres:
    // (1, 1, 0) mm ↦ (1, 2, 3) + (x̂ + ŷ)/1000 = (1 − 1/5000, 2 + 7/5000, 3).
    assert_eq!(placed(&m, 0, 13), [q(4999, 5000), q(10007, 5000), q(3, 1)]);
    assert_eq!(placed(&m, 0, 11), [q(1, 1), q(2, 1), q(3, 1)]);
    assert!(m.summary.not_applied.is_empty());
}

#[test]
fn a_relationship_written_parent_first_is_read_by_its_usage() {
    let m = read(&format!("{SQUARE}{MM_DEG}{ASSEMBLY}{SWAPPED_USE}"));
    assert_eq!(m.occurrences.len(), 2, "{:?}", m.summary.invalid);
    assert_eq!(m.occurrences[1].path, [130]);
    // #9 (the origin, x̂ = (1, 0, 0)) onto #102 (x̂ = (1, 1, 0)/√2): the
    // vertex (1, 0, 0) mm goes to (√2/2, √2/2, 0)/1000 m.
    let p = placed(&m, 1, 12);
    assert_eq!(p[0], p[1]);
    assert_eq!(p[0].clone() * &p[0], q(1, 2_000_000));
    assert!(p[0].signum() > 0);
    assert_eq!(p[2], q(0, 1));
}

#[test]
fn placement_cycles_end_and_drawings_place_nothing() {
    // The assembly placed back into the square: a cycle, cut.
    let cycle = "\
#150=(REPRESENTATION_RELATIONSHIP('','',#100,#62) REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION(#151) SHAPE_REPRESENTATION_RELATIONSHIP());\n\
#151=ITEM_DEFINED_TRANSFORMATION('','',#101,#9);\n\
#160=DRAUGHTING_MODEL('',(#161),#110);#161=MAPPED_ITEM('',#162,#102);#162=REPRESENTATION_MAP(#9,#62);\n";
    let m = read(&format!("{SQUARE}{MM_DEG}{ASSEMBLY}{cycle}"));
    assert_eq!(m.occurrences.len(), 1);
    assert_eq!(m.occurrences[0].path, [120]);
    assert_eq!(m.summary.not_applied["MAPPED_ITEM"], 1);
    assert_eq!(m.summary.not_applied["ITEM_DEFINED_TRANSFORMATION"], 1);
}

#[test]
fn a_shape_mapped_into_a_shape_representation_is_placed() {
    let mapped = "\
#170=SHAPE_REPRESENTATION('top',(#171),#110);#171=MAPPED_ITEM('',#172,#101);#172=REPRESENTATION_MAP(#9,#62);\n";
    let m = read(&format!("{SQUARE}{MM_DEG}{ASSEMBLY}{mapped}"));
    let paths: Vec<&[u64]> = m.occurrences.iter().map(|o| &o.path[..]).collect();
    assert_eq!(paths, [&[120][..], &[171][..]]);
    assert_eq!(placed(&m, 1, 13), placed(&m, 0, 13));
}

#[test]
fn doubling_placements_are_cut_at_the_limit() {
    // 20 levels, each placed twice in the next: 2²⁰ paths.
    let mut text = format!("{SQUARE}{MM_DEG}");
    let mut child = 62;
    for level in 0..20u64 {
        let rep = 1000 + 10 * level;
        text += &format!("#{rep}=SHAPE_REPRESENTATION('',(#9),#70);\n");
        for k in 1..=2 {
            text += &format!(
                "#{}=(REPRESENTATION_RELATIONSHIP('','',#{child},#{rep}) REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION(#{}) SHAPE_REPRESENTATION_RELATIONSHIP());\n#{}=ITEM_DEFINED_TRANSFORMATION('','',#9,#9);\n",
                rep + 2 * k,
                rep + 2 * k + 1,
                rep + 2 * k + 1
            );
        }
        child = rep;
    }
    let m = read(&text);
    assert_eq!(m.occurrences.len(), super::MAX_OCCURRENCES);
    assert!(m
        .summary
        .invalid
        .iter()
        .any(|(id, why)| *id == 62 && why.contains("not listed")));
}
