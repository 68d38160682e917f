//! The overlap invariant of `world_commands`: no overlap deeper than a
//! documented bound persists between a dynamic and a fixed body.
//!
//! # The bound
//!
//! Depth is measured from positions alone, in `f64`, independently of the
//! engine's narrow phase: circle–circle `r₁ + r₂ − |Δ|`, box–box the smaller
//! axis overlap, circle–box the radius minus the distance to the box (plus
//! the distance to the nearest face for a centre inside).
//!
//! A command may put a body deep into a fixed body (a spawn or a teleport
//! there is allowed). The position solver then removes, per position
//! iteration, `min(max_correction, position_correction · (depth − slop))`,
//! and the engine bounds what a body is moved out per substep: at most
//! half the speculative margin `m` per axis in the position pass, and the
//! projection out of immovable bodies stops at the edge of the body's
//! broad-phase region (ARCHITECTURE.md, "Contacts after the position
//! pass"). Along the contact normal that is at least `m/2` per substep (a
//! per-axis cap of `m/2` allows `m/2 / max(|nₓ|, |n_y|) ≥ m/2` along `n`).
//! So from the deepest overlap the current bodies allow, `d₀` (the sum of
//! the two largest half extents in the world), the capped phase takes at
//! most `d₀ / min(max_correction · position_iterations, m/2)` substeps,
//! then `ln(d₀ / TOLERANCE) / position_correction` iterations of geometric
//! decay (`−ln(1 − c) ≥ c`). The **patience** is that many steps (at
//! `substeps` substeps and `position_iterations × substeps` iterations per
//! step) plus [`GRACE`] steps. An overlap deeper than
//! `linear_slop + TOLERANCE` that lasts longer than the patience, with no
//! spawn or teleport in between, is a finding.
//!
//! # Where it applies
//!
//! Only where one dynamic body and one fixed body can settle it between
//! themselves, so the check is exact about what it claims:
//!
//! * the settings correct positions at all: `position_iterations ≥ 1`,
//!   `position_correction ≥ 1/4`, `max_correction ≥ 1/100`;
//! * the dynamic body is awake or asleep but not frozen, is attached to no
//!   constraint (a rope to a point inside a wall may hold it there), touches
//!   or overlaps exactly one fixed body (two walls can wedge it) and no
//!   kinematic or other dynamic body (pressure from other bodies is the
//!   subject of the contact work: a crowd pushing bodies into fixed ones).
//!
//! With the `strict-overlap` feature the last exclusion (other dynamic
//! bodies) is dropped: that is the crowd-pressure promise, which the engine
//! does not keep yet (see the fuzz README).

use std::collections::BTreeMap;

use clockwork2d::prelude::*;

/// Depth allowed beyond the linear slop (units): 1/32.
pub const TOLERANCE: f64 = 1.0 / 32.0;
/// Steps of patience added to the computed settling time.
pub const GRACE: u32 = 60;
/// Bodies closer than this (units) count as touching for the exclusions.
const NEAR: f64 = 1.0 / 16.0;

/// A body as the measure sees it.
#[derive(Clone, Copy, Debug)]
struct Piece {
    x: f64,
    y: f64,
    circle: bool,
    hx: f64,
    hy: f64,
}

impl Piece {
    fn of(b: &Body<Fx>) -> Piece {
        let p = b.position();
        let (circle, hx, hy) = match b.shape() {
            Shape::Circle { radius } => (true, radius.to_f64(), radius.to_f64()),
            Shape::Aabb { half_extents } => {
                (false, half_extents.x.to_f64(), half_extents.y.to_f64())
            }
        };
        Piece {
            x: p.x.to_f64(),
            y: p.y.to_f64(),
            circle,
            hx,
            hy,
        }
    }
}

/// Penetration depth of two pieces (negative: the gap between them, for
/// circle–circle and box–box exactly; for circle–box exact too).
fn depth(a: &Piece, b: &Piece) -> f64 {
    match (a.circle, b.circle) {
        (true, true) => a.hx + b.hx - (a.x - b.x).hypot(a.y - b.y),
        (false, false) => {
            let ox = a.hx + b.hx - (a.x - b.x).abs();
            let oy = a.hy + b.hy - (a.y - b.y).abs();
            ox.min(oy)
        }
        (true, false) => circle_box(a, b),
        (false, true) => circle_box(b, a),
    }
}

fn circle_box(c: &Piece, b: &Piece) -> f64 {
    let dx = (c.x - b.x).abs() - b.hx;
    let dy = (c.y - b.y).abs() - b.hy;
    if dx <= 0.0 && dy <= 0.0 {
        // Centre inside the box: out through the nearest face.
        c.hx - dx.max(dy)
    } else {
        c.hx - dx.max(0.0).hypot(dy.max(0.0))
    }
}

