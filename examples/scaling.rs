//! How the time per step grows with the number of bodies.
//!
//! ```sh
//! cargo run --release --example scaling
//! ```
//!
//! Balls like `balls5000` (circles of radius 0.25, restitution 0.5, friction
//! 0.3, sleeping off) at about 1k, 2k, 4k, 8k, 16k and 32k balls, started as
//! a loose square packing (centres 0.52 apart, seeded random velocities up
//! to 1 unit/s per axis) in a closed box just as wide and twice as tall.
//! The packed start matters: from `balls5000`'s sparse start a tall box is
//! still mid-fall when a short one has already piled up, so the big worlds
//! would be timed in a cheaper state. From the packed start every size has
//! become a resting pile within the 90 untimed steps; then 90 steps are
//! timed. The growth exponent `p` of `ms/step ∝ N^p` is fitted by least
//! squares on (ln N, ln ms/step).
//!
//! Two series, because the broad phase sweeps along x only:
//!
//! * **box 2:1** (the headline): the box keeps `balls5000`'s 2:1 shape, so
//!   both sides grow by √2 per doubling and the piles get deeper;
//! * **fixed height**: always 50 rows, only the width grows, so every ball
//!   has the same neighbourhood at every size. The difference between the
//!   two exponents is what the one-axis sweep costs when columns get taller.
//!
//! The fit uses the thread's CPU time over the timed steps (Linux:
//! `/proc/thread-self/schedstat`; it does not count time other processes
//! held the core); the wall-clock median per step is printed next to it.
#![allow(clippy::float_arithmetic)]
#![allow(clippy::cast_precision_loss)]

#[path = "support/cpu_time.rs"]
mod cpu_time;

use std::time::Instant;

use clockwork2d::prelude::World;
use clockwork2d_scene::{Generator, Scene, SceneKind, SceneMaterial, SceneSettings, SceneShape};
use cpu_time::thread_cpu_ns;

const TARGETS: [u32; 6] = [1_000, 2_000, 4_000, 8_000, 16_000, 32_000];
const SETTLE: usize = 90;
const TIMED: usize = 90;

/// Centre-to-centre distance of the packed start.
const PITCH: f64 = 0.52;

/// The ball pit with `columns × rows` balls, packed (see the module docs).
fn balls(columns: u32, rows: u32) -> Scene {
    let (c, r) = (f64::from(columns), f64::from(rows));
    // Just wide enough for the packing (a 0.01 gap at each wall); twice as
    // tall as the packing.
    let (hx, hy) = (0.5 * c * PITCH, r * PITCH);
    Scene {
        name: format!("balls{}", columns * rows),
        settings: SceneSettings {
            sleep_enabled: Some(false),
            ..SceneSettings::default()
        },
        bodies: Vec::new(),
        generators: vec![
            Generator::Walls {
                kind: SceneKind::Fixed,
                center: (0.0, hy),
                half: (hx, hy),
                thickness: 1.0,
            },
            Generator::Grid {
                columns,
                rows,
                shape: SceneShape::Circle { radius: 0.25 },
                origin: (-0.5 * PITCH * (c - 1.0), 0.26),
                spacing: (PITCH, PITCH),
                speed: 1.0,
                seed: u64::from(columns * rows),
                material: SceneMaterial {
                    restitution: 0.5,
                    friction: 0.3,
                    ..SceneMaterial::default()
                },
            },
        ],
        constraints: Vec::new(),
    }
}

/// `(ms/step from the thread's CPU time, wall-clock median ms/step)` over
/// `TIMED` steps after `SETTLE` untimed ones. The CPU figure (see
/// `support/cpu_time.rs`) falls back to the wall median where the platform
/// has no per-thread CPU time.
fn time_scene(scene: &Scene) -> (f64, f64) {
    let mut world: World = scene
        .build()
        .unwrap_or_else(|e| panic!("{}: {e}", scene.name));
    for _ in 0..SETTLE {
        world.step();
    }
    let cpu_start = thread_cpu_ns();
    let mut times: Vec<f64> = (0..TIMED)
        .map(|_| {
            let start = Instant::now();
            world.step();
            start.elapsed().as_secs_f64() * 1e3
        })
        .collect();
    let cpu_end = thread_cpu_ns();
    times.sort_by(f64::total_cmp);
    let wall = times[times.len() / 2];
    let cpu = match (cpu_start, cpu_end) {
        (Some(a), Some(b)) => b.saturating_sub(a) as f64 / 1e6 / TIMED as f64,
        _ => wall,
    };
    (cpu, wall)
}

/// Least-squares slope of ln y against ln x.
fn fitted_exponent(points: &[(f64, f64)]) -> f64 {
    let n = points.len() as f64;
    let (lx, ly): (Vec<f64>, Vec<f64>) = points.iter().map(|&(x, y)| (x.ln(), y.ln())).unzip();
    let (mx, my) = (lx.iter().sum::<f64>() / n, ly.iter().sum::<f64>() / n);
    let sxy: f64 = lx.iter().zip(&ly).map(|(x, y)| (x - mx) * (y - my)).sum();
    let sxx: f64 = lx.iter().map(|x| (x - mx) * (x - mx)).sum();
    sxy / sxx
}

fn series(name: &str, shape: impl Fn(u32) -> (u32, u32)) -> f64 {
    println!("\n## {name}\n");
    println!("| balls | grid | ms/step (CPU) | ms/step (wall, median) | µs per ball (CPU) |");
    println!("|---:|---|---:|---:|---:|");
    let mut points = Vec::new();
    for target in TARGETS {
        let (columns, rows) = shape(target);
        let n = columns * rows;
        let (cpu, wall) = time_scene(&balls(columns, rows));
        println!(
            "| {n} | {columns} × {rows} | {cpu:.2} | {wall:.2} | {:.2} |",
            cpu * 1e3 / f64::from(n)
        );
        points.push((f64::from(n), cpu));
    }
    let p = fitted_exponent(&points);
    println!("\nfitted exponent (CPU ms/step ∝ N^p, least squares on log-log): p = {p:.3}");
    p
}

#[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
fn main() {
    println!("# Scaling: balls, {SETTLE} settling steps, then {TIMED} timed steps");
    // Box 2:1: columns ≈ √(2N), rows ≈ N / columns.
    let square = series("box 2:1 (balls5000's shape)", |target| {
        let columns = (2.0 * f64::from(target)).sqrt().round() as u32;
        (
            columns,
            (f64::from(target) / f64::from(columns)).round() as u32,
        )
    });
    let wide = series("fixed height (50 rows)", |target| (target / 50, 50));
    println!("\n## Summary\n");
    println!("| series | exponent | goal ≤ 1.15 |");
    println!("|---|---:|---|");
    for (name, p) in [("box 2:1", square), ("fixed height", wide)] {
        let verdict = if p <= 1.15 { "met" } else { "not met" };
        println!("| {name} | {p:.3} | {verdict} |");
    }
}
