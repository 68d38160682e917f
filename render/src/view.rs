//! [`View`]: which rectangle of the world a picture shows.

/// Maps world coordinates (units, y up) to pixel coordinates (y down): a
/// uniform scale and an offset, so circles stay round.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct View {
    /// Picture width in pixels.
    pub width: u32,
    /// Picture height in pixels.
    pub height: u32,
    /// Pixels per world unit.
    pub scale: f64,
    /// The world point at the picture's centre.
    pub centre: (f64, f64),
}

impl View {
    /// The view of `width × height` pixels that shows the world rectangle
    /// `[min, max]` as large as fits, centred, with `margin` pixels kept free
    /// on every side. A degenerate rectangle (zero or non-finite size) is
    /// shown at one pixel per unit around its centre.
    #[must_use]
    pub fn fit(min: (f64, f64), max: (f64, f64), width: u32, height: u32, margin: u32) -> View {
        let free_w = f64::from(width.saturating_sub(2 * margin).max(1));
        let free_h = f64::from(height.saturating_sub(2 * margin).max(1));
        let (span_x, span_y) = (max.0 - min.0, max.1 - min.1);
        let scale = (free_w / span_x).min(free_h / span_y);
        let scale = if scale.is_finite() && scale > 0.0 {
            scale
        } else {
            (free_w / span_x.max(span_y)).clamp(f64::MIN_POSITIVE, 1.0)
        };
        let centre = ((min.0 + max.0) / 2.0, (min.1 + max.1) / 2.0);
        let centre = if centre.0.is_finite() && centre.1.is_finite() {
            centre
        } else {
            (0.0, 0.0)
        };
        View {
            width,
            height,
            scale,
            centre,
        }
    }

    /// The pixel position of world point `p` (pixel centres are at `+0.5`).
    #[must_use]
    pub fn to_pixel(&self, p: (f64, f64)) -> (f32, f32) {
        let x = f64::from(self.width) / 2.0 + (p.0 - self.centre.0) * self.scale;
        let y = f64::from(self.height) / 2.0 - (p.1 - self.centre.1) * self.scale;
        // Pixel coordinates far outside the picture are clamped: tiny-skia
        // works in f32 and a body frozen at the world bounds must not turn
        // into an infinite path.
        (clamp_px(x), clamp_px(y))
    }

    /// A world length in pixels.
    #[must_use]
    pub fn to_pixels(&self, length: f64) -> f32 {
        clamp_px(length * self.scale)
    }

    /// The world point at pixel `(x, y)`.
    #[must_use]
    pub fn to_world(&self, x: f64, y: f64) -> (f64, f64) {
        (
            self.centre.0 + (x - f64::from(self.width) / 2.0) / self.scale,
            self.centre.1 - (y - f64::from(self.height) / 2.0) / self.scale,
        )
    }
}

/// Limits a pixel coordinate to ±2²⁰ (far outside any picture, still exact
/// in f32) and maps NaN to the far-off value.
fn clamp_px(v: f64) -> f32 {
    const FAR: f64 = 1_048_576.0;
    if v.is_nan() {
        return FAR as f32;
    }
    v.clamp(-FAR, FAR) as f32
}
