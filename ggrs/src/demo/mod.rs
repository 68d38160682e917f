//! The example game: two players, each a ball they steer and swing from a
//! grapple rope (the origin document's rope: ray cast, attach, swing,
//! release), in an arena with a stack of boxes, loose balls and a box on a
//! spring. `examples/grapple_duel.rs` runs it headless; the tests of this
//! crate run the same harness.
//!
//! * [`arena`]: the scene;
//! * [`DuelInput`] and [`DuelRules`]: the input and its mapping to commands;
//! * [`run_synctest`]: a GGRS sync test of the game;
//! * [`run_peer`]: one peer of a peer-to-peer (rollback or lockstep)
//!   session over UDP, with desync forensics and a replay of the session.

mod arena;
mod duel_input;
mod duel_rules;
mod pair;
mod peer;
mod synctest;

pub use arena::{Arena, arena};
pub use duel_input::{AIM_DIRECTIONS, DuelInput, InputScript};
pub use duel_rules::{DesyncInjection, DuelRules, NondeterministicRules};
pub use pair::run_pair;
pub use peer::{DesyncReport, PeerError, PeerOptions, PeerOutcome, run_peer};
pub use synctest::{SyncTestOutcome, run_synctest};

/// The GGRS configuration of the game: [`DuelInput`] over UDP, the world
/// saved as itself.
#[derive(Debug)]
pub struct DuelConfig;

impl ggrs::Config for DuelConfig {
    type Input = DuelInput;
    type InputPredictor = ggrs::PredictRepeatLast;
    type State = clockwork2d::prelude::World;
    type Address = std::net::SocketAddr;
}
