//! Ropes and contacts holding the same bodies (issue 13, the reviewer's
//! N5, F5 and F6), at the default settings (dt 1/60, substeps 1, 8
//! velocity and 3 position iterations):
//!
//! * a chain of rope links (circles r 0.02 of mass 0.1 on ropes of 0.1,
//!   its two ends `ratio` times a link) laid flat on a fixed peg (a circle
//!   or a box of half size 0.5), its middle over the peg or off centre,
//!   drapes over it and hangs (or slides off), at the origin and near the
//!   world's bounds;
//! * a platform hung by two ropes from fixed points carrying a stack of
//!   boxes 1×–100× its mass;
//! * boxes linked by ropes (ropes between centres long enough for the
//!   boxes to hang apart at any angle), released horizontal, swinging and
//!   folding onto the ground.
//!
//! Before ropes and contacts sharing a body were solved as one group
//! (`src/world/step/solve.rs`, "Ropes and contacts in one group") the
//! chains stretched by up to 1146 % over a box peg, a stack of ten boxes
//! 100× the platform fell through it, and linked boxes overlapped 0.023.
//!
//! Bounds, from the physics:
//! * a rope is inextensible: the bound is a stretch under 1 % at
//!   every tick (`STRETCH`); where nothing is infeasible the engine holds
//!   far less (the settling rounds end each substep within the slop);
//! * a link should never end a tick inside the fixed peg deeper than the
//!   linear slop (the projection out of immovable bodies ends every
//!   substep within it), plus rounding (`DEPTH`), plus what a contact row
//!   cannot see of a link sliding round the peg: a row is linear in the
//!   motion along its normal at the substep's start, and a link centre
//!   sliding a distance `s` round an outline of radius of curvature `ρ`
//!   ends up to `s²/(2ρ)` deeper than its row measures. Before the narrow
//!   phase followed the ropes' turn of a link (`collision::rope_turn`), a
//!   link whose straight sweep passed the peg got no row and the ropes
//!   pulled it in: 1.1e-2 deep (20 links, ends 1000×, off centre), 2.4e-4
//!   (ends 100×, centred), 6.9e-3 (200 links nearly sliding off);
//! * at rest, every rope holds its load within `REST` of its length and
//!   every contact within `REST` of touching (`REST`: the slop plus what
//!   the position passes leave of one step's free fall), so the platform
//!   hangs at most `REST` below the height its ropes' exact length gives
//!   and box `k` of the stack rests at most `(k + 1)·REST` below its ideal
//!   height on it;
//! * two bodies never overlap by more than `REST` at the end of a tick
//!   (the contact's slop plus the position passes' remainder).
//!
//! Run with `--nocapture` to see the figures.
#![allow(clippy::float_arithmetic)] // reference values in f64

use clockwork2d::geometry::Shape;
use clockwork2d::prelude::*;

mod common;
use common::chain_stretch::worst_stretch_of_points;

/// The engine's default linear slop.
const SLOP: f64 = 1e-4;
/// How far one rope or contact may rest beyond its length or inside its
/// partner: the linear slop, plus what the position pass leaves of an
/// excess. Each of its 3 iterations corrects the fraction β = 0.8 of the
/// excess beyond the slop, leaving (1 − β)³ = 0.008 of it; the excess one
/// step can create is at most one step of free fall, g·h² = 10/3600. So
/// 1e-4 + 0.008 · 2.8e-3 = 1.22e-4 (as in tests/rope_variants.rs).
const REST: f64 = SLOP + 0.008 * 10.0 / 3600.0;
/// Where the world's bounds (±2^15) leave room for the scenes: a corner
/// 2^15 − 64 from the origin on both axes.
const FAR: (f64, f64) = (32_704.0, -32_704.0);
/// The bound on a rope's stretch, as a fraction of its length.
const STRETCH: f64 = 0.01;
/// Deepest a link may end a tick inside the fixed peg: the slop, plus a
/// few ulps (2.3e-10) of rounding per operation.
const DEPTH: f64 = SLOP + 1e-8;
/// Ticks per run (debug `cargo test` runs a shorter draping).
const TICKS: usize = if cfg!(debug_assertions) { 120 } else { 480 };

const SEGMENT: f64 = 0.1;
const LINK_RADIUS: f64 = 0.02;
const LINK_MASS: f64 = 0.1;
const PEG: f64 = 0.5;

/// The sizes of a draping: the peg's radius (or half side), each link's
/// radius and each rope's length.
#[derive(Clone, Copy, Debug)]
struct Sizes {
    peg: f64,
    link_radius: f64,
    segment: f64,
}

/// The sizes of the reviewer's chains.
const SIZES: Sizes = Sizes {
    peg: PEG,
    link_radius: LINK_RADIUS,
    segment: SEGMENT,
};

