//! Chains of ropes hanging still at default settings (issue 13).
//!
//! A chain of `n` light links (mass 0.1, rope segments 0.1 long) hangs from
//! a fixed point straight down, every rope exactly at its length, with an
//! end body `ratio` times a link's mass. In equilibrium every rope is taut
//! and each holds the weight below it, so the exact answer is: nothing
//! moves and every segment keeps its length. The tree solve gives each
//! rope the impulse that carries its load exactly; what remains is the
//! position pass's linear slop (1e-4 on a 0.1 segment = 0.1 %), so the
//! bound is the 1 % on the worst segment at any tick, with the
//! stretch over the last second no larger than over the first (never
//! growing) and no sideways motion at all (symmetry: every row is vertical,
//! so x stays exactly 0 in fixed point). Figures print with `--nocapture`.

use clockwork2d::prelude::*;

mod common;
use common::oscillators::pos;

const SEGMENT: f64 = 0.1;
const LINK_MASS: f64 = 0.1;
const HZ: usize = 60;

struct Hang {
    worst: f64,
    first_second: f64,
    last_second: f64,
    moved_sideways: bool,
}

fn hang(links: usize, ratio: f64, seconds: usize) -> Hang {
    let mut world = World::new(WorldSettings::default());
    let mut ids: Vec<BodyId> = Vec::new();
    for i in 0..links {
        let mass = if i + 1 == links {
            LINK_MASS * ratio
        } else {
            LINK_MASS
        };
        let y = -SEGMENT * (i + 1) as f64;
        let id = world
            .add_body(
                BodyDef::dynamic(Shape::circle(fx(0.02)))
                    .mass(fx(mass))
                    .position(vec2(0.0, y)),
            )
            .expect("link");
        let a = match ids.last() {
            Some(&prev) => Anchor::Body(prev),
            None => Anchor::Point(Vec2::ZERO),
        };
        world
            .add_constraint(Constraint::rope(a, Anchor::Body(id), fx(SEGMENT)))
            .expect("rope");
        ids.push(id);
    }
    let ticks = seconds * HZ;
    let mut run = Hang {
        worst: 0.0,
        first_second: 0.0,
        last_second: 0.0,
        moved_sideways: false,
    };
    for tick in 0..ticks {
        world.step();
        let mut previous = (0.0, 0.0);
        let mut stretch = 0.0f64;
        for &id in &ids {
            let p = pos(&world, id);
            run.moved_sideways |= world.body(id).unwrap().position().x != Fx::ZERO;
            stretch = stretch.max(((p.0 - previous.0).hypot(p.1 - previous.1) - SEGMENT) / SEGMENT);
            previous = p;
        }
        run.worst = run.worst.max(stretch);
        if tick < HZ {
            run.first_second = run.first_second.max(stretch);
        }
        if tick >= ticks - HZ {
            run.last_second = run.last_second.max(stretch);
        }
    }
    run
}

/// Chains up to 70 links. Longer chains do not yet meet the bound: 80
/// links stretch 0.73 % (end 1×), 1.48 % (10×), 1.88 % (300×) and 200 links
/// 2.02 % in the first second before settling to the 0.1 % slop (issue 13,
/// open).
#[test]
fn hanging_chains_with_heavy_ends_keep_their_length_for_20_s() {
    for &(links, ratio) in &[
        (50, 100.0),
        (50, 1000.0),
        (30, 10.0),
        (70, 100.0),
        (20, 1.0),
    ] {
        let run = hang(links, ratio, 20);
        println!(
            "{links} links, end {ratio}x: worst stretch {:.4} %, first second {:.4} %, last second {:.4} %, sideways motion {}",
            run.worst * 100.0,
            run.first_second * 100.0,
            run.last_second * 100.0,
            run.moved_sideways
        );
        assert!(
            run.worst < 0.01,
            "{links} links, end {ratio}x stretched {}",
            run.worst
        );
        assert!(
            run.last_second <= run.first_second,
            "{links} links, end {ratio}x: stretch grew"
        );
        assert!(
            !run.moved_sideways,
            "{links} links, end {ratio}x moved sideways"
        );
    }
}