/// Watches dynamic–fixed overlaps step after step.
#[derive(Debug)]
pub struct OverlapWatch {
    enabled: bool,
    slop: f64,
    correction: f64,
    /// Depth removed per substep in the capped phase (module notes).
    capped_rate: f64,
    substeps: f64,
    iterations_per_step: f64,
    /// Consecutive steps each (dynamic, fixed) pair has been too deep.
    deep: BTreeMap<(BodyId, BodyId), u32>,
}

impl OverlapWatch {
    /// A watch for a world with these settings.
    #[must_use]
    pub fn new(settings: &WorldSettings<Fx>) -> OverlapWatch {
        let correction = settings.position_correction.to_f64();
        let max_correction = settings.max_correction.to_f64();
        OverlapWatch {
            enabled: settings.position_iterations >= 1
                && correction >= 0.25
                && max_correction >= 0.01,
            slop: settings.linear_slop.to_f64(),
            correction,
            capped_rate: (max_correction * f64::from(settings.position_iterations))
                .min(settings.speculative_margin.to_f64() / 2.0),
            substeps: f64::from(settings.substeps),
            iterations_per_step: f64::from(settings.position_iterations * settings.substeps),
            deep: BTreeMap::new(),
        }
    }

    /// A spawn or a teleport may create an overlap legitimately: the
    /// patience starts again.
    pub fn command_applied(
        &mut self,
        command: &Command<Fx>,
        result: &Result<CommandOutcome, WorldError>,
    ) {
        if result.is_ok() && matches!(command, Command::Spawn(_) | Command::SetPosition { .. }) {
            self.deep.clear();
        }
    }

    /// Steps the settling time allows for the bodies now in the world.
    fn patience(&self, world: &World<Fx>) -> u32 {
        let mut extents: Vec<f64> = world
            .bodies()
            .map(|(_, b)| {
                let p = Piece::of(b);
                p.hx.max(p.hy)
            })
            .collect();
        extents.sort_by(|a, b| b.total_cmp(a));
        let d0 = extents.iter().take(2).sum::<f64>().max(TOLERANCE);
        let capped_steps = d0 / self.capped_rate / self.substeps;
        let decay_steps = (d0 / TOLERANCE).ln() / self.correction / self.iterations_per_step;
        let steps = (capped_steps + decay_steps).ceil();
        // Bounded by MAX_STEPS anyway; the cast saturates (a huge body and
        // a tiny margin give more steps than a u32 holds), and so does the
        // sum.
        (steps as u32).saturating_add(GRACE)
    }

    /// Checks the world after a step.
    ///
    /// # Panics
    /// When an overlap has outlasted its patience.
    pub fn after_step(&mut self, world: &World<Fx>) {
        if !self.enabled {
            return;
        }
        let strict = cfg!(feature = "strict-overlap");
        let bodies: Vec<(BodyId, BodyKind, bool, Piece)> = world
            .bodies()
            .map(|(id, b)| (id, b.kind(), b.is_frozen(), Piece::of(b)))
            .collect();
        let attached: Vec<BodyId> = world
            .constraints()
            .flat_map(|(_, c)| {
                let (a, b) = c.anchors();
                [a.body(), b.body()]
            })
            .flatten()
            .collect();
        let bound = self.slop + TOLERANCE;
        let mut still_deep = BTreeMap::new();
        for &(id, kind, frozen, piece) in &bodies {
            if kind != BodyKind::Dynamic || frozen || attached.contains(&id) {
                continue;
            }
            let mut fixed_near = Vec::new();
            let mut others_near = false;
            for &(other, other_kind, _, other_piece) in &bodies {
                if other == id {
                    continue;
                }
                let d = depth(&piece, &other_piece);
                if d <= -NEAR {
                    continue;
                }
                match other_kind {
                    BodyKind::Fixed => fixed_near.push((other, d)),
                    BodyKind::Kinematic => others_near = true,
                    BodyKind::Dynamic => others_near |= !strict,
                }
            }
            if others_near || fixed_near.len() != 1 {
                continue;
            }
            let (fixed, d) = fixed_near[0];
            if d > bound {
                let count = self.deep.get(&(id, fixed)).copied().unwrap_or(0) + 1;
                still_deep.insert((id, fixed), count);
                let patience = self.patience(world);
                assert!(
                    count <= patience,
                    "dynamic {id} has overlapped fixed {fixed} by more than {bound} for \
                     {count} steps (patience {patience}); depth now {d} at tick {}",
                    world.tick()
                );
            }
        }
        self.deep = still_deep;
    }
}
