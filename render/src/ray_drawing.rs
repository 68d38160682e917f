//! How a ray cast is drawn: the ray up to its hit, the hit point and the
//! surface normal there.

use clockwork2d::geometry::{Ray, RayHit};
use clockwork2d::prelude::Scalar;

use crate::{Canvas, Colour};

/// Draws `ray`: a line from its origin to the hit point (or dashed to its
/// full length when nothing is hit), the hit as a dot and the surface normal
/// as an arrow of `normal_length` pixels.
pub fn draw_ray<S: Scalar>(
    canvas: &mut Canvas,
    ray: &Ray<S>,
    hit: Option<&RayHit<S>>,
    normal_length: f32,
) {
    let origin = ray.origin.to_f64();
    canvas.dot(origin, 2.0, Colour::Ray);
    match hit {
        Some(hit) => {
            let point = hit.point.to_f64();
            canvas.line(origin, point, 1.0, Colour::Ray);
            canvas.arrow(point, hit.normal.to_f64(), normal_length, Colour::Normal);
            canvas.dot(point, 3.0, Colour::Hit);
        }
        None => {
            let end = ray.point_at(ray.max_distance).to_f64();
            canvas.dashed_line(origin, end, 1.0, 3.0, Colour::Ray);
        }
    }
}
