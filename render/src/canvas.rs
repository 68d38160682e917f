//! [`Canvas`]: a picture being drawn, in world coordinates.

use tiny_skia::{FillRule, Paint, PathBuilder, Pixmap, Rect, Stroke, Transform};

use crate::{Colour, RenderError, View};

/// The largest picture side, in pixels (a typo such as `--width 100000`
/// must not allocate gigabytes).
pub const MAX_SIDE: u32 = 4096;

/// A picture: a pixel buffer and the [`View`] that places the world on it.
/// Every shape is drawn in one palette [`Colour`], without anti-aliasing,
/// so each pixel is exactly one palette colour.
pub struct Canvas {
    pixmap: Pixmap,
    view: View,
}

impl Canvas {
    /// A canvas for `view`, cleared to the background colour.
    ///
    /// # Errors
    /// [`RenderError::BadSize`] when a side is zero or above [`MAX_SIDE`].
    pub fn new(view: View) -> Result<Canvas, RenderError> {
        let (w, h) = (view.width, view.height);
        if w == 0 || h == 0 || w > MAX_SIDE || h > MAX_SIDE {
            return Err(RenderError::BadSize {
                width: w,
                height: h,
            });
        }
        let pixmap = Pixmap::new(w, h).ok_or(RenderError::BadSize {
            width: w,
            height: h,
        })?;
        let mut canvas = Canvas { pixmap, view };
        canvas.clear(Colour::Background);
        Ok(canvas)
    }

    /// The view.
    #[must_use]
    pub fn view(&self) -> &View {
        &self.view
    }

    /// Width in pixels.
    #[must_use]
    pub fn width(&self) -> u32 {
        self.pixmap.width()
    }

    /// Height in pixels.
    #[must_use]
    pub fn height(&self) -> u32 {
        self.pixmap.height()
    }

    /// Fills the whole picture with `colour`.
    pub fn clear(&mut self, colour: Colour) {
        let [r, g, b] = colour.rgb();
        self.pixmap.fill(tiny_skia::Color::from_rgba8(r, g, b, 255));
    }

    /// The colour of pixel `(x, y)` (`None` outside the picture).
    #[must_use]
    pub fn colour_at(&self, x: u32, y: u32) -> Option<Colour> {
        let p = self.pixmap.pixel(x, y)?;
        Some(Colour::nearest([p.red(), p.green(), p.blue()]))
    }

    /// The colour at the pixel showing world point `p`.
    #[must_use]
    pub fn colour_at_world(&self, p: (f64, f64)) -> Option<Colour> {
        let (x, y) = self.view.to_pixel(p);
        if x < 0.0 || y < 0.0 {
            return None;
        }
        // Truncation picks the pixel containing the point.
        self.colour_at(x as u32, y as u32)
    }

    /// Every pixel as a palette index, row by row (the GIF frame).
    #[must_use]
    pub fn indices(&self) -> Vec<u8> {
        self.pixmap
            .pixels()
            .iter()
            .map(|p| Colour::nearest([p.red(), p.green(), p.blue()]).index())
            .collect()
    }

    /// Every pixel as RGB, row by row (the PNG image).
    #[must_use]
    pub fn rgb(&self) -> Vec<u8> {
        self.pixmap
            .pixels()
            .iter()
            .flat_map(|p| [p.red(), p.green(), p.blue()])
            .collect()
    }

    /// A filled circle of world radius `radius` (at least half a pixel, so
    /// a tiny body stays visible).
    pub fn fill_circle(&mut self, centre: (f64, f64), radius: f64, colour: Colour) {
        let (x, y) = self.view.to_pixel(centre);
        let r = self.view.to_pixels(radius).max(0.5);
        if let Some(path) = PathBuilder::from_circle(x, y, r) {
            self.pixmap.fill_path(
                &path,
                &paint(colour),
                FillRule::Winding,
                Transform::identity(),
                None,
            );
        }
    }

