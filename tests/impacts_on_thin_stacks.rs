//! A fast ball onto a stack of thin boxes (issue 13, F15), at the default
//! settings (dt = 1/60, substeps 1, 8 velocity + 3 position iterations,
//! slop 1e-4).
//!
//! A ball (radius 0.05 in the reviewer's scene) thrown down at 200 units/s
//! onto a column of 10 thin boxes resting on the ground. The stack rests on
//! rigid ground, so (rigid bodies) the ball meets in effect an immovable
//! floor at the stack's top:
//!
//! * **No tunnelling.** The ball never ends a tick inside a box or the
//!   ground by more than the linear slop (a speculative contact may rest one
//!   slop deep), and nor does any box end inside another or the ground by
//!   more than the slop (each contact of the column is one rigid contact
//!   allowed one slop; the column's boxes are measured pairwise).
//! * **No energy source.** Kinetic plus gravitational energy of every body
//!   never rises above its start. Measured from the stored velocities, the
//!   integrator's chord velocities: under gravity these differ from the
//!   velocity at the sample by up to g·h/2 (a body in free flight moves on
//!   the parabola whose velocity at a sample is the stored one less g·h/2
//!   along gravity), so the measured kinetic energy may differ from the
//!   true one by m·|v|·g·h/2 + m·(g·h/2)²/2 per body, either way: the ball
//!   falling at the start is measured low, rising after an e = 1 bounce
//!   measured high. The allowance is that bound at the start plus at the
//!   tick, plus the rounding allowance of the sums (see `ROUND_ENERGY`).
//!
//! Variants: box heights 0.02-0.2, widths 0.3 and 1, balls r 0.02-0.2,
//! 50-1000 units/s, ball 0.01x-100x a box's mass, e 0 and 1, bullet or not,
//! dropped from three heights (different phases of the impact within a
//! tick), at the origin and near the world's bounds; and columns of 3 and
//! 40 bodies 0.01 and 0.05 thick, of boxes or of circles (a column of
//! circles has vertical rows too), with a light or a 100x top body.
//!
//! Figures print with `--nocapture`.

mod common;
use clockwork2d::prelude::*;
use common::depth::{box_box_depth, circle_box_depth};
use common::sampled_energy::energy_and_allowance;

const SLOP: f64 = 1e-4;
const G: f64 = 10.0;
const H: f64 = 1.0 / 60.0;
/// Read-back rounding of a position: an I32F32 step is 2.3e-10 and a
/// position is rounded a few times per step; 1e-9 is four steps.
const ROUND: f64 = 1e-9;

struct Case {
    /// Bodies in the column.
    count: usize,
    /// A column of circles (diameter `thickness`) instead of boxes.
    circles: bool,
    /// The top body of the column 100x the others.
    heavy_top: bool,
    thickness: f64,
    width: f64,
    radius: f64,
    speed: f64,
    /// Ball mass over one box's mass.
    ratio: f64,
    e: f64,
    bullet: bool,
    above: f64,
    origin: (f64, f64),
}

struct Outcome {
    /// Deepest the ball went into a box or the ground.
    ball_depth: f64,
    /// Deepest any box went into another box or the ground.
    box_depth: f64,
    /// Highest energy above the start beyond the sampling allowance.
    rise: f64,
    /// The start's kinetic energy (the scale of the energy figures).
    e0: f64,
}

fn run(c: &Case) -> Outcome {
    let mut world = World::new(WorldSettings::default());
    let (ox, oy) = c.origin;
    let ground_half = (50.0, 0.5);
    let ground_at = (ox, oy - 0.5);
    world
        .add_body(
            BodyDef::fixed(Shape::aabb(vec2(ground_half.0, ground_half.1)))
                .position(vec2(ground_at.0, ground_at.1)),
        )
        .expect("ground");
    let half = (c.width / 2.0, c.thickness / 2.0);
    let boxes: Vec<BodyId> = (0..c.count)
        .map(|i| {
            let shape = if c.circles {
                Shape::circle(fx(half.1))
            } else {
                Shape::aabb(vec2(half.0, half.1))
            };
            let heavy = c.heavy_top && i + 1 == c.count;
            world
                .add_body(
                    BodyDef::dynamic(shape)
                        .mass(fx(if heavy { 100.0 } else { 1.0 }))
                        .position(vec2(ox, oy + half.1 + i as f64 * c.thickness)),
                )
                .expect("box")
        })
        .collect();
    let box_mass = world.body(boxes[0]).unwrap().mass().to_f64();
    let top = c.count as f64 * c.thickness;
    let ball = world
        .add_body(
            BodyDef::dynamic(Shape::circle(fx(c.radius)))
                .mass(fx(c.ratio * box_mass))
                .restitution(fx(c.e))
                .bullet(c.bullet)
                .position(vec2(ox, oy + top + c.radius + c.above))
                .velocity(vec2(0.0, -c.speed)),
        )
        .expect("ball");
    let mut all = boxes.clone();
    all.push(ball);
    let energy = |world: &World| energy_and_allowance(world, &all, G, H, oy);
    let (e0, allowance0) = energy(&world);
    let mut out = Outcome {
        ball_depth: f64::MIN,
        box_depth: f64::MIN,
        rise: f64::MIN,
        e0: 0.5 * c.ratio * box_mass * c.speed * c.speed,
    };
    for _ in 0..120 {
        world.step();
        let (e, allowance) = energy(&world);
        out.rise = out.rise.max(e - e0 - allowance - allowance0);
        let pc = world.body(ball).unwrap().position().to_f64();
        let pc = (pc.0 - ox, pc.1 - oy);
        out.ball_depth = out.ball_depth.max(c.radius - pc.1);
        for (i, &a) in boxes.iter().enumerate() {
            let pa = world.body(a).unwrap().position().to_f64();
            let pa = (pa.0 - ox, pa.1 - oy);
            out.box_depth = out.box_depth.max(half.1 - pa.1);
            out.ball_depth = out.ball_depth.max(if c.circles {
                c.radius + half.1 - (pc.0 - pa.0).hypot(pc.1 - pa.1)
            } else {
                circle_box_depth(pc, c.radius, pa, half)
            });
            for &b in &boxes[i + 1..] {
                let pb = world.body(b).unwrap().position().to_f64();
                let pb = (pb.0 - ox, pb.1 - oy);
                out.box_depth = out.box_depth.max(if c.circles {
                    2.0 * half.1 - (pa.0 - pb.0).hypot(pa.1 - pb.1)
                } else {
                    box_box_depth(pa, half, pb, half)
                });
            }
        }
    }
    out
}

