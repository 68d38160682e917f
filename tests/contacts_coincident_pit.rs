//! Bodies spawned at one point in a pit exactly one body wide (issue 13,
//! F10b). Between fixed walls `w` apart, boxes `w` wide cannot pass one
//! another: the only arrangement without overlap is a column. Spawned at
//! one point, they must end stacked.
//!
//! Expected, from the position pass's rate: a body moves at most half the
//! speculative margin (0.05) per axis per substep out of an overlap, so an
//! overlap of a box's height `b` (≤ 4 here) takes at most `b/0.05` = 80
//! substeps to undo, and a column of three falls into place in well under
//! a second after that; 6 s (360 ticks) is ample. Then:
//!
//! * every pair of bodies overlaps by at most the linear slop (one rigid
//!   contact may rest one slop deep);
//! * no body is inside a wall or the floor by more than the slop;
//! * the column is in order: the k-th lowest body's centre is within
//!   `(k + 1)·slop` below its ideal resting height `(k + ½)·b` (k + 1
//!   contacts in series, each one slop) and not above it by more than a
//!   slop;
//! * nobody is pushed out of the world (no `Frozen` event).
//!
//! Variants: 2 and 3 boxes, square and flat and tall boxes of 0.25-4, and
//! circles of diameter 1, spawned on the floor or in mid-air, walls 0.1
//! and 2 thick, the pit exactly the body's width, one slop wider or 30 %
//! wider (still too narrow for two side by side), at the origin and near
//! the world's bounds, and the same scene turned a quarter (gravity along
//! −x, a tunnel one box high). Before `collision::confined_pair`, 260 of
//! the 576 cases never separated (overlap up to 4.0, the whole box).
//!
//! Figures print with `--nocapture`.

use clockwork2d::prelude::*;

const SLOP: f64 = 1e-4;
/// Read-back rounding of a position: an I32F32 step is 2.3e-10 and a
/// position is rounded a few times per step; 1e-9 is four steps.
const ROUND: f64 = 1e-9;

struct Case {
    n: usize,
    /// Box half extents (across the pit, along it).
    half: (f64, f64),
    /// Spawn height of the boxes' centre above the floor, in box heights.
    spawn: f64,
    wall: f64,
    /// Extra width of the pit beyond the boxes'.
    extra: f64,
    origin: (f64, f64),
    /// Gravity along −x, the scene turned a quarter.
    turned: bool,
    /// Circles of radius `half.0` (= `half.1`) instead of boxes.
    circles: bool,
}

/// (across, along) → world coordinates: along is "up" (against gravity).
fn place(c: &Case, across: f64, along: f64) -> (f64, f64) {
    if c.turned {
        (c.origin.0 + along, c.origin.1 - across)
    } else {
        (c.origin.0 + across, c.origin.1 + along)
    }
}

fn half_world(c: &Case, across: f64, along: f64) -> (f64, f64) {
    if c.turned {
        (along, across)
    } else {
        (across, along)
    }
}

struct Outcome {
    pair: f64,
    into_walls: f64,
    order: f64,
    frozen: usize,
}

