//! The narrow phase's working memory, kept in the step context.

use crate::math::{Scalar, Vec2};
use crate::solver::restitution::BounceCandidate;
use crate::solver::row::ContactConstraint;

use super::deflected_sweep::MeetingRows;
use super::implied_rows::ImpliedScratch;

/// The narrow phase's working memory for its looks after the loop (the
/// turned sweeps, `collision::deflected_sweep`; the covered corners,
/// `collision::covered_corner`), kept across substeps so a step does not
/// allocate once warm.
#[derive(Clone, Debug, Default)]
pub(crate) struct NarrowScratch<S: Scalar> {
    /// Per slot: `MEETS`, `MEETS_IMMOVABLE`, `WANTED`, `COVERED`, `WALL_*` bits
    /// (`collision::narrow_phase`).
    pub(crate) flags: Vec<u8>,
    /// Pairs whose straight sweep missed.
    pub(crate) missed: Vec<(u32, u32)>,
    /// How many pairs' straight sweeps (and rope-turned sweeps) missed in
    /// the last run: the ropes' turns are looked at only when some did
    /// (`world::step::narrow_phase`).
    pub(crate) straight_misses: usize,
    /// Rows whose straight sweep hit, with the fraction.
    pub(crate) hits: Vec<(usize, S)>,
    /// Who meets whom.
    pub(crate) meeting: MeetingRows<S>,
    /// Rows restored after a miss, with their bounces.
    pub(crate) restored: Vec<(ContactConstraint<S>, Option<BounceCandidate<S>>)>,
    /// New index of each old row while merging.
    pub(crate) moved: Vec<u32>,
    /// Bounces of the restored rows.
    pub(crate) new_bounces: Vec<BounceCandidate<S>>,
    /// The rows' spare buffer for the merge.
    pub(crate) spare_rows: Vec<ContactConstraint<S>>,
    /// Rows of a circle at an immovable box's corner: (circle, box, row).
    pub(crate) corners: Vec<(u32, u32, usize)>,
    /// Face rows of those circles with immovable boxes: (circle, box,
    /// normal from the circle to the box).
    pub(crate) faces: Vec<(u32, u32, Vec2<S>)>,
    /// Deep rows of two movable boxes or circles
    /// (`collision::confined_pair`).
    pub(crate) confined: Vec<usize>,
    /// Face rows of movable bodies with immovable ones: (body, normal from
    /// it, gap).
    pub(crate) walls: Vec<(u32, Vec2<S>, S)>,
    /// Implied rows (`collision::implied_rows`).
    pub(crate) implied: ImpliedScratch<S>,
}
