//! How constraints are drawn: springs as coils, ropes as lines (straight
//! when taut, sagging when slack).

use clockwork2d::prelude::{Anchor, Constraint, Scalar, World};

use crate::{Canvas, Colour};

/// Where `anchor` is now, in world units (`None` for a body that is gone).
#[must_use]
pub fn anchor_position<S: Scalar>(world: &World<S>, anchor: &Anchor<S>) -> Option<(f64, f64)> {
    match *anchor {
        Anchor::Point(p) => Some(p.to_f64()),
        Anchor::Body(id) => world.body(id).map(|b| b.position().to_f64()),
        Anchor::BodyOffset(id, offset) => world.body(id).map(|b| {
            let (p, o) = (b.position().to_f64(), offset.to_f64());
            (p.0 + o.0, p.1 + o.1)
        }),
    }
}

/// Draws one constraint of `world`:
///
/// * a bendy spring: a coil from its rest point (`a + rest_offset`, marked
///   with a small ring) to `b`, and a faint line from `a` to the rest point;
/// * a radial spring: the pole from the pivot (a dot) to the body, drawn as
///   a coil;
/// * a rope: a straight line when taut (at its length, within 0.5 %), else a
///   parabola sagging downward whose arc length is the rope's length (for a
///   chord `L` and rope length `ℓ`, a parabola of sag `h` has arc length
///   ≈ `L + 8h²/(3L)`, so `h = √(3L(ℓ − L)/8)`).
pub fn draw_constraint<S: Scalar>(
    canvas: &mut Canvas,
    world: &World<S>,
    constraint: &Constraint<S>,
) {
    let (first, second) = constraint.anchors();
    let (Some(a), Some(b)) = (
        anchor_position(world, &first),
        anchor_position(world, &second),
    ) else {
        return;
    };
    match *constraint {
        Constraint::BendySpring { rest_offset, .. } => {
            let o = rest_offset.to_f64();
            let rest = (a.0 + o.0, a.1 + o.1);
            if o != (0.0, 0.0) {
                canvas.line(a, rest, 1.0, Colour::Guide);
            }
            canvas.spring(rest, b, 6, 4.0, Colour::Spring);
            canvas.dot(a, 3.0, Colour::Ink);
        }
        Constraint::RadialSpring { .. } => {
            canvas.spring(a, b, 8, 4.0, Colour::Spring);
            canvas.dot(a, 3.0, Colour::Ink);
        }
        Constraint::Rope { max_length, .. } => {
            let length = max_length.to_f64();
            let chord = ((b.0 - a.0).powi(2) + (b.1 - a.1).powi(2)).sqrt();
            if chord >= length * 0.995 || chord == 0.0 {
                canvas.line(a, b, 2.0, Colour::RopeTaut);
            } else {
                let sag = (3.0 * chord * (length - chord) / 8.0).sqrt();
                let points: Vec<(f64, f64)> = (0..=16)
                    .map(|i| {
                        let t = f64::from(i) / 16.0;
                        let drop = 4.0 * sag * t * (1.0 - t);
                        (a.0 + (b.0 - a.0) * t, a.1 + (b.1 - a.1) * t - drop)
                    })
                    .collect();
                canvas.polyline(&points, 1.5, Colour::RopeSlack);
            }
            canvas.dot(a, 2.5, Colour::Ink);
        }
    }
}
