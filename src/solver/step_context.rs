//! The step context: working buffers of a step, reused from step to step so that a world in
//! steady state allocates nothing. Derived data: never part of the state.

use super::restitution::{BounceCandidate, BounceScratch, Rebound};
use crate::collision::CachedContact;
use crate::collision::{BroadPhase, Proxy};
use crate::constraints::spring_solve::SpringScratch;
use crate::math::{Scalar, Vec2};
use crate::solver::block_solve::BlockScratch;
use crate::solver::rebound_partners::ReboundPartners;
use crate::solver::row::ContactConstraint;
use crate::solver::row_groups::RowGroups;
use crate::solver::tree_solve::TreeScratch;

/// Per-step working memory (the step context).
#[derive(Clone, Debug, Default)]
pub(crate) struct StepContext<S: Scalar> {
    /// Swept bounding boxes of the bodies, in slot order.
    pub(crate) proxies: Vec<Proxy<S>>,
    /// The broad phase's buffers and its x order from the last call.
    pub(crate) broad_phase: BroadPhase,
    /// Candidate pairs of the substep, sorted by `(a, b)`.
    pub(crate) pairs: Vec<(u32, u32)>,
    pub(crate) constraints: Vec<ContactConstraint<S>>,
    /// Velocity of each slot during the substep.
    pub(crate) velocities: Vec<Vec2<S>>,
    /// Inverse mass of each slot as the solver sees it (zero for anything
    /// that is not an awake dynamic body).
    pub(crate) inverse_masses: Vec<S>,
    /// Velocity of each slot as the narrow phase saw it (before springs and
    /// the contact solve), for [`crate::world`]'s cut of motion the solve
    /// sent beyond where contacts were looked for.
    pub(crate) predicted_velocities: Vec<Vec2<S>>,
    /// Velocity of each slot before the warm start, kept when a contact
    /// group is solved on covering trees, or a group holds ropes and
    /// contacts (`world::step::energy_guard`); empty otherwise.
    pub(crate) velocities_before_solve: Vec<Vec2<S>>,
    /// Per slot: the last group the energy guard counted it in.
    pub(crate) energy_marks: Vec<u32>,
    /// Slots (ascending) whose solved motion left their predicted motion
    /// by more than the margin allows (working memory of that cut).
    pub(crate) punched: Vec<u32>,
    /// The punched bodies' regions beyond their proxies and the immovable
    /// proxies (working memory of that cut).
    pub(crate) escape_proxies: Vec<Proxy<S>>,
    /// A broad phase of its own for those (its x order is of that set).
    pub(crate) escape_broad_phase: BroadPhase,
    /// Pairs of a punched body and an immovable one found beyond the
    /// punched body's proxy (sorted; none of them in `pairs`).
    pub(crate) escape_pairs: Vec<(u32, u32)>,
    /// Per slot: whether it is in `punched` (false for every other slot).
    pub(crate) punched_mark: Vec<bool>,
    /// `(punched body, immovable body)` pairs without a contact row: what
    /// the punched bodies are stopped at (working memory of that cut).
    pub(crate) punched_obstacles: Vec<(u32, u32)>,
    /// Pairs of two movable bodies, one of them punched, without a contact
    /// row (working memory of that cut; sorted).
    pub(crate) punched_meetings: Vec<(u32, u32)>,
    /// The displacements before the punched bodies' first cut of the
    /// substep, for holding the bodies that follow them
    /// (`world::step::punched_followers`).
    pub(crate) uncut_displacements: Vec<Vec2<S>>,
    /// Per slot, during that hold: 0, or 1 for a body cut at an obstacle,
    /// `r + 1` for a body held behind one of rank `r`.
    pub(crate) hold_rank: Vec<u32>,
    /// The rows between two movable bodies, during that hold.
    pub(crate) hold_links: Vec<u32>,
    /// Position change of each slot during the substep.
    pub(crate) displacements: Vec<Vec2<S>>,
    /// Union-find parents for islands.
    pub(crate) parents: Vec<u32>,
    /// The part `(1 − θ)·Δv` of the velocity change each slot received from
    /// springs this substep that its position does not follow (θ-method).
    pub(crate) spring_dv: Vec<Vec2<S>>,
    /// The spring rows and their solve's buffers.
    pub(crate) springs: SpringScratch<S>,
    /// Per slot, the velocity change the ropes its straight motion would
    /// stretch give it this substep (`world::step::rope_turns`); empty when
    /// no rope is stretched.
    pub(crate) rope_turns: Vec<Vec2<S>>,
    /// Active rope rows, solved in the same loop as the contacts.
    pub(crate) rope_rows: Vec<ContactConstraint<S>>,
    /// The constraint slot of each rope row.
    pub(crate) rope_slots: Vec<u32>,
    /// Each rope row's anchor offset (b − a) at the start of the substep and
    /// its length, for re-linearising in the position iterations.
    pub(crate) rope_geometry: Vec<(Vec2<S>, S)>,
    /// Each rope row's sideways stiffness for the position passes
    /// (`world::step::solve`).
    pub(crate) rope_side_stiffness: Vec<S>,
    /// Per rope row: the most one position pass corrects it.
    pub(crate) rope_correction_cap: Vec<S>,
    /// Each rope row's sideways stiffness for the velocity iterations.
    pub(crate) rope_velocity_side: Vec<S>,
    /// The same at the start of the substep's velocity iterations, before
    /// they raised it (the joint-group guard, `world::step::energy_guard`,
    /// starts a group's solve again from it).
    pub(crate) rope_velocity_side_start: Vec<S>,
    /// The sideways impulse each rope row received this substep.
    pub(crate) rope_side_impulse: Vec<S>,
    /// The rows the rope solves work on, when any rope is active: the
    /// rope rows, then the contact rows (`rope_rows.len()` is where the
    /// contacts start), so that ropes and contacts sharing a body are one
    /// group (`world::step::solve`, "Ropes and contacts in one group").
    pub(crate) joint_rows: Vec<ContactConstraint<S>>,
    /// `joint_rows` grouped by shared bodies.
    pub(crate) joint_groups: RowGroups,
    /// Contact rows grouped by shared bodies: the solves when no rope is
    /// active, and the bounce solve (`solver::restitution`) always.
    pub(crate) contact_groups: RowGroups,
    /// Working memory of the block solver.
    pub(crate) rope_block: BlockScratch<S>,
    /// Working memory of the tree solves.
    pub(crate) tree: TreeScratch<S>,
    /// Pairs touching before the tick (for contact events).
    pub(crate) touching_before: Vec<(u32, u32)>,
    /// The other half of the contact cache's double buffer.
    pub(crate) contacts_next: Vec<CachedContact<S>>,
    /// Whether each slot's body moved this substep (for the contact cache).
    pub(crate) moving: Vec<bool>,
    /// Per-island least sleep time.
    pub(crate) island_time: Vec<S>,
    /// Contact rows of this substep that may bounce (see
    /// `dynamics::restitution`).
    pub(crate) bounce_candidates: Vec<BounceCandidate<S>>,
    /// The narrow phase's second look at turned sweeps (working memory).
    pub(crate) narrow_scratch: crate::collision::NarrowScratch<S>,
    /// Slots whose displacement a bounce grew, with the displacement
    /// before it (the start of the rebound motion) and the bounce's instant.
    pub(crate) rebounds: Vec<Rebound<S>>,
    /// The broad-phase partners of each rebounding slot.
    pub(crate) rebound_partners: ReboundPartners,
    /// Per rebound (in `rebounds` order): whether the last pass of the
    /// rebound sweep shortened it, and the pass being made (working memory
    /// of `World::sweep_rebounds`).
    pub(crate) rebound_shortened: Vec<bool>,
    pub(crate) rebound_shortening: Vec<bool>,
    /// Per rebound: whether the next pass sweeps it again (a rebounding
    /// partner of it was shortened; working memory of
    /// `World::sweep_rebounds`).
    pub(crate) rebound_dirty: Vec<bool>,
    /// Per rebound: its motion as the bounce made it, and the share of it
    /// the sweep has left it (working memory of `World::sweep_rebounds`).
    pub(crate) rebound_full: Vec<Vec2<S>>,
    pub(crate) rebound_reach: Vec<S>,
    /// A broad phase of its own for the rebounds that leave their proxies
    /// (`world::step::rebound_escape`; its x order is of that query).
    pub(crate) rebound_broad_phase: BroadPhase,
    /// The pairs that query found (working memory).
    pub(crate) escape_found: Vec<(u32, u32)>,
    /// `(rebounding slot, other slot)` partners beyond the rebounding
    /// body's proxy, sorted; none of them in `pairs`.
    pub(crate) rebound_escape_pairs: Vec<(u32, u32)>,
    /// Working memory of the bounce solve.
    pub(crate) bounce: BounceScratch<S>,
    /// Displacements before the position pass (to bound its corrections).
    pub(crate) displacements_before_correction: Vec<Vec2<S>>,
    /// The displacements where the rope settling rounds stood best (the
    /// least worst excess), to go back to when a round does not improve
    /// on them.
    pub(crate) settled_displacements: Vec<Vec2<S>>,
    /// Slots of this tick whose projection out of an immovable body was
    /// stopped at the edge of their proxy (still deeper than the slop):
    /// they may not fall asleep this tick. Cleared at the start of a tick.
    pub(crate) unresolved_overlaps: Vec<u32>,
}
