//! [`Anchor`]: where a constraint attaches.

use serde::{Deserialize, Serialize};

use crate::dynamics::BodyId;
use crate::math::Fx;
use crate::math::{Scalar, Vec2};

/// One end of a constraint: a fixed point in the world, a body's centre,
/// or a point at a fixed offset from a body's centre (bodies do not rotate,
/// so an offset stays a fixed vector).
///
/// ```
/// use clockwork2d::prelude::*;
/// let hook = Anchor::Point(Vec2::new(fx(0.0), fx(6.0)));
/// let id = BodyId::from_parts(3, 0);
/// assert_eq!(Anchor::<Fx>::Body(id).body(), Some(id));
/// assert_eq!(hook.body(), None);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub enum Anchor<S: Scalar = Fx> {
    /// A fixed world point.
    Point(Vec2<S>),
    /// A body's centre.
    Body(BodyId),
    /// A body's centre plus a fixed offset.
    BodyOffset(BodyId, Vec2<S>),
}

impl<S: Scalar> Anchor<S> {
    /// The body this anchor is attached to, if any.
    #[must_use]
    pub fn body(&self) -> Option<BodyId> {
        match *self {
            Anchor::Point(_) => None,
            Anchor::Body(id) | Anchor::BodyOffset(id, _) => Some(id),
        }
    }

    /// The offset from the body's centre (zero for `Body`; the point itself
    /// for `Point`).
    #[must_use]
    pub fn local_point(&self) -> Vec2<S> {
        match *self {
            Anchor::Point(p) | Anchor::BodyOffset(_, p) => p,
            Anchor::Body(_) => Vec2::ZERO,
        }
    }
}
