//! The per-part digests of a world's state and their combination.

use super::fnv::StateHasher;

/// Number of parts of the state hash (see the module docs).
pub const PART_COUNT: usize = 6;

/// The per-part digests of a world's state (see the module docs).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct StateDigest {
    /// Tick, scalar and settings.
    pub world: u64,
    /// Every body slot.
    pub bodies: u64,
    /// The contact cache (warm-start impulses, touching flags).
    pub contacts: u64,
    /// Sleeping islands.
    pub sleep: u64,
    /// The id allocator's free list.
    pub allocator: u64,
    /// Constraints (springs, ropes) and their solver state.
    pub constraints: u64,
}

impl StateDigest {
    /// The single 64-bit state hash combining all parts.
    #[must_use]
    pub fn combined(&self) -> u64 {
        let mut h = StateHasher::default();
        for (_, part) in self.parts() {
            h.u64(part);
        }
        h.finish()
    }

    /// Every part as `(name, digest)`, in hash order. Replays store these
    /// values so that a later mismatch can name the part.
    #[must_use]
    pub fn parts(&self) -> [(&'static str, u64); PART_COUNT] {
        [
            ("world", self.world),
            ("bodies", self.bodies),
            ("contacts", self.contacts),
            ("sleep", self.sleep),
            ("allocator", self.allocator),
            ("constraints", self.constraints),
        ]
    }

    /// Names of the parts that differ between two digests.
    #[must_use]
    pub fn differing_parts(&self, other: &StateDigest) -> Vec<&'static str> {
        self.parts()
            .into_iter()
            .zip(other.parts())
            .filter(|((_, a), (_, b))| a != b)
            .map(|((name, _), _)| name)
            .collect()
    }
}
