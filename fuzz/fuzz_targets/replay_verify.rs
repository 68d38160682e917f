//! `replay_verify`: any bytes → `Replay::from_bytes` → `Replay::verify`.
//!
//! Never a panic, never unbounded memory or time. Decoding is bounded by
//! the library's own limits; re-simulation is bounded here by a budget of
//! pair-ticks (bodies + touching pairs per tick, `src/cost.rs`): a replay
//! whose full verify could cost more is re-simulated only for its first
//! ticks (with the same commands and checkpoint comparison, through the
//! public API, metering the real cost after every tick), so the fuzzer
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
use clockwork2d_fuzz::cost::pairs_near;
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
    // An upper bound on the cost of one tick of the full verify: the
    // initial bodies and their pairs, plus every spawn command as a body
    // that may touch every other body.
    let bodies = replay.initial().body_count() as u64 + 1;
    let commands = replay.commands().len() as u64;
    let per_tick = bodies
        .saturating_add(pairs_near(replay.initial(), BUDGET.saturating_add(1)))
        .saturating_add(commands.saturating_mul(bodies.saturating_add(commands)));
    if replay.ticks().saturating_mul(per_tick) <= BUDGET {
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
/// is spent (metered after every tick; the first tick is estimated).
fn partial_verify(replay: &Replay<Fx>) {
    let mut world: World<Fx> = replay.initial().clone();
    let mut spent = 0u64;
    let mut next =
        (world.body_count() as u64).saturating_add(pairs_near(&world, BUDGET.saturating_add(1)));
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
        if spent.saturating_add(next).saturating_add(extra) > BUDGET {
            return;
        }
        world.step_with(&batch);
        next = (world.body_count() as u64).saturating_add(world.touching_pairs().count() as u64);
        spent = spent.saturating_add(next);
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
