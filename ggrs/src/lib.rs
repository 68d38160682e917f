//! # clockwork2d-ggrs
//!
//! Runs a [clockwork2d] world under [GGRS](ggrs): rollback
//! sessions, lockstep sessions (`max_prediction = 0`) and sync tests.
//!
//! The whole rollback state is the [`World`](clockwork2d::World): a game
//! keeps everything that changes during play in it (bodies, constraints such
//! as a grapple rope) and maps each player's input to
//! [`Command`](clockwork2d::Command)s with an [`InputCommands`]. The glue,
//! [`SessionWorld`], serves GGRS's requests in order: save (with the
//! checksum [`World::state_hash128`](clockwork2d::World::state_hash128)),
//! load, advance.
//!
//! ```
//! use clockwork2d::prelude::*;
//! use clockwork2d_ggrs::{InputCommands, SessionWorld};
//! use ggrs::{Config, InputStatus, PlayerHandle, PredictRepeatLast, SessionBuilder};
//!
//! /// One byte per player: bit 0 pushes the player's ball to the right.
//! struct Push { balls: [BodyId; 2] }
//!
//! impl InputCommands for Push {
//!     type Input = u8;
//!     fn commands(&self, _: &World, player: PlayerHandle, input: &u8, _: InputStatus,
//!                 out: &mut Vec<Command>) {
//!         if input & 1 == 1 {
//!             // An id from a remote input is still checked by the world.
//!             out.push(Command::ApplyImpulse {
//!                 body: self.balls[player % 2],
//!                 impulse: Vec2::new(fx(0.5), fx(0.0)),
//!             });
//!         }
//!     }
//! }
//!
//! struct Cfg;
//! impl Config for Cfg {
//!     type Input = u8;
//!     type InputPredictor = PredictRepeatLast;
//!     type State = World;
//!     type Address = std::net::SocketAddr;
//! }
//!
//! let mut world = World::new(WorldSettings::default());
//! let a = world.add_body(BodyDef::dynamic(Shape::circle(fx(0.5)))).unwrap();
//! let b = world.add_body(BodyDef::dynamic(Shape::circle(fx(0.5)))
//!     .position(Vec2::new(fx(3.0), fx(0.0)))).unwrap();
//! let mut game: SessionWorld<Push> = SessionWorld::new(world, Push { balls: [a, b] });
//!
//! let mut session = SessionBuilder::<Cfg>::new()
//!     .with_num_players(2).unwrap()
//!     .with_check_distance(7)
//!     .start_synctest_session().unwrap();
//! for frame in 0..60u8 {
//!     session.add_local_input(0, frame % 3).unwrap();
//!     session.add_local_input(1, frame % 5).unwrap();
//!     // A checksum mismatch comes back as Err(MismatchedChecksum).
//!     let requests = session.advance_frame().unwrap();
//!     game.handle_requests(requests).unwrap();
//! }
//! assert_eq!(game.frame(), 60);
//! ```
//!
//! The crate also holds the example game ([`demo`]: two players with grapple
//! ropes) and the harness that runs it headless (sync test, peer-to-peer over
//! a lossy UDP link, lockstep, desync forensics, replays); see
//! `examples/grapple_duel.rs`.
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
