//! The framing shared by snapshot and replay files (layout in the
//! [module docs](super)): magic, version, crate version, scalar, a
//! kind-specific header, the payload length, the payload and a checksum.
//!
//! Reading checks the cheap, structural things first (magic, version,
//! scalar, declared length against the limit, exact total length) and only
//! then hashes the bytes, so a hostile length is refused before anything is
//! allocated or hashed.

use super::error::{FileKind, SnapshotError};
use crate::hash::StateHasher;

/// Format version written and read by this build (both kinds).
pub const FORMAT_VERSION: u16 = 1;

/// Largest payload accepted (and the bincode decoding limit): 256 MiB.
pub const PAYLOAD_LIMIT: usize = 256 << 20;

/// Longest crate-version or scalar-name string in a header.
const MAX_NAME_LEN: usize = 64;

const SNAPSHOT_MAGIC: [u8; 8] = *b"CW2DSNAP";
const REPLAY_MAGIC: [u8; 8] = *b"CW2DRPLY";

fn magic(kind: FileKind) -> [u8; 8] {
    match kind {
        FileKind::Snapshot => SNAPSHOT_MAGIC,
        FileKind::Replay => REPLAY_MAGIC,
    }
}

/// The decoded frame of a file: header fields and the payload bytes.
#[derive(Clone, Debug)]
pub(crate) struct Envelope<'a> {
    pub(crate) version: u16,
    pub(crate) crate_version: String,
    pub(crate) scalar_id: u8,
    pub(crate) scalar_name: String,
    pub(crate) extra: &'a [u8],
    pub(crate) payload: &'a [u8],
}

/// Writes a complete file around `payload`.
pub(crate) fn write(
    kind: FileKind,
    scalar_id: u8,
    scalar_name: &str,
    extra: &[u8],
    payload: &[u8],
) -> Vec<u8> {
    let version = clamp_name(env!("CARGO_PKG_VERSION"));
    let name = clamp_name(scalar_name);
    let mut out = Vec::with_capacity(payload.len() + extra.len() + 64 + version.len());
    out.extend_from_slice(&magic(kind));
    out.extend_from_slice(&FORMAT_VERSION.to_le_bytes());
    push_name(&mut out, version);
    out.push(scalar_id);
    push_name(&mut out, name);
    out.extend_from_slice(extra);
    out.extend_from_slice(&(payload.len() as u64).to_le_bytes());
    out.extend_from_slice(payload);
    let checksum = checksum(&out);
    out.extend_from_slice(&checksum.to_le_bytes());
    out
}

/// A string cut to at most [`MAX_NAME_LEN`] bytes (on a char boundary), so
/// the one-byte length prefix always fits.
fn clamp_name(s: &str) -> &str {
    let mut end = s.len().min(MAX_NAME_LEN);
    while !s.is_char_boundary(end) {
        end -= 1;
    }
    s.get(..end).unwrap_or("")
}

fn push_name(out: &mut Vec<u8>, s: &str) {
    // `clamp_name` keeps the length ≤ 64, so it fits a byte.
    out.push(u8::try_from(s.len()).unwrap_or(0));
    out.extend_from_slice(s.as_bytes());
}

/// FNV-1a-64 over `bytes` (the engine's [`StateHasher`]): catches damage,
/// not tampering.
pub(crate) fn checksum(bytes: &[u8]) -> u64 {
    let mut h = StateHasher::default();
    h.bytes(bytes);
    h.finish()
}

/// A cursor that reports truncation instead of panicking.
struct Reader<'a> {
    bytes: &'a [u8],
    pos: usize,
}

impl<'a> Reader<'a> {
    fn take(&mut self, n: usize) -> Result<&'a [u8], SnapshotError> {
        let end = self.pos.checked_add(n).ok_or(SnapshotError::Truncated {
            expected: u64::MAX,
            actual: self.bytes.len() as u64,
        })?;
        let out = self
            .bytes
            .get(self.pos..end)
            .ok_or(SnapshotError::Truncated {
                expected: end as u64,
                actual: self.bytes.len() as u64,
            })?;
        self.pos = end;
        Ok(out)
    }

    fn array<const N: usize>(&mut self) -> Result<[u8; N], SnapshotError> {
        let mut out = [0u8; N];
        out.copy_from_slice(self.take(N)?);
        Ok(out)
    }

    fn name(&mut self) -> Result<String, SnapshotError> {
        let [len] = self.array::<1>()?;
        let len = usize::from(len);
        if len > MAX_NAME_LEN {
            return Err(SnapshotError::BadHeader {
                reason: "a name or version string is longer than 64 bytes",
            });
        }
        let bytes = self.take(len)?;
        String::from_utf8(bytes.to_vec()).map_err(|_| SnapshotError::BadHeader {
            reason: "a name or version string is not UTF-8",
        })
    }
}

