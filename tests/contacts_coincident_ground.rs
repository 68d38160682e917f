//! Bodies spawned overlapping where a fixed body holds them (issue 13,
//! F10): two boxes spawned at one point on the ground never separated
//! (overlap 1.0, asleep after 2 s) because the pair's row was vertical,
//! both boxes were held by the ground's rows, and the exact tree position
//! solve dropped the pair's row as dependent without correcting it.
//!
//! Expected: the overlap is resolved (the position pass moves a body at
//! most half the speculative margin per axis per substep, so an overlap of
//! one unit takes about 1/0.05 = 20 substeps; 4 s is ample), after which
//! every pair rests within the slop of touching (`2·slop` allowed: each of
//! the two contacts in series may rest one slop deep), nobody is below the
//! ground by more than the slop, and nothing flies off (no body ends more
//! than its size above where it can rest on the others).

use clockwork2d::prelude::*;

mod common;
use common::add_ground;

const SLOP: f64 = 1e-4;

/// Worst overlap of any two of `ids` (boxes: the smaller of the x and y
/// overlaps of their boxes; circles: r_a + r_b − distance), and the lowest
/// bottom below y = 0.
fn worst(world: &World, ids: &[BodyId]) -> (f64, f64) {
    let mut overlap: f64 = 0.0;
    let mut below: f64 = 0.0;
    for (i, &a) in ids.iter().enumerate() {
        let ba = world.body(a).unwrap();
        let (pa, sa) = (ba.position().to_f64(), ba.shape());
        let half = |s: &Shape| match *s {
            Shape::Circle { radius } => (radius.to_f64(), radius.to_f64()),
            Shape::Aabb { half_extents } => half_extents.to_f64(),
        };
        below = below.max(-(pa.1 - half(&sa).1));
        for &b in &ids[i + 1..] {
            let bb = world.body(b).unwrap();
            let (pb, sb) = (bb.position().to_f64(), bb.shape());
            let (ha, hb) = (half(&sa), half(&sb));
            let o = match (sa, sb) {
                (Shape::Circle { .. }, Shape::Circle { .. }) => {
                    ha.0 + hb.0 - (pa.0 - pb.0).hypot(pa.1 - pb.1)
                }
                _ => {
                    let ox = ha.0 + hb.0 - (pa.0 - pb.0).abs();
                    let oy = ha.1 + hb.1 - (pa.1 - pb.1).abs();
                    ox.min(oy)
                }
            };
            overlap = overlap.max(o);
        }
    }
    (overlap, below)
}

#[test]
fn bodies_spawned_at_one_point_on_the_ground_separate() {
    for &(n, half, circles, dx) in &[
        (2, 0.5, false, 0.0),
        (2, 0.25, false, 0.0),
        (2, 2.0, false, 0.0),
        (3, 0.5, false, 0.0),
        (2, 0.5, false, 0.3),
        (2, 0.5, false, 0.5),
        (2, 0.5, true, 0.0),
        (4, 0.5, true, 0.0),
    ] {
        let mut w = World::new(WorldSettings::default());
        add_ground(&mut w);
        let shape = if circles {
            Shape::circle(fx(half))
        } else {
            Shape::aabb(vec2(half, half))
        };
        let ids: Vec<BodyId> = (0..n)
            .map(|i| {
                w.add_body(BodyDef::dynamic(shape).position(vec2(dx * i as f64, half)))
                    .unwrap()
            })
            .collect();
        for _ in 0..240 {
            w.step();
        }
        let (overlap, below) = worst(&w, &ids);
        let top = ids
            .iter()
            .map(|&id| w.body(id).unwrap().position().y.to_f64())
            .fold(f64::MIN, f64::max);
        println!(
            "{n} {} half {half} dx {dx}: worst overlap {overlap:.2e}, below ground {below:.2e}, top centre {top:.4}",
            if circles { "circles" } else { "boxes" }
        );
        assert!(
            overlap <= 2.0 * SLOP + 1e-9,
            "still overlapping by {overlap}"
        );
        assert!(below <= SLOP + 1e-9, "pushed {below} into the ground");
        assert!(top <= half * (2.0 * n as f64), "flung up to {top}");
    }
}

