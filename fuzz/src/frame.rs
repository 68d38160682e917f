//! Frame repair for mutated snapshot and replay files.
//!
//! The file frame (documented in the library's `snapshot` module) ends with
//! a payload length and an FNV-1a-64 checksum of every preceding byte. A
//! random mutation almost always breaks the checksum, so the fuzzer would
//! spend its time on the first few checks. [`repaired`] rewrites the
//! declared payload length to what the file actually holds and recomputes
//! the checksum, so the payload decoder and the state validation see the
//! mutated bytes. The raw bytes are always tried as well (the targets call
//! both), so the frame checks stay fuzzed too.

use clockwork2d::hash::StateHasher;

/// Which kind of file: the kind-specific header length differs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// `CW2DSNAP`, no kind-specific header.
    Snapshot,
    /// `CW2DRPLY`, a 4-byte hash interval after the scalar name.
    Replay,
}

/// The file with its payload length and checksum made consistent with its
/// bytes, or `None` when the header itself is too short to have a payload
/// (the raw bytes already exercise that path) or nothing needed repair.
#[must_use]
pub fn repaired(bytes: &[u8], kind: Kind) -> Option<Vec<u8>> {
    // magic (8) + format version (2)
    let mut pos = 10usize;
    // crate version: length byte + text
    pos = pos.checked_add(1 + usize::from(*bytes.get(pos)?))?;
    // scalar id
    pos += 1;
    // scalar name: length byte + text
    pos = pos.checked_add(1 + usize::from(*bytes.get(pos)?))?;
    if kind == Kind::Replay {
        pos += 4;
    }
    let length_at = pos;
    let payload_start = length_at.checked_add(8)?;
    // The last 8 bytes are the checksum; everything between is payload.
    let payload_len = bytes.len().checked_sub(payload_start)?.checked_sub(8)?;
    let mut out = bytes.to_vec();
    out.get_mut(length_at..payload_start)?
        .copy_from_slice(&(payload_len as u64).to_le_bytes());
    let body_end = payload_start + payload_len;
    let mut hasher = StateHasher::default();
    hasher.bytes(out.get(..body_end)?);
    out.get_mut(body_end..)?
        .copy_from_slice(&hasher.finish().to_le_bytes());
    (out != bytes).then_some(out)
}
