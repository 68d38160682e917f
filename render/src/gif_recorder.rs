//! [`GifRecorder`]: pictures in, an animated GIF out, kept small.

use std::borrow::Cow;
use std::io::Write;

use crate::{Canvas, Colour, RenderError};

/// The transparent palette index of every frame after the first: "this
/// pixel is as before". Not a drawing colour (those are 0..16).
pub const UNCHANGED: u8 = 16;

/// The GIF's global palette: the 16 drawing colours, then 16 black entries
/// (GIF palettes have a power-of-two size; index 16 is [`UNCHANGED`]).
#[must_use]
pub fn gif_global_palette() -> Vec<u8> {
    let mut palette = Colour::gif_palette();
    palette.resize(32 * 3, 0);
    palette
}

/// Writes pictures as the frames of a looping GIF.
///
/// All frames share one global palette: the 16 colours, padded to 32
/// entries with index [`UNCHANGED`] as the transparent colour. Only the
/// rectangle that changed since the previous frame is stored (disposal
/// "keep": the rest of the picture stays), pixels inside it that did not
/// change are stored as [`UNCHANGED`] (long runs of one index, which LZW
/// codes in a few bits), and a frame identical to the previous one only
/// extends its display time, so a scene that comes to rest costs almost
/// nothing.
pub struct GifRecorder<W: Write> {
    encoder: gif::Encoder<W>,
    width: u16,
    height: u16,
    delay: u16,
    /// The last picture, as palette indices (what the viewer shows now,
    /// once `pending` is written).
    previous: Option<Vec<u8>>,
    /// The last frame, not yet written (its delay may still grow).
    pending: Option<gif::Frame<'static>>,
    frames: u32,
}

impl<W: Write> GifRecorder<W> {
    /// A GIF of `width × height` pixels, each frame shown for
    /// `delay_centiseconds` (GIF time unit: 1/100 s; 0 is taken as 1).
    ///
    /// # Errors
    /// [`RenderError::BadSize`] for a side of 0 or above
    /// [`MAX_SIDE`](crate::MAX_SIDE); [`RenderError::Io`] when the header
    /// cannot be written.
    pub fn new(
        out: W,
        width: u32,
        height: u32,
        delay_centiseconds: u16,
    ) -> Result<GifRecorder<W>, RenderError> {
        let bad = RenderError::BadSize { width, height };
        if width == 0 || height == 0 || width > crate::MAX_SIDE || height > crate::MAX_SIDE {
            return Err(bad);
        }
        let (w, h) = (
            u16::try_from(width).map_err(|_| RenderError::BadSize { width, height })?,
            u16::try_from(height).map_err(|_| RenderError::BadSize { width, height })?,
        );
        let mut encoder = gif::Encoder::new(out, w, h, &gif_global_palette())?;
        encoder.set_repeat(gif::Repeat::Infinite)?;
        Ok(GifRecorder {
            encoder,
            width: w,
            height: h,
            delay: delay_centiseconds.max(1),
            previous: None,
            pending: None,
            frames: 0,
        })
    }

    /// Frames written or pending (identical consecutive pictures count once).
    #[must_use]
    pub fn frame_count(&self) -> u32 {
        self.frames
    }

    /// Adds `canvas` as the next frame.
    ///
    /// # Errors
    /// [`RenderError::BadSize`] when the canvas is not the GIF's size;
    /// [`RenderError::Io`] / [`RenderError::Encode`] when writing fails.
    pub fn add_frame(&mut self, canvas: &Canvas) -> Result<(), RenderError> {
        if canvas.width() != u32::from(self.width) || canvas.height() != u32::from(self.height) {
            return Err(RenderError::BadSize {
                width: canvas.width(),
                height: canvas.height(),
            });
        }
        let indices = canvas.indices();
        let changed = match &self.previous {
            None => Some((0, 0, self.width, self.height)),
            Some(previous) => changed_rect(previous, &indices, self.width, self.height),
        };
        match changed {
            None => {
                // Same picture: show the pending frame longer.
                if let Some(pending) = &mut self.pending
                    && pending.delay <= u16::MAX - self.delay
                {
                    pending.delay += self.delay;
                    return Ok(());
                }
                // Delay would overflow: store a one-pixel frame instead.
                self.push(sub_frame(
                    &indices,
                    None,
                    self.width,
                    (0, 0, 1, 1),
                    self.delay,
                ))?;
            }
            Some(rect) => {
                let previous = self.previous.as_deref();
                self.push(sub_frame(&indices, previous, self.width, rect, self.delay))?;
            }
        }
        self.previous = Some(indices);
        Ok(())
    }

