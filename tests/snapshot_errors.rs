//! Each way a snapshot file can be wrong gives its own typed error with a
//! readable message, and a refused restore leaves the world unchanged.

use clockwork2d::prelude::*;
use clockwork2d::replay::Recorder;
use clockwork2d::snapshot::{FileHeader, FileKind, PAYLOAD_LIMIT, SnapshotError};
use clockwork2d_scene::builtin;

mod common;
use common::file_checksum::fix_checksum;

fn stack_at(ticks: u64) -> World {
    let mut w: World = builtin("stack").unwrap().build().unwrap();
    for _ in 0..ticks {
        w.step();
    }
    w
}

/// Offset of the payload-length field (after magic, version, crate
/// version, scalar id and name).
fn length_offset(bytes: &[u8]) -> usize {
    let v = usize::from(bytes[10]);
    let name = usize::from(bytes[11 + v + 1]);
    11 + v + 2 + name
}

fn restore(bytes: &[u8]) -> Result<World, SnapshotError> {
    World::restore(bytes)
}

#[test]
fn a_good_snapshot_has_the_documented_header() {
    let bytes = stack_at(30).snapshot();
    assert_eq!(&bytes[..8], b"CW2DSNAP");
    assert_eq!(u16::from_le_bytes([bytes[8], bytes[9]]), 1);
    let header = FileHeader::read(&bytes).unwrap();
    assert_eq!(header.kind, FileKind::Snapshot);
    assert_eq!(header.crate_version, env!("CARGO_PKG_VERSION"));
    assert_eq!(header.scalar_id, Fx::ID);
    assert_eq!(header.scalar_name, "I32F32");
    assert_eq!(header.hash_interval, None);
    let at = length_offset(&bytes);
    let declared = u64::from_le_bytes(bytes[at..at + 8].try_into().unwrap());
    assert_eq!(declared, header.payload_len);
    assert_eq!(bytes.len() as u64, at as u64 + 8 + declared + 8);
}

#[test]
fn wrong_magic() {
    let mut bytes = stack_at(1).snapshot();
    bytes[0] = b'X';
    let e = restore(&bytes).unwrap_err();
    assert_eq!(
        e,
        SnapshotError::WrongMagic {
            expected: FileKind::Snapshot,
            found: None
        }
    );
    assert!(e.to_string().contains("not a clockwork2d snapshot"), "{e}");
    assert!(matches!(
        restore(b"hello world, this is not a snapshot"),
        Err(SnapshotError::WrongMagic { .. })
    ));
    assert!(matches!(
        restore(b"PNG"),
        Err(SnapshotError::WrongMagic { .. })
    ));
}

#[test]
fn a_replay_is_not_a_snapshot() {
    let mut recorder = Recorder::new(stack_at(0), 5);
    recorder.step();
    let bytes = recorder.finish().to_bytes();
    let e = restore(&bytes).unwrap_err();
    assert_eq!(
        e,
        SnapshotError::WrongMagic {
            expected: FileKind::Snapshot,
            found: Some(FileKind::Replay)
        }
    );
    assert_eq!(
        e.to_string(),
        "this is a clockwork2d replay, not a snapshot"
    );
}

#[test]
fn unsupported_version() {
    let mut bytes = stack_at(1).snapshot();
    bytes[8] = 2;
    let e = restore(&bytes).unwrap_err();
    assert_eq!(
        e,
        SnapshotError::UnsupportedVersion {
            kind: FileKind::Snapshot,
            found: 2,
            supported: 1
        }
    );
    assert!(e.to_string().contains("version 2 is not supported"), "{e}");
}

#[test]
fn wrong_scalar() {
    use fixed::types::I48F16;
    let w: World<I48F16> = builtin("stack").unwrap().build().unwrap();
    let e = restore(&w.snapshot()).unwrap_err();
    assert_eq!(
        e,
        SnapshotError::WrongScalar {
            expected: "I32F32",
            found_id: 2,
            found_name: "I48F16".to_owned()
        }
    );
    assert!(e.to_string().contains("this world uses I32F32"), "{e}");
}

#[test]
fn truncated_at_every_length() {
    let bytes = stack_at(100).snapshot();
    for n in 0..bytes.len() {
        match restore(&bytes[..n]) {
            Err(SnapshotError::Truncated { actual, .. }) => assert_eq!(actual, n as u64),
            other => panic!("length {n}: expected Truncated, got {other:?}"),
        }
    }
    let e = restore(&bytes[..bytes.len() / 2]).unwrap_err();
    assert!(e.to_string().starts_with("truncated:"), "{e}");
}

#[test]
fn trailing_bytes() {
    let mut bytes = stack_at(10).snapshot();
    bytes.extend_from_slice(&[0, 0, 0]);
    let e = restore(&bytes).unwrap_err();
    assert_eq!(e, SnapshotError::TrailingBytes { extra: 3 });
    assert!(e.to_string().contains("3 unexpected bytes"), "{e}");
}

