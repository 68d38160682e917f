//! How a whole world is drawn, and the view that fits it.

use clockwork2d::prelude::{Scalar, World};

use crate::{Canvas, RenderError, View, contact_points, draw_body, draw_constraint, draw_contact};

/// Contacts are drawn only between bodies at least this many pixels in
/// half-size on screen.
pub const MIN_CONTACT_BODY_PX: f64 = 4.0;

/// What [`draw_world`] draws. Everything by default.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Layers {
    /// Bodies (sleeping ones in their own colour).
    pub bodies: bool,
    /// Touching pairs: closest points and normal (for bodies of at least
    /// [`MIN_CONTACT_BODY_PX`] half-size on screen).
    pub contacts: bool,
    /// Springs and ropes.
    pub constraints: bool,
    /// Length of a drawn normal, in pixels.
    pub normal_length: f32,
}

impl Default for Layers {
    fn default() -> Self {
        Layers {
            bodies: true,
            contacts: true,
            constraints: true,
            normal_length: 10.0,
        }
    }
}

/// Draws `world` on `canvas` (over what is there): bodies in id order, then
/// constraints, then the contacts of the pairs that touched in the last
/// step, so the markers stay on top.
pub fn draw_world<S: Scalar>(canvas: &mut Canvas, world: &World<S>, layers: &Layers) {
    if layers.bodies {
        for (_, body) in world.bodies() {
            draw_body(canvas, body);
        }
    }
    if layers.constraints {
        for (_, constraint) in world.constraints() {
            draw_constraint(canvas, world, constraint);
        }
    }
    if layers.contacts {
        for (a, b) in world.touching_pairs() {
            if let (Some(a), Some(b)) = (world.body(a), world.body(b)) {
                // Markers larger than the bodies would bury a dense scene
                // (a pyramid seen whole): skip pairs with a body under
                // 4 pixels in half-size on screen.
                let smallest = |body: &clockwork2d::prelude::Body<S>| {
                    let (hx, hy) = body.shape().half_extents().to_f64();
                    hx.min(hy) * canvas.view().scale
                };
                if smallest(a).min(smallest(b)) < MIN_CONTACT_BODY_PX {
                    continue;
                }
                let points = contact_points(&a.shape(), a.position(), &b.shape(), b.position());
                draw_contact(canvas, &points, layers.normal_length);
            }
        }
    }
}

/// The bounding box of every body of `world` (`None` for an empty world),
/// in world units: `(min, max)`.
#[must_use]
pub fn world_extent<S: Scalar>(world: &World<S>) -> Option<((f64, f64), (f64, f64))> {
    world.bodies().fold(None, |extent, (_, body)| {
        let b = body.aabb();
        let (lo, hi) = (b.min().to_f64(), b.max().to_f64());
        Some(match extent {
            None => (lo, hi),
            Some((min, max)) => (
                (lo.0.min(min.0), lo.1.min(min.1)),
                (hi.0.max(max.0), hi.1.max(max.1)),
            ),
        })
    })
}

/// A `width × height` view showing every body of `world` with an 8-pixel
/// margin.
///
/// # Errors
/// [`RenderError::EmptyWorld`] when the world has no body to frame.
pub fn view_of_world<S: Scalar>(
    world: &World<S>,
    width: u32,
    height: u32,
) -> Result<View, RenderError> {
    let (min, max) = world_extent(world).ok_or(RenderError::EmptyWorld)?;
    Ok(View::fit(min, max, width, height, 8))
}