fn pos(world: &World, id: BodyId) -> (f64, f64) {
    world.body(id).expect("live body").position().to_f64()
}

#[derive(Clone, Copy, Debug)]
enum Peg {
    Circle,
    Box,
}

/// Depth of a link (circle of `sizes.link_radius` at `p`) inside the peg
/// (`sizes.peg`) centred at `c` (positive: overlapping).
fn peg_depth(peg: Peg, sizes: Sizes, c: (f64, f64), p: (f64, f64)) -> f64 {
    let (dx, dy) = (p.0 - c.0, p.1 - c.1);
    let (half, radius) = (sizes.peg, sizes.link_radius);
    match peg {
        Peg::Circle => half + radius - dx.hypot(dy),
        Peg::Box => {
            if dx.abs() <= half && dy.abs() <= half {
                return radius + (half - dx.abs()).min(half - dy.abs());
            }
            let (qx, qy) = (dx.clamp(-half, half), dy.clamp(-half, half));
            radius - (dx - qx).hypot(dy - qy)
        }
    }
}

/// What a draping measured: worst stretch (fraction of a rope's length)
/// and worst depth in the peg beyond what a contact row cannot see of the
/// link's slide over the tick (`s²/(2ρ)`, see the module notes) over
/// every tick.
struct Drape {
    stretch: f64,
    depth: f64,
}

/// The radius of curvature of the outline a link's centre slides round:
/// the peg's plus the link's radius (circle), or the link's radius round a
/// box's corner (the least along a box).
fn outline_radius(peg: Peg, sizes: Sizes) -> f64 {
    match peg {
        Peg::Circle => sizes.peg + sizes.link_radius,
        Peg::Box => sizes.link_radius,
    }
}

/// A chain of `links` links laid flat just above a fixed `peg` centred at
/// `centre`, the chain's middle `offset` (a fraction of its half length)
/// to the left of the peg; its two end links `ratio` times a link.
#[derive(Clone, Copy, Debug)]
struct Draping {
    links: usize,
    peg: Peg,
    sizes: Sizes,
    offset: f64,
    ratio: f64,
    centre: (f64, f64),
}

/// Runs a draping, tick by tick.
fn drape(draping: Draping) -> Drape {
    let Draping {
        links,
        peg,
        sizes,
        offset,
        ratio,
        centre,
    } = draping;
    let Sizes {
        peg: half,
        link_radius,
        segment,
    } = sizes;
    let mut world = World::new(WorldSettings::default());
    let shape = match peg {
        Peg::Circle => Shape::circle(fx(half)),
        Peg::Box => Shape::aabb(vec2(half, half)),
    };
    world
        .add_body(BodyDef::fixed(shape).position(vec2(centre.0, centre.1)))
        .expect("peg");
    let half_chain = segment * (links - 1) as f64 / 2.0;
    let x0 = centre.0 - half_chain - offset * half_chain;
    // 1e-3 above the peg's top.
    let y = centre.1 + half + link_radius + 1e-3;
    let mut ids: Vec<BodyId> = Vec::new();
    for i in 0..links {
        let end = i == 0 || i + 1 == links;
        let id = world
            .add_body(
                BodyDef::dynamic(Shape::circle(fx(link_radius)))
                    .mass(fx(if end { LINK_MASS * ratio } else { LINK_MASS }))
                    .position(vec2(x0 + segment * i as f64, y)),
            )
            .expect("link");
        if let Some(&previous) = ids.last() {
            world
                .add_constraint(Constraint::rope(
                    Anchor::Body(previous),
                    Anchor::Body(id),
                    fx(segment),
                ))
                .expect("rope");
        }
        ids.push(id);
    }
    let mut result = Drape {
        stretch: 0.0,
        depth: 0.0,
    };
    let mut before: Vec<(f64, f64)> = ids.iter().map(|&id| pos(&world, id)).collect();
    for _ in 0..TICKS {
        world.step();
        let at: Vec<(f64, f64)> = ids.iter().map(|&id| pos(&world, id)).collect();
        for pair in at.windows(2) {
            let (a, b) = (pair[0], pair[1]);
            let stretch = ((b.0 - a.0).hypot(b.1 - a.1) - segment) / segment;
            result.stretch = result.stretch.max(stretch);
        }
        for (&p, &q) in at.iter().zip(&before) {
            let slide = (p.0 - q.0).hypot(p.1 - q.1);
            let unseen = slide * slide / (2.0 * outline_radius(peg, sizes));
            result.depth = result.depth.max(peg_depth(peg, sizes, centre, p) - unseen);
        }
        before = at;
    }
    result
}

fn check_drape(links: usize, peg: Peg, offset: f64, ratio: f64, centre: (f64, f64)) {
    let failures = drape_failures(Draping {
        links,
        peg,
        sizes: SIZES,
        offset,
        ratio,
        centre,
    });
    assert!(failures.is_empty(), "{failures:?}");
}

