//! Constraint handles.

use crate::generational_id::{GenerationalId, IdKind};

/// A handle to a constraint: slot index plus generation (see
/// [`GenerationalId`]). Removing a constraint bumps its slot's generation so
/// old handles are detected as stale.
pub type ConstraintId = GenerationalId<ConstraintMarker>;

/// The kind marker of [`ConstraintId`] (never instantiated).
#[derive(Debug)]
pub enum ConstraintMarker {}

impl IdKind for ConstraintMarker {
    const TYPE_NAME: &'static str = "ConstraintId";
    const NOUN: &'static str = "constraint";
}
