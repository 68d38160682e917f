//! A fast projectile pushing a free box into a fixed wall (issue 13, N7's
//! leftover): the box's motion after the impact can be far beyond what its
//! contacts were looked for with, so it may have no row with the wall; it
//! is stopped at the wall (`src/world/step/punched_motion.rs`), and the
//! projectile behind it must be stopped too.
//!
//! Rigid bodies cannot interpenetrate, whatever the speeds: at every tick
//!
//! * the projectile is not inside the box, the box not inside the wall, the
//!   projectile not inside the wall, each by more than the linear slop (a
//!   speculative contact may rest one slop deep);
//! * the order along the line of flight is kept: projectile, box, wall
//!   (nothing passes through anything);
//! * gravity off, frictionless: the kinetic energy never rises above its
//!   start (the wall is fixed; an impact can only keep or lose energy), up
//!   to the rounding of the sums (`ROUND_ENERGY`).
//!
//! Variants: projectile speeds 50-2000 units/s, bullet flag on and off,
//! box 0.01x-1000x the projectile's mass, walls 0.02-2 thick, the box flush
//! with the wall or 1e-4 to 2 from it, e 0 and 1, at the origin and near
//! the world's bounds, flying along +x and along −y. Wider
//! ([`one_body_driven_into_a_wall_never_overlaps_anything`]): a circle or
//! a box projectile (half size 0.05 or 0.3) driving a box or a circle (half
//! size 0.05, 0.25, 1), 0.01x or 1x its mass, at 50-2000 units/s along the
//! wall's normal or 0.5 rad from it, near the bounds too: no two bodies
//! overlap by more than the slop.
//!
//! Before the hold of followers (`src/world/step/punched_followers.rs`),
//! 136 of the 1440 cases failed (the projectile up to 0.265 inside the box,
//! or pushed out through it on the wall's side) and 398 of the 1152 wider
//! ones; 8 + 24 more (a struck body 100× lighter, 2 from the wall, e = 1,
//! at 50 units/s: it bounces off the wall and meets the projectile with no
//! row between them) were left open until the stop at meetings
//! (`punched_motion.rs`, step 3).
//!
//! Figures print with `--nocapture`.

mod common;
use clockwork2d::prelude::*;
use common::depth::shape_depth;

const SLOP: f64 = 1e-4;
/// Read-back rounding of a position: an I32F32 step is 2.3e-10 and a
/// position is rounded a few times per step; 1e-9 is four steps.
const ROUND: f64 = 1e-9;
/// Rounding of the kinetic energy sum relative to its start: every impulse
/// rounds a velocity by one I32F32 step (2.3e-10) per component, changing
/// ½mv² by at most m·v·2.3e-10, i.e. 4.6e-10/v of it; 60 ticks of at most
/// (8 + 1 + 3) solves of 2 rows on 2 bodies at v ≥ 50 give
/// 60·12·2·2·4.6e-10/50 ≈ 2.7e-11. 1e-8 leaves a wide margin.
const ROUND_ENERGY: f64 = 1e-8;

struct Case {
    speed: f64,
    bullet: bool,
    /// Box mass over the projectile's.
    ratio: f64,
    wall: f64,
    gap: f64,
    e: f64,
    origin: (f64, f64),
    /// Flying along −y instead of +x.
    down: bool,
}

#[derive(Clone, Copy)]
struct Outcome {
    ball_in_box: f64,
    box_in_wall: f64,
    ball_in_wall: f64,
    out_of_order: bool,
    rise: f64,
    e0: f64,
}

const R: f64 = 0.05;
const HALF: f64 = 0.25;

