//! `snapshot_restore`: any bytes → `World::restore`.
//!
//! Never a panic. Any accepted world satisfies the validation invariants
//! (restore validates; here that is checked again through its own
//! snapshot), and so does every world it steps into: it steps 10 ticks, and
//! at the start and after every tick its snapshot restores to the same
//! hash and the same bytes, the restored copy steps in lockstep with the
//! original, and no body leaves a tick faster than `max_speed` (per axis).
//!
//! Each input is tried raw (frame checks) and with its payload length and
//! checksum repaired (payload decoding and validation).
//!
//! Time is bounded by a budget of pair-ticks (`src/cost.rs`): a valid world
//! of many overlapping bodies costs about 3 µs per touching pair per tick,
//! so it is stepped fewer than 10 ticks (or none) instead of stalling the
//! fuzzer; the restore and round-trip checks always run.
#![no_main]

use clockwork2d::prelude::{Fx, World};
use clockwork2d_fuzz::cost::step_within;
use clockwork2d_fuzz::frame::{Kind, repaired};
use clockwork2d_fuzz::roundtrip::assert_roundtrip;
use libfuzzer_sys::fuzz_target;

/// Ticks an accepted world is stepped (within the budget).
const TICKS: u64 = 10;
/// Most pair-ticks (bodies + touching pairs, summed over the ticks) spent
/// on the original world; the copy costs as much again. About 0.5 s in a
/// release build at the measured 3 µs per pair-tick, so a few seconds in
/// the instrumented fuzz build: far below libFuzzer's 30 s timeout even on
/// a loaded machine. `large_pyramid` (5 051 bodies, ~15 000 pairs) gets 7
/// ticks.
const BUDGET: u64 = 150_000;

fn exercise(bytes: &[u8]) {
    let Ok(mut world) = World::<Fx>::restore(bytes) else {
        return;
    };
    let mut copy = assert_roundtrip(&world, "restored");
    step_within(&mut world, TICKS, BUDGET, |world, tick| {
        copy.step();
        assert_eq!(
            world.state_hash(),
            copy.state_hash(),
            "the restored copy diverged at tick {tick} after the restore"
        );
        assert_roundtrip(world, &format!("tick {tick}"));
        let max_speed = world.settings().max_speed;
        for (id, body) in world.bodies() {
            let v = body.velocity();
            assert!(
                v.x.abs() <= max_speed && v.y.abs() <= max_speed,
                "{id} left tick {tick} at {v:?}, above max_speed {max_speed}"
            );
        }
    });
}

fuzz_target!(|data: &[u8]| {
    exercise(data);
    if let Some(fixed) = repaired(data, Kind::Snapshot) {
        exercise(&fixed);
    }
});
