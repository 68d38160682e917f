//! Events of one step, in a deterministic order.

use serde::{Deserialize, Serialize};

use crate::dynamics::BodyId;

/// Something that happened during the last step.
///
/// Order within a step: contact ends, then contact begins (each sorted by
/// the pair's ids), then bodies that fell asleep, then bodies that woke, then
/// bodies frozen at the bounds (each sorted by id).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Serialize, Deserialize)]
pub enum Event {
    /// Two bodies stopped touching (`a < b`). Touching means within the
    /// linear slop, or exchanging a contact impulse (a speculative bounce).
    ContactEnded(BodyId, BodyId),
    /// Two bodies started touching (`a < b`).
    ContactBegan(BodyId, BodyId),
    /// A body fell asleep.
    Slept(BodyId),
    /// A body woke up.
    Woke(BodyId),
    /// A body left the world bounds and was frozen.
    Frozen(BodyId),
}
