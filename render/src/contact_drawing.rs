//! How a contact is drawn: the two closest points and the normal.

use clockwork2d::prelude::Scalar;

use crate::{Canvas, Colour, ContactPoints};

/// Draws a contact: a segment between the closest points (the penetration
/// or the gap), a dot on each, and the normal as an arrow of `normal_length`
/// pixels from `a`'s point (it points from `a` to `b`).
pub fn draw_contact<S: Scalar>(canvas: &mut Canvas, points: &ContactPoints<S>, normal_length: f32) {
    canvas.line(points.on_a, points.on_b, 1.0, Colour::ContactPoint);
    canvas.arrow(
        points.on_a,
        points.contact.normal.to_f64(),
        normal_length,
        Colour::Normal,
    );
    canvas.dot(points.on_a, 2.5, Colour::ContactPoint);
    canvas.dot(points.on_b, 2.5, Colour::ContactPoint);
}
