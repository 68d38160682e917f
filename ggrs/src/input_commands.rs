//! [`InputCommands`]: how a game turns one player's input into world
//! commands.

use clockwork2d::prelude::{Command, Fx, Scalar, World};
use ggrs::{InputStatus, PlayerHandle};

/// Turns the input of one player on one frame into [`Command`]s.
///
/// This is the only game logic the glue calls. It must be a pure function
/// of its arguments: the same world, player, input and status give the same
/// commands on every peer (it is called again for every re-simulated frame,
/// so it must not keep state of its own; state that changes during play
/// belongs in the [`World`], which is what rollback saves and restores).
///
/// Remote inputs are whatever a peer sent, so `commands` may receive any
/// value of `Input`. It does not need to validate what it builds: every
/// command goes through [`World::apply`], which refuses an invalid one with
/// a typed error and leaves the world unchanged (the refusal is counted in
/// [`FrameReport::refused`](crate::FrameReport::refused)). Refusals are
/// deterministic, so they never desynchronise peers.
pub trait InputCommands<S: Scalar = Fx> {
    /// The input type of the session (the GGRS `Config::Input`).
    type Input;

    /// Appends to `out` the commands of `player` for the frame that is about
    /// to be simulated from `world`. `status` says whether GGRS confirmed the
    /// input, predicted it, or the player is disconnected (then `input` is
    /// the default input).
    fn commands(
        &self,
        world: &World<S>,
        player: PlayerHandle,
        input: &Self::Input,
        status: InputStatus,
        out: &mut Vec<Command<S>>,
    );
}
