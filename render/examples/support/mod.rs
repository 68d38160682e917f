//! What every demo shares: where its GIF goes, the recorder, and trails.
#![allow(dead_code)] // Each demo uses a different part of this module.

use std::collections::VecDeque;
use std::fs::File;
use std::io::BufWriter;
use std::path::PathBuf;

use clockwork2d_render::{Canvas, Colour, GifRecorder, RenderError, View};

/// A demo's animation being written: `docs/demos/NAME.gif` under the
/// workspace root, or the path given as the first argument.
pub struct Demo {
    path: PathBuf,
    gif: GifRecorder<BufWriter<File>>,
    view: View,
}

impl Demo {
    /// Starts the GIF of demo `name` for `view`, each frame shown for
    /// `delay` hundredths of a second.
    pub fn start(name: &str, view: View, delay: u16) -> Result<Demo, RenderError> {
        let path = std::env::args_os().nth(1).map_or_else(
            || {
                // The workspace root is the render crate's parent.
                let render = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
                let root = render.parent().map_or(render.clone(), PathBuf::from);
                root.join("docs/demos").join(format!("{name}.gif"))
            },
            PathBuf::from,
        );
        if let Some(dir) = path.parent() {
            std::fs::create_dir_all(dir)?;
        }
        let out = BufWriter::new(File::create(&path)?);
        let gif = GifRecorder::new(out, view.width, view.height, delay)?;
        Ok(Demo { path, gif, view })
    }

    /// A blank canvas for the next frame.
    pub fn canvas(&self) -> Result<Canvas, RenderError> {
        Canvas::new(self.view)
    }

    /// Adds a finished frame.
    pub fn add(&mut self, canvas: &Canvas) -> Result<(), RenderError> {
        self.gif.add_frame(canvas)
    }

    /// Writes the file and prints its size.
    pub fn finish(self) -> Result<(), RenderError> {
        let frames = self.gif.frame_count();
        self.gif
            .finish()?
            .into_inner()
            .map_err(|e| RenderError::Io(e.into_error()))?;
        let bytes = std::fs::metadata(&self.path)?.len();
        println!(
            "wrote {} ({}x{}, {frames} frames, {bytes} bytes)",
            self.path.display(),
            self.view.width,
            self.view.height
        );
        Ok(())
    }
}

/// The last `len` positions of something moving, drawn as a thin line.
pub struct Trail {
    points: VecDeque<(f64, f64)>,
    len: usize,
}

impl Trail {
    /// An empty trail of at most `len` points.
    pub fn new(len: usize) -> Trail {
        Trail {
            points: VecDeque::with_capacity(len),
            len,
        }
    }

    /// Appends a position (dropping the oldest beyond `len`).
    pub fn push(&mut self, p: (f64, f64)) {
        if self.points.len() == self.len {
            self.points.pop_front();
        }
        self.points.push_back(p);
    }

    /// Forgets every point.
    pub fn clear(&mut self) {
        self.points.clear();
    }

    /// Draws the trail.
    pub fn draw(&self, canvas: &mut Canvas, colour: Colour) {
        let points: Vec<(f64, f64)> = self.points.iter().copied().collect();
        if points.len() >= 2 {
            canvas.polyline(&points, 1.0, colour);
        }
    }
}

/// `Vec2` from two `f64` literals (converted once, at the edge).
pub fn v(x: f64, y: f64) -> clockwork2d::prelude::Vec2 {
    clockwork2d::prelude::Vec2::new(clockwork2d::prelude::fx(x), clockwork2d::prelude::fx(y))
}