fn run(c: &Case) -> Outcome {
    let mut world = World::new(WorldSettings {
        gravity: if c.turned {
            vec2(-10.0, 0.0)
        } else {
            vec2(0.0, -10.0)
        },
        ..WorldSettings::default()
    });
    let (a, b) = c.half;
    let inner = a + c.extra / 2.0;
    let depth = 2.0 * b * (c.n as f64 + 2.0);
    let fixed = |world: &mut World, across: f64, along: f64, ha: f64, hl: f64| {
        let p = place(c, across, along);
        let h = half_world(c, ha, hl);
        world
            .add_body(BodyDef::fixed(Shape::aabb(vec2(h.0, h.1))).position(vec2(p.0, p.1)))
            .expect("fixed");
    };
    // Floor (its top is along = 0) and the two walls.
    fixed(&mut world, 0.0, -0.5, inner + 2.0 * c.wall, 0.5);
    for side in [-1.0, 1.0] {
        fixed(
            &mut world,
            side * (inner + c.wall / 2.0),
            depth / 2.0,
            c.wall / 2.0,
            depth / 2.0,
        );
    }
    let ids: Vec<BodyId> = (0..c.n)
        .map(|_| {
            let p = place(c, 0.0, c.spawn * 2.0 * b + b);
            let h = half_world(c, a, b);
            let shape = if c.circles {
                Shape::circle(fx(a))
            } else {
                Shape::aabb(vec2(h.0, h.1))
            };
            world
                .add_body(BodyDef::dynamic(shape).position(vec2(p.0, p.1)))
                .expect("body")
        })
        .collect();
    let mut frozen = 0;
    for _ in 0..360 {
        world.step();
        frozen += world
            .events()
            .iter()
            .filter(|e| matches!(e, Event::Frozen(_)))
            .count();
    }
    // Back to (across, along) coordinates.
    let local = |id: BodyId| {
        let p = world.body(id).unwrap().position().to_f64();
        let (dx, dy) = (p.0 - c.origin.0, p.1 - c.origin.1);
        if c.turned { (-dy, dx) } else { (dx, dy) }
    };
    let pos: Vec<(f64, f64)> = ids.iter().map(|&id| local(id)).collect();
    let mut out = Outcome {
        pair: f64::MIN,
        into_walls: f64::MIN,
        order: f64::MIN,
        frozen,
    };
    for (i, p) in pos.iter().enumerate() {
        out.into_walls = out.into_walls.max(b - p.1).max(p.0.abs() + a - inner);
        for q in &pos[i + 1..] {
            let o = if c.circles {
                2.0 * a - (p.0 - q.0).hypot(p.1 - q.1)
            } else {
                (2.0 * a - (p.0 - q.0).abs()).min(2.0 * b - (p.1 - q.1).abs())
            };
            out.pair = out.pair.max(o);
        }
    }
    // A column: only where two bodies cannot lie side by side (the pit
    // narrower than two bodies; the boxes of a pit 30 % wider rest
    // stepped, still one on another). Circles in a pit `ε` wider than
    // their diameter rest up to `ε + 2·slop` apart across it (each may sit
    // a slop into its wall), which lowers each contact in the column by up
    // to `(ε + 2·slop)²/(2·2r)` (a chord of the circle of radius 2r).
    let mut along: Vec<f64> = pos.iter().map(|p| p.1).collect();
    along.sort_by(f64::total_cmp);
    let lean = if c.circles {
        (c.extra + 2.0 * SLOP).powi(2) / (4.0 * a)
    } else {
        0.0
    };
    if !(c.circles && c.extra > SLOP) {
        for (k, y) in along.iter().enumerate() {
            let ideal = (2 * k + 1) as f64 * b;
            let below = ideal - y - (k + 1) as f64 * SLOP - k as f64 * lean;
            let above = y - ideal - SLOP;
            out.order = out.order.max(below).max(above);
        }
    }
    out
}

#[test]
fn boxes_spawned_at_one_point_in_a_pit_one_box_wide_end_stacked() {
    let mut cases = Vec::new();
    for n in [2, 3] {
        for (half, circles) in [
            ((0.5, 0.5), false),
            ((0.25, 0.25), false),
            ((2.0, 2.0), false),
            ((1.0, 0.1), false),
            ((0.1, 1.0), false),
            ((0.5, 0.5), true),
        ] {
            for spawn in [0.0, 3.0] {
                for wall in [0.1, 2.0] {
                    // Exactly the width, one slop wider, and 30 % wider
                    // (too narrow for two side by side: the pair spreads
                    // to the walls, then must still stack).
                    for extra in [0.0, SLOP, 0.6 * half.0] {
                        for origin in [(0.0, 0.0), (30_000.0, -30_000.0)] {
                            for turned in [false, true] {
                                cases.push(Case {
                                    n,
                                    half,
                                    spawn,
                                    wall,
                                    extra,
                                    origin,
                                    turned,
                                    circles,
                                });
                            }
                        }
                    }
                }
            }
        }
    }
    let mut failures = Vec::new();
    let (mut pair, mut walls, mut order) = (f64::MIN, f64::MIN, f64::MIN);
    for c in &cases {
        let o = run(c);
        pair = pair.max(o.pair);
        walls = walls.max(o.into_walls);
        order = order.max(o.order);
        // A pair's overlap is the difference of two positions, each
        // carrying the read-back rounding: 2·ROUND.
        if o.pair > SLOP + 2.0 * ROUND
            || o.into_walls > SLOP + ROUND
            || o.order > ROUND
            || o.frozen > 0
        {
            failures.push(format!(
                "{} {} half {:?} spawn {} wall {} extra {} at {:?} turned {}: pair overlap {:.6e}, into walls {:.6e}, out of order {:.3e}, frozen {}",
                c.n, if c.circles { "circles" } else { "boxes" }, c.half, c.spawn, c.wall, c.extra, c.origin, c.turned, o.pair, o.into_walls, o.order, o.frozen
            ));
        }
    }
    println!(
        "{} cases: worst pair overlap {pair:.3e}, into walls {walls:.3e}, out of order {order:.3e}; {} fail",
        cases.len(),
        failures.len()
    );
    for f in failures.iter().take(40) {
        println!("  {f}");
    }
    assert!(
        failures.is_empty(),
        "{} of {} cases fail",
        failures.len(),
        cases.len()
    );
}
