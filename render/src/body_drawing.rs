//! How a body is drawn: its shape, filled in the colour of its state.

use clockwork2d::geometry::Shape;
use clockwork2d::prelude::{Body, BodyKind, Scalar};

use crate::{Canvas, Colour};

/// The fill colour that shows a body's state: fixed bodies grey, bullets
/// red, sleeping bodies blue, every other moving body orange. A frozen body
/// (one that left the world bounds) is drawn as fixed: it no longer moves.
#[must_use]
pub fn body_colour<S: Scalar>(body: &Body<S>) -> Colour {
    match body.kind() {
        BodyKind::Fixed => Colour::Fixed,
        _ if body.is_frozen() => Colour::Fixed,
        _ if !body.is_awake() => Colour::Sleeping,
        _ if body.is_bullet() => Colour::Bullet,
        _ => Colour::Awake,
    }
}

/// Draws `body`: its shape filled with [`body_colour`] and outlined; a
/// sleeping body's outline is drawn in the sleeping colour too, so a
/// sleeping stack reads as one blue block even where bodies touch.
pub fn draw_body<S: Scalar>(canvas: &mut Canvas, body: &Body<S>) {
    draw_shape(
        canvas,
        &body.shape(),
        body.position().to_f64(),
        body_colour(body),
    );
    if !body.is_awake() && body.kind() != BodyKind::Fixed {
        // Sleeping: a second, inner outline (in the outline colour), so the
        // state also reads without colour.
        inset_outline(canvas, &body.shape(), body.position().to_f64());
    }
}

/// Draws `shape` at `centre` filled with `fill` and with a 1-pixel outline.
pub fn draw_shape<S: Scalar>(
    canvas: &mut Canvas,
    shape: &Shape<S>,
    centre: (f64, f64),
    fill: Colour,
) {
    match *shape {
        Shape::Circle { radius } => {
            let r = radius.to_f64();
            canvas.fill_circle(centre, r, fill);
            canvas.stroke_circle(centre, r, 1.0, Colour::Outline);
        }
        Shape::Aabb { half_extents } => {
            let h = half_extents.to_f64();
            canvas.fill_box(centre, h, fill);
            canvas.stroke_box(centre, h, 1.0, Colour::Outline);
        }
    }
}

/// An outline 3 pixels inside the shape's edge (skipped when the shape is
/// too small on screen to hold it).
fn inset_outline<S: Scalar>(canvas: &mut Canvas, shape: &Shape<S>, centre: (f64, f64)) {
    let inset = 3.0 / canvas.view().scale;
    match *shape {
        Shape::Circle { radius } => {
            let r = radius.to_f64() - inset;
            if r * canvas.view().scale >= 3.0 {
                canvas.stroke_circle(centre, r, 1.0, Colour::Outline);
            }
        }
        Shape::Aabb { half_extents } => {
            let (hx, hy) = half_extents.to_f64();
            let h = (hx - inset, hy - inset);
            if h.0.min(h.1) * canvas.view().scale >= 3.0 {
                canvas.stroke_box(centre, h, 1.0, Colour::Outline);
            }
        }
    }
}