fn run(c: &Case) -> Outcome {
    let mut world = World::new(WorldSettings {
        gravity: vec2(0.0, 0.0),
        sleep_enabled: false,
        ..WorldSettings::default()
    });
    // Local coordinates: s along the flight, q across it.
    let to_world = |s: f64, q: f64| {
        if c.down {
            vec2(c.origin.0 + q, c.origin.1 - s)
        } else {
            vec2(c.origin.0 + s, c.origin.1 + q)
        }
    };
    let to_local = |p: (f64, f64)| {
        let (dx, dy) = (p.0 - c.origin.0, p.1 - c.origin.1);
        if c.down { (-dy, dx) } else { (dx, dy) }
    };
    let wall_half = if c.down {
        vec2(1.0, c.wall / 2.0)
    } else {
        vec2(c.wall / 2.0, 1.0)
    };
    // The wall's near face is at s = 0.
    world
        .add_body(BodyDef::fixed(Shape::aabb(wall_half)).position(to_world(c.wall / 2.0, 0.0)))
        .expect("wall");
    let box_at = -c.gap - HALF;
    // The projectile's mass (the box's is set from it, within the
    // engine's range 2^-10..2^20).
    let ball_mass = 0.1;
    let boxed_mass = c.ratio * ball_mass;
    let boxed = world
        .add_body(
            BodyDef::dynamic(Shape::aabb(vec2(HALF, HALF)))
                .friction(fx(0.0))
                .mass(fx(boxed_mass))
                .position(to_world(box_at, 0.0)),
        )
        .expect("box");
    // The projectile starts 1.3 ticks of flight before the box.
    let start = box_at - HALF - R - 1.3 * c.speed / 60.0 - 0.01;
    let v = if c.down {
        vec2(0.0, -c.speed)
    } else {
        vec2(c.speed, 0.0)
    };
    let ball = world
        .add_body(
            BodyDef::dynamic(Shape::circle(fx(R)))
                .mass(fx(ball_mass))
                .friction(fx(0.0))
                .restitution(fx(c.e))
                .bullet(c.bullet)
                .position(to_world(start, 0.0))
                .velocity(v),
        )
        .expect("ball");
    let kinetic = |world: &World| {
        [ball, boxed].iter().fold(0.0, |e, &id| {
            let b = world.body(id).unwrap();
            let (vx, vy) = b.velocity().to_f64();
            e + 0.5 * b.mass().to_f64() * (vx * vx + vy * vy)
        })
    };
    let e0 = kinetic(&world);
    let mut out = Outcome {
        ball_in_box: f64::MIN,
        box_in_wall: f64::MIN,
        ball_in_wall: f64::MIN,
        out_of_order: false,
        rise: f64::MIN,
        e0,
    };
    for _ in 0..60 {
        world.step();
        let pb = to_local(world.body(ball).unwrap().position().to_f64());
        let px = to_local(world.body(boxed).unwrap().position().to_f64());
        // Circle in box: the circle's depth past the box's near face when
        // it is level with the box (it flies along its axis, q = 0).
        let (dx, dq) = ((pb.0 - px.0).abs() - HALF, (pb.1 - px.1).abs() - HALF);
        let outside = dx.max(0.0).hypot(dq.max(0.0));
        let inside = dx.max(dq).min(0.0);
        out.ball_in_box = out.ball_in_box.max(R - (outside + inside));
        out.box_in_wall = out.box_in_wall.max(px.0 + HALF);
        out.ball_in_wall = out.ball_in_wall.max(pb.0 + R);
        out.out_of_order |= pb.0 > px.0;
        out.rise = out.rise.max(kinetic(&world) - e0);
    }
    out
}

fn passes(o: &Outcome) -> bool {
    o.ball_in_box <= SLOP + ROUND
        && o.box_in_wall <= SLOP + ROUND
        && o.ball_in_wall <= SLOP + ROUND
        && !o.out_of_order
        && o.rise <= ROUND_ENERGY * o.e0
}

fn describe(c: &Case, o: &Outcome) -> String {
    format!(
        "v {} bullet {} ratio {} wall {} gap {} e {} at {:?} down {}: ball in box {:.3e}, box in wall {:.3e}, ball in wall {:.3e}, out of order {}, energy rise {:.3e} of {:.3e}",
        c.speed,
        c.bullet,
        c.ratio,
        c.wall,
        c.gap,
        c.e,
        c.origin,
        c.down,
        o.ball_in_box,
        o.box_in_wall,
        o.ball_in_wall,
        o.out_of_order,
        o.rise,
        o.e0
    )
}

