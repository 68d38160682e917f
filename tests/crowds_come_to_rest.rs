//! A crowd in a closed room comes to rest and sleeps, and a body that stands
//! still reports no velocity (issue 13, N6).
//!
//! Scenes: 100–500 circles and boxes of random sizes (radius or half extents
//! drawn from 0.05–0.24 or 0.05–0.12) spawned on a grid of 16 columns 0.5
//! apart in an 8 × 16 room of fixed walls (0.02, 0.1 or 2 thick), dropped
//! under g = 10 or g = 100, with several seeds. Every body has density 1 (so
//! masses differ up to 23×: the groups are solved directly).
//!
//! # What the physics says
//!
//! * **Rest, then sleep.** Contacts are inelastic (restitution 0) and the
//!   bodies do not rotate, so a body stops at its first contact and every
//!   later motion is a slide or a fall off another body, each shorter than
//!   the room. The highest body starts `H ≤ 16` above the floor and lands
//!   after at most `t_fall = √(2H/g)` (1.8 s at g = 10); the heap's
//!   rearrangements afterwards are falls of at most one body size
//!   (0.48: 0.31 s at g = 10) repeated down at most the heap's height in
//!   bodies, bounded by a second `t_fall`; then an island sleeps after
//!   `time_to_sleep` = 0.5 s below the sleep speed. So every body is asleep
//!   by `2·t_fall + time_to_sleep` (3.3–4.1 s at g = 10; the crowds measured
//!   sleep in 1.1–2.4 s). Asserted at g = 10 only: at g = 100 the crowds
//!   rest (the other two checks hold) but still move at 0.1–1 units/s
//!   after 20 s, as before session 7 (one substep of gravity is 33 times
//!   the sleep speed; see the note at the assertion).
//! * **No phantom velocity.** A body's stored velocity is its motion over
//!   the step, `Δx = v·h`, plus the position pass's correction, which
//!   removes penetration beyond the linear slop only. A body resting on its
//!   neighbours moves less than the slop in a tick, so its velocity is at
//!   most what one substep of gravity adds before the contacts cancel it,
//!   `g·h`, plus the correction's share `slop/h`: `|v| ≤ g·h + slop/h`
//!   (0.173 units/s at g = 10), averaged over the `WINDOW` ticks it stood
//!   still (an impact on a resting body leaves a residual velocity of the
//!   iterative sweeps for a tick: 0.39 units/s once under a 500-body
//!   crowd). Before the fix a whole column of a crowd of 300 stood still
//!   (2.4e-5 per tick) while reporting `v_y = −3.0`: the block solve of
//!   its group ran out of active-set rounds in every sweep, so its rows'
//!   velocities were never solved, gravity piled up in the stored velocity
//!   and only the position pass held the column (its bound 0.05 per tick
//!   is the 3.0); the crowd never slept.
//! * **Containment.** The walls are fixed: no body reaches past a wall's
//!   inner face by more than the slop (plus 1e-9 of literal rounding, as in
//!   `crowds_stay_inside.rs`).
//!
//! Run with `--nocapture` to see the figures. Debug runs check the first
//! scenes only (the test profile is slow); release runs all of them.

use clockwork2d::prelude::*;

mod common;
use common::add_closed_room;
use common::split_mix::SplitMix;

const SLOP: f64 = 1e-4;
const H: f64 = 1.0 / 60.0;
/// Rounding of the stored centres and half extents (4 roundings of 2⁻³²).
const ROUNDING: f64 = 1e-9;
/// The room's interior half width and half height.
const HALF: (f64, f64) = (4.0, 8.0);
/// Ticks a body must stay within the slop of where it is to count as
/// standing still; its speed is averaged over them (a sixth of a second:
/// an impact into a resting body leaves an unconverged velocity for a tick
/// or two, which the next sweeps remove; a phantom velocity lasts).
const WINDOW: usize = 10;
/// `time_to_sleep` of the default settings.
const TIME_TO_SLEEP: f64 = 0.5;

/// One crowd: body count, largest size, wall thickness, g, seed.
type Crowd = (usize, f64, f64, f64, u64);

fn crowd(&(count, size, wall, g, seed): &Crowd) -> (World, Vec<BodyId>) {
    let mut world = World::new(WorldSettings {
        gravity: vec2(0.0, -g),
        ..WorldSettings::default()
    });
    let (hw, hh) = HALF;
    add_closed_room(&mut world, (0.0, 0.0), (hw, hh), wall);
    let mut rng = SplitMix(seed);
    let bodies = (0..count)
        .map(|k| {
            let x = -hw + 0.25 + 0.5 * (k % 16) as f64;
            let y = -hh + 0.25 + 0.5 * (k / 16) as f64;
            let s = rng.range(0.05, size);
            let shape = if rng.unit() < 0.5 {
                Shape::circle(fx(s))
            } else {
                Shape::aabb(vec2(s, rng.range(0.05, size)))
            };
            world
                .add_body(BodyDef::dynamic(shape).position(vec2(x, y)))
                .expect("body")
        })
        .collect();
    (world, bodies)
}

