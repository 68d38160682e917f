//! [`WorldSettings`]: everything that configures a world.

use serde::{Deserialize, Serialize};

use super::error::WorldError;
use crate::geometry::Aabb;
use crate::math::Fx;
use crate::math::{Scalar, Vec2, WORLD_LIMIT};

/// Most solver iterations accepted (bounds the work of one step).
pub const MAX_ITERATIONS: u32 = 256;
/// Most substeps accepted (bounds the work of one step).
pub const MAX_SUBSTEPS: u32 = 64;

/// The settings of a world. `Default` gives gravity (0, -10), dt = 1/60,
/// 8 velocity and 3 position iterations, no substeps, sleeping on, and
/// bounds of ±[`WORLD_LIMIT`] on each axis.
///
/// ```
/// use clockwork2d::prelude::*;
/// let mut settings = WorldSettings::default();
/// settings.gravity = Vec2::new(fx(0.0), fx(-9.81));
/// settings.velocity_iterations = 12;
/// let world: World = World::try_new(settings).unwrap();
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct WorldSettings<S: Scalar = Fx> {
    /// Acceleration of gravity (units/s²).
    pub gravity: Vec2<S>,
    /// Seconds per tick, in (0, 1].
    pub dt: S,
    /// Sequential-impulse iterations per substep, 1..=256.
    pub velocity_iterations: u32,
    /// Position-correction iterations per substep, 0..=256.
    pub position_iterations: u32,
    /// Substeps per tick, 1..=64 (each of dt / substeps).
    pub substeps: u32,
    /// Sleeping: resting islands stop being simulated until woken.
    pub sleep_enabled: bool,
    /// Speed below which a body counts as resting (units/s).
    pub sleep_linear_threshold: S,
    /// Seconds an island must rest before it sleeps.
    pub time_to_sleep: S,
    /// Approach speed below which restitution is ignored (units/s), so that
    /// resting contacts do not bounce.
    pub restitution_threshold: S,
    /// Penetration allowed without correction (units).
    pub linear_slop: S,
    /// Fraction of the remaining penetration corrected per position
    /// iteration, in [0, 1].
    pub position_correction: S,
    /// Largest position correction per iteration (units).
    pub max_correction: S,
    /// Distance beyond the swept box within which contacts are created
    /// speculatively (units).
    pub speculative_margin: S,
    /// Largest speed a body may have (units/s); faster velocities are
    /// clamped per axis. Keeps a step's motion far inside the number range.
    pub max_speed: S,
    /// The world's bounds: a body whose centre leaves them is frozen (held
    /// still, reported by an event). Must lie within ±`WORLD_LIMIT`.
    pub bounds: Aabb<S>,
}

impl<S: Scalar> Default for WorldSettings<S> {
    fn default() -> Self {
        let limit = S::from_int(WORLD_LIMIT);
        WorldSettings {
            gravity: Vec2::new(S::ZERO, S::from_int(-10)),
            dt: S::from_ratio(1, 60),
            velocity_iterations: 8,
            position_iterations: 3,
            substeps: 1,
            sleep_enabled: true,
            sleep_linear_threshold: S::from_ratio(1, 20),
            time_to_sleep: S::from_ratio(1, 2),
            restitution_threshold: S::ONE,
            linear_slop: S::from_ratio(1, 10_000),
            position_correction: S::from_ratio(4, 5),
            max_correction: S::from_ratio(1, 5),
            speculative_margin: S::from_ratio(1, 10),
            max_speed: S::from_int(4096),
            bounds: Aabb::new(Vec2::ZERO, Vec2::new(limit, limit)),
        }
    }
}

impl<S: Scalar> WorldSettings<S> {
    /// Checks every field against its documented range.
    ///
    /// # Errors
    /// [`WorldError::InvalidSettings`] naming the first bad field.
    pub fn validate(&self) -> Result<(), WorldError> {
        let bad = |field: &'static str, reason: &'static str| {
            Err(WorldError::InvalidSettings { field, reason })
        };
        let limit = S::from_int(WORLD_LIMIT);
        let g_limit = S::from_int(1 << 12);
        if self.gravity.x.abs() > g_limit || self.gravity.y.abs() > g_limit {
            return bad("gravity", "each component must be within ±4096");
        }
        if !self.dt.is_positive() || self.dt > S::ONE {
            return bad("dt", "must be in (0, 1] seconds");
        }
        if self.velocity_iterations == 0 || self.velocity_iterations > MAX_ITERATIONS {
            return bad("velocity_iterations", "must be in 1..=256");
        }
        if self.position_iterations > MAX_ITERATIONS {
            return bad("position_iterations", "must be in 0..=256");
        }
        if self.substeps == 0 || self.substeps > MAX_SUBSTEPS {
            return bad("substeps", "must be in 1..=64");
        }
        let non_negative = [
            ("sleep_linear_threshold", self.sleep_linear_threshold),
            ("time_to_sleep", self.time_to_sleep),
            ("restitution_threshold", self.restitution_threshold),
            ("linear_slop", self.linear_slop),
            ("max_correction", self.max_correction),
            ("speculative_margin", self.speculative_margin),
        ];
        for (field, value) in non_negative {
            if value.is_negative() || value > limit {
                return bad(field, "must be in [0, 32768]");
            }
        }
        if self.position_correction.is_negative() || self.position_correction > S::ONE {
            return bad("position_correction", "must be in [0, 1]");
        }
        if !self.max_speed.is_positive() || self.max_speed > S::from_int(1 << 16) {
            return bad("max_speed", "must be in (0, 65536] units/s");
        }
        let (lo, hi) = (self.bounds.min(), self.bounds.max());
        let inside = |v: S| v >= limit.neg() && v <= limit;
        if !self.bounds.half_extents.x.is_positive()
            || !self.bounds.half_extents.y.is_positive()
            || !inside(lo.x)
            || !inside(lo.y)
            || !inside(hi.x)
            || !inside(hi.y)
        {
            return bad(
                "bounds",
                "must have positive extents and lie within ±32768 on each axis",
            );
        }
        Ok(())
    }
}
