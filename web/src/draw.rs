//! Flat draw lists for the page's canvas: the world's bodies, constraints
//! and touching pairs as `f32` records (floats only here, at the edge: each
//! value is one conversion from `Fx`, no arithmetic).

use clockwork2d::geometry::Shape;
use clockwork2d::prelude::{Anchor, BodyKind, Constraint, Fx, Vec2, World};

/// Numbers per body in [`Playground::bodies`](crate::Playground::bodies):
/// `[shape, x, y, half_x, half_y, kind, state]` with shape 0 = circle
/// (`half_x = half_y` = radius), 1 = box; kind 0 = fixed, 1 = kinematic,
/// 2 = dynamic; state 0 = awake, 1 = asleep, 2 = frozen (left the world
/// bounds).
pub const BODY_STRIDE: usize = 7;

/// Numbers per constraint in
/// [`Playground::constraints`](crate::Playground::constraints):
/// `[kind, ax, ay, bx, by, length]` with kind 0 = bendy spring (length 0),
/// 1 = radial spring (rest length), 2 = rope (its length); `a`, `b` the
/// anchors' world positions.
pub const CONSTRAINT_STRIDE: usize = 6;

fn f(value: Fx) -> f32 {
    value.to_num::<f32>()
}

/// Every body, in id order, [`BODY_STRIDE`] numbers each.
pub(crate) fn bodies(world: &World) -> Vec<f32> {
    let mut out = Vec::with_capacity(world.body_count() * BODY_STRIDE);
    for (_, body) in world.bodies() {
        let p = body.position();
        let (shape, half) = match body.shape() {
            Shape::Circle { radius } => (0.0, Vec2::new(radius, radius)),
            Shape::Aabb { half_extents } => (1.0, half_extents),
        };
        let kind = match body.kind() {
            BodyKind::Fixed => 0.0,
            BodyKind::Kinematic => 1.0,
            BodyKind::Dynamic => 2.0,
        };
        let state = if body.is_frozen() {
            2.0
        } else if body.is_awake() {
            0.0
        } else {
            1.0
        };
        out.extend_from_slice(&[shape, f(p.x), f(p.y), f(half.x), f(half.y), kind, state]);
    }
    out
}

/// Where an anchor is now (`None` for a body that is gone).
pub(crate) fn anchor_position(world: &World, anchor: Anchor) -> Option<Vec2> {
    match anchor {
        Anchor::Point(p) => Some(p),
        Anchor::Body(id) => world.body(id).map(|b| b.position()),
        Anchor::BodyOffset(id, offset) => world.body(id).map(|b| b.position() + offset),
    }
}

/// Every constraint, in id order, [`CONSTRAINT_STRIDE`] numbers each.
pub(crate) fn constraints(world: &World) -> Vec<f32> {
    let mut out = Vec::new();
    for (_, constraint) in world.constraints() {
        let (a, b) = constraint.anchors();
        let (Some(a), Some(b)) = (anchor_position(world, a), anchor_position(world, b)) else {
            continue;
        };
        let (kind, length) = match *constraint {
            Constraint::BendySpring { .. } => (0.0, 0.0),
            Constraint::RadialSpring { rest_length, .. } => (1.0, f(rest_length)),
            Constraint::Rope { max_length, .. } => (2.0, f(max_length)),
        };
        out.extend_from_slice(&[kind, f(a.x), f(a.y), f(b.x), f(b.y), length]);
    }
    out
}

/// The centres of every touching pair, `[ax, ay, bx, by]` each.
pub(crate) fn contacts(world: &World) -> Vec<f32> {
    let mut out = Vec::new();
    for (a, b) in world.touching_pairs() {
        if let (Some(a), Some(b)) = (world.body(a), world.body(b)) {
            let (pa, pb) = (a.position(), b.position());
            out.extend_from_slice(&[f(pa.x), f(pa.y), f(pb.x), f(pb.y)]);
        }
    }
    out
}
