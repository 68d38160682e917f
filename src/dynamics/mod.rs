//! Bodies, ids, the contact solver and sleeping.

mod body;
mod body_id;
pub(crate) mod contact_solver;
pub(crate) mod islands;
pub(crate) mod row_groups;

pub(crate) use body::NO_ISLAND;
pub use body::{Body, BodyDef, BodyKind, MassSpec};
pub use body_id::BodyId;
