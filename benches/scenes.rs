//! Criterion benchmarks of one `World::step()` on the named benchmark scenes,
//! and of 10 000 ray casts into the large pyramid.
//!
//! Every scene here is also a built-in scene file (`scenes/*.ron`), so the
//! same workload can be timed from the command line:
//!
//! ```sh
//! cargo bench --bench scenes                  # all of them, a few minutes
//! cargo bench --bench scenes -- large_pyramid # one
//! cargo run --release -- run large_pyramid --ticks 300 --hash-every 0
//! ```
//!
//! Sleeping is off in every scene (`sleep_enabled: false` in the files):
//! the point is the cost of the broad phase, narrow phase and solver, which
//! sleeping would hide once a pile comes to rest.
//!
//! The world is built once per benchmark and keeps stepping across
//! criterion's iterations (rebuilding it per iteration would time the scene
//! builder). Scenes that start in motion are first settled for a while so
//! the timed steps are the steady state, not the initial free fall.
//!
//! Sample sizes and measurement times are small so that a full
//! `cargo bench` finishes in a few minutes on a 2-core machine; the
//! per-step times are milliseconds, so 10 samples still give a usable
//! confidence interval.
#![allow(clippy::float_arithmetic)]

use std::hint::black_box;
use std::time::Duration;

use clockwork2d::prelude::*;
use clockwork2d_scene::builtin;
use criterion::{Criterion, Throughput, criterion_group, criterion_main};

/// Builds a built-in scene with the default scalar. The scene files are
/// compiled into the crate, so this cannot fail for the names used here.
fn world(name: &str) -> World {
    builtin(name)
        .and_then(|scene| scene.build())
        .unwrap_or_else(|e| panic!("built-in scene {name}: {e}"))
}

/// `(benchmark name, built-in scene, steps to settle before timing)`.
///
/// * `large_pyramid`: Box2D's benchmark, 5050 boxes; starts at rest.
/// * `balls`: 5000 circles thrown about in a walled box; after 3 s most of
///   them have fallen into a pile, the steady state of a ball pit.
/// * `springs`: a 32 × 32 lattice on 2016 bendy springs; starts moving at
///   once (it sags under gravity), no settling needed.
/// * `ropes`: 40 chains of 20 links; they swing for several seconds, time
///   them mid-swing.
const STEP_SCENES: &[(&str, &str, u32)] = &[
    ("large_pyramid", "large_pyramid", 0),
    ("balls", "balls5000", 180),
    ("springs", "springs_grid", 30),
    ("ropes", "ropes_chains", 30),
];

fn step_benches(c: &mut Criterion) {
    let mut group = c.benchmark_group("step");
    group
        .sample_size(10)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(4));
    for &(name, scene, settle) in STEP_SCENES {
        let mut w = world(scene);
        for _ in 0..settle {
            w.step();
        }
        group.bench_function(name, |b| b.iter(|| w.step()));
        // Keep the state alive to the end of the measurement (and make sure
        // the optimiser cannot drop the steps).
        black_box(w.state_hash());
    }
    group.finish();
}

/// SplitMix64 (the scene builder's generator): deterministic rays without
/// pulling in a random-number crate.
fn splitmix(state: &mut u64) -> u64 {
    *state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
    let mut z = *state;
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// A float in [0, 1) from the generator (53 random bits).
#[allow(clippy::cast_precision_loss)]
fn unit(state: &mut u64) -> f64 {
    (splitmix(state) >> 11) as f64 / (1u64 << 53) as f64
}

/// `count` rays from a circle of radius 150 around the pyramid, each aimed
/// at a random point of the pyramid's bounding box (x in ±50, y in 0..100),
/// max distance 300: almost every ray hits a box, a few pass through gaps
/// near the slanted sides and hit the ground or nothing.
fn pyramid_rays(count: usize) -> Vec<(Vec2, Vec2, Fx)> {
    let mut state = 7;
    (0..count)
        .map(|_| {
            let angle = unit(&mut state) * std::f64::consts::TAU;
            let origin = (150.0 * angle.cos(), 50.0 + 150.0 * angle.sin());
            let target = (-50.0 + 100.0 * unit(&mut state), 100.0 * unit(&mut state));
            (
                Vec2::new(fx(origin.0), fx(origin.1)),
                Vec2::new(fx(target.0 - origin.0), fx(target.1 - origin.1)),
                fx(300.0),
            )
        })
        .collect()
}

/// Ray casts into the large pyramid (5050 boxes):
///
/// * `raycasts`: 10 000 rays through a [`QueryIndex`]; the index is built
///   inside the timed closure, once per iteration, so its O(n log n) build
///   is part of the time (the way a game would use it: build once per tick,
///   cast many rays).
/// * `raycasts_linear_1000`: the first 1000 of the same rays through
///   `World::raycast`, which tests every body (O(n) per ray): the baseline.
///   Only a tenth of the rays, so the bench stays short; its time × 10 is
///   comparable with `raycasts`, and the per-element throughput directly.
/// * `query_index_build`: the build alone.
fn raycast_bench(c: &mut Criterion) {
    const RAYS: usize = 10_000;
    const LINEAR_RAYS: usize = 1_000;
    let w = world("large_pyramid");
    let rays = pyramid_rays(RAYS);
    let mut group = c.benchmark_group("query");
    group
        .sample_size(10)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(4))
        .throughput(Throughput::Elements(RAYS as u64));
    group.bench_function("raycasts", |b| {
        b.iter(|| {
            let index = w.query_index();
            let mut hits = 0u32;
            for &(origin, direction, max) in &rays {
                if index.raycast(origin, direction, max).is_some() {
                    hits += 1;
                }
            }
            black_box(hits)
        });
    });
    group.throughput(Throughput::Elements(LINEAR_RAYS as u64));
    group.bench_function("raycasts_linear_1000", |b| {
        b.iter(|| {
            let mut hits = 0u32;
            for &(origin, direction, max) in rays.iter().take(LINEAR_RAYS) {
                if w.raycast(origin, direction, max).is_some() {
                    hits += 1;
                }
            }
            black_box(hits)
        });
    });
    group.throughput(Throughput::Elements(1));
    group.bench_function("query_index_build", |b| {
        b.iter(|| black_box(w.query_index()));
    });
    group.finish();
}

criterion_group!(benches, step_benches, raycast_bench);
criterion_main!(benches);
