//! Replays: an initial snapshot, the commands of every tick, and state
//! hashes every K ticks, so that anyone can re-simulate a recorded session
//! and check it bit for bit.
//!
//! ```
//! use clockwork2d::prelude::*;
//! use clockwork2d::replay::{Recorder, Replay};
//! let mut world = World::new(WorldSettings::default());
//! let ball = world.add_body(BodyDef::dynamic(Shape::circle(fx(0.5)))).unwrap();
//! let mut recorder = Recorder::new(world, 10);
//! for tick in 0..30 {
//!     let commands = if tick == 5 {
//!         vec![Command::ApplyImpulse { body: ball, impulse: Vec2::new(fx(1.0), fx(0.0)) }]
//!     } else {
//!         Vec::new()
//!     };
//!     recorder.step_with(&commands);
//! }
//! let replay = recorder.finish();
//! let bytes = replay.to_bytes();
//! let again: Replay = Replay::from_bytes(&bytes).unwrap();
//! let report = again.verify().unwrap();
//! assert_eq!(report.ticks, 30);
//! ```
//!
//! # File layout (format version 1)
//!
//! The frame of [`crate::snapshot`] with magic `CW2DRPLY` and a 4-byte
//! kind-specific header: the hash interval K (`u32` LE, ≥ 1). The payload
//! (bincode 2 standard, serde) is, in order:
//!
//! 1. the initial world as a complete snapshot file (length-prefixed bytes,
//!    with its own header and checksum);
//! 2. the number of ticks recorded (`u64`);
//! 3. the commands: a list of `(tick, command)` in application order, where
//!    `tick` is the world tick at which the command is applied (before the
//!    step that moves the world from `tick` to `tick + 1`); ticks never
//!    decrease;
//! 4. the checkpoints: `(tick, state hash, part digests)` for the initial
//!    state, every K ticks after it, and the final state, in tick order.
//!    The part digests are those of [`crate::hash::StateDigest::parts`], so
//!    a divergence names the parts that differ.
//!
//! Decoding follows the snapshot rules (bounded, typed errors, never a
//! panic) and also bounds the replay's own tables: at most
//! [`MAX_REPLAY_TICKS`] ticks, [`MAX_REPLAY_COMMANDS`] commands and
//! [`MAX_CHECKPOINTS`] checkpoints, so verifying a replay is bounded work
//! too. A [`Recorder`] that goes past these limits produces a replay that
//! [`Replay::from_bytes`] refuses.

mod recorder;
mod verify;

use serde::{Deserialize, Serialize};

pub use recorder::Recorder;
pub use verify::{Divergence, VerifyReport};

use crate::hash::StateDigest;
use crate::math::Fx;
use crate::math::Scalar;
use crate::snapshot::{
    FileHeader, FileKind, SnapshotError, bounded, decode_payload, encode_payload, read_envelope,
    write_envelope,
};
use crate::world::{Command, World};

/// Most ticks a replay may hold (2²⁶, about 12 days at 60 Hz): bounds the
/// work a hostile file can ask of [`Replay::verify`].
pub const MAX_REPLAY_TICKS: u64 = 1 << 26;
/// Most commands a replay may hold (2²⁰).
pub const MAX_REPLAY_COMMANDS: usize = 1 << 20;
/// Most checkpoints a replay may hold (2²⁰): with K = 1 that is about 4.8
/// hours at 60 Hz; a larger interval records longer sessions.
pub const MAX_CHECKPOINTS: usize = 1 << 20;
/// Most part digests per checkpoint (more than the state has parts).
const MAX_PARTS: usize = 64;

/// The state hash of one tick, with its per-part digests.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Checkpoint {
    /// The world tick (after the step).
    pub tick: u64,
    /// [`World::state_hash`] at that tick.
    pub hash: u64,
    /// The part digests, in the order of [`StateDigest::parts`].
    #[serde(deserialize_with = "bounded::<_, _, MAX_PARTS>")]
    pub parts: Vec<u64>,
}

impl Checkpoint {
    /// The checkpoint of a world's current state.
    #[must_use]
    pub fn of<S: Scalar>(world: &World<S>) -> Checkpoint {
        let digest = world.state_digest();
        Checkpoint {
            tick: world.tick(),
            hash: digest.combined(),
            parts: digest.parts().iter().map(|(_, d)| *d).collect(),
        }
    }

