//! [`render_run`]: simulate a world and write what it does to a file.

use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::Path;

use clockwork2d::prelude::{Scalar, World};

use crate::{
    Canvas, GifRecorder, Layers, OutputFormat, RenderError, draw_world, view_of_world, write_png,
};

/// How [`render_run`] films a world.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RenderOptions {
    /// Ticks to simulate.
    pub ticks: u64,
    /// A GIF frame every this many ticks (≥ 1); unused for a PNG.
    pub every: u64,
    /// Picture width in pixels.
    pub width: u32,
    /// Picture height in pixels.
    pub height: u32,
    /// What to draw.
    pub layers: Layers,
}

impl Default for RenderOptions {
    fn default() -> Self {
        RenderOptions {
            ticks: 300,
            every: 2,
            width: 480,
            height: 320,
            layers: Layers::default(),
        }
    }
}

/// What [`render_run`] wrote.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RenderSummary {
    /// GIF or PNG.
    pub format: OutputFormat,
    /// Frames in the file (1 for a PNG; identical consecutive GIF frames
    /// count once).
    pub frames: u32,
    /// The world's tick when the last picture was drawn.
    pub final_tick: u64,
}

/// Steps `world` `options.ticks` times and writes `path`: a GIF with a frame
/// at the start and every `options.every` ticks (and at the end), each
/// shown for that much simulated time, or, for a `.png` path, a PNG of the
/// final state. The view is fitted to the bodies at the start and kept.
/// `progress` is called after every tick with the number of ticks done.
///
/// Everything that can be checked before simulating is checked first, and
/// nothing is written then: the file's format, the picture size, the frame
/// interval and that the world has bodies to frame.
///
/// # Errors
/// [`RenderError::UnsupportedFormat`], [`RenderError::BadSize`],
/// [`RenderError::BadFrameInterval`], [`RenderError::EmptyWorld`]
/// before anything is done; [`RenderError::Io`] / [`RenderError::Encode`]
/// when writing fails.
pub fn render_run<S: Scalar>(
    world: &mut World<S>,
    options: &RenderOptions,
    path: &Path,
    mut progress: impl FnMut(u64),
) -> Result<RenderSummary, RenderError> {
    let format = OutputFormat::from_path(path)?;
    if options.every == 0 {
        return Err(RenderError::BadFrameInterval);
    }
    let view = view_of_world(world, options.width, options.height)?;
    // Checks the size before the file is created.
    let mut canvas = Canvas::new(view)?;
    let out = BufWriter::new(File::create(path)?);
    match format {
        OutputFormat::Png => {
            for done in 1..=options.ticks {
                world.step();
                progress(done);
            }
            draw_world(&mut canvas, world, &options.layers);
            let mut out = out;
            write_png(&canvas, &mut out)?;
            out.flush()?;
            Ok(RenderSummary {
                format,
                frames: 1,
                final_tick: world.tick(),
            })
        }
        OutputFormat::Gif => {
            // GIF delays are in hundredths of a second: every·dt·100,
            // rounded, at least 1.
            let seconds = world.settings().dt.to_f64() * options.every as f64;
            let delay = (seconds * 100.0).round().clamp(1.0, f64::from(u16::MAX)) as u16;
            let mut gif = GifRecorder::new(out, view.width, view.height, delay)?;
            draw_world(&mut canvas, world, &options.layers);
            gif.add_frame(&canvas)?;
            for done in 1..=options.ticks {
                world.step();
                progress(done);
                if done.is_multiple_of(options.every) || done == options.ticks {
                    canvas.clear(crate::Colour::Background);
                    draw_world(&mut canvas, world, &options.layers);
                    gif.add_frame(&canvas)?;
                }
            }
            let frames = gif.frame_count();
            gif.finish()?.flush()?;
            Ok(RenderSummary {
                format,
                frames,
                final_tick: world.tick(),
            })
        }
    }
}
