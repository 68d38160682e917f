//! [`OutputFormat`]: which file a picture is written as.

use std::path::Path;

use crate::RenderError;

/// The picture formats this crate writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OutputFormat {
    /// An animated GIF: one frame per drawn picture.
    Gif,
    /// A PNG of one picture.
    Png,
}

impl OutputFormat {
    /// The format named by `path`'s extension (`.gif` or `.png`, any case).
    ///
    /// # Errors
    /// [`RenderError::UnsupportedFormat`] for any other or no extension.
    pub fn from_path(path: &Path) -> Result<OutputFormat, RenderError> {
        match path
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase)
            .as_deref()
        {
            Some("gif") => Ok(OutputFormat::Gif),
            Some("png") => Ok(OutputFormat::Png),
            _ => Err(RenderError::UnsupportedFormat(path.to_path_buf())),
        }
    }
}
