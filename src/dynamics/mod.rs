//! Bodies, their ids, and islands (union-find) for sleeping and grouping.

mod body;
mod body_id;
pub(crate) mod islands;

pub(crate) use body::NO_ISLAND;
pub use body::{Body, BodyDef, BodyKind, MassSpec};
pub use body_id::{BodyId, BodyMarker};
