//! Crowds (issue 12): coincident or deeply overlapping bodies separate
//! deterministically in directions that spread them, and no crowd pressure
//! pushes a dynamic body into or through a fixed body.
//!
//! A closed container of fixed walls 2 thick; bodies spawned all at one
//! point inside it (or in a corner, pressed into two walls). The checks:
//!
//! * at **every** tick over 20 s, every centre is inside the container's
//!   interior (a centre in a wall or beyond is a body forced into or
//!   through it), and the deepest overlap of any body with a wall is
//!   reported;
//! * after 10 s (and at 20 s) the deepest overlap between any two bodies is
//!   under 0.05 — the pile has spread into a resting heap.
//!
//! Run with `--nocapture` to see the figures.

mod common;

use clockwork2d::prelude::*;
use common::depth::{half_extents, shape_depth};

const WALL: f64 = 2.0;

/// A closed box of fixed walls `WALL` thick around the interior
/// `[-half_w, half_w] × [0, height]`.
fn container(world: &mut World, half_w: f64, height: f64) {
    let t = WALL / 2.0;
    // Floor and ceiling span the full outer width.
    for y in [-t, height + t] {
        world
            .add_body(BodyDef::fixed(Shape::aabb(vec2(half_w + WALL, t))).position(vec2(0.0, y)))
            .unwrap();
    }
    for x in [-half_w - t, half_w + t] {
        world
            .add_body(
                BodyDef::fixed(Shape::aabb(vec2(t, height / 2.0))).position(vec2(x, height / 2.0)),
            )
            .unwrap();
    }
}

/// Deepest overlap between any two of `bodies` (sorted sweep on x).
fn max_overlap(world: &World, ids: &[BodyId]) -> f64 {
    let mut items: Vec<(f64, f64, Shape, f64)> = ids
        .iter()
        .map(|&id| {
            let b = world.body(id).unwrap();
            let p = b.position();
            (
                p.x.to_f64(),
                p.y.to_f64(),
                b.shape(),
                half_extents(b.shape()).0,
            )
        })
        .collect();
    items.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut worst = f64::NEG_INFINITY;
    for i in 0..items.len() {
        for j in i + 1..items.len() {
            if items[j].0 - items[j].3 > items[i].0 + items[i].3 {
                break;
            }
            let d = shape_depth(
                items[i].2,
                (items[i].0, items[i].1),
                items[j].2,
                (items[j].0, items[j].1),
            );
            worst = worst.max(d);
        }
    }
    worst
}

struct Outcome {
    worst_outside_count: usize,
    worst_wall_depth: f64,
    overlap_10s: f64,
    overlap_20s: f64,
}

/// Spawns `shapes` all at `spawn` in a container, runs 20 s checking every
/// tick.
fn crowd(shapes: &[Shape], half_w: f64, height: f64, spawn: (f64, f64)) -> Outcome {
    let mut world = World::new(WorldSettings::default());
    container(&mut world, half_w, height);
    let ids: Vec<BodyId> = shapes
        .iter()
        .map(|&s| {
            world
                .add_body(BodyDef::dynamic(s).position(vec2(spawn.0, spawn.1)))
                .unwrap()
        })
        .collect();
    let mut out = Outcome {
        worst_outside_count: 0,
        worst_wall_depth: 0.0,
        overlap_10s: 0.0,
        overlap_20s: 0.0,
    };
    for tick in 1..=1200 {
        world.step();
        let mut outside = 0;
        for &id in &ids {
            let b = world.body(id).unwrap();
            let (x, y) = (b.position().x.to_f64(), b.position().y.to_f64());
            let (hx, hy) = half_extents(b.shape());
            if x.abs() > half_w || !(0.0..=height).contains(&y) {
                outside += 1;
            }
            // Overlap of the body's extent with the walls (for circles the
            // bounding box's overlap bounds the real one from above).
            let depth = (x.abs() + hx - half_w).max(hy - y).max(y + hy - height);
            out.worst_wall_depth = out.worst_wall_depth.max(depth);
        }
        out.worst_outside_count = out.worst_outside_count.max(outside);
        if tick == 600 {
            out.overlap_10s = max_overlap(&world, &ids);
        }
    }
    out.overlap_20s = max_overlap(&world, &ids);
    out
}