    /// Names of the parts whose digests differ from `digest` (all of them
    /// if the checkpoint was written with another list of parts).
    #[must_use]
    pub fn differing_parts(&self, digest: &StateDigest) -> Vec<&'static str> {
        let actual = digest.parts();
        if actual.len() != self.parts.len() {
            return actual.iter().map(|(name, _)| *name).collect();
        }
        actual
            .iter()
            .zip(&self.parts)
            .filter(|((_, a), e)| a != *e)
            .map(|((name, _), _)| *name)
            .collect()
    }
}

/// A recorded session: build one with [`Recorder`], store it with
/// [`Replay::to_bytes`], check it with [`Replay::verify`].
#[derive(Clone, Debug)]
pub struct Replay<S: Scalar = Fx> {
    pub(crate) crate_version: String,
    pub(crate) hash_interval: u32,
    pub(crate) initial: World<S>,
    pub(crate) ticks: u64,
    pub(crate) commands: Vec<(u64, Command<S>)>,
    pub(crate) checkpoints: Vec<Checkpoint>,
}

/// The payload as written. Field order must match [`PayloadIn`].
#[derive(Serialize)]
#[serde(bound = "")]
struct PayloadOut<'a, S: Scalar> {
    initial: &'a [u8],
    ticks: u64,
    commands: &'a [(u64, Command<S>)],
    checkpoints: &'a [Checkpoint],
}

/// The payload as read, tables bounded. Field order must match
/// [`PayloadOut`].
#[derive(Deserialize)]
#[serde(bound = "")]
struct PayloadIn<S: Scalar> {
    #[serde(deserialize_with = "bounded::<_, _, { crate::snapshot::PAYLOAD_LIMIT }>")]
    initial: Vec<u8>,
    ticks: u64,
    #[serde(deserialize_with = "bounded::<_, _, MAX_REPLAY_COMMANDS>")]
    commands: Vec<(u64, Command<S>)>,
    #[serde(deserialize_with = "bounded::<_, _, MAX_CHECKPOINTS>")]
    checkpoints: Vec<Checkpoint>,
}

impl<S: Scalar> Replay<S> {
    /// The world the replay starts from.
    #[must_use]
    pub fn initial(&self) -> &World<S> {
        &self.initial
    }

    /// Ticks recorded.
    #[must_use]
    pub fn ticks(&self) -> u64 {
        self.ticks
    }

    /// Ticks between recorded state hashes (K).
    #[must_use]
    pub fn hash_interval(&self) -> u32 {
        self.hash_interval
    }

    /// Version of the crate that wrote the replay (this crate's version for
    /// a replay recorded in this process).
    #[must_use]
    pub fn crate_version(&self) -> &str {
        &self.crate_version
    }

    /// Every recorded command with the tick at which it is applied, in
    /// order.
    #[must_use]
    pub fn commands(&self) -> &[(u64, Command<S>)] {
        &self.commands
    }

    /// The recorded checkpoints, in tick order (the first is the initial
    /// state, the last the final state).
    #[must_use]
    pub fn checkpoints(&self) -> &[Checkpoint] {
        &self.checkpoints
    }

    /// The recorded state hash of the final tick.
    #[must_use]
    pub fn final_hash(&self) -> u64 {
        self.checkpoints.last().map_or(0, |c| c.hash)
    }

    /// The world tick at which the replay ends.
    #[must_use]
    pub fn final_tick(&self) -> u64 {
        self.initial.tick().wrapping_add(self.ticks)
    }

    /// Assembles a replay from its parts (for tools that log sessions
    /// themselves, e.g. a lockstep server), with the same table checks as
    /// [`Replay::from_bytes`]. `commands` are `(tick, command)` in
    /// application order; `checkpoints` must be at the initial tick, every
    /// `hash_interval` ticks after it, and at the final tick.
    ///
    /// # Errors
    /// [`SnapshotError::Invalid`] (part `"replay"`) for inconsistent tables,
    /// or the initial world's own invalidity.
    pub fn from_parts(
        initial: World<S>,
        hash_interval: u32,
        ticks: u64,
        commands: Vec<(u64, Command<S>)>,
        checkpoints: Vec<Checkpoint>,
    ) -> Result<Replay<S>, SnapshotError> {
        initial.validate()?;
        if commands.len() > MAX_REPLAY_COMMANDS || checkpoints.len() > MAX_CHECKPOINTS {
            return Err(SnapshotError::invalid(
                "replay",
                "more commands or checkpoints than a replay file may hold",
            ));
        }
        let replay = Replay {
            crate_version: env!("CARGO_PKG_VERSION").to_owned(),
            hash_interval,
            initial,
            ticks,
            commands,
            checkpoints,
        };
        replay.check_tables()?;
        Ok(replay)
    }

