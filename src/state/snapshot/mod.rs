//! Snapshots: the whole state of a [`World`] as bytes, and back.
//!
//! `restore(snapshot(w))` continues bit-identically to `w`, at any tick,
//! mid-contact and mid-sleep: the snapshot holds everything a later step
//! reads (bodies, the contact cache with its warm-start impulses, sleep
//! timers and islands, constraints with their impulses, the id allocators
//! with their free lists, the tick, the settings and the last step's
//! events). Only the step context (the step's working buffers) is left
//! out; it is rebuilt from the state at the start of every step.
//!
//! ```
//! use clockwork2d::prelude::*;
//! let mut world = World::new(WorldSettings::default());
//! world.add_body(BodyDef::dynamic(Shape::circle(fx(0.5)))).unwrap();
//! world.step();
//! let bytes = world.snapshot();
//! let mut copy: World = World::restore(&bytes).unwrap();
//! world.step();
//! copy.step();
//! assert_eq!(world.state_hash(), copy.state_hash());
//! ```
//!
//! # File layout (format version 1)
//!
//! All fixed-width integers are little endian. Snapshot and replay files
//! share the frame; only the magic and the kind-specific header differ.
//!
//! | bytes | field |
//! |---|---|
//! | 8 | magic: `CW2DSNAP` (snapshot) or `CW2DRPLY` (replay) |
//! | 2 | format version, `u16` (1) |
//! | 1 + n | crate version that wrote the file: length byte (≤ 64), UTF-8 |
//! | 1 | scalar id ([`Scalar::ID`]: 1 = `I32F32`, 2 = `I48F16`, 100 = `f64`, 101 = `f32`) |
//! | 1 + m | scalar name ([`Scalar::NAME`]): length byte (≤ 64), UTF-8 |
//! | k | kind-specific header (snapshot: none; replay: hash interval `u32`) |
//! | 8 | payload length `L`, `u64`, at most [`PAYLOAD_LIMIT`] (256 MiB) |
//! | L | payload: bincode 2, `standard()` configuration (varint integers), via serde |
//! | 8 | checksum: FNV-1a-64 of every preceding byte, `u64` |
//!
//! The checksum detects damage (truncated downloads, flipped bits), not
//! tampering: anyone can recompute it. Tampered files are caught by the
//! validation of the contents (see [`SnapshotError::Invalid`]) and, for
//! replays, by the recorded state hashes.
//!
//! The crate version is informational: a file is read whatever crate
//! version wrote it, as long as the format version matches, but the
//! determinism promise (and so a replay's hashes) holds only for the same
//! crate version.
//!
//! The snapshot payload is a compact image of the world (see the
//! `payload` module): body prototypes (shape, mass, material) are stored
//! once and shared, which keeps a snapshot well under 100 bytes per body.
//!
//! # Reading untrusted bytes
//!
//! [`World::restore`] never panics. It checks, in order: magic, format
//! version, scalar, declared payload length against the limit (before
//! allocating), exact total length, checksum; then decodes with bincode's
//! byte limit and per-table element limits ([`MAX_SNAPSHOT_SLOTS`] body
//! slots, [`MAX_SNAPSHOT_CONSTRAINTS`] constraint slots), and finally
//! validates every invariant of the state. Each failure has its own
//! [`SnapshotError`] variant.

mod bounded_seq;
mod envelope;
mod error;
mod payload;

pub use envelope::{FORMAT_VERSION, PAYLOAD_LIMIT};
pub use error::{FileKind, InvalidState, SnapshotError};
pub use payload::{MAX_SNAPSHOT_CONSTRAINTS, MAX_SNAPSHOT_SLOTS};

pub(crate) use bounded_seq::bounded;
pub(crate) use envelope::{Envelope, read as read_envelope, write as write_envelope};
pub(crate) use envelope::{decode as decode_payload, encode as encode_payload};

use crate::math::Scalar;
use crate::world::World;

/// The header of a snapshot or replay file, readable without knowing its
/// scalar type (what `clockwork2d info` prints).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FileHeader {
    /// Snapshot or replay.
    pub kind: FileKind,
    /// Format version.
    pub format_version: u16,
    /// Version of the crate that wrote the file.
    pub crate_version: String,
    /// Scalar id ([`Scalar::ID`]).
    pub scalar_id: u8,
    /// Scalar name ([`Scalar::NAME`]).
    pub scalar_name: String,
    /// Payload length in bytes.
    pub payload_len: u64,
    /// The replay's hash interval (ticks between recorded state hashes);
    /// `None` for snapshots.
    pub hash_interval: Option<u32>,
}

impl FileHeader {
    /// Reads and checks the frame of a snapshot or replay (magic, version,
    /// lengths, checksum) without decoding the payload.
    ///
    /// # Errors
    /// Any framing [`SnapshotError`]; a file that is neither kind gives
    /// [`SnapshotError::WrongMagic`] with `expected: Snapshot`.
    pub fn read(bytes: &[u8]) -> Result<FileHeader, SnapshotError> {
        let kind = if bytes.starts_with(b"CW2DRPLY") {
            FileKind::Replay
        } else {
            FileKind::Snapshot
        };
        let extra_len = match kind {
            FileKind::Snapshot => 0,
            FileKind::Replay => 4,
        };
        let env = read_envelope(bytes, kind, extra_len, None)?;
        Ok(Self::from_envelope(kind, &env))
    }

    pub(crate) fn from_envelope(kind: FileKind, env: &Envelope<'_>) -> FileHeader {
        let hash_interval = match kind {
            FileKind::Snapshot => None,
            FileKind::Replay => env.extra.try_into().ok().map(u32::from_le_bytes),
        };
        FileHeader {
            kind,
            format_version: env.version,
            crate_version: env.crate_version.clone(),
            scalar_id: env.scalar_id,
            scalar_name: env.scalar_name.clone(),
            payload_len: env.payload.len() as u64,
            hash_interval,
        }
    }
}

impl<S: Scalar> World<S> {
    /// The whole state as bytes (layout in [`crate::snapshot`]). Restoring
    /// them with [`World::restore`] gives a world that continues
    /// bit-identically.
    #[must_use]
    pub fn snapshot(&self) -> Vec<u8> {
        let payload = payload::encode(self);
        write_envelope(FileKind::Snapshot, S::ID, S::NAME, &[], &payload)
    }

    /// Rebuilds a world from [`World::snapshot`] bytes.
    ///
    /// # Errors
    /// A [`SnapshotError`] saying why the bytes were refused (see the
    /// [module docs](crate::snapshot) for the order of the checks).
    pub fn restore(bytes: &[u8]) -> Result<World<S>, SnapshotError> {
        let env = read_envelope(bytes, FileKind::Snapshot, 0, Some((S::ID, S::NAME)))?;
        let world = payload::decode::<S>(env.payload)?;
        world.validate()?;
        Ok(world)
    }

    /// Replaces this world by the one in `bytes`; on error the world is
    /// unchanged (the bytes are fully decoded and validated first).
    ///
    /// # Errors
    /// As [`World::restore`].
    pub fn restore_into(&mut self, bytes: &[u8]) -> Result<(), SnapshotError> {
        *self = World::restore(bytes)?;
        Ok(())
    }
}

#[cfg(test)]
mod tests;
