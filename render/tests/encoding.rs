//! GIF and PNG files decode back to the pictures that were drawn: size,
//! frame count, and the colour of known pixels.

use clockwork2d_render::{
    Canvas, Colour, GifRecorder, OutputFormat, RenderError, UNCHANGED, View, write_png,
};
use std::path::Path;

fn view(width: u32, height: u32) -> View {
    View {
        width,
        height,
        scale: 10.0,
        centre: (0.0, 0.0),
    }
}

/// A picture of a dot at world x = `x` (10 px/unit, origin centred).
fn frame(x: f64) -> Canvas {
    let mut canvas = Canvas::new(view(64, 48)).unwrap();
    canvas.fill_circle((x, 0.0), 0.5, Colour::Awake);
    canvas
}

/// Decodes a GIF into full pictures (palette indices), one per frame,
/// composing sub-rectangle frames over the previous picture (disposal
/// "keep"), and each frame's delay.
fn decode_gif(bytes: &[u8]) -> (u16, u16, Vec<(Vec<u8>, u16)>) {
    let mut options = gif::DecodeOptions::new();
    options.set_color_output(gif::ColorOutput::Indexed);
    let mut decoder = options.read_info(bytes).unwrap();
    let (w, h) = (decoder.width(), decoder.height());
    let mut screen = vec![0_u8; usize::from(w) * usize::from(h)];
    let mut frames = Vec::new();
    while let Some(f) = decoder.read_next_frame().unwrap() {
        for y in 0..usize::from(f.height) {
            for x in 0..usize::from(f.width) {
                let at = (usize::from(f.top) + y) * usize::from(w) + usize::from(f.left) + x;
                let index = f.buffer[y * usize::from(f.width) + x];
                if Some(index) != f.transparent {
                    screen[at] = index;
                }
            }
        }
        frames.push((screen.clone(), f.delay));
    }
    (w, h, frames)
}

#[test]
fn gif_round_trip_gives_back_every_frame() {
    let pictures: Vec<Canvas> = (0..5).map(|i| frame(-2.0 + f64::from(i))).collect();
    let mut gif = GifRecorder::new(Vec::new(), 64, 48, 4).unwrap();
    for p in &pictures {
        gif.add_frame(p).unwrap();
    }
    assert_eq!(gif.frame_count(), 5);
    let bytes = gif.finish().unwrap();
    let (w, h, frames) = decode_gif(&bytes);
    assert_eq!((w, h), (64, 48));
    assert_eq!(frames.len(), 5);
    for ((decoded, delay), picture) in frames.iter().zip(&pictures) {
        assert_eq!(decoded, &picture.indices());
        assert_eq!(*delay, 4);
    }
    // The dot of frame 2 is at world (0, 0) = pixel (32, 24).
    assert_eq!(frames[2].0[24 * 64 + 32], Colour::Awake.index());
    assert_eq!(frames[0].0[24 * 64 + 32], Colour::Background.index());
    // The global palette is the crate's 16 colours, padded to 32.
    let mut options = gif::DecodeOptions::new();
    options.set_color_output(gif::ColorOutput::Indexed);
    let decoder = options.read_info(bytes.as_slice()).unwrap();
    let palette = decoder.global_palette().unwrap();
    assert_eq!(&palette[..48], Colour::gif_palette().as_slice());
    assert_eq!(palette.len(), 32 * 3);
}

#[test]
fn identical_frames_lengthen_the_previous_one_instead_of_adding_one() {
    let mut gif = GifRecorder::new(Vec::new(), 64, 48, 3).unwrap();
    for x in [0.0, 0.0, 0.0, 1.0] {
        gif.add_frame(&frame(x)).unwrap();
    }
    assert_eq!(gif.frame_count(), 2);
    let (_, _, frames) = decode_gif(&gif.finish().unwrap());
    let delays: Vec<u16> = frames.iter().map(|f| f.1).collect();
    assert_eq!(delays, [9, 3]);
    assert_eq!(frames[1].0, frame(1.0).indices());
}

