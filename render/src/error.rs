//! [`RenderError`]: everything that can go wrong making a picture.

use std::fmt;
use std::path::PathBuf;

/// A picture could not be made or written. Each message says what to
/// change.
#[derive(Debug)]
#[non_exhaustive]
pub enum RenderError {
    /// A picture side is zero or larger than [`MAX_SIDE`](crate::MAX_SIDE).
    BadSize {
        /// Requested width in pixels.
        width: u32,
        /// Requested height in pixels.
        height: u32,
    },
    /// The output path's extension names no format this crate writes.
    UnsupportedFormat(PathBuf),
    /// A world without bodies has nothing to frame.
    EmptyWorld,
    /// A frame every 0 ticks.
    BadFrameInterval,
    /// Reading or writing a file failed.
    Io(std::io::Error),
    /// The GIF or PNG encoder refused the data.
    Encode(String),
}

impl fmt::Display for RenderError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            RenderError::BadSize { width, height } => write!(
                f,
                "picture size {width}x{height} is not allowed: each side must be 1..={} pixels",
                crate::MAX_SIDE
            ),
            RenderError::UnsupportedFormat(path) => write!(
                f,
                "cannot tell the picture format of {}: use a .gif (animation) or .png (one frame) file name",
                path.display()
            ),
            RenderError::EmptyWorld => {
                write!(f, "the world has no bodies, so there is nothing to frame")
            }
            RenderError::BadFrameInterval => {
                write!(f, "a frame every 0 ticks is not possible: give 1 or more")
            }
            RenderError::Io(e) => write!(f, "cannot write the picture: {e}"),
            RenderError::Encode(e) => write!(f, "cannot encode the picture: {e}"),
        }
    }
}

impl std::error::Error for RenderError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            RenderError::Io(e) => Some(e),
            _ => None,
        }
    }
}

impl From<std::io::Error> for RenderError {
    fn from(e: std::io::Error) -> Self {
        RenderError::Io(e)
    }
}

impl From<gif::EncodingError> for RenderError {
    fn from(e: gif::EncodingError) -> Self {
        match e {
            gif::EncodingError::Io(e) => RenderError::Io(e),
            other => RenderError::Encode(other.to_string()),
        }
    }
}

impl From<png::EncodingError> for RenderError {
    fn from(e: png::EncodingError) -> Self {
        match e {
            png::EncodingError::IoError(e) => RenderError::Io(e),
            other => RenderError::Encode(other.to_string()),
        }
    }
}
