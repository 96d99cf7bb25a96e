//! `mesh FILE... -o OUT.obj|OUT.stl|OUT.ply [--density N] [--scalar exact|f64]`.

use super::{charge_each, load_all_exact, on_exact, patch_f64, ExactScalar, ScalarKind};
use exact_bezier::io::Patch;
use exact_bezier::limits::MAX_MESH_VERTICES;
use exact_bezier::render::mesh::Mesh;
use exact_bezier::Error;
use serde_json::{json, Value};

/// Arguments of `mesh`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Input files (JSON) of rect and tri patches; all go into one mesh.
    #[arg(required = true)]
    files: Vec<String>,
    /// Output file: .obj (with vertex normals), .stl (ASCII, facet normals) or .ply (ASCII, vertex normals).
    #[arg(short, long)]
    output: String,
    /// Steps per parameter: (N+1)² vertices per rect patch, (N+1)(N+2)/2 per tri patch.
    #[arg(long, default_value_t = 32)]
    density: usize,
    /// Scalar for points and normals (exact: computed exactly, then rounded).
    #[arg(long, value_enum, default_value = "f64")]
    scalar: ScalarKind,
}

/// Write the mesh; reports `{"output", "vertices", "triangles"}`.
pub fn run(a: &Args) -> Result<Value, Error> {
    on_exact!(load_all_exact(&a.files)?, patches => mesh_of(a, &patches))
}

/// Mesh `patches` and write the output file of `a`.
fn mesh_of<T: ExactScalar>(a: &Args, patches: &[Patch<T>]) -> Result<Value, Error> {
    let n1 = a.density as u64 + 1;
    let vertices = patches.len() as u64 * n1 * n1;
    if vertices > MAX_MESH_VERTICES {
        return Err(Error::Limit(format!(
            "{} patches at --density {} give about {vertices} vertices, over the limit of {MAX_MESH_VERTICES}",
            patches.len(),
            a.density
        )));
    }
    // A point, two partial derivatives and a normal per vertex, at
    // parameters i/N (measured: about 4 evaluations' work).
    let param_bits = 2 * (64 - n1.leading_zeros() as u64);
    charge_each("mesh", patches, a.scalar, |s| {
        let (ops, bits) = (
            12 * s.eval_ops(),
            s.grown_bits(s.total_degree(), param_bits),
        );
        (ops.saturating_mul(n1 * n1), bits)
    })?;
    let mesh = match a.scalar {
        ScalarKind::Exact => Mesh::from_patches(patches, a.density)?,
        ScalarKind::F64 => {
            let pf = patches
                .iter()
                .map(patch_f64)
                .collect::<Result<Vec<_>, _>>()?;
            Mesh::from_patches(&pf, a.density)?
        }
    };
    let lower = a.output.to_ascii_lowercase();
    let text = match lower.rsplit('.').next() {
        Some("obj") => mesh.to_obj(),
        Some("stl") => mesh.to_stl(),
        Some("ply") => mesh.to_ply(),
        _ => {
            return Err(Error::Format(format!(
                "the output {:?} must end in .obj, .stl or .ply",
                a.output
            )))
        }
    };
    super::plot::write_output(&a.output, text.as_bytes())?;
    Ok(json!({
        "output": a.output,
        "vertices": mesh.positions.len(),
        "triangles": mesh.triangles.len(),
    }))
}
