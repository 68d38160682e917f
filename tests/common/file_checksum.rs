//! Re-sealing edited snapshot and replay files.

use clockwork2d::hash::StateHasher;

/// Rewrites the trailing checksum (FNV-1a-64 of every preceding byte, the
/// file frame's last 8 bytes) so that a test's edit is judged on its
/// contents, not caught by the checksum. Shorter than 8 bytes: left as is.
pub fn fix_checksum(bytes: &mut [u8]) {
    if bytes.len() < 8 {
        return;
    }
    let n = bytes.len() - 8;
    let mut h = StateHasher::default();
    h.bytes(&bytes[..n]);
    bytes[n..].copy_from_slice(&h.finish().to_le_bytes());
}