/// Runs `world` for 4 s (240 ticks; see the module notes: about 20
/// substeps resolve a unit overlap) and checks `ids` against the module's
/// bounds: pairs within `2·slop` of touching, nobody more than the slop
/// below y = `floor`, and no `Frozen` event (nobody pushed out of the
/// world's bounds).
fn settle_and_check(world: &mut World, ids: &[BodyId], floor: f64, label: &str) {
    let mut frozen = 0;
    for _ in 0..240 {
        world.step();
        frozen += world
            .events()
            .iter()
            .filter(|e| matches!(e, Event::Frozen(_)))
            .count();
    }
    let (overlap, below) = worst(world, ids);
    let below = below + floor;
    println!("{label}: worst overlap {overlap:.2e}, below floor {below:.2e}, frozen {frozen}");
    assert!(
        overlap <= 2.0 * SLOP + 1e-9,
        "{label}: still overlapping by {overlap}"
    );
    assert!(
        below <= SLOP + 1e-9,
        "{label}: pushed {below} into the floor"
    );
    assert_eq!(frozen, 0, "{label}: a body was pushed out of the world");
}

/// Variants of the coincident spawn: a coincident pair on top of a resting
/// stack, a box and a circle at one point, and a coincident pair in a
/// corner of walls that sit on the world's bounds (a body pushed out
/// through the wall would leave the bounds and be frozen).
#[test]
fn coincident_spawns_in_stacks_with_circles_and_at_the_bounds_separate() {
    // A pair at one point on top of a 3-box stack.
    let mut w = World::new(WorldSettings::default());
    add_ground(&mut w);
    let mut ids = common::add_stack(&mut w, 3, 0.0);
    for _ in 0..2 {
        ids.push(common::add_unit_box(&mut w, 0.0, 3.5));
    }
    settle_and_check(&mut w, &ids, 0.0, "pair on a 3-stack");

    // A unit box and a circle of radius 0.5 at one point on the ground,
    // both orders of creation.
    for circle_first in [false, true] {
        let mut w = World::new(WorldSettings::default());
        add_ground(&mut w);
        let boxed = BodyDef::dynamic(Shape::aabb(vec2(0.5, 0.5))).position(vec2(0.0, 0.5));
        let round = BodyDef::dynamic(Shape::circle(fx(0.5))).position(vec2(0.0, 0.5));
        let defs = if circle_first {
            [round, boxed]
        } else {
            [boxed, round]
        };
        let ids: Vec<BodyId> = defs.iter().map(|d| w.add_body(*d).unwrap()).collect();
        settle_and_check(
            &mut w,
            &ids,
            0.0,
            &format!("box+circle, circle first {circle_first}"),
        );
    }

    // A pair at one point in the bottom-left corner of a world whose bounds
    // are [-4, 4] × [-1, 7]: the floor and the wall are fixed boxes lying
    // just inside the bounds, the boxes spawn touching both.
    let mut w = World::new(WorldSettings {
        bounds: Aabb::new(vec2(0.0, 3.0), vec2(4.0, 4.0)),
        ..WorldSettings::default()
    });
    w.add_body(BodyDef::fixed(Shape::aabb(vec2(4.0, 0.5))).position(vec2(0.0, -0.5)))
        .unwrap();
    w.add_body(BodyDef::fixed(Shape::aabb(vec2(0.5, 3.0))).position(vec2(-3.5, 3.0)))
        .unwrap();
    let ids: Vec<BodyId> = (0..2)
        .map(|_| common::add_unit_box(&mut w, -2.5, 0.5))
        .collect();
    settle_and_check(&mut w, &ids, 0.0, "pair in a corner at the bounds");
    for &id in &ids {
        let x = w.body(id).unwrap().position().x.to_f64();
        assert!(x >= -2.5 - SLOP - 1e-9, "pushed {x} into the wall");
    }
}
