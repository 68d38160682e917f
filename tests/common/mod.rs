//! Set-up shared by the integration tests: scene builders (here), how far a
//! chain of ropes is stretched (`chain_stretch`), how deep two shapes
//! overlap (`depth`), edited files (`file_checksum`), proptest
//! strategies (`fx_strategies`), the oscillator tests' settings and probes
//! (`oscillators`), raw-bit access to the fixed-point types for exact
//! reference arithmetic (`raw_fixed`), resting scenes of boxes and their
//! measures (`resting`), the energy of bodies read at tick ends with its
//! sampling allowance (`sampled_energy`), a seeded random generator for
//! random scenes (`split_mix`).
//!
//! Every float here is a literal or a test-side measurement converted at the
//! edge with `fx()` / `to_f64()`; the simulation itself sees only `Fx`.
#![allow(dead_code)] // each test crate uses a different subset

pub mod chain_stretch;
pub mod depth;
pub mod file_checksum;
pub mod fx_strategies;
pub mod oscillators;
pub mod raw_fixed;
pub mod resting;
pub mod sampled_energy;
pub mod split_mix;

use clockwork2d::prelude::*;

/// A fixed ground box whose top face is the line y = 0 (half extents
/// 50 × 0.5, centre (0, -0.5)).
pub fn add_ground(world: &mut World) -> BodyId {
    world
        .add_body(BodyDef::fixed(Shape::aabb(vec2(50.0, 0.5))).position(vec2(0.0, -0.5)))
        .expect("ground")
}

/// A closed room of four fixed walls `wall` thick around the interior of
/// half extents `half` centred at `centre` (floor and ceiling span the
/// side walls too, so the corners are closed).
pub fn add_closed_room(world: &mut World, centre: (f64, f64), half: (f64, f64), wall: f64) {
    let ((hw, hh), t) = (half, wall / 2.0);
    for (half, at) in [
        ((hw + wall, t), (0.0, -hh - t)),
        ((hw + wall, t), (0.0, hh + t)),
        ((t, hh), (-hw - t, 0.0)),
        ((t, hh), (hw + t, 0.0)),
    ] {
        world
            .add_body(
                BodyDef::fixed(Shape::aabb(vec2(half.0, half.1)))
                    .position(vec2(centre.0 + at.0, centre.1 + at.1)),
            )
            .expect("wall");
    }
}

/// A unit box (half extents 0.5, density 1, so mass 1) at `(x, y)`.
pub fn add_unit_box(world: &mut World, x: f64, y: f64) -> BodyId {
    world
        .add_body(BodyDef::dynamic(Shape::aabb(vec2(0.5, 0.5))).position(vec2(x, y)))
        .expect("unit box")
}

/// A vertical stack of `n` unit boxes on the ground at x = 0, box `i` placed
/// at `y = 0.5 + i·(1 + gap)` (so each rests on the one below after falling
/// `gap`). Returns the ids bottom first.
pub fn add_stack(world: &mut World, n: usize, gap: f64) -> Vec<BodyId> {
    (0..n)
        .map(|i| add_unit_box(world, 0.0, 0.5 + i as f64 * (1.0 + gap)))
        .collect()
}

/// A pyramid of unit boxes: row `r` (0 at the bottom) holds `rows - r` boxes
/// spaced `spacing` apart horizontally, centred on x = 0, at the ideal
/// resting height `0.5 + r` (each box touches the two below it). Returns
/// `(id, row)` bottom row first.
pub fn add_pyramid(world: &mut World, rows: usize, spacing: f64) -> Vec<(BodyId, usize)> {
    let mut ids = Vec::new();
    for r in 0..rows {
        let count = rows - r;
        for j in 0..count {
            let x = (j as f64 - (count as f64 - 1.0) / 2.0) * spacing;
            ids.push((add_unit_box(world, x, 0.5 + r as f64), r));
        }
    }
    ids
}

/// A tiny deterministic PRNG (SplitMix64), so test scenes need no crate.
#[derive(Clone, Debug)]
pub struct Rng(pub u64);

impl Rng {
    /// Next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// A float uniformly in `[lo, hi)` (53 random bits).
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        let unit = (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
        lo + (hi - lo) * unit
    }
}

/// The y coordinate of a body as f64 (reporting only).
pub fn y_of(world: &World, id: BodyId) -> f64 {
    world.body(id).expect("live body").position().y.to_f64()
}
