//! [`RollbackState`]: what the glue hands GGRS to keep for a frame, and how
//! it comes back.

use clockwork2d::prelude::{Fx, Scalar, World};
use clockwork2d::snapshot::SnapshotError;

/// A saved copy of a world that GGRS keeps in its state cells.
///
/// Two implementations are provided, both complete (everything that
/// affects a later step is kept, see the engine's snapshot guarantees):
///
/// * [`World`] itself: a `clone` to save, a `clone_from` to load. Fastest;
///   the memory is the world's own layout.
/// * [`SnapshotState`]: the snapshot bytes ([`World::snapshot`]) to save,
///   [`World::restore_into`] to load. Smaller, portable, and what a game
///   would send over a wire or write to disk; slower to make and to load.
///
/// The rollback-cost report (`examples/rollback_cost.rs`) measures both.
pub trait RollbackState<S: Scalar = Fx>: Clone + Send + Sync + 'static {
    /// A copy of `world`.
    fn save(world: &World<S>) -> Self;

    /// Overwrites `world` with the saved copy.
    ///
    /// # Errors
    /// The [`SnapshotError`] of a saved copy that cannot be restored (only
    /// possible for byte forms; the world is then unchanged).
    fn load(&self, world: &mut World<S>) -> Result<(), SnapshotError>;
}

impl<S: Scalar> RollbackState<S> for World<S> {
    fn save(world: &World<S>) -> Self {
        world.clone()
    }

    fn load(&self, world: &mut World<S>) -> Result<(), SnapshotError> {
        world.clone_from(self);
        Ok(())
    }
}

/// A world saved as snapshot bytes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SnapshotState(pub Vec<u8>);

impl<S: Scalar> RollbackState<S> for SnapshotState {
    fn save(world: &World<S>) -> Self {
        SnapshotState(world.snapshot())
    }

    fn load(&self, world: &mut World<S>) -> Result<(), SnapshotError> {
        world.restore_into(&self.0)
    }
}
