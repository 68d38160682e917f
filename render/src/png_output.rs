//! Writing one picture as a PNG.

use std::io::Write;

use crate::{Canvas, Colour, RenderError};

/// Writes `canvas` to `out` as an 8-bit indexed PNG with the 16-colour
/// palette (every pixel is a palette colour, so this is lossless).
///
/// # Errors
/// [`RenderError::Io`] or [`RenderError::Encode`] when writing fails.
pub fn write_png<W: Write>(canvas: &Canvas, out: W) -> Result<(), RenderError> {
    let mut encoder = png::Encoder::new(out, canvas.width(), canvas.height());
    encoder.set_color(png::ColorType::Indexed);
    encoder.set_depth(png::BitDepth::Eight);
    encoder.set_palette(Colour::gif_palette());
    encoder.set_compression(png::Compression::High);
    let mut writer = encoder.write_header()?;
    writer.write_image_data(&canvas.indices())?;
    writer.finish()?;
    Ok(())
}
