//! [`SessionError`]: what can go wrong while serving GGRS requests.

use core::fmt;

use clockwork2d::snapshot::SnapshotError;
use ggrs::Frame;

/// A request that the glue could not serve. Each one means the caller broke
/// the GGRS contract (requests out of order, a cell from another session) or
/// a saved state could not be read; the world is left as it was before the
/// failing request.
#[derive(Clone, Debug, PartialEq)]
pub enum SessionError {
    /// A save or load named another frame than the one the world is at
    /// (after the load: the one the loaded state is at).
    FrameMismatch {
        /// The request (`"save"` or `"load"`).
        request: &'static str,
        /// The frame GGRS named.
        requested: Frame,
        /// The frame the world is (or the loaded state was) at.
        actual: Frame,
    },
    /// A load request whose cell holds no state.
    EmptyCell {
        /// The frame GGRS asked to load.
        frame: Frame,
    },
    /// The saved state could not be restored.
    Load(SnapshotError),
    /// GGRS refused a call (its message).
    Session(String),
}

impl fmt::Display for SessionError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SessionError::FrameMismatch {
                request,
                requested,
                actual,
            } => write!(
                f,
                "{request} request for frame {requested} while the world is at frame {actual}: \
                 serve the requests of one advance_frame call in the order given, and only once"
            ),
            SessionError::EmptyCell { frame } => write!(
                f,
                "load request for frame {frame} on a cell that holds no state: was every save \
                 request served?"
            ),
            SessionError::Load(e) => write!(f, "the saved state cannot be loaded: {e}"),
            SessionError::Session(e) => write!(f, "GGRS: {e}"),
        }
    }
}

impl std::error::Error for SessionError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            SessionError::Load(e) => Some(e),
            _ => None,
        }
    }
}
