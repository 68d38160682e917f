//! [`Replay::verify`]: re-simulate and compare with the recorded hashes.

use core::fmt;

use super::{Checkpoint, Replay};
use crate::math::Scalar;
use crate::world::World;

/// A replay that re-simulated to the recorded hashes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct VerifyReport {
    /// Ticks re-simulated.
    pub ticks: u64,
    /// Checkpoints compared (including the initial state).
    pub checkpoints: usize,
    /// The world tick at the end.
    pub final_tick: u64,
    /// The state hash at the end (equal to the recorded one).
    pub final_hash: u64,
    /// The 128-bit state hash at the end.
    pub final_hash128: u128,
}

/// The first checkpoint at which the re-simulation differs from the
/// recording. The divergence happened in the ticks since the previous
/// checkpoint (record with a smaller hash interval to narrow it down).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Divergence {
    /// The world tick of the checkpoint.
    pub tick: u64,
    /// The recorded state hash.
    pub expected: u64,
    /// The re-simulated state hash.
    pub actual: u64,
    /// The parts of the state whose digests differ ("bodies", "contacts",
    /// ...).
    pub parts: Vec<&'static str>,
    /// The crate version that recorded the replay.
    pub recorded_with: String,
}

impl fmt::Display for Divergence {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "diverged at tick {}: state hash 0x{:016x}, recorded 0x{:016x}",
            self.tick, self.actual, self.expected
        )?;
        if self.parts.is_empty() {
            write!(f, " (the part digests agree: the recorded hash is damaged)")?;
        } else {
            write!(f, "; parts that differ: {}", self.parts.join(", "))?;
        }
        let ours = env!("CARGO_PKG_VERSION");
        if self.recorded_with != ours {
            write!(
                f,
                " (recorded with clockwork2d {}, replayed with {ours}: results are only \
                 promised to match within one version)",
                self.recorded_with
            )?;
        }
        Ok(())
    }
}

impl std::error::Error for Divergence {}

impl<S: Scalar> Replay<S> {
    /// Re-simulates the replay from its initial snapshot with its commands
    /// and compares the state hash (and part digests) at every checkpoint.
    ///
    /// # Errors
    /// The first [`Divergence`].
    pub fn verify(&self) -> Result<VerifyReport, Divergence> {
        self.verify_with_progress(|_, _| {})
    }

    /// As [`Replay::verify`], calling `progress(done, total)` after every
    /// tick (for progress bars).
    ///
    /// # Errors
    /// The first [`Divergence`].
    pub fn verify_with_progress(
        &self,
        mut progress: impl FnMut(u64, u64),
    ) -> Result<VerifyReport, Divergence> {
        let mut world = self.initial.clone();
        let mut checkpoints = self.checkpoints.iter();
        let mut compared = 0;
        let mut check = |world: &World<S>, checkpoint: Option<&Checkpoint>| {
            let Some(c) = checkpoint else {
                return Ok(());
            };
            compared += 1;
            let digest = world.state_digest();
            let actual = digest.combined();
            let parts = c.differing_parts(&digest);
            if actual == c.hash && parts.is_empty() && world.tick() == c.tick {
                return Ok(());
            }
            Err(Divergence {
                tick: c.tick,
                expected: c.hash,
                actual,
                parts,
                recorded_with: self.crate_version.clone(),
            })
        };
        check(&world, checkpoints.next())?;
        let k = u64::from(self.hash_interval.max(1));
        let mut next_command = 0;
        let mut batch = Vec::new();
        for done in 1..=self.ticks {
            let tick = world.tick();
            batch.clear();
            while let Some((t, c)) = self.commands.get(next_command)
                && *t == tick
            {
                batch.push(c.clone());
                next_command += 1;
            }
            world.step_with(&batch);
            if done % k == 0 || done == self.ticks {
                check(&world, checkpoints.next())?;
            }
            progress(done, self.ticks);
        }
        Ok(VerifyReport {
            ticks: self.ticks,
            checkpoints: compared,
            final_tick: world.tick(),
            final_hash: world.state_hash(),
            final_hash128: world.state_hash128(),
        })
    }
}
