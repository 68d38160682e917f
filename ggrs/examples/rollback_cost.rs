//! The cost of one GGRS rollback of 8 frames against the 16.7 ms frame
//! budget at 60 Hz, for 200, 1000 and 5000 bodies, with the world saved as
//! a `World` clone and as snapshot bytes.
//!
//! One rollback = load the saved state of frame F, then 8 times: step
//! (with no commands) and save the new state with its checksum
//! (`state_hash128`), which is what GGRS asks for when an input 8 frames
//! old turns out mispredicted. The scene: N balls (radius 0.25) dropped on
//! a grid into a box, after 90 ticks of settling, so the state holds a
//! full contact cache and most bodies are awake and touching.
//!
//! The third row of each size saves the world without a checksum on 7
//! of the 8 frames, as `SessionWorld::with_checksum_interval` does between
//! GGRS's checksum frames.
//!
//! Each figure is the median of `--reps` repetitions (wall time, this
//! machine). Run with
//! `cargo run --release -p clockwork2d-ggrs --example rollback_cost`.

use std::time::{Duration, Instant};

use clockwork2d::prelude::*;
use clockwork2d_ggrs::{RollbackState, SnapshotState};

const ROLLBACK_FRAMES: usize = 8;
const BUDGET_MS: f64 = 1000.0 / 60.0;

fn balls_in_a_box(n: i32) -> Result<World, WorldError> {
    let mut world = World::new(WorldSettings::default());
    // Columns so that the pile is about as wide as it is tall.
    let columns = (1..).find(|c| c * c >= n).unwrap_or(1).max(10);
    let half_width = Fx::from_int(columns).div(Fx::from_int(4)).add(fx(1.0));
    let wall_height = Fx::from_int(n / columns + 4);
    world.add_body(
        BodyDef::fixed(Shape::aabb(Vec2::new(half_width.add(fx(1.0)), fx(0.5))))
            .position(Vec2::new(Fx::ZERO, fx(-0.5))),
    )?;
    for side in [-1, 1] {
        world.add_body(
            BodyDef::fixed(Shape::aabb(Vec2::new(fx(0.5), wall_height))).position(Vec2::new(
                Fx::from_int(side).mul(half_width.add(fx(0.5))),
                wall_height,
            )),
        )?;
    }
    for i in 0..n {
        let (col, row) = (i % columns, i / columns);
        // 0.5 apart horizontally, staggered by 0.1 on odd rows so the pile
        // does not stand in perfect columns.
        let x = Fx::from_int(col - columns / 2)
            .div(Fx::from_int(2))
            .add(Fx::from_int(row % 2).div(Fx::from_int(10)));
        let y = Fx::from_int(row).mul(fx(0.55)).add(fx(0.5));
        world.add_body(
            BodyDef::dynamic(Shape::circle(fx(0.25)))
                .position(Vec2::new(x, y))
                .restitution(fx(0.1)),
        )?;
    }
    for _ in 0..90 {
        world.step();
    }
    Ok(world)
}

fn median(mut v: Vec<Duration>) -> f64 {
    v.sort();
    v[v.len() / 2].as_secs_f64() * 1000.0
}

/// Times of (load, step, save, checksum) summed over one rollback.
struct Rollback {
    total: f64,
    load: f64,
    step: f64,
    save: f64,
    checksum: f64,
}

fn rollback<St: RollbackState>(base: &World, reps: usize, checksum_every: usize) -> Rollback {
    let saved = St::save(base);
    let mut world = base.clone();
    let (mut total, mut load, mut step, mut save, mut checksum) =
        (vec![], vec![], vec![], vec![], vec![]);
    let mut cells: Vec<Option<(St, u128)>> = (0..ROLLBACK_FRAMES).map(|_| None).collect();
    for _ in 0..reps {
        // Start from another state, as after running ahead.
        world.step();
        let t0 = Instant::now();
        saved.load(&mut world).expect("a saved state loads");
        let t1 = Instant::now();
        let (mut s_step, mut s_save, mut s_hash) = (Duration::ZERO, Duration::ZERO, Duration::ZERO);
        for (i, cell) in cells.iter_mut().enumerate() {
            let a = Instant::now();
            world.step();
            let b = Instant::now();
            let state = St::save(&world);
            let c = Instant::now();
            let checksum = if i % checksum_every == 0 {
                world.state_hash128()
            } else {
                0
            };
            *cell = Some((state, checksum));
            s_hash += c.elapsed();
            s_save += c - b;
            s_step += b - a;
        }
        total.push(t0.elapsed());
        load.push(t1 - t0);
        step.push(s_step);
        save.push(s_save);
        checksum.push(s_hash);
    }
    std::hint::black_box(&cells);
    Rollback {
        total: median(total),
        load: median(load),
        step: median(step),
        save: median(save),
        checksum: median(checksum),
    }
}

fn main() -> Result<(), WorldError> {
    let reps = std::env::args()
        .skip_while(|a| a != "--reps")
        .nth(1)
        .and_then(|r| r.parse().ok())
        .unwrap_or(21);
    println!(
        "one rollback of {ROLLBACK_FRAMES} frames (load + {ROLLBACK_FRAMES} × (step + save with \
         checksum)), median of {reps}, ms; budget {BUDGET_MS:.1} ms"
    );
    println!(
        "| bodies | saved state | state size | rollback | of budget | load | 8 steps | 8 saves | 8 checksums |"
    );
    println!("|---|---|---|---|---|---|---|---|---|");
    for n in [200, 1000, 5000] {
        let world = balls_in_a_box(n)?;
        let snapshot_bytes = world.snapshot().len();
        for (name, r, size) in [
            (
                "World clone",
                rollback::<World>(&world, reps, 1),
                format!("{} bodies in memory", world.body_count()),
            ),
            (
                "snapshot bytes",
                rollback::<SnapshotState>(&world, reps, 1),
                format!("{snapshot_bytes} B"),
            ),
            (
                "World clone, checksum 1 frame in 8",
                rollback::<World>(&world, reps, ROLLBACK_FRAMES),
                format!("{} bodies in memory", world.body_count()),
            ),
        ] {
            println!(
                "| {n} | {name} | {size} | {:.3} | {:.1} % | {:.3} | {:.3} | {:.3} | {:.3} |",
                r.total,
                100.0 * r.total / BUDGET_MS,
                r.load,
                r.step,
                r.save,
                r.checksum
            );
        }
    }
    Ok(())
}
