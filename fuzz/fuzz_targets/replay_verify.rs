//! `replay_verify`: any bytes → `Replay::from_bytes` → `Replay::verify`.
//!
//! Never a panic, never unbounded memory or time. Decoding is bounded by
//! the library's own limits; re-simulation is bounded here by a budget of
//! body-ticks: a replay whose full verify would cost more is re-simulated
//! only for its first ticks (with the same commands and checkpoint
//! comparison, through the public API), so the fuzzer keeps its speed.
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
use clockwork2d_fuzz::frame::{Kind, repaired};
use libfuzzer_sys::fuzz_target;

/// Most body-ticks re-simulated per input.
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
    let bodies = replay.initial().body_count() as u64 + 1;
    if replay.ticks().saturating_mul(bodies) <= BUDGET {
        if let Ok(report) = replay.verify() {
            assert_eq!(report.ticks, replay.ticks());
            assert_eq!(report.final_tick, replay.final_tick());
            assert_eq!(report.final_hash, replay.final_hash());
        }
    } else {
        partial_verify(&replay, BUDGET / bodies);
    }
}

/// Re-simulates the first `ticks` ticks with the recorded commands, as
/// `verify` does, stopping at the first checkpoint that differs.
fn partial_verify(replay: &Replay<Fx>, ticks: u64) {
    let mut world: World<Fx> = replay.initial().clone();
    let mut commands = replay.commands().iter().peekable();
    let mut checkpoints = replay.checkpoints().iter().peekable();
    let mut batch = Vec::new();
    for _ in 0..ticks {
        batch.clear();
        while let Some((t, c)) = commands.peek() {
            if *t != world.tick() {
                break;
            }
            batch.push(c.clone());
            commands.next();
        }
        world.step_with(&batch);
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
