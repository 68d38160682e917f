//! Long heavy rope chains that swing into things keep their length: a
//! chain of 200 ropes of 0.1 (links: circles r 0.02 of mass 0.1) with an
//! end 100× or 1000× a link, released horizontal from a fixed point, swings
//! down and its heavy end strikes the ground 15 below the anchor (the chain
//! is 20 long), or sweeps through a column of ten unit boxes standing on a
//! ground 21 below, knocking it over. 20 s at default settings (5 s in
//! debug).
//!
//! The physics: a rope is inextensible; the bound is a stretch
//! under 1 % at every tick, and a chain that has come to rest holds at the
//! slop: a rope settles within `slop + (1 − β)³·g·h²` of its length
//! (tests/rope_variants.rs: 1.22e-4 on 0.1, i.e. 0.122 %), checked over the
//! last second.
//!
//! Run with `--nocapture` to see the figures.

use clockwork2d::prelude::*;

mod common;
use common::chain_stretch::worst_stretch;

const LINKS: usize = 200;
const SEGMENT: f64 = 0.1;
const LINK_MASS: f64 = 0.1;
const TICKS: usize = if cfg!(debug_assertions) { 300 } else { 1200 };
/// The settled rope allowance over the segment: (slop + 0.2³·g·h²) / 0.1.
const SETTLED: f64 = (1e-4 + 0.008 * 10.0 / 3600.0) / SEGMENT;

#[derive(Clone, Copy, Debug)]
enum Target {
    /// A fixed ground whose top is 15 below the anchor.
    Ground,
    /// Ten unit boxes in a column at x = −3 on a ground 21 below the anchor.
    BoxColumn,
}

/// Runs one chain; returns (worst stretch, worst stretch over the last
/// second, fastest box speed seen).
fn swing(ratio: f64, target: Target) -> (f64, f64, f64) {
    let mut world = World::new(WorldSettings::default());
    let mut boxes = Vec::new();
    let ground_top = match target {
        Target::Ground => -15.0,
        Target::BoxColumn => -21.0,
    };
    world
        .add_body(
            BodyDef::fixed(Shape::aabb(vec2(50.0, 0.5))).position(vec2(0.0, ground_top - 0.5)),
        )
        .expect("ground");
    if let Target::BoxColumn = target {
        for i in 0..10 {
            boxes.push(
                world
                    .add_body(
                        BodyDef::dynamic(Shape::aabb(vec2(0.5, 0.5)))
                            .position(vec2(-3.0, ground_top + 0.5 + i as f64)),
                    )
                    .expect("box"),
            );
        }
    }
    let mut links: Vec<BodyId> = Vec::new();
    for i in 0..LINKS {
        let end = i + 1 == LINKS;
        // The end is a little larger (r 0.05, still 0.03 clear of its
        // neighbour at full length) and `ratio` times heavier.
        let id = world
            .add_body(
                BodyDef::dynamic(Shape::circle(fx(if end { 0.05 } else { 0.02 })))
                    .mass(fx(if end { LINK_MASS * ratio } else { LINK_MASS }))
                    .position(vec2(SEGMENT * (i + 1) as f64, 0.0)),
            )
            .expect("link");
        let above = links
            .last()
            .map_or(Anchor::Point(Vec2::ZERO), |&p| Anchor::Body(p));
        world
            .add_constraint(Constraint::rope(above, Anchor::Body(id), fx(SEGMENT)))
            .expect("rope");
        links.push(id);
    }
    let (mut worst, mut last, mut fastest_box) = (0.0f64, 0.0f64, 0.0f64);
    for tick in 1..=TICKS {
        world.step();
        let stretch = worst_stretch(&world, (0.0, 0.0), &links, SEGMENT);
        worst = worst.max(stretch);
        if tick + 60 > TICKS {
            last = last.max(stretch);
        }
        for &b in &boxes {
            let v = world.body(b).unwrap().velocity().to_f64();
            fastest_box = fastest_box.max(v.0.hypot(v.1));
        }
    }
    (worst, last, fastest_box)
}

#[test]
fn chains_of_200_ropes_with_heavy_ends_hold_when_they_strike() {
    for target in [Target::Ground, Target::BoxColumn] {
        for ratio in [100.0, 1000.0] {
            let (worst, last, fastest_box) = swing(ratio, target);
            println!(
                "200 links, end x{ratio}, into {target:?}: worst stretch {:.4} %, last second {:.4} % (settled bound {:.4} %), fastest box {fastest_box:.2} units/s",
                100.0 * worst,
                100.0 * last,
                100.0 * SETTLED
            );
            assert!(
                worst < 0.01,
                "{target:?} x{ratio}: stretch {worst} at some tick"
            );
            if !cfg!(debug_assertions) {
                assert!(last <= SETTLED, "{target:?} x{ratio}: last second {last}");
            }
            if let Target::BoxColumn = target {
                assert!(fastest_box > 1.0, "the chain missed the boxes");
            }
        }
    }
}
