//! The solver: constraint rows (contacts and ropes), their grouping by
//! shared bodies, the sequential-impulse and direct (block) solves, and the
//! per-step context that holds the buffers of one step.
//!
//! Rows come from the narrow phase ([`crate::collision`]) and from ropes
//! ([`crate::constraints`]); the step pipeline ([`crate::world`]) runs the
//! solves. See ARCHITECTURE.md.

pub(crate) mod block_solve;
pub(crate) mod flight_reflection;
pub(crate) mod forest_cover;
pub(crate) mod rebound_partners;
pub(crate) mod restitution;
pub(crate) mod row;
pub(crate) mod row_groups;
pub(crate) mod sparse_solve;
mod step_context;
pub(crate) mod tree_plan;
pub(crate) mod tree_solve;

pub(crate) use step_context::StepContext;
