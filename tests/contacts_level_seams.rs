//! Level seams (issue 13, F9): a body sliding over a floor made of tiles
//! whose tops are flush must not catch on the seams (a "ghost collision":
//! a frictionless box at 3 over two fixed tiles with tops at y = 0 stopped
//! dead at the seam; over a row of resting boxes it was slowed from 2 to
//! 0.39; a circle at 60 hopped 1.96 units at the seams).
//!
//! Expected (frictionless, so nothing acts along the floor but contacts
//! with side faces): the body keeps its velocity exactly (rounding: 1e-6)
//! and travels `v·t`; its height stays within the slop of resting (a
//! resting contact may be up to one slop deep). A tile higher than the one
//! the body rests on by more than the slop is a wall: the body stops with
//! its face on the tile's side. A body sliding off the end of the floor
//! falls as soon as nothing is under it. Tile widths 0.3–2.5, speeds 0.01
//! to 100 units/s (1.7 units a tick: several seams per tick), tile tops
//! 1e-6 apart, gravity on, off and sideways, boxes and circles.
//! (Slower than `slop/h` = 0.006 units/s the rule cannot tell motion from
//! rest: `collision::level_seam`.)

use clockwork2d::prelude::*;

const SLOP: f64 = 1e-4;
const DT: f64 = 1.0 / 60.0;

/// A world (sleep off) with a floor of fixed frictionless tiles, half
/// height 0.5, laid from x = −2 on: tile `k` has width `width(k)` and top
/// `top(k)`; tiles are added until they reach `x_end`.
fn floor(
    gravity: (f64, f64),
    x_end: f64,
    width: impl Fn(usize) -> f64,
    top: impl Fn(usize) -> f64,
) -> World {
    let mut world = World::new(WorldSettings {
        gravity: vec2(gravity.0, gravity.1),
        sleep_enabled: false,
        ..WorldSettings::default()
    });
    let mut x = -2.0;
    let mut k = 0;
    while x < x_end {
        let w = width(k);
        world
            .add_body(
                BodyDef::fixed(Shape::aabb(vec2(w / 2.0, 0.5)))
                    .position(vec2(x + w / 2.0, top(k) - 0.5))
                    .friction(fx(0.0)),
            )
            .unwrap();
        x += w;
        k += 1;
    }
    world
}

/// A frictionless unit box or circle of radius 0.5 resting on the floor at
/// x = −1.5, moving at `v` along x.
fn slider(world: &mut World, circle: bool, v: f64) -> BodyId {
    let shape = if circle {
        Shape::circle(fx(0.5))
    } else {
        Shape::aabb(vec2(0.5, 0.5))
    };
    world
        .add_body(
            BodyDef::dynamic(shape)
                .position(vec2(-1.5, 0.5))
                .velocity(vec2(v, 0.0))
                .friction(fx(0.0)),
        )
        .unwrap()
}

/// Slides for `ticks` and checks velocity, distance and height against
/// the module's bounds (`top_error`: how far the tile tops stray from 0).
fn check_slide(world: &mut World, id: BodyId, v: f64, ticks: usize, top_error: f64, label: &str) {
    let (mut worst_dy, mut worst_dv): (f64, f64) = (0.0, 0.0);
    for _ in 0..ticks {
        world.step();
        let b = world.body(id).unwrap();
        worst_dy = worst_dy.max((b.position().y.to_f64() - 0.5).abs());
        worst_dv = worst_dv.max((b.velocity().x.to_f64() - v).abs());
    }
    let x = world.body(id).unwrap().position().x.to_f64();
    let expected = -1.5 + v * ticks as f64 * DT;
    println!(
        "{label}: x {x:.6} (expected {expected:.6}), worst |dv| {worst_dv:.2e}, |dy| {worst_dy:.2e}"
    );
    // Nothing acts along x: the velocity is kept to rounding, the distance
    // to `ticks` times it (rounding of the position sums: 1e-4 is ample).
    assert!(worst_dv <= 1e-6, "{label}: slowed by {worst_dv}");
    assert!(
        (x - expected).abs() <= 1e-4,
        "{label}: x {x} against {expected}"
    );
    assert!(
        worst_dy <= SLOP + top_error + 1e-9,
        "{label}: height off by {worst_dy}"
    );
}

