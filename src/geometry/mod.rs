//! Geometry: shapes, closest points, contact tests, ray casts and time of
//! impact. All generic over the [`Scalar`](crate::math::Scalar).
//!
//! Conventions used by every function here:
//!
//! * A contact's `normal` is a unit vector pointing **from shape `a` to
//!   shape `b`**; `separation` is the signed distance between the surfaces
//!   (negative = penetration depth). Moving `b` by `-separation * normal`
//!   brings the shapes to touching.
//! * Ties and degenerate cases have documented, deterministic answers
//!   (never a division by zero): coincident centres give the normal `+Y`
//!   `(0, 1)`, and equal penetration on both axes picks the y axis.

mod closest_point;
mod contact;
mod contact_aabb_aabb;
mod contact_circle_aabb;
mod contact_circle_circle;
mod ray;
mod ray_aabb;
mod ray_circle;
mod segment_cast;
mod shapes;
mod toi;

pub use closest_point::{SegmentPoint, closest_point_on_segment};
pub use contact::Contact;
pub use contact_aabb_aabb::contact_aabb_aabb;
pub use contact_circle_aabb::{contact_aabb_circle, contact_circle_aabb};
pub use contact_circle_circle::contact_circle_circle;
pub use ray::{Ray, RayHit};
pub use ray_aabb::ray_aabb;
pub use ray_circle::{ray_circle, ray_circle_roots};
pub use shapes::{Aabb, Circle, Shape};
pub use toi::{Toi, toi_aabb_aabb, toi_circle_aabb, toi_circle_circle};
