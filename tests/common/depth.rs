//! How deep two shapes overlap, measured in f64 from their read-back
//! centres and sizes (positive: overlapping; negative: the gap between
//! them, exact for two circles and a circle and a box, the larger of the
//! two axis gaps for two boxes).

use clockwork2d::prelude::*;

/// Half extents of a shape's bounding box (a circle's radius on both axes).
pub fn half_extents(shape: Shape) -> (f64, f64) {
    match shape {
        Shape::Circle { radius } => (radius.to_f64(), radius.to_f64()),
        Shape::Aabb { half_extents } => half_extents.to_f64(),
    }
}

/// Depth of the circle of radius `r` at `c` in the box of `half` extents
/// at `p`: `r` minus the distance from the centre to the box, the distance
/// counted negative inside (to the nearest face).
pub fn circle_box_depth(c: (f64, f64), r: f64, p: (f64, f64), half: (f64, f64)) -> f64 {
    let (dx, dy) = ((c.0 - p.0).abs() - half.0, (c.1 - p.1).abs() - half.1);
    let outside = dx.max(0.0).hypot(dy.max(0.0));
    let inside = dx.max(dy).min(0.0);
    r - (outside + inside)
}

/// Overlap of the boxes of half extents `a` at `p` and `b` at `q`: the
/// smaller of the x and y overlaps (how far one must move to separate
/// them).
pub fn box_box_depth(p: (f64, f64), a: (f64, f64), q: (f64, f64), b: (f64, f64)) -> f64 {
    let ox = a.0 + b.0 - (p.0 - q.0).abs();
    let oy = a.1 + b.1 - (p.1 - q.1).abs();
    ox.min(oy)
}

/// Depth of the overlap of shape `sa` at `pa` and shape `sb` at `pb`.
pub fn shape_depth(sa: Shape, pa: (f64, f64), sb: Shape, pb: (f64, f64)) -> f64 {
    match (sa, sb) {
        (Shape::Circle { radius: ra }, Shape::Circle { radius: rb }) => {
            ra.to_f64() + rb.to_f64() - (pb.0 - pa.0).hypot(pb.1 - pa.1)
        }
        (Shape::Aabb { .. }, Shape::Aabb { .. }) => {
            box_box_depth(pa, half_extents(sa), pb, half_extents(sb))
        }
        (Shape::Circle { radius }, Shape::Aabb { .. }) => {
            circle_box_depth(pa, radius.to_f64(), pb, half_extents(sb))
        }
        (Shape::Aabb { .. }, Shape::Circle { radius }) => {
            circle_box_depth(pb, radius.to_f64(), pa, half_extents(sa))
        }
    }
}