/// Rounding allowance of the energy sums, relative to the start's kinetic
/// energy: every impulse rounds a velocity by one I32F32 step (2.3e-10) per
/// component; a body at speed v changes its kinetic energy by m·v·2.3e-10
/// per rounding, relative (2.3e-10/v)·2 of ½mv²; over 120 ticks of at most
/// (8 + 1 + 3) sweeps of 21 rows that is ≤ 120·12·21·2·2.3e-10/50 ≈ 3e-10
/// of E0 at the slowest throw (50 units/s); the columns of 40 bodies 0.01
/// thick (each sees the 10 below within the speculative margin: about 450
/// rows) are thrown at 200 units/s or more, ≤ 120·12·450·2·2.3e-10/200
/// ≈ 1.5e-9. 1e-8·E0 is several times either.
const ROUND_ENERGY: f64 = 1e-8;

/// Runs every case; prints the figures and asserts none fails.
fn check(cases: &[Case]) {
    let mut failures = Vec::new();
    let (mut worst_ball, mut worst_box, mut worst_rise) = (f64::MIN, f64::MIN, f64::MIN);
    for c in cases {
        let o = run(c);
        worst_ball = worst_ball.max(o.ball_depth);
        worst_box = worst_box.max(o.box_depth);
        worst_rise = worst_rise.max(o.rise / o.e0);
        if o.ball_depth > SLOP + ROUND || o.box_depth > SLOP + ROUND || o.rise > ROUND_ENERGY * o.e0
        {
            failures.push(format!(
                "n {} circles {} heavy top {} t {} w {} r {} v {} ratio {} e {} bullet {} above {} at {:?}: ball depth {:.3e}, box depth {:.3e}, energy rise {:.3e} of E0 {:.3e}",
                c.count, c.circles, c.heavy_top, c.thickness, c.width, c.radius, c.speed, c.ratio, c.e, c.bullet, c.above, c.origin,
                o.ball_depth, o.box_depth, o.rise, o.e0
            ));
        }
    }
    println!(
        "{} cases: worst ball depth {worst_ball:.3e}, worst box depth {worst_box:.3e}, worst energy rise {worst_rise:.3e} of E0; {} fail",
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

#[test]
fn a_fast_ball_never_tunnels_into_a_stack_of_thin_boxes_nor_gains_energy() {
    let mut cases = Vec::new();
    for thickness in [0.02, 0.05, 0.1, 0.2] {
        for (width, radius) in [(1.0, 0.05), (0.3, 0.02), (1.0, 0.2)] {
            for speed in [50.0, 200.0, 1000.0] {
                for ratio in [0.01, 1.0, 100.0] {
                    for e in [0.0, 1.0] {
                        for bullet in [false, true] {
                            for above in [0.0, 0.37, 2.9] {
                                for origin in [(0.0, 0.0), (30_000.0, -30_000.0)] {
                                    cases.push(Case {
                                        count: 10,
                                        circles: false,
                                        heavy_top: false,
                                        thickness,
                                        width,
                                        radius,
                                        speed,
                                        ratio,
                                        e,
                                        bullet,
                                        above,
                                        origin,
                                    });
                                }
                            }
                        }
                    }
                }
            }
        }
    }
    check(&cases);
}

#[test]
fn columns_of_other_heights_and_of_circles_hold_a_fast_ball_too() {
    let mut cases = Vec::new();
    for count in [3, 40] {
        for thickness in [0.01, 0.05] {
            for circles in [false, true] {
                for heavy_top in [false, true] {
                    for speed in [200.0, 1000.0] {
                        for ratio in [0.01, 1.0, 100.0] {
                            for e in [0.0, 1.0] {
                                for bullet in [false, true] {
                                    cases.push(Case {
                                        count,
                                        circles,
                                        heavy_top,
                                        thickness,
                                        width: 1.0,
                                        radius: 0.05,
                                        speed,
                                        ratio,
                                        e,
                                        bullet,
                                        above: 0.0,
                                        origin: (0.0, 0.0),
                                    });
                                }
                            }
                        }
                    }
                }
            }
        }
    }
    check(&cases);
}
