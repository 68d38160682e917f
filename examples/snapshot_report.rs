//! Snapshot and replay numbers: snapshot size per body, encode and restore
//! time for 5000 bodies, and replay verification speed.
//!
//! ```text
//! cargo run --release --example snapshot_report
//! ```
#![allow(clippy::float_arithmetic, clippy::cast_precision_loss)]

use std::time::{Duration, Instant};

use clockwork2d::prelude::World;
use clockwork2d::replay::Recorder;
use clockwork2d_scene::builtin;

fn scene(name: &str, ticks: u64) -> World {
    let mut world: World = builtin(name)
        .expect("built-in scene")
        .build()
        .expect("scene builds");
    for _ in 0..ticks {
        world.step();
    }
    world
}

/// Median of `runs` timings of `f`.
fn time<T>(runs: usize, mut f: impl FnMut() -> T) -> Duration {
    let mut times: Vec<Duration> = (0..runs)
        .map(|_| {
            let start = Instant::now();
            std::hint::black_box(f());
            start.elapsed()
        })
        .collect();
    times.sort();
    times[runs / 2]
}

fn size(label: &str, world: &World) {
    let bytes = world.snapshot().len();
    let bodies = world.body_count();
    let asleep = world.bodies().filter(|(_, b)| !b.is_awake()).count();
    println!(
        "{label:<28} {bodies:>5} bodies ({asleep:>4} asleep/fixed), {:>5} touching pairs: {bytes:>7} bytes = {:>5.1} bytes/body",
        world.touching_pairs().count(),
        bytes as f64 / bodies as f64,
    );
}

fn main() {
    println!("== snapshot size");
    size("pyramid, resting (10 s)", &scene("pyramid", 600));
    size("balls, moving (2 s)", &scene("balls", 120));
    size("mixed (5 s)", &scene("mixed", 300));
    size("balls5000, moving (1 s)", &scene("balls5000", 60));

    println!("== snapshot encode / restore, 5000 bodies");
    let big = scene("balls5000", 60);
    let bytes = big.snapshot();
    let encode = time(21, || big.snapshot());
    let restore = time(21, || {
        World::<clockwork2d::prelude::Fx>::restore(&bytes).expect("restores")
    });
    let hash = time(21, || big.state_hash());
    let hash128 = time(21, || big.state_hash128());
    println!(
        "balls5000 ({} bodies, {} bytes): encode {:.3} ms, restore (decode + validate) {:.3} ms, \
         state_hash {:.3} ms, state_hash128 {:.3} ms",
        big.body_count(),
        bytes.len(),
        encode.as_secs_f64() * 1e3,
        restore.as_secs_f64() * 1e3,
        hash.as_secs_f64() * 1e3,
        hash128.as_secs_f64() * 1e3
    );

    println!("== replay verify speed, pyramid");
    for k in [1, 60] {
        let mut recorder = Recorder::new(scene("pyramid", 0), k);
        let start = Instant::now();
        for _ in 0..600 {
            recorder.step();
        }
        let record = start.elapsed();
        let replay = recorder.finish();
        let file = replay.to_bytes().len();
        let start = Instant::now();
        let report = replay.verify().expect("verifies");
        let verify = start.elapsed();
        println!(
            "pyramid 600 ticks, hash every {k:>2}: record {:>7.0} ticks/s, verify {:>7.0} ticks/s, file {file} bytes",
            600.0 / record.as_secs_f64(),
            report.ticks as f64 / verify.as_secs_f64()
        );
    }
}