/// Reads the frame of a `kind` file whose kind-specific header is
/// `extra_len` bytes. With `scalar = Some((id, name))` a file for another
/// scalar is refused (before its length and checksum are looked at).
pub(crate) fn read<'a>(
    bytes: &'a [u8],
    kind: FileKind,
    extra_len: usize,
    scalar: Option<(u8, &'static str)>,
) -> Result<Envelope<'a>, SnapshotError> {
    let expected = magic(kind);
    let head = bytes.get(..expected.len()).unwrap_or(bytes);
    if head != expected.get(..head.len()).unwrap_or(&[]) {
        let other = match kind {
            FileKind::Snapshot => FileKind::Replay,
            FileKind::Replay => FileKind::Snapshot,
        };
        let found = (head == magic(other)).then_some(other);
        return Err(SnapshotError::WrongMagic {
            expected: kind,
            found,
        });
    }
    let mut r = Reader { bytes, pos: 0 };
    r.take(expected.len())?;
    let version = u16::from_le_bytes(r.array()?);
    if version != FORMAT_VERSION {
        return Err(SnapshotError::UnsupportedVersion {
            kind,
            found: version,
            supported: FORMAT_VERSION,
        });
    }
    let crate_version = r.name()?;
    let [scalar_id] = r.array::<1>()?;
    let scalar_name = r.name()?;
    if let Some((id, name)) = scalar
        && id != scalar_id
    {
        return Err(SnapshotError::WrongScalar {
            expected: name,
            found_id: scalar_id,
            found_name: scalar_name,
        });
    }
    let extra = r.take(extra_len)?;
    let declared = u64::from_le_bytes(r.array()?);
    if declared > PAYLOAD_LIMIT as u64 {
        return Err(SnapshotError::TooLarge {
            declared,
            limit: PAYLOAD_LIMIT as u64,
        });
    }
    // Below the limit, so it fits a usize on every target we build for
    // (the limit is far below 2³²).
    let length = usize::try_from(declared).map_err(|_| SnapshotError::TooLarge {
        declared,
        limit: PAYLOAD_LIMIT as u64,
    })?;
    let body_start = r.pos;
    let total = body_start.saturating_add(length).saturating_add(8);
    if bytes.len() < total {
        return Err(SnapshotError::Truncated {
            expected: total as u64,
            actual: bytes.len() as u64,
        });
    }
    if bytes.len() > total {
        return Err(SnapshotError::TrailingBytes {
            extra: (bytes.len() - total) as u64,
        });
    }
    let payload = r.take(length)?;
    let stored = u64::from_le_bytes(r.array()?);
    let computed = checksum(bytes.get(..body_start + length).unwrap_or(&[]));
    if stored != computed {
        return Err(SnapshotError::BadChecksum { stored, computed });
    }
    Ok(Envelope {
        version,
        crate_version,
        scalar_id,
        scalar_name,
        extra,
        payload,
    })
}

/// The bincode configuration of every payload: standard (little endian,
/// varint integers) with a hard limit on the bytes a decode may claim.
pub(crate) fn config() -> impl bincode::config::Config {
    bincode::config::standard().with_limit::<PAYLOAD_LIMIT>()
}

/// Decodes a whole payload with [`config`]; leftover bytes are an error.
pub(crate) fn decode<T: serde::de::DeserializeOwned>(payload: &[u8]) -> Result<T, SnapshotError> {
    let (value, read) =
        bincode::serde::decode_from_slice::<T, _>(payload, config()).map_err(|e| {
            SnapshotError::Decode {
                reason: e.to_string(),
            }
        })?;
    if read != payload.len() {
        return Err(SnapshotError::Decode {
            reason: format!("{} bytes left over after the payload", payload.len() - read),
        });
    }
    Ok(value)
}

/// Encodes a payload with [`config`]. Encoding our own types into a vector
/// cannot fail; an error would mean a bug, and gives an empty payload that
/// the reader refuses rather than a panic.
pub(crate) fn encode<T: serde::Serialize>(value: &T) -> Vec<u8> {
    bincode::serde::encode_to_vec(value, config()).unwrap_or_default()
}
