//! Rasterizing our SVG to PNG with `resvg` (pure Rust, built without its
//! text feature: no fonts are loaded, so `<text>` labels appear in the SVG
//! only; the PNG shows weights by control-point size).

use crate::error::Error;
use resvg::{tiny_skia, usvg};

/// The PNG bytes of an SVG document, at the document's own pixel size.
///
/// # Errors
///
/// [`Error::Format`] if the SVG cannot be parsed or the size is zero.
pub(crate) fn rasterize(svg: &str) -> Result<Vec<u8>, Error> {
    let tree = usvg::Tree::from_str(svg, &usvg::Options::default())
        .map_err(|e| Error::Format(format!("cannot read the SVG to rasterize: {e}")))?;
    let size = tree.size().to_int_size();
    let mut pixmap = tiny_skia::Pixmap::new(size.width(), size.height())
        .ok_or_else(|| Error::Format("cannot rasterize an empty picture".into()))?;
    resvg::render(
        &tree,
        tiny_skia::Transform::identity(),
        &mut pixmap.as_mut(),
    );
    pixmap
        .encode_png()
        .map_err(|e| Error::Format(format!("cannot encode the PNG: {e}")))
}
