//! `clockwork2d render`: writes a GIF or PNG that decodes to the requested
//! size and frame count; refuses bad arguments with exit code 2 and a
//! one-line reason, writing nothing.

use std::path::{Path, PathBuf};
use std::process::{Command as Process, Output};

fn cli(args: &[&str]) -> Output {
    Process::new(env!("CARGO_BIN_EXE_clockwork2d"))
        .args(args)
        .output()
        .expect("run clockwork2d")
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

fn scratch(test: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("cw2d-render-cli-{}-{test}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

#[test]
fn render_writes_a_gif_with_a_frame_every_k_ticks() {
    let out = scratch("gif").join("balls.gif");
    // The ball pit starts in the air, so every frame differs: ticks 0, 10,
    // 20 and 30.
    let o = cli(&[
        "render",
        "balls",
        "--ticks",
        "30",
        "--every",
        "10",
        "--width",
        "160",
        "--height",
        "120",
        "-o",
        s(&out),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(
        stdout.contains("4 frames") && stdout.contains("tick 30"),
        "{stdout}"
    );
    let bytes = std::fs::read(&out).unwrap();
    let mut decoder = gif::DecodeOptions::new()
        .read_info(bytes.as_slice())
        .unwrap();
    assert_eq!((decoder.width(), decoder.height()), (160, 120));
    let mut frames = 0;
    while decoder.read_next_frame().unwrap().is_some() {
        frames += 1;
    }
    assert_eq!(frames, 4);
}

#[test]
fn render_writes_a_png_of_the_last_tick() {
    let out = scratch("png").join("pyramid.png");
    let o = cli(&[
        "render",
        "pyramid",
        "--ticks",
        "5",
        "--width",
        "200",
        "--height",
        "150",
        "-o",
        s(&out),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let file = std::fs::File::open(&out).unwrap();
    let reader = png::Decoder::new(std::io::BufReader::new(file))
        .read_info()
        .unwrap();
    assert_eq!((reader.info().width, reader.info().height), (200, 150));
}

#[test]
fn render_refuses_bad_arguments_and_writes_nothing() {
    let dir = scratch("bad");
    let cases: [(&[&str], &str); 6] = [
        (&["render", "stack", "-o", "out.jpg"], "use a .gif"),
        (&["render", "stack", "-o", "out"], "use a .gif"),
        (
            &["render", "no_such_scene", "-o", "out.gif"],
            "no_such_scene",
        ),
        (
            &["render", "stack", "--every", "0", "-o", "out.gif"],
            "every",
        ),
        (
            &["render", "stack", "--width", "0", "-o", "out.gif"],
            "width",
        ),
        (
            &["render", "stack", "--height", "5000", "-o", "out.png"],
            "height",
        ),
    ];
    for (args, reason) in cases {
        let args: Vec<String> = args
            .iter()
            .map(|a| {
                if a.starts_with("out") {
                    s(&dir.join(a)).to_owned()
                } else {
                    (*a).to_owned()
                }
            })
            .collect();
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let o = cli(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        assert!(stderr(&o).contains(reason), "{args:?}: {}", stderr(&o));
    }
    assert_eq!(
        std::fs::read_dir(&dir).unwrap().count(),
        0,
        "a file was written"
    );
    // No output at all: a usage error.
    let o = cli(&["render", "stack"]);
    assert_eq!(o.status.code(), Some(2));
}