#[test]
fn bodies_slide_over_flush_tiles_without_catching() {
    // Debug builds: fewer speeds (the test profile is slow); release: all.
    let speeds: &[f64] = if cfg!(debug_assertions) {
        &[0.01, 3.0, 100.0]
    } else {
        &[0.01, 0.5, 3.0, 20.0, 60.0, 100.0]
    };
    for &w in &[0.5, 1.0, 2.5] {
        for &v in speeds {
            for gravity in [true, false] {
                for circle in [false, true] {
                    let ticks = 60;
                    let x_end = -1.5 + v * ticks as f64 * DT + 4.0;
                    let g = if gravity { (0.0, -10.0) } else { (0.0, 0.0) };
                    let mut world = floor(g, x_end, |_| w, |_| 0.0);
                    let id = slider(&mut world, circle, v);
                    let label = format!("w {w} v {v} gravity {gravity} circle {circle}");
                    check_slide(&mut world, id, v, ticks, 0.0, &label);
                }
            }
        }
    }
}

/// Tiles of mixed widths (0.3 to 2.5, narrower than the body or wider),
/// and tile tops 1e-6 up and down (a level floor built from rounded
/// coordinates): the body slides on; its height follows the tops within
/// the slop.
#[test]
fn mixed_widths_and_tops_a_micron_apart_do_not_catch() {
    let widths = [0.3, 1.7, 0.9, 2.5, 0.45, 1.0];
    for &v in &[0.5, 3.0, 60.0] {
        for circle in [false, true] {
            let x_end = -1.5 + v + 4.0;
            let mut world = floor((0.0, -10.0), x_end, |k| widths[k % widths.len()], |_| 0.0);
            let id = slider(&mut world, circle, v);
            check_slide(
                &mut world,
                id,
                v,
                60,
                0.0,
                &format!("mixed widths v {v} circle {circle}"),
            );
            let mut world = floor(
                (0.0, -10.0),
                x_end,
                |_| 0.5,
                |k| if k % 2 == 0 { 1e-6 } else { -1e-6 },
            );
            let id = slider(&mut world, circle, v);
            check_slide(
                &mut world,
                id,
                v,
                60,
                1e-6,
                &format!("tops ±1e-6 v {v} circle {circle}"),
            );
        }
    }
}

/// Gravity along −x and a "floor" of tiles stacked along y (a wall the
/// body leans on): a body sliding along the wall (along +y) passes the
/// seams as on a floor — the rule has no preferred axis.
#[test]
fn sideways_gravity_slides_along_a_wall_of_tiles() {
    for circle in [false, true] {
        let v = 3.0;
        let mut world = World::new(WorldSettings {
            gravity: vec2(-10.0, 0.0),
            sleep_enabled: false,
            ..WorldSettings::default()
        });
        for k in 0..12 {
            world
                .add_body(
                    BodyDef::fixed(Shape::aabb(vec2(0.5, 0.5)))
                        .position(vec2(-0.5, -2.0 + k as f64 + 0.5))
                        .friction(fx(0.0)),
                )
                .unwrap();
        }
        let shape = if circle {
            Shape::circle(fx(0.5))
        } else {
            Shape::aabb(vec2(0.5, 0.5))
        };
        let id = world
            .add_body(
                BodyDef::dynamic(shape)
                    .position(vec2(0.5, -1.5))
                    .velocity(vec2(0.0, v))
                    .friction(fx(0.0)),
            )
            .unwrap();
        let (mut worst_dx, mut worst_dv): (f64, f64) = (0.0, 0.0);
        for _ in 0..60 {
            world.step();
            let b = world.body(id).unwrap();
            worst_dx = worst_dx.max((b.position().x.to_f64() - 0.5).abs());
            worst_dv = worst_dv.max((b.velocity().y.to_f64() - v).abs());
        }
        let y = world.body(id).unwrap().position().y.to_f64();
        println!("sideways circle {circle}: y {y:.6}, |dv| {worst_dv:.2e}, |dx| {worst_dx:.2e}");
        assert!(worst_dv <= 1e-6, "slowed by {worst_dv}");
        assert!((y - (-1.5 + v)).abs() <= 1e-4, "y {y}");
        assert!(worst_dx <= SLOP + 1e-9, "off the wall by {worst_dx}");
    }
}