fn reach(world: &World, id: BodyId) -> f64 {
    let b = world.body(id).unwrap();
    let (x, y) = b.position().to_f64();
    let (ex, ey) = match b.shape() {
        Shape::Circle { radius } => (radius.to_f64(), radius.to_f64()),
        Shape::Aabb { half_extents } => half_extents.to_f64(),
    };
    (x.abs() + ex - HALF.0).max(y.abs() + ey - HALF.1)
}

#[test]
fn crowds_in_closed_rooms_come_to_rest_without_phantom_velocity() {
    let crowds: &[Crowd] = &[
        // The reviewer's scene (N6): seed 4 never slept.
        (300, 0.24, 0.1, 10.0, 4),
        (300, 0.24, 0.1, 100.0, 1),
        (300, 0.24, 0.02, 10.0, 7),
        (500, 0.12, 0.1, 10.0, 11),
        (300, 0.24, 0.1, 100.0, 2),
        (100, 0.24, 2.0, 10.0, 12),
        (300, 0.24, 2.0, 10.0, 13),
        (500, 0.24, 0.1, 10.0, 14),
        (300, 0.12, 0.02, 100.0, 15),
        (500, 0.24, 0.1, 100.0, 16),
        (300, 0.24, 0.1, 10.0, 17),
        (300, 0.24, 0.1, 10.0, 18),
        (300, 0.24, 0.02, 100.0, 19),
        (200, 0.24, 0.1, 10.0, 20),
    ];
    let checked = if cfg!(debug_assertions) {
        2
    } else {
        crowds.len()
    };
    for c in &crowds[..checked] {
        let &(count, size, wall, g, seed) = c;
        let (mut world, bodies) = crowd(c);
        // Highest spawn row above the floor (centre), plus its size.
        let height = 0.25 + 0.5 * ((count - 1) / 16) as f64 + size;
        let t_fall = (2.0 * height / g).sqrt();
        let bound = 2.0 * t_fall + TIME_TO_SLEEP;
        let ticks = (bound / H).ceil() as usize;
        let phantom_bound = g * H + SLOP / H;
        // Each body's positions and speeds over the last `WINDOW` ticks.
        let mut history: Vec<Vec<((f64, f64), f64)>> = vec![Vec::new(); bodies.len()];
        let (mut worst_reach, mut worst_phantom) = (f64::MIN, 0.0f64);
        let mut asleep_at = None;
        for tick in 1..=ticks {
            world.step();
            for (i, &id) in bodies.iter().enumerate() {
                let b = world.body(id).unwrap();
                let p = b.position().to_f64();
                let (vx, vy) = b.velocity().to_f64();
                let past = &mut history[i];
                if past.len() == WINDOW {
                    past.remove(0);
                }
                past.push((p, vx.hypot(vy)));
                let r = reach(&world, id);
                worst_reach = worst_reach.max(r);
                assert!(
                    r <= SLOP + ROUNDING,
                    "{c:?}: body {i} {r} past a wall at tick {tick}"
                );
                let moved = past
                    .iter()
                    .map(|(q, _)| (q.0 - p.0).hypot(q.1 - p.1))
                    .fold(0.0, f64::max);
                if past.len() == WINDOW && moved <= SLOP {
                    // The velocity of tick k moved the body from its
                    // position at tick k − 1: the first entry's belongs to
                    // the motion before the window (a landing).
                    let speed =
                        past[1..].iter().map(|&(_, s)| s).sum::<f64>() / (WINDOW - 1) as f64;
                    worst_phantom = worst_phantom.max(speed);
                    assert!(
                        speed <= phantom_bound,
                        "{c:?}: body {i} stayed within {moved:.2e} for {WINDOW} ticks up to tick {tick} but reports {speed:.4} units/s on average (bound {phantom_bound:.4})"
                    );
                }
            }
            if asleep_at.is_none() && bodies.iter().all(|&id| !world.body(id).unwrap().is_awake()) {
                asleep_at = Some(tick);
            }
        }
        println!(
            "{count} bodies ≤ {size}, wall {wall}, g {g}, seed {seed}: asleep at tick {asleep_at:?} (bound {ticks}), \
             worst |v| of a body still within the slop {worst_phantom:.4} (bound {phantom_bound:.4}), reach {worst_reach:.2e}"
        );
        // Under g = 100 the crowds rest (no phantom velocity, contained)
        // but do not sleep: a substep of gravity is 1.67 units/s, 33 times
        // the sleep speed, and the sweeps over one group of ~860 rows leave
        // residuals of 0.1–1 units/s (before session 7 as well). Not
        // asserted; the figure is printed.
        assert!(
            g > 10.0 || asleep_at.is_some(),
            "{c:?}: not every body asleep after {ticks} ticks (2·t_fall + time_to_sleep)"
        );
    }
}
