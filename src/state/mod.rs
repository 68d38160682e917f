//! The state schema, in one home: what a world's state is and every view of
//! it — the state hash ([`hash`]), the snapshot payload and its envelope
//! ([`snapshot`]), validation of a decoded state ([`validate`]) and the
//! field-by-field difference of two states ([`diff`]).
//!
//! Each of them destructures [`World`](crate::world::World) exhaustively (no `..`),
//! so a new field of the world fails to compile in every one of them until
//! it is hashed, written, validated and compared (or explicitly skipped, as
//! the derived step context is). See ARCHITECTURE.md, "State".

pub mod diff;
pub mod hash;
pub mod snapshot;
pub(crate) mod validate;
