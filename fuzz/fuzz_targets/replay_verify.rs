//! `replay_verify`: any bytes → `Replay::from_bytes` → `Replay::verify`.
//!
//! Never a panic, never unbounded memory or time. Decoding is bounded by
//! the library's own limits; re-simulation is bounded here by a budget of
//! pair-ticks (bodies + touching pairs per tick, `src/cost.rs`): a replay
//! whose full verify could cost more is re-simulated only for its first
//! ticks (with the same commands and checkpoint comparison, through the
//! public API, estimating every tick before it and metering it after), so the fuzzer
//! keeps its speed.
//!
//! An accepted replay also round-trips: `to_bytes` → `from_bytes` gives
//! the same bytes. When a verify succeeds its report must agree with the
//! replay (tick count, final tick, final hash).
//!
//! Each input is tried raw and with its outer frame repaired (payload
//! length and checksum), so mutations reach the payload decoder.
#![no_main]

use clockwork2d::prelude::{Fx, World};
use clockwork2d::replay::Replay;
use clockwork2d_fuzz::cost::{most_pairs, tick_cost};
use clockwork2d_fuzz::frame::{Kind, repaired};
use libfuzzer_sys::fuzz_target;

/// Most pair-ticks re-simulated per input.
const BUDGET: u64 = 20_000;

fn exercise(bytes: &[u8]) {
    let Ok(replay) = Replay::<Fx>::from_bytes(bytes) else {
        return;
    };
    let again = replay.to_bytes();
    match Replay::<Fx>::from_bytes(&again) {
        Ok(copy) => assert!(copy.to_bytes() == again, "replay bytes do not round-trip"),
        Err(e) => panic!("a decoded replay's own bytes were refused: {e}"),
    }
    // An upper bound on the cost of the full verify, which cannot be
    // metered as it runs: the first tick by the pairs near the initial
    // bodies, every later tick by the most pairs the bodies can form (one
    // tick can multiply the pairs: see `src/cost.rs`), and every spawn
    // command as a body that may touch every other body.
    let bodies = replay.initial().body_count() as u64 + 1;
    let commands = replay.commands().len() as u64;
    let spawned = commands.saturating_mul(bodies.saturating_add(commands));
    let first = tick_cost(replay.initial(), BUDGET.saturating_add(1)).saturating_add(spawned);
    let later = bodies
        .saturating_add(commands)
        .saturating_add(most_pairs(bodies.saturating_add(commands)))
        .saturating_add(spawned);
    let full_cost = match replay.ticks() {
        0 => 0,
        ticks => first.saturating_add((ticks - 1).saturating_mul(later)),
    };
    if full_cost <= BUDGET {
        if let Ok(report) = replay.verify() {
            assert_eq!(report.ticks, replay.ticks());
            assert_eq!(report.final_tick, replay.final_tick());
            assert_eq!(report.final_hash, replay.final_hash());
        }
    } else {
        partial_verify(&replay);
    }
}

/// Re-simulates the first ticks with the recorded commands, as `verify`
/// does, stopping at the first checkpoint that differs or when the budget
/// is spent (every tick estimated before it is stepped and metered after).
fn partial_verify(replay: &Replay<Fx>) {
    let mut world: World<Fx> = replay.initial().clone();
    let mut spent = 0u64;
    let mut commands = replay.commands().iter().peekable();
    let mut checkpoints = replay.checkpoints().iter().peekable();
    let mut batch = Vec::new();
    for _ in 0..replay.ticks() {
        batch.clear();
        while let Some((t, c)) = commands.peek() {
            if *t != world.tick() {
                break;
            }
            batch.push(c.clone());
            commands.next();
        }
        // Each command may add a body touching every other one.
        let extra = (batch.len() as u64)
            .saturating_mul((world.body_count() as u64).saturating_add(batch.len() as u64));
        let left = BUDGET.saturating_sub(spent);
        let estimate = tick_cost(&world, left.saturating_add(1)).saturating_add(extra);
        if estimate > left {
            return;
        }
        world.step_with(&batch);
        let reported =
            (world.body_count() as u64).saturating_add(world.touching_pairs().count() as u64);
        spent = spent.saturating_add(estimate.max(reported));
        while checkpoints.peek().is_some_and(|c| c.tick < world.tick()) {
            checkpoints.next();
        }
        if let Some(c) = checkpoints.peek()
            && c.tick == world.tick()
            && c.hash != world.state_hash()
        {
            return;
        }
    }
}

fuzz_target!(|data: &[u8]| {
    exercise(data);
    if let Some(fixed) = repaired(data, Kind::Replay) {
        exercise(&fixed);
    }
});
