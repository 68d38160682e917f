//! A seeded, scripted input: the commands `clockwork2d record` uses when no
//! input file is given, and what the golden replays are made of.

use clockwork2d::dynamics::{BodyDef, BodyId, BodyKind};
use clockwork2d::geometry::Shape;
use clockwork2d::math::{Scalar, Vec2};
use clockwork2d::world::{Command, World};

/// SplitMix64 (integer only, the same everywhere).
fn splitmix(state: &mut u64) -> u64 {
    *state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
    let mut z = *state;
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// An integer in `lo..=hi` from the generator.
fn between(state: &mut u64, lo: i32, hi: i32) -> i32 {
    let span = u64::try_from(i64::from(hi) - i64::from(lo) + 1)
        .unwrap_or(1)
        .max(1);
    let offset = i32::try_from(splitmix(state) % span).unwrap_or(0);
    lo.saturating_add(offset)
}

/// Picks one element.
fn pick<T: Copy>(state: &mut u64, items: &[T]) -> Option<T> {
    let n = u64::try_from(items.len()).ok().filter(|&n| n > 0)?;
    items
        .get(usize::try_from(splitmix(state) % n).ok()?)
        .copied()
}

/// The commands of the scripted input for the world's current tick, a pure
/// function of `(world state, seed)`:
///
/// * every 15 ticks (at 7 mod 15) an impulse on a random dynamic body
///   (a velocity change of up to ±3 units/s sideways, up to 6 up);
/// * every 40 ticks (at 20) a spawn: a circle or a box dropped 2 units
///   above the highest body;
/// * every 60 ticks (at 45) a despawn of a random dynamic body;
/// * every 100 ticks (at 80) a new velocity for a random dynamic body;
/// * every 90 ticks (at 30) a wake;
/// * every 120 ticks (at 110) a despawn of an id that does not exist
///   (refused, so replays exercise refused commands too).
///
/// ```
/// use clockwork2d::prelude::*;
/// use clockwork2d_scene::scripted_commands;
/// let mut world: World = clockwork2d_scene::builtin("stack").unwrap().build().unwrap();
/// for _ in 0..200 {
///     let commands = scripted_commands(&world, 7);
///     world.step_with(&commands);
/// }
/// ```
#[must_use]
pub fn scripted_commands<S: Scalar>(world: &World<S>, seed: u64) -> Vec<Command<S>> {
    let tick = world.tick();
    let due = |period: u64, phase: u64| tick % period == phase;
    let actions = [
        due(15, 7),
        due(40, 20),
        due(60, 45),
        due(100, 80),
        due(90, 30),
        due(120, 110),
    ];
    if !actions.contains(&true) {
        return Vec::new();
    }
    let mut state = seed ^ tick.wrapping_mul(0xD1B5_4A32_D192_ED03);
    let dynamic: Vec<(BodyId, S, Vec2<S>)> = world
        .bodies()
        .filter(|(_, b)| b.kind() == BodyKind::Dynamic && !b.is_frozen())
        .map(|(id, b)| (id, b.mass(), b.position()))
        .collect();
    let mut out = Vec::new();
    let [impulse, spawn, despawn, velocity, wake, stale] = actions;
    if impulse && let Some((body, mass, _)) = pick(&mut state, &dynamic) {
        let dv = Vec2::new(
            S::from_ratio(between(&mut state, -48, 48), 16),
            S::from_ratio(between(&mut state, 0, 96), 16),
        );
        out.push(Command::ApplyImpulse {
            body,
            impulse: dv.scale(mass),
        });
    }
    if spawn {
        let top = world
            .bodies()
            .map(|(_, b)| b.aabb().max().y)
            .fold(S::ZERO, S::max);
        let x = pick(&mut state, &dynamic).map_or(S::ZERO, |(_, _, p)| p.x);
        let x = x.add(S::from_ratio(between(&mut state, -16, 16), 16));
        let shape = if splitmix(&mut state).is_multiple_of(2) {
            Shape::circle(S::from_ratio(between(&mut state, 4, 8), 16))
        } else {
            Shape::aabb(Vec2::new(
                S::from_ratio(between(&mut state, 5, 8), 16),
                S::from_ratio(between(&mut state, 5, 8), 16),
            ))
        };
        let position = Vec2::new(x, top.add(S::from_int(2)));
        out.push(Command::Spawn(BodyDef::dynamic(shape).position(position)));
    }
    if despawn && let Some((body, _, _)) = pick(&mut state, &dynamic) {
        out.push(Command::Despawn(body));
    }
    if velocity && let Some((body, _, _)) = pick(&mut state, &dynamic) {
        out.push(Command::SetVelocity {
            body,
            velocity: Vec2::new(
                S::from_ratio(between(&mut state, -32, 32), 16),
                S::from_ratio(between(&mut state, 0, 48), 16),
            ),
        });
    }
    if wake && let Some((body, _, _)) = pick(&mut state, &dynamic) {
        out.push(Command::Wake(body));
    }
    if stale {
        out.push(Command::Despawn(BodyId::from_parts(u32::MAX - 1, 7)));
    }
    out
}