    /// The replay as bytes (layout in the [module docs](self)).
    #[must_use]
    pub fn to_bytes(&self) -> Vec<u8> {
        let initial = self.initial.snapshot();
        let payload = encode_payload(&PayloadOut {
            initial: &initial,
            ticks: self.ticks,
            commands: &self.commands,
            checkpoints: &self.checkpoints,
        });
        write_envelope(
            FileKind::Replay,
            S::ID,
            S::NAME,
            &self.hash_interval.to_le_bytes(),
            &payload,
        )
    }

    /// Reads a replay, checking its frame, its initial snapshot and the
    /// consistency of its tables (it does not re-simulate: that is
    /// [`Replay::verify`]).
    ///
    /// # Errors
    /// A [`SnapshotError`]: the framing errors of snapshots, those of the
    /// embedded initial snapshot, and [`SnapshotError::Invalid`] with part
    /// `"replay"` for inconsistent tables.
    pub fn from_bytes(bytes: &[u8]) -> Result<Replay<S>, SnapshotError> {
        let env = read_envelope(bytes, FileKind::Replay, 4, Some((S::ID, S::NAME)))?;
        let header = FileHeader::from_envelope(FileKind::Replay, &env);
        let hash_interval = header.hash_interval.unwrap_or(0);
        let p: PayloadIn<S> = decode_payload(env.payload)?;
        let initial = World::restore(&p.initial)?;
        let replay = Replay {
            crate_version: header.crate_version,
            hash_interval,
            initial,
            ticks: p.ticks,
            commands: p.commands,
            checkpoints: p.checkpoints,
        };
        replay.check_tables()?;
        Ok(replay)
    }

    /// The ticks that must carry a checkpoint: the start, every K ticks,
    /// and the end.
    fn expected_checkpoint_ticks(&self) -> impl Iterator<Item = u64> + '_ {
        let start = self.initial.tick();
        let k = u64::from(self.hash_interval.max(1));
        let regular = (0..=self.ticks / k).map(move |i| start.wrapping_add(i * k));
        let last = (!self.ticks.is_multiple_of(k)).then(|| start.wrapping_add(self.ticks));
        regular.chain(last)
    }

    fn check_tables(&self) -> Result<(), SnapshotError> {
        let bad = |what: String| Err(SnapshotError::invalid("replay", what));
        if self.hash_interval == 0 {
            return bad("the hash interval must be at least 1".to_owned());
        }
        if self.ticks > MAX_REPLAY_TICKS {
            return bad(format!(
                "{} ticks is above the limit of {MAX_REPLAY_TICKS}",
                self.ticks
            ));
        }
        let start = self.initial.tick();
        let Some(end) = start.checked_add(self.ticks) else {
            return bad("the tick count runs past the end of the tick counter".to_owned());
        };
        // Checkpoints bound the work of a verify: the tick count must match
        // them, so it is at most K × MAX_CHECKPOINTS.
        let expected = (self.ticks / u64::from(self.hash_interval))
            .saturating_add(1)
            .saturating_add(u64::from(
                !self.ticks.is_multiple_of(u64::from(self.hash_interval)),
            ));
        if expected != self.checkpoints.len() as u64 {
            return bad(format!(
                "{} checkpoints for {} ticks at interval {} ({expected} expected)",
                self.checkpoints.len(),
                self.ticks,
                self.hash_interval
            ));
        }
        for (c, tick) in self
            .checkpoints
            .iter()
            .zip(self.expected_checkpoint_ticks())
        {
            if c.tick != tick {
                return bad(format!(
                    "checkpoint at tick {} where tick {tick} was expected",
                    c.tick
                ));
            }
        }
        let mut previous = start;
        for (tick, _) in &self.commands {
            if *tick < previous || *tick >= end {
                return bad(format!(
                    "command at tick {tick} is out of order or outside ticks {start}..{end}"
                ));
            }
            previous = *tick;
        }
        Ok(())
    }
}