    /// A circle outline of world radius `radius`, `width` pixels wide.
    pub fn stroke_circle(&mut self, centre: (f64, f64), radius: f64, width: f32, colour: Colour) {
        let (x, y) = self.view.to_pixel(centre);
        let r = self.view.to_pixels(radius).max(0.5);
        if let Some(path) = PathBuilder::from_circle(x, y, r) {
            self.stroke_path(&path, width, colour);
        }
    }

    /// A filled circle of `radius` pixels (a marker whose size does not
    /// depend on the zoom).
    pub fn dot(&mut self, centre: (f64, f64), radius: f32, colour: Colour) {
        let (x, y) = self.view.to_pixel(centre);
        if let Some(path) = PathBuilder::from_circle(x, y, radius.max(0.5)) {
            self.pixmap.fill_path(
                &path,
                &paint(colour),
                FillRule::Winding,
                Transform::identity(),
                None,
            );
        }
    }

    /// A filled axis-aligned box, given its centre and half extents.
    pub fn fill_box(&mut self, centre: (f64, f64), half: (f64, f64), colour: Colour) {
        if let Some(rect) = self.pixel_rect(centre, half) {
            self.pixmap
                .fill_rect(rect, &paint(colour), Transform::identity(), None);
        }
    }

    /// A box outline, `width` pixels wide.
    pub fn stroke_box(&mut self, centre: (f64, f64), half: (f64, f64), width: f32, colour: Colour) {
        if let Some(rect) = self.pixel_rect(centre, half) {
            let path = PathBuilder::from_rect(rect);
            self.stroke_path(&path, width, colour);
        }
    }

    /// A straight line from `a` to `b`, `width` pixels wide.
    pub fn line(&mut self, a: (f64, f64), b: (f64, f64), width: f32, colour: Colour) {
        self.polyline(&[a, b], width, colour);
    }

    /// A line through `points`, `width` pixels wide.
    pub fn polyline(&mut self, points: &[(f64, f64)], width: f32, colour: Colour) {
        let mut builder = PathBuilder::new();
        for (i, &p) in points.iter().enumerate() {
            let (x, y) = self.view.to_pixel(p);
            if i == 0 {
                builder.move_to(x, y);
            } else {
                builder.line_to(x, y);
            }
        }
        if let Some(path) = builder.finish() {
            self.stroke_path(&path, width, colour);
        }
    }

    /// A dashed line from `a` to `b`: dashes and gaps of `dash` pixels.
    pub fn dashed_line(
        &mut self,
        a: (f64, f64),
        b: (f64, f64),
        width: f32,
        dash: f32,
        colour: Colour,
    ) {
        let (pa, pb) = (self.view.to_pixel(a), self.view.to_pixel(b));
        let mut builder = PathBuilder::new();
        builder.move_to(pa.0, pa.1);
        builder.line_to(pb.0, pb.1);
        let Some(path) = builder.finish() else {
            return;
        };
        let mut stroke = Stroke {
            width,
            ..Stroke::default()
        };
        stroke.dash = tiny_skia::StrokeDash::new(vec![dash, dash], 0.0);
        self.pixmap
            .stroke_path(&path, &paint(colour), &stroke, Transform::identity(), None);
    }

