//! [`SnapshotError`]: why a snapshot or replay file was refused.

use core::fmt;

pub use crate::state::validate::InvalidState;

/// Which kind of clockwork2d file a byte string is (told apart by its
/// magic bytes).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FileKind {
    /// A world snapshot ([`crate::world::World::snapshot`]).
    Snapshot,
    /// A replay ([`crate::replay::Replay`]).
    Replay,
}

impl fmt::Display for FileKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            FileKind::Snapshot => "snapshot",
            FileKind::Replay => "replay",
        })
    }
}

/// Why a snapshot or replay could not be read. Each cause has its own
/// variant so that callers (and the CLI's one-line reasons) can tell a
/// truncated download from a file of another engine version.
///
/// Reading never panics and never allocates more than the declared limits
/// allow, whatever the bytes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum SnapshotError {
    /// The file does not start with the magic bytes of the expected kind.
    WrongMagic {
        /// The kind that was expected.
        expected: FileKind,
        /// The kind the file is, if it is the other clockwork2d kind.
        found: Option<FileKind>,
    },
    /// A format version this build cannot read.
    UnsupportedVersion {
        /// The file's kind.
        kind: FileKind,
        /// The version in the file.
        found: u16,
        /// The version this build reads and writes.
        supported: u16,
    },
    /// A header field is malformed (e.g. a version string that is too long
    /// or not UTF-8).
    BadHeader {
        /// What is wrong.
        reason: &'static str,
    },
    /// The file was written for another scalar type.
    WrongScalar {
        /// The scalar this world uses.
        expected: &'static str,
        /// The scalar id in the file.
        found_id: u8,
        /// The scalar name in the file.
        found_name: String,
    },
    /// The declared payload length is above the decoding limit (refused
    /// before anything is allocated).
    TooLarge {
        /// The declared length in bytes.
        declared: u64,
        /// The limit in bytes.
        limit: u64,
    },
    /// The file ends early.
    Truncated {
        /// The length the header implies (or the least length that could
        /// hold the next field).
        expected: u64,
        /// The actual length.
        actual: u64,
    },
    /// Bytes follow the checksum.
    TrailingBytes {
        /// How many.
        extra: u64,
    },
    /// The checksum does not match the contents: the file was damaged.
    BadChecksum {
        /// The checksum stored in the file.
        stored: u64,
        /// The checksum of the bytes read.
        computed: u64,
    },
    /// The payload is not a valid encoding (bad tag, overlong integer,
    /// limit exceeded, bytes left over).
    Decode {
        /// The decoder's explanation.
        reason: String,
    },
    /// The payload decodes but describes a state the engine could not have
    /// produced (a dead id, a negative radius, an unsorted contact list...).
    Invalid(InvalidState),
}

impl SnapshotError {
    /// An [`SnapshotError::Invalid`] for `part`.
    pub(crate) fn invalid(part: &'static str, detail: impl Into<String>) -> Self {
        SnapshotError::Invalid(InvalidState::new(part, detail))
    }
}

impl From<InvalidState> for SnapshotError {
    fn from(e: InvalidState) -> Self {
        SnapshotError::Invalid(e)
    }
}

impl fmt::Display for SnapshotError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SnapshotError::WrongMagic {
                expected,
                found: Some(found),
            } => write!(f, "this is a clockwork2d {found}, not a {expected}"),
            SnapshotError::WrongMagic {
                expected,
                found: None,
            } => write!(
                f,
                "not a clockwork2d {expected} (wrong magic bytes at the start of the file)"
            ),
            SnapshotError::UnsupportedVersion {
                kind,
                found,
                supported,
            } => write!(
                f,
                "{kind} format version {found} is not supported (this build reads version {supported})"
            ),
            SnapshotError::BadHeader { reason } => write!(f, "malformed header: {reason}"),
            SnapshotError::WrongScalar {
                expected,
                found_id,
                found_name,
            } => write!(
                f,
                "written for scalar {found_name:?} (id {found_id}), but this world uses {expected}"
            ),
            SnapshotError::TooLarge { declared, limit } => write!(
                f,
                "declared payload of {declared} bytes is above the limit of {limit} bytes"
            ),
            SnapshotError::Truncated { expected, actual } => {
                write!(f, "truncated: {actual} bytes, at least {expected} expected")
            }
            SnapshotError::TrailingBytes { extra } => {
                write!(f, "{extra} unexpected bytes after the checksum")
            }
            SnapshotError::BadChecksum { stored, computed } => write!(
                f,
                "checksum mismatch (stored 0x{stored:016x}, computed 0x{computed:016x}): the file is damaged"
            ),
            SnapshotError::Decode { reason } => write!(f, "payload does not decode: {reason}"),
            SnapshotError::Invalid(state) => write!(f, "invalid contents: {state}"),
        }
    }
}

impl std::error::Error for SnapshotError {}
