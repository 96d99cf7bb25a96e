//! Pictures and meshes of curves and patches (feature `render`): SVG and
//! PNG drawings ([`plot`]) and triangle meshes with exact normals ([`Mesh`]).

pub mod mesh;
pub mod plot;

pub use mesh::{curve_jet, normal_direction, rect_jet, tri_jet, Jet, Mesh};