    /// Writes the last frame and the GIF trailer and gives back the writer.
    ///
    /// # Errors
    /// [`RenderError::Io`] / [`RenderError::Encode`] when writing fails.
    pub fn finish(mut self) -> Result<W, RenderError> {
        if let Some(frame) = self.pending.take() {
            self.encoder.write_frame(&frame)?;
        }
        Ok(self.encoder.into_inner()?)
    }

    fn push(&mut self, frame: gif::Frame<'static>) -> Result<(), RenderError> {
        if let Some(previous) = self.pending.replace(frame) {
            self.encoder.write_frame(&previous)?;
        }
        self.frames += 1;
        Ok(())
    }
}

/// The smallest rectangle `(left, top, width, height)` holding every pixel
/// that differs between `a` and `b` (`None` when they are equal).
fn changed_rect(a: &[u8], b: &[u8], width: u16, height: u16) -> Option<(u16, u16, u16, u16)> {
    let w = usize::from(width);
    let (mut x0, mut y0, mut x1, mut y1) = (usize::MAX, usize::MAX, 0, 0);
    for y in 0..usize::from(height) {
        let (ra, rb) = (&a[y * w..(y + 1) * w], &b[y * w..(y + 1) * w]);
        if ra == rb {
            continue;
        }
        let first = ra.iter().zip(rb).position(|(p, q)| p != q).unwrap_or(0);
        let last = w
            - 1
            - ra.iter()
                .rev()
                .zip(rb.iter().rev())
                .position(|(p, q)| p != q)
                .unwrap_or(0);
        x0 = x0.min(first);
        x1 = x1.max(last);
        y0 = y0.min(y);
        y1 = y1.max(y);
    }
    if x0 == usize::MAX {
        return None;
    }
    // All four fit in u16: they are below width and height.
    let narrow = |v: usize| u16::try_from(v).unwrap_or(u16::MAX);
    Some((
        narrow(x0),
        narrow(y0),
        narrow(x1 - x0 + 1),
        narrow(y1 - y0 + 1),
    ))
}

/// The GIF frame holding rectangle `rect` of the full-size picture
/// `indices`, with the pixels equal in `previous` (when given) stored as
/// [`UNCHANGED`].
fn sub_frame(
    indices: &[u8],
    previous: Option<&[u8]>,
    width: u16,
    rect: (u16, u16, u16, u16),
    delay: u16,
) -> gif::Frame<'static> {
    let (left, top, w, h) = rect;
    let stride = usize::from(width);
    let mut buffer = Vec::with_capacity(usize::from(w) * usize::from(h));
    for y in usize::from(top)..usize::from(top) + usize::from(h) {
        let start = y * stride + usize::from(left);
        let row = &indices[start..start + usize::from(w)];
        match previous {
            None => buffer.extend_from_slice(row),
            Some(previous) => {
                let before = &previous[start..start + usize::from(w)];
                buffer.extend(
                    row.iter()
                        .zip(before)
                        .map(|(&now, &was)| if now == was { UNCHANGED } else { now }),
                );
            }
        }
    }
    gif::Frame {
        delay,
        dispose: gif::DisposalMethod::Keep,
        left,
        top,
        width: w,
        height: h,
        transparent: previous.map(|_| UNCHANGED),
        buffer: Cow::Owned(buffer),
        ..gif::Frame::default()
    }
}
