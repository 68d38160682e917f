//! Helpers shared by the fuzz targets in `fuzz_targets/`.
//!
//! * [`cost`]: what a step costs (bodies + touching pairs), and stepping
//!   within a budget of pair-ticks.
//! * [`frame`]: repairs the frame of a mutated snapshot or replay (payload
//!   length and checksum), so that mutations reach the decoder and the
//!   validation instead of stopping at the checksum.
//! * [`roundtrip`]: the snapshot round-trip invariant every accepted world
//!   must satisfy.
//! * [`world_script`]: the structured input of the stateful target and its
//!   invariant checks.
//! * [`geometry_check`]: the input and checks of `geometry_differential`
//!   (`Fx` against the `f64` reference and the geometry, with the derived
//!   error bounds).
//! * [`numbers`]: arbitrary scalars that hit the interesting values (zero,
//!   one ulp, the documented limits and just past them) far more often
//!   than uniform bits would.
#![forbid(unsafe_code)]

pub mod cost;
pub mod frame;
pub mod geometry_check;
pub mod numbers;
pub mod overlap;
pub mod roundtrip;
pub mod world_script;
