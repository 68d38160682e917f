//! A fast ball onto two or three columns of thin boxes standing side by
//! side (issue 13, after F15), at the default settings (dt = 1/60,
//! substeps 1, 8 velocity + 3 position iterations, slop 1e-4).
//!
//! Columns of 10 boxes 0.02 or 0.05 thick and 1 wide rest on rigid ground,
//! touching (gap 0), 1e-4 or 0.03 apart; a ball arrives at 50-1000 units/s
//! at the centre of one column. The rows between the columns (side by
//! side, and across the gap at a slant) close cycles, so the columns and
//! the ball are one cyclic group. Rigid bodies on rigid ground: the struck
//! column is in effect an immovable floor at its top, and the columns
//! beside it have no reason to move at all:
//!
//! * **No tunnelling.** The ball never ends a tick inside a box or the
//!   ground by more than the linear slop (a speculative contact may rest
//!   one slop deep), and nor does any box end inside another box (of its
//!   column or of the next: the boxes are measured pairwise) or the ground
//!   by more than the slop.
//! * **No energy source.** Kinetic plus gravitational energy of every body
//!   never rises above its start. Measured from the stored velocities, the
//!   integrator's chord velocities: under gravity these differ from the
//!   velocity at the sample by up to g·h/2, so the measured kinetic energy
//!   of a body may differ from the true one by m·|v|·g·h/2 + m·(g·h/2)²/2
//!   either way (the ball falling at the start is measured low, rising
//!   after an e = 1 bounce measured high). The allowance is that bound at
//!   the start plus at the tick, plus the rounding allowance of the sums
//!   ([`ROUND_ENERGY`]).
//!
//! Before the fix 672 of these 1 008 throws failed (and 556 of the 1 080
//! variants, 120 of 144 with columns of circles): boxes ended wholly
//! inside the box below (box depth 0.125 in this family, 13.2 units
//! through the ground among the variants); the group was solved by 8 sweeps of
//! sequential impulses, which carry an impact down a chain of `n` rows only
//! in `O(n²)` sweeps.
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

/// Rounding allowance of the energy sums, relative to the start's kinetic
/// energy E0: every impulse rounds a velocity by one I32F32 step (2.3e-10)
/// per component; a body at speed v changes its kinetic energy by
/// m·v·2.3e-10 per rounding, relative (2.3e-10/v)·2 of ½mv². Three columns
/// of 10 boxes 0.02 thick and the ball make at most about 300 rows (each
/// box sees the four below it within the speculative margin, and its
/// neighbours across the seam); over 120 ticks of at most (8 + 1 + 3)
/// sweeps that is ≤ 120·12·300·2·2.3e-10/50 ≈ 4e-9 of E0 at the slowest
/// throw (50 units/s). 1e-8·E0 is over twice that.
const ROUND_ENERGY: f64 = 1e-8;

#[derive(Clone, Copy, Debug)]
struct Case {
    /// Columns side by side, `pitch` = width + gap apart.
    columns: usize,
    /// Bodies per column.
    count: usize,
    gap: f64,
    /// Columns of circles (diameter `thickness`, the width too) instead of
    /// boxes.
    circles: bool,
    /// The top body of each column 100x the others.
    heavy_top: bool,
    thickness: f64,
    width: f64,
    radius: f64,
    speed: f64,
    /// Ball mass over one box's mass.
    ratio: f64,
    e: f64,
    bullet: bool,
    /// Where the ball arrives, in pitches from the first column's centre
    /// (0: its centre, 1: the second's, 0.5: the seam between them).
    aim: f64,
    /// Extra drop height above the top (a different phase of the impact
    /// within a tick).
    above: f64,
    origin: (f64, f64),
}

impl Case {
    fn base() -> Case {
        Case {
            columns: 2,
            count: 10,
            gap: 0.0,
            circles: false,
            heavy_top: false,
            thickness: 0.02,
            width: 1.0,
            radius: 0.05,
            speed: 200.0,
            ratio: 1.0,
            e: 0.0,
            bullet: false,
            aim: 0.0,
            above: 0.0,
            origin: (0.0, 0.0),
        }
    }
}

struct Outcome {
    /// Deepest the ball went into a body or the ground.
    ball_depth: f64,
    /// Deepest any body of the columns went into another or the ground.
    box_depth: f64,
    /// Highest energy above the start beyond the sampling allowance.
    rise: f64,
    /// The start's kinetic energy (the scale of the energy figures).
    e0: f64,
}

