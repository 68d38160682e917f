//! The contact cache: what a contact remembers from one step to the next.

use serde::{Deserialize, Serialize};

use crate::math::Scalar;

/// A contact of the last substep, keyed by its slot pair `(a, b)`, `a < b`.
///
/// The accumulated impulses warm-start the solver in the next step, which
/// is what makes stacks converge in a few iterations; they are therefore
/// part of the state (hash and snapshot).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub(crate) struct CachedContact<S: Scalar> {
    /// Slot index of the first body (the smaller).
    pub(crate) a: u32,
    /// Slot index of the second body.
    pub(crate) b: u32,
    /// Accumulated normal impulse.
    pub(crate) normal_impulse: S,
    /// Accumulated friction impulse along the tangent `perp(normal)`.
    pub(crate) tangent_impulse: S,
    /// Whether the pair touched at the end of the substep.
    pub(crate) touching: bool,
}