#[test]
fn a_projectile_pushing_a_box_into_a_wall_never_passes_into_it() {
    let mut cases = Vec::new();
    for speed in [50.0, 300.0, 2000.0] {
        for bullet in [true, false] {
            for ratio in [0.01, 1.0, 1000.0] {
                for wall in [0.02, 2.0] {
                    for gap in [0.0, 1e-4, 0.05, 0.3, 2.0] {
                        for e in [0.0, 1.0] {
                            for origin in [(0.0, 0.0), (30_000.0, -30_000.0)] {
                                for down in [false, true] {
                                    cases.push(Case {
                                        speed,
                                        bullet,
                                        ratio,
                                        wall,
                                        gap,
                                        e,
                                        origin,
                                        down,
                                    });
                                }
                            }
                        }
                    }
                }
            }
        }
    }
    let mut failures = Vec::new();
    let (mut a, mut b, mut w, mut rise) = (f64::MIN, f64::MIN, f64::MIN, f64::MIN);
    for c in &cases {
        let o = run(c);
        a = a.max(o.ball_in_box);
        b = b.max(o.box_in_wall);
        w = w.max(o.ball_in_wall);
        rise = rise.max(o.rise / o.e0);
        if !passes(&o) {
            failures.push(describe(c, &o));
        }
    }
    println!(
        "{} cases: worst ball in box {a:.3e}, box in wall {b:.3e}, ball in wall {w:.3e}, energy rise {rise:.3e} of E0; {} fail",
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

/// One variant of the wider family: a projectile driving a row of `count`
/// struck bodies into a fixed wall.
#[derive(Clone, Copy, Debug)]
struct Row {
    speed: f64,
    projectile_box: bool,
    /// Projectile half size (radius or half side).
    projectile_size: f64,
    count: usize,
    struck_box: bool,
    /// Struck bodies' half size.
    size: f64,
    /// Each struck body's mass over the projectile's.
    ratio: f64,
    /// Free space between struck bodies.
    spacing: f64,
    /// Free space between the last struck body and the wall.
    gap: f64,
    /// Whether the wall is there (without it the row flies free).
    wall: bool,
    e: f64,
    /// Angle of the flight from the wall's normal, radians (the row is
    /// laid along the flight; the wall is axis-aligned).
    angle: f64,
    origin: (f64, f64),
}

fn shape_of(boxed: bool, size: f64) -> Shape {
    if boxed {
        Shape::aabb(vec2(size, size))
    } else {
        Shape::circle(fx(size))
    }
}

/// Worst overlap of any two bodies (the wall included, if there) over 60
/// ticks.
fn run_row(r: &Row) -> f64 {
    let mut world = World::new(WorldSettings {
        gravity: vec2(0.0, 0.0),
        sleep_enabled: false,
        ..WorldSettings::default()
    });
    let (o, u) = (r.origin, (r.angle.cos(), r.angle.sin()));
    let wall_half = vec2(1.0, 20.0);
    let wall_at = (o.0 + 1.0, o.1);
    let mut bodies = Vec::new();
    if r.wall {
        bodies.push((
            world
                .add_body(
                    BodyDef::fixed(Shape::aabb(wall_half)).position(vec2(wall_at.0, wall_at.1)),
                )
                .expect("wall"),
            Shape::aabb(wall_half),
        ));
    }
    let shape = shape_of(r.struck_box, r.size);
    // The struck bodies lie on the line of flight through the last one,
    // whose centre is `gap + size` before the wall's face; their centres
    // are `2·reach + spacing` apart along it (`reach`: a body's extent
    // along the flight, `size·(|u_x| + |u_y|)` for a box at an angle).
    let reach = if r.struck_box {
        r.size * (u.0.abs() + u.1.abs())
    } else {
        r.size
    };
    let last = (o.0 - r.gap - r.size, o.1);
    let projectile_mass = 0.1;
    for k in 0..r.count {
        let back = (r.count - 1 - k) as f64 * (2.0 * reach + r.spacing);
        let id = world
            .add_body(
                BodyDef::dynamic(shape)
                    .friction(fx(0.0))
                    .mass(fx(r.ratio * projectile_mass))
                    .position(vec2(last.0 - back * u.0, last.1 - back * u.1)),
            )
            .expect("struck");
        bodies.push((id, shape));
    }
    let first_back = (r.count - 1) as f64 * (2.0 * reach + r.spacing);
    let first = (last.0 - first_back * u.0, last.1 - first_back * u.1);
    let projectile_reach = if r.projectile_box {
        r.projectile_size * (u.0.abs() + u.1.abs())
    } else {
        r.projectile_size
    };
    let start = reach + projectile_reach + 1.3 * r.speed / 60.0 + 0.01;
    let pshape = shape_of(r.projectile_box, r.projectile_size);
    let projectile = world
        .add_body(
            BodyDef::dynamic(pshape)
                .mass(fx(projectile_mass))
                .friction(fx(0.0))
                .restitution(fx(r.e))
                .position(vec2(first.0 - start * u.0, first.1 - start * u.1))
                .velocity(vec2(r.speed * u.0, r.speed * u.1)),
        )
        .expect("projectile");
    bodies.push((projectile, pshape));
    let mut worst = f64::MIN;
    for _ in 0..60 {
        world.step();
        let at: Vec<(f64, f64)> = bodies
            .iter()
            .map(|(id, _)| world.body(*id).unwrap().position().to_f64())
            .collect();
        for i in 0..bodies.len() {
            for j in i + 1..bodies.len() {
                worst = worst.max(shape_depth(bodies[i].1, at[i], bodies[j].1, at[j]));
            }
        }
    }
    worst
}

/// The rows of the wider family with `count` struck bodies.
fn rows(count: usize) -> Vec<Row> {
    let mut rows = Vec::new();
    for speed in [50.0, 300.0, 2000.0] {
        for (projectile_box, projectile_size) in [(false, 0.05), (true, 0.05), (false, 0.3)] {
            for (struck_box, size) in [(true, 0.05), (true, 0.25), (false, 0.25), (true, 1.0)] {
                for ratio in [0.01, 1.0] {
                    for gap in [0.3, 2.0] {
                        for e in [0.0, 1.0] {
                            for angle in [0.0, 0.5] {
                                for origin in [(0.0, 0.0), (32_000.0, -32_000.0)] {
                                    rows.push(Row {
                                        speed,
                                        projectile_box,
                                        projectile_size,
                                        count,
                                        struck_box,
                                        size,
                                        ratio,
                                        spacing: 0.05,
                                        gap,
                                        wall: true,
                                        e,
                                        angle,
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
    rows
}

/// The rows that overlap by more than the slop (rigid bodies cannot
/// interpenetrate: a resting contact may overlap by the slop, plus the
/// read-back rounding), with the worst overlap of all.
fn overlapping(rows: &[Row]) -> (Vec<String>, f64) {
    let mut failures = Vec::new();
    let mut worst = f64::MIN;
    for r in rows {
        let d = run_row(r);
        worst = worst.max(d);
        if d > SLOP + ROUND {
            failures.push(format!("{r:?}: overlap {d:.3e}"));
        }
    }
    println!(
        "{} rows of {}: worst overlap {worst:.3e}; {} fail",
        rows.len(),
        rows[0].count,
        failures.len()
    );
    for f in failures.iter().take(30) {
        println!("  {f}");
    }
    (failures, worst)
}

/// Runs `rows` and asserts that none overlaps beyond the slop.
fn assert_none_overlap(rows: &[Row]) {
    let (failures, _) = overlapping(rows);
    assert!(
        failures.is_empty(),
        "{} of {} rows overlap",
        failures.len(),
        rows.len()
    );
}

#[test]
fn one_body_driven_into_a_wall_never_overlaps_anything() {
    assert_none_overlap(&rows(1));
}

/// Two bodies in a row driven along the wall's normal (the family's 576
/// rows of 2 at angle 0): no two bodies overlap by more than the slop.
///
/// Before the rebound sweep moved rebounding partners along their own
/// rebounds (`World::sweep_rebounds`), 96 of them failed, every one with
/// e = 1: the projectile launches both struck bodies together, and the
/// sweep of the one behind, against the end of the one ahead (not yet
/// moved), stopped it where that end lay across its path: 0.018 into the
/// other at 50 units/s (two boxes of the projectile's mass, half size
/// 0.05), up to 0.5 with struck bodies 100× lighter.
#[test]
fn rows_of_two_driven_along_the_wall_normal_never_overlap() {
    let rows: Vec<Row> = rows(2).into_iter().filter(|r| r.angle == 0.0).collect();
    assert_eq!(rows.len(), 576);
    assert_none_overlap(&rows);
}

/// Four bodies in a row driven along the wall's normal (the family's 576
/// rows of 4 at angle 0), and rows of 3 and of 8 flush with each other
/// (spacing 0) along it: no two bodies overlap by more than the slop.
///
/// Before the hold took the end approaching the other as a row's follower
/// (`world/step/punched_followers.rs`), 156 of them failed, with e = 0 as
/// with e = 1: bodies cut at the wall one by one (each reaching it through
/// those ahead), the second stopped short by its meeting with the last,
/// and the third, held behind the last, was taken for the second's
/// follower; moving away from it, it left the row closed by up to 1.79
/// (boxes of half size 1 at 2000 units/s; 0.31 with boxes of 0.25, 100×
/// lighter than the ball, at 300 units/s); and 108 of the rows of 3 and 132
/// of the rows of 8.
#[test]
fn rows_of_four_driven_along_the_wall_normal_never_overlap() {
    let along = |r: &Row| r.angle == 0.0;
    let mut rows: Vec<Row> = rows(4).into_iter().filter(along).collect();
    assert_eq!(rows.len(), 576);
    for count in [3, 8] {
        rows.extend(
            self::rows(count)
                .into_iter()
                .filter(along)
                .map(|r| Row { spacing: 0.0, ..r }),
        );
    }
    assert_none_overlap(&rows);
}

/// The family's rows of `count` bodies of the projectile's mass, one per
/// variant of projectile, shape, speed, spacing, e and origin (at the gap
/// 0.3 only: the gap to a wall that is not there does not matter), for the
/// free rows below.
fn free_row_variants(count: usize) -> Vec<Row> {
    self::rows(count)
        .into_iter()
        .filter(|r| r.ratio == 1.0 && r.angle != 0.0 && r.gap == 0.3)
        .collect()
}

/// `r` struck at `angle` with no wall, flying inward near the origin or
/// near the world's bounds (-32 000, -32 000).
fn free_row(r: Row, angle: f64) -> Row {
    Row {
        angle,
        wall: false,
        origin: if r.origin == (0.0, 0.0) {
            r.origin
        } else {
            (-32_000.0, -32_000.0)
        },
        ..r
    }
}

/// A free row (no wall) of 2, 3 or 4 bodies of the projectile's mass,
/// 0.05 apart along the line of flight, struck at 0.2, 0.5 or 1.2 rad from
/// the x axis (the family's projectiles, struck shapes, speeds, e 0 and 1;
/// near the origin and near the world's bounds, flying inward): no two
/// bodies overlap by more than the slop.
///
/// The projectile's rows with every struck body (within the margin of its
/// flight) and the struck bodies' rows with each other close cycles; the
/// bodies are of even masses and rest on nothing, so the group was left to
/// the 8 sweeps of sequential impulses, which did not converge: the rows
/// along one line are nearly dependent (the projectile's rows with the
/// first and the second body say almost what the first's row with the
/// second says). A ball at 2000 units/s into two circles of its mass left
/// the first circle closing on the second at 23.4 units/s against the
/// 3 units/s its 0.05 gap allows, 0.18 inside it a tick later (with the
/// wall: `rows_of_several_bodies_driven_into_a_wall_still_open`). 222 of
/// these 1296 rows failed; the group struck by one body now takes the
/// exact sparse solve (`RowGroups::classify`).
#[test]
fn free_rows_of_equal_bodies_struck_at_a_slant_never_overlap() {
    let mut rows = Vec::new();
    for count in [2, 3, 4] {
        let variants = free_row_variants(count);
        for angle in [0.2, 0.5, 1.2] {
            rows.extend(variants.iter().map(|&r| free_row(r, angle)));
        }
    }
    assert_eq!(rows.len(), 1296);
    assert_none_overlap(&rows);
}

/// Still open (issue 13): rows of 2 and of 4 bodies at 0.5 rad from the
/// wall's normal. Of these 1152 rows, 14 fail (40 before the meetings
/// were timed again after the hold, 148 before a free row
/// struck by one body took the exact sparse solve, 164 before the hold's
/// follower was the approaching end, 334 before the rebound sweep's
/// partners moved; of all 2304 rows: 700 then, 1788 before the hold of
/// followers, 1000 before the stop at meetings): 10 rows of 4 at 300
/// units/s, e = 0, with struck bodies a hundred times lighter than the
/// ball (not traced); 4 rows of 4 of the ball's
/// mass, which reach the wall touching, so the group rests on it and is
/// struck at a slant on two rows at once (sequential impulses). Not
/// in this family, also open: rows along the normal spaced wider or
/// longer, e.g. rows of 8 spaced 0.05 (30 of 576 fail) or 0.5 (78), rows
/// of 6 spaced 0.5 (18), rows of 3 spaced 0.5 (6).
#[test]
#[ignore = "open: rows of several bodies (issue 13)"]
fn rows_of_several_bodies_driven_into_a_wall_still_open() {
    let mut rows: Vec<Row> = rows(2).into_iter().filter(|r| r.angle != 0.0).collect();
    rows.extend(self::rows(4).into_iter().filter(|r| r.angle != 0.0));
    let (failures, _) = overlapping(&rows);
    assert!(
        failures.is_empty(),
        "{} of {} rows overlap",
        failures.len(),
        rows.len()
    );
}

/// Rows of bodies flush with each other (spacing 0) along the line of
/// flight, of even masses (each 1× or 2× the projectile's: the exact solve
/// of a struck group is for masses within 4× of each other), struck at a
/// slant: free rows of 2, 3 or 4 at 0.2, 0.5 and 1.2 rad (2× only at 0.2
/// and 1.2), and rows of 2 of the projectile's mass driven into the wall at
/// 0.2 and 0.5 rad (gaps 0.3 and 2); the family's projectiles, struck
/// shapes, speeds and e 0 and 1, near the origin and near the world's
/// bounds (free rows flying inward). No two bodies overlap by more than
/// the slop: rigid bodies do not interpenetrate, and a resting contact may
/// overlap by the slop plus the read-back rounding (`SLOP + ROUND`).
///
/// The bodies of such a row touch each other at a slant, at rest relative
/// to each other, when the projectile strikes the first. Those slow
/// slanted rows made the group "not struck by one body", so it kept the
/// 8 sweeps of sequential impulses, which do not converge on rows along
/// one line: a ball of a circle's mass at 2000 units/s into two circles at
/// 0.2 rad (e = 0) ended the solve at 1059 units/s behind circles at 460
/// (the back one) and 441 units/s, and a tick later the circles were 0.23
/// inside each other (`RowGroups::classify`, `resting_or_struck`). 426 of
/// these 2736 rows failed (worst overlap 0.31); slow rows touching at a
/// slant no longer count against a group resting on nothing.
#[test]
fn flush_rows_of_even_masses_struck_at_a_slant_never_overlap() {
    let mut rows = Vec::new();
    let flush = |r: Row, angle: f64, ratio: f64| Row {
        ratio,
        spacing: 0.0,
        ..free_row(r, angle)
    };
    for count in [2, 3, 4] {
        let variants = free_row_variants(count);
        for angle in [0.2, 0.5, 1.2] {
            rows.extend(variants.iter().map(|&r| flush(r, angle, 1.0)));
        }
        for angle in [0.2, 1.2] {
            rows.extend(variants.iter().map(|&r| flush(r, angle, 2.0)));
        }
    }
    for angle in [0.2, 0.5] {
        rows.extend(
            self::rows(2)
                .into_iter()
                .filter(|r| r.ratio == 1.0 && r.angle != 0.0)
                .map(|r| Row {
                    angle,
                    spacing: 0.0,
                    ..r
                }),
        );
    }
    assert_eq!(rows.len(), 2736);
    assert_none_overlap(&rows);
}

/// Rows of 2 to 8 boxes of half size 1, each 100× lighter than the
/// projectile, 0 or 0.05 apart, driven into the wall at 0.2 rad (rows of 2
/// to 6) and 1.2 rad (2 to 8) from its normal, and the family's rows of 2
/// at 0.5 rad; the family's projectiles, speeds, gaps, e 0 and 1, near the
/// origin and near the world's bounds: no two bodies overlap by more than
/// the slop (`SLOP + ROUND`, as in the family).
///
/// The projectile launches the first box far faster than itself (up to
/// twice its speed, e = 1), so the narrow phase gives the pair no row (the
/// box leaves faster than the projectile follows). When the boxes ahead
/// are cut at the wall, the first box is held behind them
/// (`world/step/punched_followers.rs`) short of its path, and the
/// projectile, whose meeting with it was timed against that longer path,
/// flew into it: a ball at 50 units/s, 0.11 behind a box it had launched
/// at 86.9 units/s towards a second box 0.3 from the wall, ended 0.30
/// inside it. The meetings are now timed again after the hold
/// (`world/step/punched_motion.rs`). 192 of these 1368 rows failed (worst
/// overlap 0.95).
#[test]
fn rows_of_far_lighter_boxes_driven_into_a_wall_at_a_slant_never_overlap() {
    let mut rows = Vec::new();
    for count in [2, 3, 4, 6, 8] {
        let variants: Vec<Row> = self::rows(count)
            .into_iter()
            .filter(|r| r.struck_box && r.size == 1.0 && r.ratio == 0.01 && r.angle != 0.0)
            .collect();
        if count == 2 {
            rows.extend(variants.iter().copied());
        }
        for angle in [0.2, 1.2] {
            if angle == 0.2 && count == 8 {
                continue;
            }
            for spacing in [0.0, 0.05] {
                rows.extend(variants.iter().map(|&r| Row {
                    angle,
                    spacing,
                    ..r
                }));
            }
        }
    }
    assert_eq!(rows.len(), 1368);
    assert_none_overlap(&rows);
}