/// The next tile a little lower (the box steps down onto it) or higher
/// within the slop: passes. Higher by more than the slop: it is a wall;
/// the box's face stops on its side (x of the box's right face = the
/// seam, within the slop) and the box stays on its own tile. A circle
/// meeting a step higher by more than the slop is lifted over it or
/// stopped (its rounded edge meets the step's corner): it is only
/// checked not to pass through the step.
#[test]
fn a_higher_tile_still_blocks() {
    for &(step, blocks) in &[
        (-0.001, false),
        (-1e-4, false),
        (0.5e-4, false),
        (0.01, true),
        (0.2, true),
    ] {
        for &v in &[3.0, 20.0] {
            // Tile 0 from −2 to 0, tile 1 from 0 to 20, with its top at `step`.
            let mut world = floor((0.0, -10.0), 20.0, |k| [2.0, 20.0][k], |k| [0.0, step][k]);
            let id = slider(&mut world, false, v);
            // 60 ticks: the box reaches the seam (its face 1 unit away)
            // after 1/v s and, if it passes, ends at −1.5 + v·1 s.
            for _ in 0..60 {
                world.step();
            }
            let b = world.body(id).unwrap();
            let (x, vx) = (b.position().x.to_f64(), b.velocity().x.to_f64());
            println!("step {step} v {v}: x {x:.6}, vx {vx:.6}");
            if blocks {
                assert!(
                    (x + 0.5).abs() <= SLOP + 1e-9,
                    "the box's face at {} not on the seam",
                    x + 0.5
                );
                assert!(vx.abs() <= 1e-6, "still moving at {vx}");
            } else {
                assert!(x >= -1.5 + v - 1e-3, "caught at the seam: x {x}");
            }
        }
    }
}

/// A body sliding off the end of a flush floor falls once nothing is under
/// it (a box when its left face passes the edge, a circle when its centre
/// does): it must not hover on the seam rule. The edge is at x = 0; at 3
/// units/s a box leaves at t = 2/3 s (tick 40), a circle at 1/2 s (tick
/// 30). Free fall from rest under semi-implicit Euler drops `g·h²·n(n+1)/2`
/// in `n` ticks; two ticks of slack for the moment of leaving.
#[test]
fn a_body_sliding_off_the_floor_falls() {
    for (circle, leave_tick) in [(false, 40usize), (true, 30usize)] {
        let v = 3.0;
        let mut world = floor((0.0, -10.0), 0.0, |_| 0.5, |_| 0.0);
        let id = slider(&mut world, circle, v);
        for _ in 0..60 {
            world.step();
        }
        let y = world.body(id).unwrap().position().y.to_f64();
        let n = (60 - leave_tick - 2) as f64;
        let least_drop = 10.0 * DT * DT * n * (n + 1.0) / 2.0;
        println!(
            "off the edge, circle {circle}: dropped {:.4} (at least {least_drop:.4})",
            0.5 - y
        );
        assert!(0.5 - y >= least_drop, "hovered: dropped only {}", 0.5 - y);
    }
}

/// A frictionless box sliding at 2 over a row of 10 touching unit boxes
/// resting on the ground keeps its speed (was slowed to 0.39), and does
/// not push the row (each resting box stays within the slop of its place:
/// momentum along x is the slider's alone).
#[test]
fn a_box_slides_over_a_row_of_resting_boxes() {
    for circle in [false, true] {
        let mut world = World::new(WorldSettings {
            sleep_enabled: false,
            ..WorldSettings::default()
        });
        world
            .add_body(BodyDef::fixed(Shape::aabb(vec2(50.0, 0.5))).position(vec2(0.0, -0.5)))
            .unwrap();
        let row: Vec<BodyId> = (0..10)
            .map(|k| {
                world
                    .add_body(
                        BodyDef::dynamic(Shape::aabb(vec2(0.5, 0.5))).position(vec2(k as f64, 0.5)),
                    )
                    .unwrap()
            })
            .collect();
        let shape = if circle {
            Shape::circle(fx(0.5))
        } else {
            Shape::aabb(vec2(0.5, 0.5))
        };
        let id = world
            .add_body(
                BodyDef::dynamic(shape)
                    .position(vec2(0.0, 1.5))
                    .velocity(vec2(2.0, 0.0))
                    .friction(fx(0.0)),
            )
            .unwrap();
        let mut worst_push: f64 = 0.0;
        for _ in 0..120 {
            world.step();
            for (k, &r) in row.iter().enumerate() {
                let x = world.body(r).unwrap().position().x.to_f64();
                worst_push = worst_push.max((x - k as f64).abs());
            }
        }
        let b = world.body(id).unwrap();
        let vx = b.velocity().x.to_f64();
        println!(
            "over resting boxes, circle {circle}: x {:.4} vx {vx:.6}, row pushed {worst_push:.2e}",
            b.position().x.to_f64()
        );
        assert!((vx - 2.0).abs() <= 1e-3, "slowed to {vx}");
        assert!(worst_push <= SLOP + 1e-9, "row pushed {worst_push}");
    }
}