/// Runs a draping, prints its figures and returns what broke its bounds.
fn drape_failures(draping: Draping) -> Vec<String> {
    let d = drape(draping);
    let case = format!("{draping:?}");
    println!(
        "{case}: worst stretch {:.4} % (bound {:.1} %), deepest in the peg beyond the unseen slide {:.3e} (bound {DEPTH:.3e})",
        100.0 * d.stretch,
        100.0 * STRETCH,
        d.depth
    );
    let mut failures = Vec::new();
    if d.stretch > STRETCH {
        failures.push(format!("{case}: stretch {}", d.stretch));
    }
    if d.depth > DEPTH {
        failures.push(format!("{case}: {} deep in the peg", d.depth));
    }
    failures
}

/// Chains of 20 and 50 links over circle and box pegs, centred and off
/// centre, ends 1×, 100× and 1000×.
#[test]
fn chains_draped_over_pegs_keep_their_length() {
    for peg in [Peg::Circle, Peg::Box] {
        for links in [20, 50] {
            for offset in [0.0, 0.3] {
                for ratio in [1.0, 100.0, 1000.0] {
                    check_drape(links, peg, offset, ratio, (0.0, 0.0));
                }
            }
        }
    }
}

/// Chains sliding round pegs of other sizes, with thinner and thicker
/// links, shorter ropes and heavier ends: no link sinks into the peg
/// beyond the slop (and what its row cannot see of its slide).
#[test]
fn links_sliding_round_pegs_never_sink_into_them() {
    let mut failures = Vec::new();
    for peg in [Peg::Circle, Peg::Box] {
        for peg_size in [0.2, 2.0] {
            for (link_radius, segment) in [(0.01, 0.1), (0.045, 0.1), (0.02, 0.05)] {
                for (offset, ratio) in [(0.3, 100.0), (0.6, 1000.0), (0.3, 1000.0)] {
                    let sizes = Sizes {
                        peg: peg_size,
                        link_radius,
                        segment,
                    };
                    failures.extend(drape_failures(Draping {
                        links: 20,
                        peg,
                        sizes,
                        offset,
                        ratio,
                        centre: (0.0, 0.0),
                    }));
                }
            }
        }
    }
    assert!(
        failures.is_empty(),
        "{} failures: {failures:#?}",
        failures.len()
    );
}

/// The reviewer's chain of 200 links (N5: 442–18 880 % before), centred,
/// off centre and nearly sliding off, and near the world's bounds.
#[test]
fn chains_of_200_links_draped_over_pegs_keep_their_length() {
    for peg in [Peg::Circle, Peg::Box] {
        for (offset, ratio, centre) in [
            (0.0, 1.0, (0.0, 0.0)),
            (0.0, 100.0, (0.0, 0.0)),
            (0.3, 1.0, (0.0, 0.0)),
            (0.3, 100.0, (0.0, 0.0)),
            (0.9, 10.0, (0.0, 0.0)),
            (0.3, 100.0, FAR),
        ] {
            check_drape(200, peg, offset, ratio, centre);
        }
    }
}

/// A platform (half extents 1.5 × 0.1, mass 1) hung from (±1.4, top) by
/// two ropes of length 2 to its top corners, carrying `n` unit boxes of
/// mass `box_mass` stacked above its middle; returns (worst sag of the
/// platform below the height its ropes' length gives, worst sink of a box
/// below its ideal height on the platform, relative to `(k + 1)·REST`),
/// both over the last second of 6.
fn hung_platform(n: usize, box_mass: f64, at: (f64, f64)) -> (f64, f64) {
    let mut world = World::new(WorldSettings::default());
    let top = at.1 + 12.0;
    // Ropes taut at the start: the platform's top 2 below the anchors.
    let platform_y = top - 2.0 - 0.1;
    let platform = world
        .add_body(
            BodyDef::dynamic(Shape::aabb(vec2(1.5, 0.1)))
                .mass(fx(1.0))
                .position(vec2(at.0, platform_y)),
        )
        .expect("platform");
    for x in [-1.4, 1.4] {
        world
            .add_constraint(Constraint::rope(
                Anchor::Point(vec2(at.0 + x, top)),
                Anchor::BodyOffset(platform, vec2(x, 0.1)),
                fx(2.0),
            ))
            .expect("rope");
    }
    let boxes: Vec<BodyId> = (0..n)
        .map(|k| {
            world
                .add_body(
                    BodyDef::dynamic(Shape::aabb(vec2(0.5, 0.5)))
                        .mass(fx(box_mass))
                        .position(vec2(at.0, platform_y + 0.6 + k as f64)),
                )
                .expect("box")
        })
        .collect();
    let (mut sag, mut sink) = (0.0f64, 0.0f64);
    let ticks = if cfg!(debug_assertions) { 120 } else { 360 };
    for tick in 1..=ticks {
        world.step();
        if tick + 60 <= ticks {
            continue;
        }
        let py = pos(&world, platform).1;
        sag = sag.max(platform_y - py);
        for (k, &b) in boxes.iter().enumerate() {
            let below = py + 0.6 + k as f64 - pos(&world, b).1;
            sink = sink.max(below / (k + 1) as f64);
        }
    }
    (sag, sink)
}

