//! `render_run` films a world into a GIF or PNG file: the right number of
//! frames of the right size, the final state in the PNG, and typed errors
//! (with no file written and the world not stepped) for bad requests.

use std::path::PathBuf;

use clockwork2d::prelude::*;
use clockwork2d_render::{
    Colour, OutputFormat, RenderError, RenderOptions, render_run, view_of_world,
};

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("cw2d-render-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
}

/// Ground and a ball falling from rest at height 3 (it lands after about
/// √(2·2.5/10) ≈ 0.7 s = 42 ticks, so it moves in every early frame).
fn falling_ball() -> (World, BodyId) {
    let mut world = World::new(WorldSettings::default());
    world
        .add_body(BodyDef::fixed(Shape::aabb(vec2(3.0, 0.5))).position(vec2(0.0, -0.5)))
        .unwrap();
    let ball = world
        .add_body(BodyDef::dynamic(Shape::circle(fx(0.5))).position(vec2(0.0, 3.0)))
        .unwrap();
    (world, ball)
}

#[test]
fn gif_has_a_frame_at_the_start_every_k_ticks_and_at_the_end() {
    let (mut world, _) = falling_ball();
    let path = scratch("fall.gif");
    let options = RenderOptions {
        ticks: 10,
        every: 3,
        width: 96,
        height: 80,
        ..RenderOptions::default()
    };
    let mut calls = Vec::new();
    let summary = render_run(&mut world, &options, &path, |done| calls.push(done)).unwrap();
    assert_eq!(calls, (1..=10).collect::<Vec<u64>>());
    // Ticks 0, 3, 6, 9 and 10.
    assert_eq!(summary.frames, 5);
    assert_eq!(summary.format, OutputFormat::Gif);
    assert_eq!(summary.final_tick, 10);
    assert_eq!(world.tick(), 10);
    let bytes = std::fs::read(&path).unwrap();
    let mut decoder = gif::DecodeOptions::new()
        .read_info(bytes.as_slice())
        .unwrap();
    assert_eq!((decoder.width(), decoder.height()), (96, 80));
    let mut delays = Vec::new();
    while let Some(frame) = decoder.read_next_frame().unwrap() {
        delays.push(frame.delay);
    }
    // 3 ticks of 1/60 s = 5 hundredths of a second.
    assert_eq!(delays, [5, 5, 5, 5, 5]);
}

#[test]
fn png_shows_the_final_state() {
    let (mut world, ball) = falling_ball();
    let view = view_of_world(&world, 120, 120).unwrap();
    let path = scratch("fall.png");
    let options = RenderOptions {
        ticks: 30,
        width: 120,
        height: 120,
        ..RenderOptions::default()
    };
    let summary = render_run(&mut world, &options, &path, |_| {}).unwrap();
    assert_eq!(
        (summary.format, summary.frames, summary.final_tick),
        (OutputFormat::Png, 1, 30)
    );
    let decoder = png::Decoder::new(std::io::BufReader::new(std::fs::File::open(&path).unwrap()));
    let mut reader = decoder.read_info().unwrap();
    assert_eq!((reader.info().width, reader.info().height), (120, 120));
    let mut pixels = vec![0; reader.output_buffer_size().unwrap()];
    reader.next_frame(&mut pixels).unwrap();
    // The ball after 30 ticks (fallen 10·0.5²/2 ≈ 1.25, still in the air)
    // is where the world says, and no longer at its start.
    let at = |p: (f64, f64)| {
        let (x, y) = view.to_pixel(p);
        pixels[y as usize * 120 + x as usize]
    };
    let now = world.body(ball).unwrap().position().to_f64();
    assert!(now.1 < 2.0 && now.1 > 1.0, "{now:?}");
    assert_eq!(at(now), Colour::Awake.index());
    assert_eq!(at((0.0, 3.0)), Colour::Background.index());
}

#[test]
fn bad_requests_are_refused_before_anything_is_done() {
    let (mut world, _) = falling_ball();
    let before = world.state_hash();
    let cases: [(&str, RenderOptions); 4] = [
        ("out.jpg", RenderOptions::default()),
        (
            "zero-every.gif",
            RenderOptions {
                every: 0,
                ..RenderOptions::default()
            },
        ),
        (
            "zero-width.gif",
            RenderOptions {
                width: 0,
                ..RenderOptions::default()
            },
        ),
        (
            "huge.png",
            RenderOptions {
                height: 100_000,
                ..RenderOptions::default()
            },
        ),
    ];
    for (name, options) in cases {
        let path = scratch(name);
        let err = render_run(&mut world, &options, &path, |_| {}).unwrap_err();
        match name {
            "out.jpg" => assert!(matches!(err, RenderError::UnsupportedFormat(_)), "{err}"),
            "zero-every.gif" => assert!(matches!(err, RenderError::BadFrameInterval), "{err}"),
            _ => assert!(matches!(err, RenderError::BadSize { .. }), "{err}"),
        }
        assert!(!path.exists(), "{name} was written");
    }
    let mut empty = World::new(WorldSettings::default());
    let path = scratch("empty.gif");
    let err = render_run(&mut empty, &RenderOptions::default(), &path, |_| {}).unwrap_err();
    assert!(matches!(err, RenderError::EmptyWorld), "{err}");
    assert!(!path.exists());
    // A directory that does not exist: an I/O error naming the cause.
    let path = scratch("no/such/dir/out.gif");
    let err = render_run(&mut world, &RenderOptions::default(), &path, |_| {}).unwrap_err();
    assert!(matches!(err, RenderError::Io(_)), "{err}");
    // None of it stepped the world.
    assert_eq!((world.tick(), world.state_hash()), (0, before));
}