    /// An arrow from world point `from` along the unit world direction
    /// `direction`, `length` pixels long, with a head: how normals are drawn.
    pub fn arrow(&mut self, from: (f64, f64), direction: (f64, f64), length: f32, colour: Colour) {
        let (x0, y0) = self.view.to_pixel(from);
        // Pixel y points down.
        let (dx, dy) = (direction.0 as f32, -(direction.1 as f32));
        let norm = (dx * dx + dy * dy).sqrt();
        if !norm.is_finite() || norm == 0.0 {
            return;
        }
        let (ux, uy) = (dx / norm, dy / norm);
        let (x1, y1) = (x0 + ux * length, y0 + uy * length);
        let head = (length * 0.35).clamp(3.0, 7.0);
        let mut builder = PathBuilder::new();
        builder.move_to(x0, y0);
        builder.line_to(x1, y1);
        builder.move_to(
            x1 - ux * head - uy * head * 0.6,
            y1 - uy * head + ux * head * 0.6,
        );
        builder.line_to(x1, y1);
        builder.line_to(
            x1 - ux * head + uy * head * 0.6,
            y1 - uy * head - ux * head * 0.6,
        );
        if let Some(path) = builder.finish() {
            self.stroke_path(&path, 1.5, colour);
        }
    }

    /// A coil spring from `a` to `b`: a zigzag of `coils` teeth, `amplitude`
    /// pixels to each side, with short straight leads at both ends.
    pub fn spring(
        &mut self,
        a: (f64, f64),
        b: (f64, f64),
        coils: u32,
        amplitude: f32,
        colour: Colour,
    ) {
        let (pa, pb) = (self.view.to_pixel(a), self.view.to_pixel(b));
        let (dx, dy) = (pb.0 - pa.0, pb.1 - pa.1);
        let length = (dx * dx + dy * dy).sqrt();
        if !length.is_finite() || length < 1.0 {
            return;
        }
        let (ux, uy) = (dx / length, dy / length);
        let (nx, ny) = (-uy, ux);
        let lead = 0.15 * length;
        let teeth = 2 * coils.max(1);
        let mut builder = PathBuilder::new();
        builder.move_to(pa.0, pa.1);
        builder.line_to(pa.0 + ux * lead, pa.1 + uy * lead);
        for i in 0..teeth {
            let t = lead + (length - 2.0 * lead) * (i as f32 + 0.5) / teeth as f32;
            let side = if i % 2 == 0 { amplitude } else { -amplitude };
            builder.line_to(pa.0 + ux * t + nx * side, pa.1 + uy * t + ny * side);
        }
        builder.line_to(pb.0 - ux * lead, pb.1 - uy * lead);
        builder.line_to(pb.0, pb.1);
        if let Some(path) = builder.finish() {
            self.stroke_path(&path, 1.5, colour);
        }
    }

    /// A thin horizontal bar along the bottom edge, filled to `fraction`
    /// (0..=1) of the width: how far through its run an animation is.
    pub fn progress_bar(&mut self, fraction: f64, colour: Colour) {
        let w = f64::from(self.width()) * fraction.clamp(0.0, 1.0);
        let h = self.height() as f32;
        if let Some(rect) = Rect::from_xywh(0.0, h - 3.0, w as f32, 3.0) {
            self.pixmap
                .fill_rect(rect, &paint(colour), Transform::identity(), None);
        }
    }

    fn pixel_rect(&self, centre: (f64, f64), half: (f64, f64)) -> Option<Rect> {
        let (x0, y0) = self.view.to_pixel((centre.0 - half.0, centre.1 + half.1));
        let (x1, y1) = self.view.to_pixel((centre.0 + half.0, centre.1 - half.1));
        // At least one pixel wide and high, so thin walls stay visible.
        Rect::from_ltrb(x0, y0, x1.max(x0 + 1.0), y1.max(y0 + 1.0))
    }

    fn stroke_path(&mut self, path: &tiny_skia::Path, width: f32, colour: Colour) {
        let stroke = Stroke {
            width,
            ..Stroke::default()
        };
        self.pixmap
            .stroke_path(path, &paint(colour), &stroke, Transform::identity(), None);
    }
}

/// A solid, aliased paint: every covered pixel gets exactly `colour`.
fn paint(colour: Colour) -> Paint<'static> {
    let [r, g, b] = colour.rgb();
    let mut paint = Paint::default();
    paint.set_color_rgba8(r, g, b, 255);
    paint.anti_alias = false;
    paint
}
