//! Working buffers of a step, reused from step to step so that a world in
//! steady state allocates nothing. Derived data: never part of the state.

use super::broad_phase::Proxy;
use crate::dynamics::contact_solver::ContactConstraint;
use crate::math::{Scalar, Vec2};

/// Per-step working memory.
#[derive(Clone, Debug, Default)]
pub(crate) struct StepScratch<S: Scalar> {
    pub(crate) proxies: Vec<Proxy<S>>,
    pub(crate) pairs: Vec<(u32, u32)>,
    pub(crate) constraints: Vec<ContactConstraint<S>>,
    /// Velocity of each slot during the substep.
    pub(crate) velocities: Vec<Vec2<S>>,
    /// Inverse mass of each slot as the solver sees it (zero for anything
    /// that is not an awake dynamic body).
    pub(crate) inverse_masses: Vec<S>,
    /// Position change of each slot during the substep.
    pub(crate) displacements: Vec<Vec2<S>>,
    /// Union-find parents for islands.
    pub(crate) parents: Vec<u32>,
}
