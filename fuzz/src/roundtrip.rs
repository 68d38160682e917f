//! The snapshot round-trip invariant (promise 2 of the design: snapshots
//! are complete).

use clockwork2d::prelude::{Fx, World};

/// Checks that `world`'s snapshot restores, that the restored world has the
/// same state hash (64- and 128-bit) and writes the same bytes, and returns
/// the restored copy.
///
/// # Panics
/// On any violation: that is the finding.
pub fn assert_roundtrip(world: &World<Fx>, context: &str) -> World<Fx> {
    let bytes = world.snapshot();
    let copy = match World::<Fx>::restore(&bytes) {
        Ok(copy) => copy,
        Err(e) => panic!("{context}: the world's own snapshot was refused: {e}"),
    };
    assert_eq!(
        copy.state_hash(),
        world.state_hash(),
        "{context}: restore changed the state hash"
    );
    assert_eq!(
        copy.state_hash128(),
        world.state_hash128(),
        "{context}: restore changed the 128-bit state hash"
    );
    assert!(
        copy.snapshot() == bytes,
        "{context}: restore → snapshot gave different bytes"
    );
    copy
}