fn check(label: &str, o: &Outcome) {
    println!(
        "{label}: most outside at any tick {}, deepest wall overlap {:.4}, max body overlap at 10 s {:.4}, at 20 s {:.4}",
        o.worst_outside_count, o.worst_wall_depth, o.overlap_10s, o.overlap_20s
    );
    assert_eq!(
        o.worst_outside_count, 0,
        "{label}: bodies left the container"
    );
    assert!(
        o.overlap_10s < 0.05,
        "{label}: overlap {} after 10 s",
        o.overlap_10s
    );
    assert!(
        o.overlap_20s < 0.05,
        "{label}: overlap {} after 20 s",
        o.overlap_20s
    );
}

#[test]
fn five_hundred_coincident_circles_stay_in_their_container() {
    let shapes = vec![Shape::circle(fx(0.15)); 500];
    let o = crowd(&shapes, 6.0, 12.0, (0.0, 6.0));
    check("500 coincident circles r 0.15", &o);
}

#[test]
fn two_hundred_coincident_boxes_stay_in_their_container() {
    let shapes = vec![Shape::aabb(vec2(0.2, 0.2)); 200];
    let o = crowd(&shapes, 6.0, 12.0, (0.0, 6.0));
    check("200 coincident boxes 0.4×0.4", &o);
}

/// Variants: mixed shapes and sizes at one point, a crowd spawned in a
/// corner (pressed into two walls at once), a small container.
#[test]
fn coincident_crowd_variants_stay_in_their_container() {
    let mixed: Vec<Shape> = (0..150)
        .map(|i| match i % 3 {
            0 => Shape::circle(fx(0.1 + 0.02 * f64::from(i % 5))),
            1 => Shape::aabb(vec2(0.15, 0.1)),
            _ => Shape::aabb(vec2(0.12, 0.2)),
        })
        .collect();
    let o = crowd(&mixed, 5.0, 8.0, (0.0, 4.0));
    check("150 mixed circles and boxes at one point", &o);
    let circles = vec![Shape::circle(fx(0.2)); 120];
    let o = crowd(&circles, 4.0, 6.0, (-3.8, 0.2));
    check("120 circles spawned in the bottom-left corner", &o);
    let boxes = vec![Shape::aabb(vec2(0.25, 0.25)); 30];
    // A corner crowd of boxes spreads along the two walls; the column
    // along the side wall must fit under the ceiling (30 boxes may all go
    // up the wall: 7.5 units). Boxes cannot rotate, and a column of boxes
    // jammed between a fixed floor and ceiling with their least-penetration
    // axis vertical has no way out: that scene is not one a container can
    // resolve (see the closing note of issue 12).
    let o = crowd(&boxes, 2.6, 8.0, (2.35, 0.25));
    check(
        "30 boxes spawned in the bottom-right corner of a 5.2×8 box",
        &o,
    );
}

/// Two coincident bodies separate sideways (not always along +y), in a
/// direction that depends on the pair, and the result is deterministic.
#[test]
fn coincident_pairs_separate_in_spread_directions() {
    let mut directions = Vec::new();
    for extra in 0..8 {
        let mut world = World::new(WorldSettings {
            gravity: Vec2::ZERO,
            ..WorldSettings::default()
        });
        // Spawn a few bodies elsewhere first so the pair's ids differ.
        for k in 0..extra {
            world
                .add_body(
                    BodyDef::fixed(Shape::circle(fx(0.1)))
                        .position(vec2(50.0 + f64::from(k), 50.0)),
                )
                .unwrap();
        }
        let a = world
            .add_body(BodyDef::dynamic(Shape::circle(fx(0.5))))
            .unwrap();
        let b = world
            .add_body(BodyDef::dynamic(Shape::circle(fx(0.5))))
            .unwrap();
        for _ in 0..60 {
            world.step();
        }
        let (pa, pb) = (
            world.body(a).unwrap().position(),
            world.body(b).unwrap().position(),
        );
        let d = pb - pa;
        let (dx, dy) = (d.x.to_f64(), d.y.to_f64());
        println!("pair after {extra} other bodies: separated along ({dx:+.3}, {dy:+.3})");
        assert!(dx.hypot(dy) > 0.99, "did not separate: {dx}, {dy}");
        directions.push((dx / dx.hypot(dy), dy / dx.hypot(dy)));
    }
    // Not all the same direction: the pairs spread.
    let distinct = directions
        .iter()
        .filter(|d| (d.0 - directions[0].0).abs() > 0.1 || (d.1 - directions[0].1).abs() > 0.1)
        .count();
    assert!(distinct > 0, "every coincident pair separated the same way");
}
