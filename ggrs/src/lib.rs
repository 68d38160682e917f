#![doc = include_str!("../README.md")]
#![forbid(unsafe_code)]
// The game rules and the glue are on the simulation path: no floats.
#![deny(clippy::float_arithmetic)]

pub mod demo;
mod error;
mod input_commands;
pub mod net;
mod rollback_state;
mod seeded_rng;
mod session_world;

pub use error::SessionError;
pub use input_commands::InputCommands;
pub use rollback_state::{RollbackState, SnapshotState};
pub use seeded_rng::SeededRng;
pub use session_world::{FORENSIC_COPIES, FrameReport, HASH_HISTORY, RefusedCommand, SessionWorld};