fn run(c: &Case) -> Outcome {
    let mut world = World::new(WorldSettings::default());
    let (ox, oy) = c.origin;
    world
        .add_body(BodyDef::fixed(Shape::aabb(vec2(50.0, 0.5))).position(vec2(ox, oy - 0.5)))
        .expect("ground");
    let width = if c.circles { c.thickness } else { c.width };
    let half = (width / 2.0, c.thickness / 2.0);
    let pitch = width + c.gap;
    let mut bodies = Vec::new();
    for column in 0..c.columns {
        for i in 0..c.count {
            let shape = if c.circles {
                Shape::circle(fx(half.1))
            } else {
                Shape::aabb(vec2(half.0, half.1))
            };
            let heavy = c.heavy_top && i + 1 == c.count;
            let at = vec2(
                ox + column as f64 * pitch,
                oy + half.1 + i as f64 * c.thickness,
            );
            let body = BodyDef::dynamic(shape)
                .mass(fx(if heavy { 100.0 } else { 1.0 }))
                .position(at);
            bodies.push(world.add_body(body).expect("body"));
        }
    }
    let box_mass = 1.0;
    let top = c.count as f64 * c.thickness;
    let ball = world
        .add_body(
            BodyDef::dynamic(Shape::circle(fx(c.radius)))
                .mass(fx(c.ratio * box_mass))
                .restitution(fx(c.e))
                .bullet(c.bullet)
                .position(vec2(ox + c.aim * pitch, oy + top + c.radius + c.above))
                .velocity(vec2(0.0, -c.speed)),
        )
        .expect("ball");
    let mut all = bodies.clone();
    all.push(ball);
    let energy = |world: &World| energy_and_allowance(world, &all, G, H, oy);
    let (e0, allowance0) = energy(&world);
    let mut out = Outcome {
        ball_depth: f64::MIN,
        box_depth: f64::MIN,
        rise: f64::MIN,
        e0: 0.5 * c.ratio * box_mass * c.speed * c.speed,
    };
    let mut at = Vec::with_capacity(bodies.len());
    for _ in 0..120 {
        world.step();
        let (e, allowance) = energy(&world);
        out.rise = out.rise.max(e - e0 - allowance - allowance0);
        let pc = world.body(ball).unwrap().position().to_f64();
        let pc = (pc.0 - ox, pc.1 - oy);
        out.ball_depth = out.ball_depth.max(c.radius - pc.1);
        at.clear();
        at.extend(bodies.iter().map(|&id| {
            let p = world.body(id).unwrap().position().to_f64();
            (p.0 - ox, p.1 - oy)
        }));
        for (i, &pa) in at.iter().enumerate() {
            out.box_depth = out.box_depth.max(half.1 - pa.1);
            out.ball_depth = out.ball_depth.max(if c.circles {
                c.radius + half.1 - (pc.0 - pa.0).hypot(pc.1 - pa.1)
            } else {
                circle_box_depth(pc, c.radius, pa, half)
            });
            for &pb in &at[i + 1..] {
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

/// Runs every case and prints the figures; returns the failures.
fn failures(cases: &[Case]) -> Vec<String> {
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
                "{c:?}: ball depth {:.3e}, box depth {:.3e}, energy rise {:.3e} of E0 {:.3e}",
                o.ball_depth, o.box_depth, o.rise, o.e0
            ));
        }
    }
    println!(
        "{} cases: worst ball depth {worst_ball:.3e}, worst box depth {worst_box:.3e}, worst energy rise {worst_rise:.3e} of E0; {} fail",
        cases.len(),
        failures.len()
    );
    // Forty failures are printed; every one with the ALL_FAILS environment
    // variable set (to compare failure lists between builds).
    let shown = if std::env::var_os("ALL_FAILS").is_some() {
        usize::MAX
    } else {
        40
    };
    for f in failures.iter().take(shown) {
        println!("  {f}");
    }
    failures
}

fn check(cases: &[Case]) {
    let failed = failures(cases);
    assert!(
        failed.is_empty(),
        "{} of {} cases fail",
        failed.len(),
        cases.len()
    );
}