/// F5: a stack of 1–10 boxes 1×–100× the platform's mass stays on a
/// rope-held platform (before: a stack of 10 at 100× fell through it, 5
/// at 100× sank 0.30 into it, one box at 100× 0.048).
#[test]
fn a_platform_hung_by_ropes_carries_heavy_stacks() {
    for n in [1, 5, 10] {
        for box_mass in [1.0, 10.0, 100.0] {
            for at in [(0.0, 0.0), (FAR.0, FAR.1 + 16.0)] {
                let (sag, sink) = hung_platform(n, box_mass, at);
                println!(
                    "platform with {n} boxes of mass {box_mass} at {at:?}: sag {sag:.3e} (bound {REST:.3e}), sink per box {sink:.3e} (bound {REST:.3e})"
                );
                assert!(sag <= REST, "{n} x {box_mass}: platform sag {sag}");
                assert!(sink <= REST, "{n} x {box_mass}: stack sink {sink}");
            }
        }
    }
}

/// `n` square boxes of half size `half` linked centre to centre by ropes
/// of `length` (at least 1.25 × the boxes' width, so two linked boxes can
/// hang apart at any angle) from a fixed point, released horizontal over a
/// fixed ground, the last box `ratio` times the others (mass 1); returns
/// (worst overlap of two boxes, worst stretch) over every tick.
fn linked_boxes(n: usize, half: f64, length: f64, ratio: f64) -> (f64, f64) {
    let mut world = World::new(WorldSettings::default());
    let ground_top = -(n as f64) * length * 0.7;
    world
        .add_body(
            BodyDef::fixed(Shape::aabb(vec2(50.0, 0.5))).position(vec2(0.0, ground_top - 0.5)),
        )
        .expect("ground");
    let mut ids: Vec<BodyId> = Vec::new();
    for i in 0..n {
        let id = world
            .add_body(
                BodyDef::dynamic(Shape::aabb(vec2(half, half)))
                    .mass(fx(if i + 1 == n { ratio } else { 1.0 }))
                    .position(vec2(length * (i + 1) as f64, 0.0)),
            )
            .expect("box");
        let above = ids
            .last()
            .map_or(Anchor::Point(Vec2::ZERO), |&p| Anchor::Body(p));
        world
            .add_constraint(Constraint::rope(above, Anchor::Body(id), fx(length)))
            .expect("rope");
        ids.push(id);
    }
    let (mut overlap, mut stretch) = (0.0f64, 0.0f64);
    for _ in 0..TICKS {
        world.step();
        let at: Vec<(f64, f64)> = ids.iter().map(|&id| pos(&world, id)).collect();
        for i in 0..n {
            for j in i + 1..n {
                let ox = 2.0 * half - (at[i].0 - at[j].0).abs();
                let oy = 2.0 * half - (at[i].1 - at[j].1).abs();
                overlap = overlap.max(ox.min(oy));
            }
        }
        stretch = stretch.max(worst_stretch_of_points(
            (0.0, 0.0),
            at.iter().copied(),
            length,
        ));
    }
    (overlap, stretch)
}

/// F6: boxes linked by ropes never overlap beyond `REST` (before: 0.0085
/// and 0.023 for 10 boxes, ropes 0.25, end 1× / 100×). Not yet: chains of
/// 30 equal boxes (half 0.05 on ropes of 0.15, half 0.1 on 0.3) folding
/// into a pile on the ground overlap 2.6e-3 / 1.9e-3 (see the issue's
/// notes).
#[test]
fn boxes_linked_by_ropes_do_not_overlap() {
    for (n, half, length) in [
        (10, 0.1, 0.25),
        (20, 0.1, 0.3),
        (10, 0.25, 0.8),
        (20, 0.05, 0.15),
    ] {
        for ratio in [1.0, 100.0, 1000.0] {
            let (overlap, stretch) = linked_boxes(n, half, length, ratio);
            println!(
                "{n} boxes of half {half} on ropes of {length}, end x{ratio}: overlap {overlap:.3e} (bound {REST:.3e}), stretch {:.4} %",
                100.0 * stretch
            );
            assert!(overlap <= REST, "{n} boxes x{ratio}: overlap {overlap}");
            assert!(stretch <= STRETCH, "{n} boxes x{ratio}: stretch {stretch}");
        }
    }
}
