//! Chains of ropes at default settings (issue 13).
//!
//! A chain of `n` light links (mass 0.1 each) joined by ropes of length
//! `segment`, from a fixed point, with an end body `ratio` times a link's
//! mass. Measured: the worst segment stretch `(|x_k − x_{k−1}| − ℓ)/ℓ` at
//! any tick, over the first second and over the last second.
//!
//! *Hanging still*: the chain hangs straight down, every rope exactly at
//! its length. In equilibrium every rope is taut and holds the weight below
//! it, so the exact answer is: nothing moves and every segment keeps its
//! length. The tree solve gives each rope the impulse that carries its load
//! exactly; what may remain is the position pass's linear slop (1e-4, i.e.
//! 0.1 % of a 0.1 segment), so the bounds are the issue's 1 % at any tick,
//! the last second no worse than the first (or than the slop: never
//! growing), and no sideways motion at all (symmetry: every row is
//! vertical, so x stays exactly 0 in fixed point).
//!
//! *Released horizontal*: the chain starts straight along +x, at rest, and
//! swings down under gravity. Bounds: 1 % at any tick, the last second no
//! worse than the first second or the slop.
//!
//! Figures print with `--nocapture`.

use clockwork2d::prelude::*;

mod common;
use common::oscillators::pos;

const LINK_MASS: f64 = 0.1;
const HZ: usize = 60;

/// One chain: its shape and the settings it runs at.
#[derive(Clone, Copy, Debug)]
struct Chain {
    links: usize,
    ratio: f64,
    segment: f64,
    radius: f64,
    substeps: u32,
    horizontal: bool,
}

impl Chain {
    fn hanging(links: usize, ratio: f64) -> Self {
        Chain {
            links,
            ratio,
            segment: 0.1,
            radius: 0.02,
            substeps: 1,
            horizontal: false,
        }
    }
}

struct Run {
    worst: f64,
    first_second: f64,
    last_second: f64,
    moved_sideways: bool,
}

fn run(chain: Chain, seconds: usize) -> Run {
    let mut world = World::new(WorldSettings {
        substeps: chain.substeps,
        ..WorldSettings::default()
    });
    let mut ids: Vec<BodyId> = Vec::new();
    for i in 0..chain.links {
        let mass = if i + 1 == chain.links {
            LINK_MASS * chain.ratio
        } else {
            LINK_MASS
        };
        let along = chain.segment * (i + 1) as f64;
        let at = if chain.horizontal {
            vec2(along, 0.0)
        } else {
            vec2(0.0, -along)
        };
        let id = world
            .add_body(
                BodyDef::dynamic(Shape::circle(fx(chain.radius)))
                    .mass(fx(mass))
                    .position(at),
            )
            .expect("link");
        let a = match ids.last() {
            Some(&prev) => Anchor::Body(prev),
            None => Anchor::Point(Vec2::ZERO),
        };
        world
            .add_constraint(Constraint::rope(a, Anchor::Body(id), fx(chain.segment)))
            .expect("rope");
        ids.push(id);
    }
    let ticks = seconds * HZ;
    let mut run = Run {
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
            stretch = stretch
                .max(((p.0 - previous.0).hypot(p.1 - previous.1) - chain.segment) / chain.segment);
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

/// Runs `chain` for 20 s, prints its figures and checks the bounds of the
/// module docs; returns the worst stretch.
fn check(chain: Chain) -> f64 {
    let r = run(chain, 20);
    let Chain {
        links,
        ratio,
        segment,
        radius,
        substeps,
        horizontal,
    } = chain;
    let how = if horizontal {
        "released horizontal"
    } else {
        "hanging"
    };
    println!(
        "{links} links of {segment} (radius {radius}), end {ratio}x, {how}, substeps {substeps}: worst stretch {:.4} %, first second {:.4} %, last second {:.4} %",
        r.worst * 100.0,
        r.first_second * 100.0,
        r.last_second * 100.0,
    );
    assert!(r.worst < 0.01, "{chain:?} stretched {}", r.worst);
    // The position pass leaves a rope up to the linear slop long.
    let slop = 1e-4 / segment;
    assert!(
        r.last_second <= r.first_second.max(slop) + 1e-9,
        "{chain:?}: stretch grew from {} to {}",
        r.first_second,
        r.last_second
    );
    if !horizontal {
        assert!(!r.moved_sideways, "{chain:?} moved sideways");
    }
    r.worst
}

/// The issue's matrix for hanging chains: 50 and 200 links, ends 100× and
/// 1000×, and 80 links with an end 1× (which stretched 0.73 % before the
/// active-set fix: a chain whose rope slacks round to a few ulps above 0
/// released them one per round).
#[test]
fn hanging_chains_of_50_and_200_links_with_heavy_ends_keep_their_length_for_20_s() {
    for &(links, ratio) in &[
        (50, 100.0),
        (50, 1000.0),
        (200, 100.0),
        (200, 1000.0),
        (80, 1.0),
        (20, 1.0),
    ] {
        check(Chain::hanging(links, ratio));
    }
}

/// Other link geometries: short and long segments, thin and fat links
/// (fat enough that neighbours are within the speculative margin and get
/// contact rows).
#[test]
fn hanging_chains_of_other_segment_lengths_and_radii_keep_their_length() {
    for &(links, segment, radius) in &[
        (200, 0.05, 0.01),
        (100, 0.25, 0.1),
        (60, 1.0, 0.45),
        (120, 0.1, 0.049),
    ] {
        check(Chain {
            segment,
            radius,
            ..Chain::hanging(links, 1000.0)
        });
    }
}

/// More substeps are never worse: substeps 2 and 4 against 1 on a hanging
/// 200-link chain with an end 1000×.
#[test]
fn hanging_chain_is_not_worse_with_more_substeps() {
    let one = check(Chain::hanging(200, 1000.0));
    for substeps in [2, 4] {
        let more = check(Chain {
            substeps,
            ..Chain::hanging(200, 1000.0)
        });
        assert!(more <= one.max(1e-3), "substeps {substeps}: {more} > {one}");
    }
}

/// Released horizontal, the cases that hold at the defaults today: 50 links
/// with an end 10× at substeps 1, 2 and 4, and an end 100× at substeps 4
/// (which stretched 1259 % after the tree solve landed, before the
/// active-set fix). Heavier ends at fewer substeps do not hold yet: see
/// `released_horizontal_matrix_of_the_issue`.
#[test]
fn chains_released_horizontal_keep_their_length() {
    for &(ratio, substeps) in &[(10.0, 1), (10.0, 2), (10.0, 4), (100.0, 4)] {
        check(Chain {
            horizontal: true,
            substeps,
            ..Chain::hanging(50, ratio)
        });
    }
}

/// The issue's matrix released horizontal at the defaults: 50 and 200 links,
/// ends 100× and 1000×. NOT MET YET (issue 13 open): 50 links 100× reach
/// thousands of % (a light link under the heavy end's tension turns within
/// a step faster than the velocity solve's frozen row directions can
/// follow). Run with `--ignored` to measure.
#[test]
#[ignore = "issue 13: heavy-end chains released horizontal are unstable at substeps 1"]
fn released_horizontal_matrix_of_the_issue() {
    for &(links, ratio) in &[(50, 100.0), (50, 1000.0), (200, 100.0), (200, 1000.0)] {
        check(Chain {
            horizontal: true,
            ..Chain::hanging(links, ratio)
        });
    }
}
