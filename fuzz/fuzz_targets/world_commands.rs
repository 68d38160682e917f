//! `world_commands` (stateful): an arbitrary small world and an arbitrary
//! stream of commands, steps and restore points, with hostile values and
//! stale ids; the invariants are listed in `src/world_script.rs`.
#![no_main]

use clockwork2d_fuzz::world_script::{Script, run};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|script: Script| {
    run(&script);
});
