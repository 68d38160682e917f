//! `snapshot_restore`: any bytes → `World::restore`.
//!
//! Never a panic. Any accepted world satisfies the validation invariants
//! (restore validates; here that is checked again through its own
//! snapshot), and so does every world it steps into: it steps 10 ticks, and
//! at the start and after every tick its snapshot restores to the same
//! hash and the same bytes, and the restored copy steps in lockstep with
//! the original.
//!
//! Each input is tried raw (frame checks) and with its payload length and
//! checksum repaired (payload decoding and validation).
#![no_main]

use clockwork2d::prelude::{Fx, World};
use clockwork2d_fuzz::frame::{Kind, repaired};
use clockwork2d_fuzz::roundtrip::assert_roundtrip;
use libfuzzer_sys::fuzz_target;

/// Ticks an accepted world is stepped.
const TICKS: u64 = 10;

fn exercise(bytes: &[u8]) {
    let Ok(mut world) = World::<Fx>::restore(bytes) else {
        return;
    };
    let mut copy = assert_roundtrip(&world, "restored");
    for tick in 1..=TICKS {
        world.step();
        copy.step();
        assert_eq!(
            world.state_hash(),
            copy.state_hash(),
            "the restored copy diverged at tick {tick} after the restore"
        );
        assert_roundtrip(&world, &format!("tick {tick}"));
    }
}

fuzz_target!(|data: &[u8]| {
    exercise(data);
    if let Some(fixed) = repaired(data, Kind::Snapshot) {
        exercise(&fixed);
    }
});
