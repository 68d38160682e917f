//! The mechanical energy of bodies under gravity as a test reads it at
//! tick ends, with the allowance its sampling needs.
//!
//! The engine's velocity is the chord velocity of the step (symplectic
//! Euler), which differs from the true velocity at the tick's end by up to
//! half a step of gravity, `g·h/2`. The kinetic energy read with it is
//! off by at most `m·|v|·g·h/2 + m·(g·h/2)²/2` per body (expand
//! `½·m·|v ± g·h/2|²`), so an energy that never rises may read that much
//! above its start: the allowance.

use clockwork2d::prelude::*;

/// `(E, allowance)` of `ids` in `world`: `E = Σ ½·m·|v|² + m·g·(y − floor)`
/// under gravity `g` (downwards) with steps of `h`, and the sampling
/// allowance of the module notes.
pub fn energy_and_allowance(
    world: &World,
    ids: &[BodyId],
    g: f64,
    h: f64,
    floor: f64,
) -> (f64, f64) {
    ids.iter().fold((0.0, 0.0), |(e, allowance), &id| {
        let b = world.body(id).expect("live body");
        let m = b.mass().to_f64();
        let (vx, vy) = b.velocity().to_f64();
        let y = b.position().y.to_f64() - floor;
        let speed = vx.hypot(vy);
        (
            e + 0.5 * m * speed * speed + m * g * y,
            allowance + m * speed * g * h / 2.0 + m * (g * h / 2.0).powi(2) / 2.0,
        )
    })
}
