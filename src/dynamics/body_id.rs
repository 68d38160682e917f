//! Body handles.

use crate::generational_id::{GenerationalId, IdKind};

/// A handle to a body: a slot index plus the generation of the slot (see
/// [`GenerationalId`]).
///
/// Ids are handed out in a deterministic order: the most recently freed
/// slot first (LIFO free list), else a new slot at the end.
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
pub type BodyId = GenerationalId<BodyMarker>;

/// The kind marker of [`BodyId`] (never instantiated).
#[derive(Debug)]
pub enum BodyMarker {}

impl IdKind for BodyMarker {
    const TYPE_NAME: &'static str = "BodyId";
    const NOUN: &'static str = "body";
}
