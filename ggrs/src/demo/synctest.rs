//! [`run_synctest`]: a GGRS sync test of the game.

use std::time::{Duration, Instant};

use clockwork2d::prelude::World;
use ggrs::{Frame, GgrsError, SessionBuilder};

use super::{DuelConfig, DuelInput, InputScript};
use crate::{InputCommands, SessionError, SessionWorld};

/// What a sync test found.
#[derive(Clone, Debug, PartialEq)]
pub struct SyncTestOutcome {
    /// Frames advanced (without the re-simulations).
    pub frames: Frame,
    /// Frames simulated in all, re-simulations included.
    pub simulated: u64,
    /// Wall time.
    pub elapsed: Duration,
    /// The first checksum mismatch GGRS reported: the frame it was found
    /// at and the frames whose checksums differed. `None`: deterministic.
    pub mismatch: Option<(Frame, Vec<Frame>)>,
    /// `state_hash128` at the end.
    pub final_hash: u128,
    /// Commands the world refused (from the random inputs).
    pub refused: usize,
}

/// Runs a `SyncTestSession` with `check_distance` for `frames` frames, both
/// players driven by [`InputScript`]s seeded from `seed`: every frame GGRS
/// rolls back `check_distance` frames, re-simulates, and compares the
/// checksums. Stops at the first mismatch.
///
/// # Errors
/// A [`SessionError`] if a request cannot be served (a bug in the glue, or
/// a GGRS error other than a mismatch, reported as
/// [`SessionError::FrameMismatch`] is impossible here).
pub fn run_synctest<M>(
    world: World,
    rules: M,
    frames: Frame,
    check_distance: usize,
    seed: u64,
) -> Result<SyncTestOutcome, SessionError>
where
    M: InputCommands<Input = DuelInput>,
{
    let start = Instant::now();
    let mut game: SessionWorld<M> = SessionWorld::new(world, rules);
    let mut session = SessionBuilder::<DuelConfig>::new()
        .with_num_players(2)
        .and_then(|b| {
            b.with_max_prediction_window(check_distance + 1)
                .with_check_distance(check_distance)
                .start_synctest_session()
        })
        .map_err(|e| SessionError::Session(e.to_string()))?;
    let mut scripts = [InputScript::new(seed), InputScript::new(seed ^ 0x5EED)];
    let mut simulated = 0u64;
    let mut refused = 0usize;
    let mut mismatch = None;
    for _ in 0..frames {
        for (handle, script) in scripts.iter_mut().enumerate() {
            session
                .add_local_input(handle, script.next_input())
                .map_err(|e| SessionError::Session(e.to_string()))?;
        }
        match session.advance_frame() {
            Ok(requests) => {
                let report = game.handle_requests(requests)?;
                simulated += u64::from(report.advances);
                refused += report.refused.len();
            }
            Err(GgrsError::MismatchedChecksum {
                current_frame,
                mismatched_frames,
            }) => {
                mismatch = Some((current_frame, mismatched_frames));
                break;
            }
            Err(e) => return Err(SessionError::Session(e.to_string())),
        }
    }

    Ok(SyncTestOutcome {
        frames: game.frame(),
        simulated,
        elapsed: start.elapsed(),
        mismatch,
        final_hash: game.checksum(),
        refused,
    })
}
