//! Generational body handles and their allocator.

use serde::{Deserialize, Serialize};

/// A handle to a body: a slot index plus the generation of the slot.
///
/// When a body is removed its slot's generation is bumped, so an old handle
/// to that slot is detected as stale instead of silently naming a new body.
/// Both parts are `u32` (never `usize`, whose width differs between
/// targets), and ids are handed out in a deterministic order: the most
/// recently freed slot first (LIFO free list), else a new slot at the end.
///
/// ```
/// use clockwork2d::prelude::*;
/// let mut world = World::new(WorldSettings::default());
/// let a = world.add_body(BodyDef::dynamic(Shape::circle(fx(0.5)))).unwrap();
/// world.remove_body(a).unwrap();
/// let b = world.add_body(BodyDef::dynamic(Shape::circle(fx(0.5)))).unwrap();
/// assert_eq!(b.index(), a.index());
/// assert_ne!(b.generation(), a.generation());
/// assert!(world.body(a).is_none()); // the stale handle names nothing
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
pub struct BodyId {
    index: u32,
    generation: u32,
}

impl BodyId {
    /// Builds a handle from its parts (for tools that store ids; the world
    /// validates every id it is given).
    #[must_use]
    pub const fn from_parts(index: u32, generation: u32) -> Self {
        BodyId { index, generation }
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

impl core::fmt::Display for BodyId {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(f, "body {} (gen {})", self.index, self.generation)
    }
}
