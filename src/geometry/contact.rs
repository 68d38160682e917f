//! The result type of the contact tests.

use serde::{Deserialize, Serialize};

use crate::math::Fx;
use crate::math::{Scalar, Vec2};

/// The contact between two shapes `a` and `b`.
///
/// ```
/// use clockwork2d::geometry::*;
/// use clockwork2d::prelude::*;
/// let a = Circle::new(Vec2::new(fx(0.0), fx(0.0)), fx(1.0));
/// let b = Circle::new(Vec2::new(fx(3.0), fx(0.0)), fx(1.0));
/// let c = contact_circle_circle(&a, &b);
/// assert_eq!(c.separation, fx(1.0)); // a gap of 1
/// assert_eq!(c.normal, Vec2::new(fx(1.0), fx(0.0))); // from a to b
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct Contact<S: Scalar = Fx> {
    /// Unit normal pointing from `a` to `b`.
    pub normal: Vec2<S>,
    /// Signed distance between the surfaces along `normal`: positive is a
    /// gap, negative is penetration depth.
    pub separation: S,
}

impl<S: Scalar> Contact<S> {
    /// The same contact seen from `b`: same separation, opposite normal.
    #[inline]
    #[must_use]
    pub fn flipped(self) -> Self {
        Contact {
            normal: -self.normal,
            separation: self.separation,
        }
    }
}