#[test]
fn bad_checksum() {
    let mut bytes = stack_at(10).snapshot();
    let middle = bytes.len() / 2;
    bytes[middle] ^= 0x10;
    let e = restore(&bytes).unwrap_err();
    assert!(matches!(e, SnapshotError::BadChecksum { .. }), "{e:?}");
    assert!(e.to_string().contains("damaged"), "{e}");
}

#[test]
fn declared_length_above_the_limit_is_refused_before_reading() {
    let mut bytes = stack_at(10).snapshot();
    let at = length_offset(&bytes);
    let huge = (PAYLOAD_LIMIT as u64) + 1;
    bytes[at..at + 8].copy_from_slice(&huge.to_le_bytes());
    let e = restore(&bytes).unwrap_err();
    assert_eq!(
        e,
        SnapshotError::TooLarge {
            declared: huge,
            limit: PAYLOAD_LIMIT as u64
        }
    );
    bytes[at..at + 8].copy_from_slice(&u64::MAX.to_le_bytes());
    assert!(matches!(
        restore(&bytes),
        Err(SnapshotError::TooLarge { .. })
    ));
    // Just under the limit: the file is too short, refused without reading.
    bytes[at..at + 8].copy_from_slice(&(PAYLOAD_LIMIT as u64).to_le_bytes());
    assert!(matches!(
        restore(&bytes),
        Err(SnapshotError::Truncated { .. })
    ));
}

#[test]
fn payload_that_does_not_decode() {
    let mut bytes = stack_at(10).snapshot();
    let start = length_offset(&bytes) + 8;
    // An enum tag far out of range early in the payload.
    for b in &mut bytes[start..start + 40] {
        *b = 0xFF;
    }
    fix_checksum(&mut bytes);
    let e = restore(&bytes).unwrap_err();
    assert!(matches!(e, SnapshotError::Decode { .. }), "{e:?}");
    assert!(e.to_string().starts_with("payload does not decode"), "{e}");
}

#[test]
fn huge_table_lengths_are_refused_without_allocating() {
    // An empty world's payload ends with the empty tables (one zero byte
    // each). Claim 2^62 entries in each in turn: the bounded decoder must
    // refuse before reserving memory.
    let empty = World::new(WorldSettings::default());
    let bytes = empty.snapshot();
    let end = bytes.len() - 8;
    let mut refused = 0;
    for back in 1..=7 {
        let i = end - back;
        if bytes[i] != 0 {
            continue;
        }
        let mut patched = bytes[..i].to_vec();
        patched.push(0xFD); // bincode varint: a u64 follows
        patched.extend_from_slice(&(1u64 << 62).to_le_bytes());
        patched.extend_from_slice(&bytes[i + 1..]);
        let at = length_offset(&patched);
        let len = u64::from_le_bytes(patched[at..at + 8].try_into().unwrap()) + 8;
        patched[at..at + 8].copy_from_slice(&len.to_le_bytes());
        fix_checksum(&mut patched);
        let e = restore(&patched).unwrap_err();
        assert!(matches!(e, SnapshotError::Decode { .. }), "{e:?}");
        refused += 1;
    }
    assert!(refused >= 5);
}

#[test]
fn left_over_payload_bytes_are_refused() {
    let mut bytes = stack_at(10).snapshot();
    let at = length_offset(&bytes);
    let len = u64::from_le_bytes(bytes[at..at + 8].try_into().unwrap());
    let end = bytes.len() - 8;
    bytes.insert(end, 0);
    bytes[at..at + 8].copy_from_slice(&(len + 1).to_le_bytes());
    fix_checksum(&mut bytes);
    let e = restore(&bytes).unwrap_err();
    assert!(matches!(e, SnapshotError::Decode { .. }), "{e:?}");
    assert!(e.to_string().contains("left over"), "{e}");
}

#[test]
fn refused_restore_into_leaves_the_world_unchanged() {
    let mut world = stack_at(50);
    let before = world.snapshot();
    let hash = world.state_hash();
    let mut other = stack_at(80).snapshot();
    other.truncate(other.len() - 1);
    assert!(world.restore_into(&other).is_err());
    assert!(world.restore_into(b"garbage").is_err());
    assert_eq!(world.state_hash(), hash);
    assert_eq!(world.snapshot(), before);
    // And a good one is taken.
    let good = stack_at(80);
    world.restore_into(&good.snapshot()).unwrap();
    assert_eq!(world.state_hash(), good.state_hash());
}

#[test]
fn every_error_reads_as_one_line() {
    let errors = [
        restore(b"").unwrap_err(),
        restore(b"CW2DSNAP").unwrap_err(),
        restore(b"nope nope nope").unwrap_err(),
    ];
    for e in errors {
        let text = e.to_string();
        assert!(!text.is_empty() && !text.contains('\n'), "{text:?}");
    }
}