#[test]
fn gif_refuses_bad_sizes_and_frames_of_another_size() {
    assert!(matches!(
        GifRecorder::new(Vec::new(), 0, 10, 4),
        Err(RenderError::BadSize { .. })
    ));
    assert!(matches!(
        GifRecorder::new(Vec::new(), 10, 70_000, 4),
        Err(RenderError::BadSize { .. })
    ));
    let mut gif = GifRecorder::new(Vec::new(), 32, 32, 4).unwrap();
    assert!(matches!(
        gif.add_frame(&frame(0.0)),
        Err(RenderError::BadSize { .. })
    ));
    // The refused frame left nothing behind: an empty but valid GIF.
    assert_eq!(gif.frame_count(), 0);
    let (_, _, frames) = decode_gif(&gif.finish().unwrap());
    assert!(frames.is_empty());
}

#[test]
fn png_round_trip_gives_back_the_picture() {
    let picture = frame(1.5);
    let mut bytes = Vec::new();
    write_png(&picture, &mut bytes).unwrap();
    let decoder = png::Decoder::new(std::io::Cursor::new(bytes));
    let mut reader = decoder.read_info().unwrap();
    let info = reader.info();
    assert_eq!((info.width, info.height), (64, 48));
    assert_eq!(info.color_type, png::ColorType::Indexed);
    assert_eq!(
        info.palette.as_deref(),
        Some(Colour::gif_palette().as_slice())
    );
    let mut buffer = vec![0; reader.output_buffer_size().unwrap()];
    reader.next_frame(&mut buffer).unwrap();
    assert_eq!(buffer, picture.indices());
    // The dot at world (1.5, 0) = pixel (47, 24).
    assert_eq!(buffer[24 * 64 + 47], Colour::Awake.index());
}

#[test]
fn the_palette_names_every_pixel_exactly() {
    // Sixteen distinct colours: nearest() finds each one itself.
    for c in Colour::ALL {
        assert_eq!(Colour::nearest(c.rgb()), c);
        assert_eq!(Colour::ALL[usize::from(c.index())], c);
    }
    // A drawn picture uses palette colours only (no anti-aliasing).
    let picture = frame(0.3);
    let palette: Vec<[u8; 3]> = Colour::ALL.iter().map(|c| c.rgb()).collect();
    for px in picture.rgb().chunks(3) {
        assert!(palette.contains(&[px[0], px[1], px[2]]), "{px:?}");
    }
}

#[test]
fn the_format_comes_from_the_file_name() {
    assert_eq!(
        OutputFormat::from_path(Path::new("a/b.gif")).unwrap(),
        OutputFormat::Gif
    );
    assert_eq!(
        OutputFormat::from_path(Path::new("B.PNG")).unwrap(),
        OutputFormat::Png
    );
    for bad in ["out.jpg", "out", "gif", "out.gif.txt"] {
        let err = OutputFormat::from_path(Path::new(bad)).unwrap_err();
        assert!(
            matches!(err, RenderError::UnsupportedFormat(_)),
            "{bad}: {err}"
        );
        assert!(err.to_string().contains(".gif"), "{err}");
    }
}

#[test]
fn later_frames_store_only_what_changed() {
    // Two pictures differing in one 1-unit dot: the second frame is a small
    // rectangle around the dot, and inside it the pixels that stayed
    // background are stored as the transparent UNCHANGED index.
    let mut gif = GifRecorder::new(Vec::new(), 64, 48, 4).unwrap();
    gif.add_frame(&frame(-2.0)).unwrap();
    let mut second = frame(-2.0);
    second.fill_circle((1.0, 1.0), 0.5, Colour::Sleeping);
    gif.add_frame(&second).unwrap();
    let bytes = gif.finish().unwrap();
    let mut options = gif::DecodeOptions::new();
    options.set_color_output(gif::ColorOutput::Indexed);
    let mut decoder = options.read_info(bytes.as_slice()).unwrap();
    let first = decoder.read_next_frame().unwrap().unwrap();
    assert_eq!(
        (first.width, first.height, first.transparent),
        (64, 48, None)
    );
    let f = decoder.read_next_frame().unwrap().unwrap();
    // The dot: radius 5 px around pixel (42, 14): at most 11×11.
    assert!(f.width <= 11 && f.height <= 11, "{}x{}", f.width, f.height);
    assert!(f.left >= 36 && f.top >= 8, "at ({}, {})", f.left, f.top);
    assert_eq!(f.transparent, Some(UNCHANGED));
    assert!(f.buffer.contains(&UNCHANGED));
    assert!(f.buffer.contains(&Colour::Sleeping.index()));
    assert!(!f.buffer.contains(&Colour::Background.index()));
}