/// The reviewer's family at a column's centre: 2 and 3 columns, gaps 0,
/// 1e-4 and 0.03, on the first or the second column (and on the seam of
/// touching columns), boxes 0.02 and 0.05 thick, 50-1000 units/s, ball
/// 0.01x-100x a box, e 0 and 1, balls of radius 0.05 and 0.2 (1 008
/// throws).
#[test]
fn a_fast_ball_on_columns_side_by_side_neither_sinks_a_box_nor_gains_energy() {
    let mut cases = Vec::new();
    for columns in [2, 3] {
        for (gap, aim) in [
            (0.0, 0.0),
            (0.0, 1.0),
            (0.0, 0.5),
            (1e-4, 0.0),
            (1e-4, 1.0),
            (0.03, 0.0),
            (0.03, 1.0),
        ] {
            {
                for thickness in [0.02, 0.05] {
                    for speed in [50.0, 200.0, 1000.0] {
                        for ratio in [0.01, 1.0, 100.0] {
                            for e in [0.0, 1.0] {
                                for radius in [0.05, 0.2] {
                                    cases.push(Case {
                                        columns,
                                        gap,
                                        aim,
                                        thickness,
                                        speed,
                                        ratio,
                                        e,
                                        radius,
                                        ..Case::base()
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

/// Variants the family does not name, thrown from the top of the columns
/// (`above` 0) or dropped from above them: the middle and the last of
/// three columns, other gaps (1e-3, 0.01, 0.08), 3 and 20 boxes per
/// column, a heavy (100x) top box on every column, bullets, near the
/// world's bounds.
fn variants(above: f64) -> Vec<Case> {
    let mut cases = Vec::new();
    for gap in [1e-3, 0.01, 0.08] {
        for (columns, aim) in [(3, 1.0), (3, 2.0), (2, 0.0)] {
            for count in [3, 20] {
                for heavy_top in [false, true] {
                    for speed in [50.0, 1000.0] {
                        for ratio in [1.0, 100.0] {
                            for e in [0.0, 1.0] {
                                for bullet in [false, true] {
                                    for origin in [(0.0, 0.0), (30_000.0, -30_000.0)] {
                                        cases.push(Case {
                                            columns,
                                            count,
                                            gap,
                                            aim,
                                            heavy_top,
                                            speed,
                                            ratio,
                                            e,
                                            bullet,
                                            above,
                                            origin,
                                            ..Case::base()
                                        });
                                    }
                                }
                            }
                        }
                    }
                }
            }
        }
    }
    cases
}

/// Every variant, a ball 100x a box, elastic (e = 1), at 1000 units/s onto
/// columns of only 3 boxes among them (its bounce drives the boxes below
/// into each other and the ground, and the impact's impulses are left in
/// the column after the ball has gone): before the fix those 72 throws
/// gained up to 0.65 of the ball's energy (36 failed; boxes thrown up at
/// `max_speed`).
#[test]
fn other_gaps_counts_and_placements_hold_the_ball_too() {
    check(&variants(0.0));
}

/// The same variants dropped from 0.37 and 2.9 above the columns
/// (arriving within a tick, at two phases of it), the ball of a box's
/// mass. Before session 15's fix 128 of these 1 152 throws failed (3
/// columns, 50 units/s): every box below the ball is within the
/// speculative margin, and taken in index order the ball's row to the
/// first column's bottom box (0.63 away at a slant, not closing within the
/// substep) joined it to the group's spanning tree, leaving its row to the
/// box it struck off the exact solve: the struck column sank 3.7e-3 into
/// itself.
#[test]
fn a_ball_of_a_boxs_mass_dropped_onto_columns_side_by_side_is_caught() {
    let cases: Vec<Case> = [0.37, 2.9]
        .into_iter()
        .flat_map(variants)
        .filter(|c| c.ratio == 1.0)
        .collect();
    check(&cases);
}

/// Still open: the same drops from 0.37 and 2.9 with the ball 100x a box,
/// and every drop from 0.9 (the ball arrives just after a tick begins): a
/// box ends up to 0.02 into the one below. Traced: the heavy ball's catch
/// by its speculative row is warm-started into the next substep, and
/// 20-box columns under it make a group of uneven masses above the block
/// solver's size (its covering trees: 20-box columns with 100x top boxes
/// too, struck by a ball of a box's mass from 0.9). 224 of these 2 304
/// throws fail: 128 of the 1 152 heavy balls from 0.37 and 2.9, 96 of the
/// 1 152 drops from 0.9 (272 before the exact sparse solve of uneven
/// groups, 304 before session 15's fix; the drops from 0.37
/// and 2.9 with both masses: 1 464 of 2 304 failed before session 13's
/// fix, 424 before session 14's, 280 before session 15's).
#[test]
#[ignore = "issue 13: a ball dropped from a height onto columns side by side; 224 of 2304 throws fail"]
fn a_ball_dropped_from_a_height_onto_columns_side_by_side_still_open() {
    let mut cases: Vec<Case> = [0.37, 2.9]
        .into_iter()
        .flat_map(variants)
        .filter(|c| c.ratio == 100.0)
        .collect();
    cases.extend(variants(0.9));
    check(&cases);
}

/// Columns of circles (a column of circles has vertical rows too) side by
/// side, the given gaps apart, struck at the centre of the first or the
/// middle column.
fn circle_columns(gaps: &[f64]) -> Vec<Case> {
    let mut cases = Vec::new();
    for &gap in gaps {
        for (columns, aim) in [(2, 0.0), (3, 1.0)] {
            for thickness in [0.02, 0.05] {
                for speed in [50.0, 200.0, 1000.0] {
                    for ratio in [0.01, 1.0, 100.0] {
                        for e in [0.0, 1.0] {
                            cases.push(Case {
                                columns,
                                gap,
                                aim,
                                circles: true,
                                thickness,
                                speed,
                                ratio,
                                e,
                                ..Case::base()
                            });
                        }
                    }
                }
            }
        }
    }
    cases
}

/// Columns of circles 0.01 and 0.03 apart (the circles of neighbouring
/// columns see each other at a slant within the speculative margin).
#[test]
fn columns_of_circles_side_by_side_hold_the_ball_too() {
    check(&circle_columns(&[0.01, 0.03]));
}

/// Columns of circles touching side by side (gap 0 or 1e-4). The impact
/// shifts the circles sideways by about 1e-6, so the rows along the
/// columns and between them lie off the axes by about 1e-4 rad; the group
/// counted as neither resting nor struck and kept sequential impulses
/// after the impact: circles sank up to 5e-3 into the ones below (a ball
/// 0.01x a circle at 50 units/s: 3e-3, settling and sinking again every
/// few ticks) and, with the impact's impulses warm-started into them, went
/// up to 1 670 units through the ground (energy up to 16.6 of the
/// ball's).
/// 60 of these 144 throws failed before session 15's fix (120 before
/// session 13's).
#[test]
fn columns_of_touching_circles_side_by_side_hold_the_ball_too() {
    check(&circle_columns(&[0.0, 1e-4]));
}

/// A ball of a box's mass bouncing (e = 1) on the seam between two
/// columns 0.03 apart, at 50 and 200 units/s: it lands on the two top
/// corners and leaves again, and no box moves. At 50 units/s every row of
/// the ball to the boxes below closes within the substep; taken in index
/// order, its rows to the bottom boxes of both columns (0.43 away at a
/// slant) joined it to the group's spanning tree, and its rows to the two
/// top boxes it lands on (0.0022 apart) were left off the exact solve:
/// every one of these 8 throws failed (boxes sunk up to 6.7e-3 into each
/// other, energy up to 0.14 of the ball's above the start) until the rows
/// that meet within the substep were taken nearest first.
#[test]
fn a_ball_bouncing_on_the_seam_between_two_columns_apart_leaves_them_standing() {
    let mut cases = Vec::new();
    for thickness in [0.02, 0.05] {
        for speed in [50.0, 200.0] {
            for radius in [0.05, 0.2] {
                cases.push(Case {
                    columns: 2,
                    gap: 0.03,
                    aim: 0.5,
                    thickness,
                    speed,
                    e: 1.0,
                    radius,
                    ..Case::base()
                });
            }
        }
    }
    check(&cases);
}

/// Still open: the ball on the seam between two columns that stand apart
/// (gap 1e-4 or 0.03; on a seam of touching columns it passes). The ball
/// sits in the gap on the two top corners; its rows to the boxes below
/// reach down the seam at a slant, which no rule marks as implied (the
/// implied rows are along an axis), and its row to the ground, apart by
/// the columns' height, is folded into the exact solve before the rows of
/// the columns and leaves a row of a column dependent (left to sequential
/// impulses). Folding such rows last fixed a few and broke a crowd test.
/// 166 of these 288 throws fail (227 before session 13's fix, 217 before
/// session 14's, 212 before the rows meeting within the substep were
/// taken nearest first, 198 before rows within 2^-10 of an axis counted
/// as along it, 192 before the exact sparse solve of uneven groups; box
/// depth up to 20.3). 164 before the sparse solve released contradicting
/// rows: two throws (2 columns 1e-4 apart, ball 100× at 200 units/s, e 0)
/// now end a box 1.03e-4 and 1.58e-4 deep (slop 1e-4): at the first tick
/// the ball, 4.6e-6 above one top and resting on the other, keeps no
/// impulse on the row apart (the row its further refinement would empty),
/// so one column takes the whole catch.
#[test]
#[ignore = "issue 13: a fast ball on the seam between columns apart; 166 of 288 throws fail"]
fn a_fast_ball_on_the_seam_between_columns_apart_still_open() {
    let mut cases = Vec::new();
    for columns in [2, 3] {
        for gap in [1e-4, 0.03] {
            for thickness in [0.02, 0.05] {
                for speed in [50.0, 200.0, 1000.0] {
                    for ratio in [0.01, 1.0, 100.0] {
                        for e in [0.0, 1.0] {
                            for radius in [0.05, 0.2] {
                                cases.push(Case {
                                    columns,
                                    gap,
                                    aim: 0.5,
                                    thickness,
                                    speed,
                                    ratio,
                                    e,
                                    radius,
                                    ..Case::base()
                                });
                            }
                        }
                    }
                }
            }
        }
    }
    check(&cases);
}

/// Columns of circles touching side by side (gap 0 or 1e-4), a ball
/// dropped onto the centre of the first or the middle column from 0.37,
/// 0.9 and 2.9 above it (arriving within a tick, at three phases of it),
/// ball radius 0.05 and 0.2, circles 0.02 and 0.05 across.
fn circle_drops(ratio: f64) -> Vec<Case> {
    let mut cases = Vec::new();
    for above in [0.37, 0.9, 2.9] {
        for radius in [0.05, 0.2] {
            for thickness in [0.02, 0.05] {
                for gap in [0.0, 1e-4] {
                    for (columns, aim) in [(2, 0.0), (3, 1.0)] {
                        for count in [3, 20] {
                            for speed in [50.0, 1000.0] {
                                for e in [0.0, 1.0] {
                                    cases.push(Case {
                                        columns,
                                        count,
                                        gap,
                                        aim,
                                        circles: true,
                                        thickness,
                                        radius,
                                        speed,
                                        ratio,
                                        e,
                                        above,
                                        ..Case::base()
                                    });
                                }
                            }
                        }
                    }
                }
            }
        }
    }
    cases
}

/// A ball of a circle's mass dropped onto columns of touching circles
/// lands on the circle below it and stops there (e = 0) or leaves again
/// (e = 1); no circle moves. The ball is wider than a circle, so as it
/// falls it sees the tops of the neighbouring columns within the
/// speculative margin too, at a slant, and its rows to them also close
/// within the substep. Their gaps along their normals are shorter (0.29
/// against 0.37 below, for 2 columns of 3 circles 0.05 across and a ball
/// of radius 0.05), but the ball closes them more slowly (37 against 50
/// units/s) and would meet them later: the exact solve leaves them
/// inactive. Taken nearest first, the slanted row joined the ball to the
/// group's spanning tree and the row below was left to sequential
/// impulses, which threw the ball and the top circle sideways; the rows
/// of the column, now off the axes, left the catch on the next tick to
/// sequential impulses too, and a circle sank 0.02 into the one below.
/// 207 of these 384 drops failed until the rows meeting within the
/// substep were taken soonest first.
#[test]
fn a_ball_dropped_onto_columns_of_touching_circles_lands_on_the_circle_below() {
    check(&circle_drops(1.0));
}

/// A ball 10×, 100× or 1 000× a circle bouncing (e = 1) on short columns
/// of touching or nearly touching circles (3 or 5 per column, 0.02 or
/// 0.05 across, gaps 0, 1e-4 and 1e-3; two columns struck at the first's
/// centre, three at the middle's or the last's), thrown from the top or
/// dropped from 0.37 above, at `speed`. The columns stand on rigid ground,
/// so the struck column is in effect a rigid floor: no circle moves into
/// another or the ground, and the energy never rises (the bounds and
/// their derivation are those of the family at the top of the file).
fn heavy_bounces(ratios: &[f64], speeds: &[f64]) -> Vec<Case> {
    let throws: Vec<(f64, f64)> = ratios
        .iter()
        .flat_map(|&ratio| speeds.iter().map(move |&speed| (ratio, speed)))
        .collect();
    bounces_on_short_columns(&[(2, 0.0), (3, 1.0), (3, 2.0)], &throws)
}

/// Elastic bounces (e = 1) of a ball on short columns of circles, every
/// `(ratio, speed)` of `throws` on every `(columns, aim)` of `layouts`:
/// 3 or 5 circles per column, 0.02 or 0.05 across, gaps 0, 1e-4 and 1e-3,
/// thrown from the top or dropped from 0.37 above.
fn bounces_on_short_columns(layouts: &[(usize, f64)], throws: &[(f64, f64)]) -> Vec<Case> {
    let mut cases = Vec::new();
    for &(ratio, speed) in throws {
        for &(columns, aim) in layouts {
            for count in [3, 5] {
                for thickness in [0.02, 0.05] {
                    for gap in [0.0, 1e-4, 1e-3] {
                        for above in [0.0, 0.37] {
                            cases.push(Case {
                                columns,
                                count,
                                gap,
                                aim,
                                circles: true,
                                thickness,
                                speed,
                                ratio,
                                e: 1.0,
                                above,
                                ..Case::base()
                            });
                        }
                    }
                }
            }
        }
    }
    cases
}

/// Balls 10× and 100× a circle at 50 and 1 000 units/s, and 1 000× at 50.
/// After the bounce the struck column, pressed down by the catch, moved
/// down at about a circle's share of the ball's impulse (0.44 units/s, 2
/// columns of 3, ball 100×, 50 units/s), faster than `|g|·h`, so its rows
/// to the next column at a slant (0.02 apart along their normals, and
/// parting) counted as fast rows at a slant holding several bodies: the
/// group kept sequential impulses, which could not take the catch's
/// impulse, warm-started into the next substep after the ball had left,
/// back out of the column in 8 sweeps. The bottom circle left at 465
/// units/s, and the energy rose to 3 times the ball's. 168 of these 360
/// bounces failed (box depth up to 390, energy up to 48 times the ball's)
/// until a row apart whose gap the velocities do not close within the
/// substep stopped counting (it carries no impulse).
#[test]
fn a_heavy_ball_bouncing_on_short_columns_of_circles_leaves_them_standing() {
    let mut cases = heavy_bounces(&[10.0, 100.0], &[50.0, 1000.0]);
    cases.extend(heavy_bounces(&[1000.0], &[50.0]));
    check(&cases);
}

/// Elastic bounces of very heavy, very fast balls, `(ratio, speed)` of
/// `throws`, on the layouts of [`heavy_bounces`], at the origin and at
/// (30 000, −30 000).
fn very_heavy_bounces(throws: &[(f64, f64)]) -> Vec<Case> {
    let cases = bounces_on_short_columns(&[(2, 0.0), (3, 1.0), (3, 2.0)], throws);
    let far = cases.iter().map(|&c| Case {
        origin: (30_000.0, -30_000.0),
        ..c
    });
    cases.iter().copied().chain(far).collect()
}

/// A ball 1 000× a circle at 1 000 units/s (the reviewer's class), 300×
/// at 1 000 units/s and 1 000× at 300 units/s (the catch's impulse,
/// 2·ratio·speed, 6e5 to 2e6 per row) leaves short columns of circles
/// standing (bounds of the family at the top of the file).
///
/// The first tick's velocity solve (the sparse solve) held rows that
/// contradict each other: the ball, moving 16 units within the tick,
/// sees every circle of the column below it and the ground within the
/// speculative margin, and the rows ball–ground, ball–bottom circle and
/// bottom circle–ground are one constraint (the first is the sum of the
/// others) with targets −15, −12 and 0 units/s. The regularised solve
/// splits the difference (1.5 units/s short on two rows) and each round of
/// refinement only moves the impulses along the dependent direction by
/// the contradiction over ε (about 1e5 per round against 9e5 on the
/// ball–ground row), so the refinement stopped (its shortfall no longer
/// halved) with the columns moving sideways at up to 11 units/s; the
/// struck column, off the axis, left the next tick's group to sequential
/// impulses, which could not take the catch's warm-started impulses back
/// out after the ball had gone: its circles left at `max_speed`. 160 of
/// these 432 bounces failed (54 of the 72 at 1 000× and 1 000 units/s;
/// box depth up to 19, energy up to 1.8 times the ball's over the start)
/// until a stalled refinement released the row its rounds would have
/// emptied first.
#[test]
fn a_very_heavy_fast_ball_on_short_columns_of_circles_leaves_them_standing() {
    check(&very_heavy_bounces(&[
        (1000.0, 1000.0),
        (300.0, 1000.0),
        (1000.0, 300.0),
    ]));
}

/// Still open: heavier or faster still (3 000× at 1 000 units/s, 1 000×
/// at 3 000, 10 000× at 300: 3e6 to 6e6 per row). Only three columns of
/// five circles 0.02 across fail, the ball on the middle or the last:
/// 32 of these 432 bounces (box depth up to 270, energy up to 0.41 of the
/// ball's over the start; all 432 failed before contradicting rows were
/// released).
#[test]
#[ignore = "issue 13: balls 3000x at 1000 units/s, 1000x at 3000, 10000x at 300 on columns of circles; 32 of 432 bounces fail"]
fn heavier_faster_balls_on_short_columns_of_circles_still_open() {
    check(&very_heavy_bounces(&[
        (3000.0, 1000.0),
        (1000.0, 3000.0),
        (10_000.0, 300.0),
    ]));
}

/// The ball's velocity and the fastest circle's speed after the first
/// tick (`c.above` must let the ball arrive within it), and the ball's
/// velocity after the same tick with the columns replaced by a fixed
/// floor at their top.
fn first_bounce(c: &Case) -> ((f64, f64), f64, (f64, f64)) {
    let throw = |world: &mut World, top: f64| {
        world
            .add_body(
                BodyDef::dynamic(Shape::circle(fx(c.radius)))
                    .mass(fx(c.ratio))
                    .restitution(fx(c.e))
                    .position(vec2(0.0, top + c.radius + c.above))
                    .velocity(vec2(0.0, -c.speed)),
            )
            .expect("ball")
    };
    let top = c.count as f64 * c.thickness;
    let pitch = c.thickness + c.gap;
    let mut world = World::new(WorldSettings::default());
    world
        .add_body(BodyDef::fixed(Shape::aabb(vec2(50.0, 0.5))).position(vec2(0.0, -0.5)))
        .expect("ground");
    let mut circles = Vec::new();
    for column in 0..c.columns {
        for i in 0..c.count {
            let at = vec2(
                (column as f64 - c.aim) * pitch,
                c.thickness / 2.0 + i as f64 * c.thickness,
            );
            let body = BodyDef::dynamic(Shape::circle(fx(c.thickness / 2.0)))
                .mass(fx(1.0))
                .position(at);
            circles.push(world.add_body(body).expect("circle"));
        }
    }
    let ball = throw(&mut world, top);
    world.step();
    let fastest = circles
        .iter()
        .map(|&id| {
            let v = world.body(id).unwrap().velocity().to_f64();
            v.0.hypot(v.1)
        })
        .fold(0.0, f64::max);
    let on_columns = world.body(ball).unwrap().velocity().to_f64();
    let mut floor = World::new(WorldSettings::default());
    floor
        .add_body(BodyDef::fixed(Shape::aabb(vec2(50.0, 0.5))).position(vec2(0.0, top - 0.5)))
        .expect("floor");
    let alone = throw(&mut floor, top);
    floor.step();
    (
        on_columns,
        fastest,
        floor.body(alone).unwrap().velocity().to_f64(),
    )
}

/// A ball 0.01× to 1 000× a circle (e = 1) thrown onto the top of columns
/// of circles standing on rigid ground, or dropped from 0.37 above them
/// (arriving within the first tick at 50 and 1 000 units/s): a column on
/// rigid ground is a rigid floor, so the ball leaves it as it leaves a
/// fixed floor at the column's top, and no circle moves. Variants: one
/// column; two struck at the first, three at the middle or the last;
/// touching or 1e-4 or 1e-3 apart; 3 or 5 circles 0.02 or 0.05 across.
///
/// Bound: the exact solve of a group leaves each active row within 2^-20
/// units/s of its target (its stopping rule; rounding leaves rows within
/// it), and a body's velocity is carried to the ground by at most one row
/// per body of the group (at most 16 here), so both the ball's departure
/// from the floor's and a circle's speed are within 16·2^-20 ≈ 1.5e-5
/// units/s.
///
/// Before the bounce of a group solved exactly took the refined sparse
/// solve (it took the dense block solve, regularised by 2^-16 and not
/// refined, for groups of up to 64 rows), a ball 100× a circle at 1 000
/// units/s left two columns of 3 at 991 units/s and the struck column
/// moving down at 3, 6 and 9 units/s: the heavy ball on a column on the
/// ground is nearly statically indeterminate (the ball's row, the
/// column's and the ground's carry one force; the smallest eigenvalue of
/// the scaled matrix is about the ball's share of the inverse masses),
/// and the regularisation left the impulse short by `ε/(λ + ε)` of it.
/// Of the 96 bounces of a ball 1 000× at 1 000 units/s, 61 were off (up
/// to 9.8 units/s) until a stalled refinement of the sparse solve
/// released a row of contradicting rows (see
/// [`a_very_heavy_fast_ball_on_short_columns_of_circles_leaves_them_standing`]).
#[test]
fn a_heavy_ball_leaves_columns_of_circles_as_it_leaves_the_ground() {
    const BOUND: f64 = 16.0 / 1_048_576.0;
    let mut failures = Vec::new();
    let mut worst: f64 = 0.0;
    let mut cases = 0;
    let throws: Vec<(f64, f64)> = [0.01, 1.0, 10.0, 100.0, 1000.0]
        .into_iter()
        .flat_map(|ratio| [50.0, 1000.0].map(|speed| (ratio, speed)))
        .collect();
    let layouts = [(1, 0.0), (2, 0.0), (3, 1.0), (3, 2.0)];
    for c in bounces_on_short_columns(&layouts, &throws) {
        let (ball, fastest, floor) = first_bounce(&c);
        let off = (ball.0 - floor.0).hypot(ball.1 - floor.1);
        worst = worst.max(off).max(fastest);
        cases += 1;
        if off > BOUND || fastest > BOUND {
            failures.push(format!(
                "{c:?}: ball {ball:?} (floor {floor:?}), fastest circle {fastest:.3e}"
            ));
        }
    }
    println!(
        "{cases} bounces: worst {worst:.3e} units/s; {} fail",
        failures.len()
    );
    for f in &failures {
        println!("  {f}");
    }
    assert!(
        failures.is_empty(),
        "{} of {cases} bounces fail",
        failures.len()
    );
}

/// Columns of circles the families above do not name: touching or 1e-4
/// or 1e-3 apart; two columns struck at the first's centre, three at the
/// middle's or the last's, four on the seam between the two inner ones
/// (the ball rests on two circles at a slant); 3 and 20 circles, with and
/// without a top circle 100× the others; 50 and 1 000 units/s; the ball
/// 0.01×, 1× and 100× a circle; e 0 and 1; thrown from the top or
/// dropped from 0.37 above.
fn circle_column_variants() -> Vec<Case> {
    let mut cases = Vec::new();
    for gap in [0.0, 1e-4, 1e-3] {
        for (columns, aim) in [(2, 0.0), (3, 1.0), (3, 2.0), (4, 1.5)] {
            for count in [3, 20] {
                for heavy_top in [false, true] {
                    for speed in [50.0, 1000.0] {
                        for ratio in [0.01, 1.0, 100.0] {
                            for e in [0.0, 1.0] {
                                for above in [0.0, 0.37] {
                                    cases.push(Case {
                                        columns,
                                        count,
                                        gap,
                                        aim,
                                        circles: true,
                                        heavy_top,
                                        thickness: 0.05,
                                        speed,
                                        ratio,
                                        e,
                                        above,
                                        ..Case::base()
                                    });
                                }
                            }
                        }
                    }
                }
            }
        }
    }
    cases
}

/// Still open: columns of circles in general, and the drops above with a
/// ball 0.01× or 100× a circle. Uneven masses (a heavy top circle, a
/// heavy or light ball) and the ball on the seam between two circles (its
/// rows truly at a slant: it pushes the columns apart, which friction
/// should hold, tan 19.5° = 0.35 < 0.6) still sink circles into each
/// other. 309 of these 1 152 variants fail (346 before rows apart that
/// the velocities do not close stopped counting, 373 before the rows
/// meeting within the substep were taken soonest first, 511 before the
/// exact sparse solve, 557 before rows within 2^-10 of an axis counted as
/// along it), and 195 of the 768 drops (291 before rows apart that do not
/// close stopped counting).
#[test]
#[ignore = "issue 13: columns of circles in general; 309 of 1152 variants and 195 of 768 drops fail"]
fn columns_of_circles_in_general_still_open() {
    let mut cases = circle_column_variants();
    cases.extend(circle_drops(0.01));
    cases.extend(circle_drops(100.0));
    check(&cases);
}
