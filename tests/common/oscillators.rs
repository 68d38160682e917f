//! Set-up and probes of the spring, rope and pendulum tests, which compare
//! trajectories with analytic solutions.

use clockwork2d::prelude::*;

/// The engine's tick, 1/60 s.
pub const H: f64 = 1.0 / 60.0;

/// Default settings with gravity `(0, -g)` and sleeping off: an oscillator
/// or a pendulum passes through zero velocity at every turning point and
/// must never be put to sleep there.
pub fn settings(g: f64) -> WorldSettings {
    WorldSettings {
        gravity: vec2(0.0, -g),
        sleep_enabled: false,
        ..WorldSettings::default()
    }
}

/// A live body's position as floats (measurement only).
pub fn pos(world: &World, id: BodyId) -> (f64, f64) {
    world.body(id).expect("live body").position().to_f64()
}

/// A live body's velocity as floats (measurement only).
pub fn vel(world: &World, id: BodyId) -> (f64, f64) {
    world.body(id).expect("live body").velocity().to_f64()
}
