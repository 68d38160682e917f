//! Generational constraint handles.

use serde::{Deserialize, Serialize};

/// A handle to a constraint: slot index plus generation, like
/// [`crate::dynamics::BodyId`]. Removing a constraint bumps its slot's generation so
/// old handles are detected as stale.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
pub struct ConstraintId {
    index: u32,
    generation: u32,
}

impl ConstraintId {
    /// Builds a handle from its parts (the world validates every id).
    #[must_use]
    pub const fn from_parts(index: u32, generation: u32) -> Self {
        ConstraintId { index, generation }
    }
    /// The slot index.
    #[must_use]
    pub const fn index(self) -> u32 {
        self.index
    }
    /// The slot's generation when this handle was issued.
    #[must_use]
    pub const fn generation(self) -> u32 {
        self.generation
    }
}

impl core::fmt::Display for ConstraintId {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(f, "constraint {} (gen {})", self.index, self.generation)
    }
}
