//! Balls on and against stacks (issue 13 variants), at the default settings
//! (dt = 1/60, substeps 1, 8 velocity + 3 position iterations, slop 1e-4).
//!
//! * A ball resting on a column of unit boxes: n + 1 contacts in series,
//!   each allowed to rest at most one linear slop deep, so no body sits
//!   more than (n + 1)·slop below its ideal height; nothing lifts a body
//!   (no energy source), so none ever rises above it; every contact normal
//!   is ±y, so x never changes (exactly, in fixed point).
//! * A ball dropped on a column: energy cannot grow, so the first rebound
//!   apex is at most e²·h above the resting point (e the pair's
//!   restitution, h the drop height); afterwards the pile settles to the
//!   same (n + 1)·slop bound and sleeps.
//! * A striker hitting a row of bodies, gravity off, frictionless: the
//!   x momentum is conserved up to rounding; the kinetic energy never
//!   rises; a perfectly inelastic row (e = 0) ends moving together at
//!   M·u / (M + n·m); elastic collisions that happen one per step (gaps
//!   the striker needs more than a step to close) end as the textbook
//!   sequence: the striker stops and the last body leaves at u.
//!
//! Figures print with `--nocapture`.

use clockwork2d::prelude::*;

mod common;
use common::add_ground;

const HZ: u64 = 60;
const SLOP: f64 = 1e-4;
/// Fixed-point rounding allowance for a position compared with an exact
/// value: I32F32 steps are 2.3e-10 and a settled body's position has
/// been rounded a few times per step; 1e-9 is four steps.
const ROUND: f64 = 1e-9;

fn unit_column(world: &mut World, n: usize) -> Vec<(BodyId, f64)> {
    (0..n)
        .map(|i| {
            let y = 0.5 + i as f64;
            let id = world
                .add_body(BodyDef::dynamic(Shape::aabb(vec2(0.5, 0.5))).position(vec2(0.0, y)))
                .expect("box");
            (id, y)
        })
        .collect()
}

/// What a settle run measured: the worst sink below, the worst rise above
/// the ideal heights (over every tick), whether x ever changed, and the tick
/// from which everything stayed asleep.
struct Settle {
    sink: f64,
    rise: f64,
    moved_x: bool,
    asleep_from: Option<u64>,
}

fn settle(world: &mut World, bodies: &[(BodyId, f64)], ticks: u64) -> Settle {
    let x0: Vec<Fx> = bodies
        .iter()
        .map(|&(id, _)| world.body(id).unwrap().position().x)
        .collect();
    let mut s = Settle {
        sink: 0.0,
        rise: 0.0,
        moved_x: false,
        asleep_from: None,
    };
    for t in 1..=ticks {
        world.step();
        let mut asleep = true;
        for (k, &(id, ideal)) in bodies.iter().enumerate() {
            let body = world.body(id).unwrap();
            let dy = body.position().y.to_f64() - ideal;
            s.sink = s.sink.max(-dy);
            s.rise = s.rise.max(dy);
            s.moved_x |= body.position().x != x0[k];
            asleep &= !body.is_awake();
        }
        s.asleep_from = match (asleep, s.asleep_from) {
            (true, None) => Some(t),
            (true, from) => from,
            (false, _) => None,
        };
    }
    s
}

#[test]
fn a_ball_resting_on_a_box_stack_stays_within_n_slop_without_drift_and_sleeps() {
    // (boxes, ball radius, ball mass)
    for (n, r, m) in [
        (10, 0.5, 1.0),
        (30, 0.5, 1.0),
        (10, 0.25, 1.0),
        (10, 0.1, 0.01),
        (10, 2.0, 1.0),
        (10, 0.5, 100.0),
        (30, 0.5, 1000.0),
    ] {
        let mut world = World::new(WorldSettings::default());
        add_ground(&mut world);
        let mut bodies = unit_column(&mut world, n);
        let top = n as f64 + r;
        let ball = world
            .add_body(
                BodyDef::dynamic(Shape::circle(fx(r)))
                    .mass(fx(m))
                    .position(vec2(0.0, top)),
            )
            .expect("ball");
        bodies.push((ball, top));
        let s = settle(&mut world, &bodies, 10 * HZ);
        let bound = (n + 1) as f64 * SLOP;
        println!(
            "ball r {r} m {m} on {n} boxes: worst sink {:.6} (bound {bound:.4}), worst rise {:.1e}, x moved {}, asleep from tick {:?}",
            s.sink, s.rise, s.moved_x, s.asleep_from
        );
        assert!(s.sink <= bound + ROUND);
        assert!(s.rise <= ROUND);
        assert!(!s.moved_x);
        assert!(s.asleep_from.is_some_and(|t| t < 4 * HZ));
    }
}

#[test]
fn a_ball_dropped_on_a_stack_rebounds_at_most_e2_h_then_settles_within_n_slop() {
    // (boxes, ball radius, ball mass, drop height above rest, restitution)
    for (n, r, m, h, e) in [
        (10, 0.5, 1.0, 2.0, 0.0),
        (10, 0.5, 1.0, 2.0, 0.5),
        (30, 0.5, 1.0, 2.0, 0.5),
        (10, 0.5, 10.0, 2.0, 0.5),
        (10, 0.5, 100.0, 2.0, 0.0),
        (10, 0.5, 0.01, 5.0, 0.8),
        (10, 0.2, 1.0, 0.7, 0.5),
        (5, 0.5, 1.0, 10.0, 0.5),
        (1, 0.5, 1.0, 2.0, 0.5),
    ] {
        let mut world = World::new(WorldSettings::default());
        add_ground(&mut world);
        let mut bodies = unit_column(&mut world, n);
        let rest = n as f64 + r;
        let ball = world
            .add_body(
                BodyDef::dynamic(Shape::circle(fx(r)))
                    .mass(fx(m))
                    .restitution(fx(e))
                    .position(vec2(0.0, rest + h)),
            )
            .expect("ball");
        // The first rebound: from the first tick the ball moves up until
        // it stops rising.
        let mut apex = f64::MIN;
        let mut rising = false;
        let mut ticks = 0;
        while ticks < 10 * HZ {
            world.step();
            ticks += 1;
            let b = world.body(ball).unwrap();
            let vy = b.velocity().y.to_f64();
            if vy > 0.0 {
                rising = true;
                apex = apex.max(b.position().y.to_f64() - rest);
            } else if rising {
                break;
            }
        }
        bodies.push((ball, rest));
        // Bound: the ball meets the top box at most (n + 1)·slop below
        // the ideal contact point, so it falls at most h + (n + 1)·slop
        // and, launched at e times its impact speed (or slower), rises
        // at most e² times that above the contact, which itself lies at
        // most (n + 1)·slop below the ideal: e²·h + (n + 1)·slop.
        let bound = e * e * h + (n + 1) as f64 * SLOP;
        let s = settle(&mut world, &bodies, 10 * HZ);
        println!(
            "ball r {r} m {m} e {e} dropped {h} on {n} boxes: first rebound apex {:.5} (e²h {:.5}); then worst sink {:.6}, rise {:.1e}, x moved {}, asleep from {:?}",
            apex.max(0.0),
            e * e * h,
            s.sink,
            s.rise,
            s.moved_x,
            s.asleep_from
        );
        assert!(apex <= bound + ROUND);
        // After the bounces (restitution stops below the 1 unit/s
        // threshold) the pile rests like the resting case above.
        assert!(s.sink <= (n + 1) as f64 * SLOP + ROUND);
        assert!(!s.moved_x);
        assert!(s.asleep_from.is_some());
    }
}

/// A striker of mass `striker_mass` at speed `u` into `n` bodies of mass 1
/// (half size 0.5, boxes or circles) lying along x with `gap` between them,
/// gravity off, friction 0, restitution `e` on every body. Returns the
/// final x velocities (striker first), the worst |Δp_x| and the highest
/// kinetic energy rise over two seconds.
fn strike(
    n: usize,
    circles: bool,
    e: f64,
    gap: f64,
    u: f64,
    striker_mass: f64,
) -> (Vec<f64>, f64, f64) {
    let mut world = World::new(WorldSettings {
        gravity: Vec2::ZERO,
        sleep_enabled: false,
        ..WorldSettings::default()
    });
    let shape = || {
        if circles {
            Shape::circle(fx(0.5))
        } else {
            Shape::aabb(vec2(0.5, 0.5))
        }
    };
    let mut ids = vec![
        world
            .add_body(
                BodyDef::dynamic(shape())
                    .mass(fx(striker_mass))
                    .friction(fx(0.0))
                    .restitution(fx(e))
                    .position(vec2(-1.5, 0.0))
                    .velocity(vec2(u, 0.0)),
            )
            .expect("striker"),
    ];
    for i in 0..n {
        ids.push(
            world
                .add_body(
                    BodyDef::dynamic(shape())
                        .mass(fx(1.0))
                        .friction(fx(0.0))
                        .restitution(fx(e))
                        .position(vec2(i as f64 * (1.0 + gap), 0.0)),
                )
                .expect("row"),
        );
    }
    let sums = |world: &World| {
        ids.iter().fold((0.0, 0.0), |(p, k), &id| {
            let b = world.body(id).unwrap();
            let m = b.mass().to_f64();
            let (vx, vy) = b.velocity().to_f64();
            (p + m * vx, k + 0.5 * m * (vx * vx + vy * vy))
        })
    };
    let (p0, k0) = sums(&world);
    let (mut dp, mut dk) = (0.0f64, f64::MIN);
    for _ in 0..2 * HZ {
        world.step();
        let (p, k) = sums(&world);
        dp = dp.max((p - p0).abs());
        dk = dk.max(k - k0);
    }
    let v = ids
        .iter()
        .map(|&id| world.body(id).unwrap().velocity().x.to_f64())
        .collect();
    (v, dp, dk)
}

/// Rounding allowance on momentum and energy sums: each impulse moves a
/// velocity by a rounded amount (one I32F32 step, 2.3e-10, per component
/// and application); over 120 ticks of at most (8 + 1) sweeps of ≤ 21 rows,
/// each touching two bodies of mass ≤ 10, the sum drifts at most
/// 120 · 9 · 21 · 2 · 10 · 2.3e-10 ≈ 1.1e-4 in the very worst case. The
/// measured drift is ≤ 7e-9; the allowance is the worst case.
const SUM_ROUND: f64 = 1.1e-4;

#[test]
fn a_striker_into_a_row_conserves_x_momentum_and_never_gains_kinetic_energy() {
    for n in [1, 2, 5, 20] {
        for circles in [false, true] {
            for e in [0.0, 0.5, 1.0] {
                for gap in [0.0, 0.01, 0.1] {
                    for m in [1.0, 10.0] {
                        let (v, dp, dk) = strike(n, circles, e, gap, 5.0, m);
                        assert!(
                            dp <= SUM_ROUND && dk <= SUM_ROUND,
                            "n {n} circles {circles} e {e} gap {gap} m {m}: |Δp| {dp:e}, ΔKE {dk:e}, v {v:?}"
                        );
                    }
                }
            }
        }
    }
}

#[test]
fn a_perfectly_inelastic_row_moves_on_together_at_the_momentum_speed() {
    for (n, circles, gap, u, m) in [
        (5, false, 0.0, 2.0, 1.0),
        (5, true, 0.0, 2.0, 1.0),
        (5, false, 0.01, 2.0, 1.0),
        (5, true, 0.01, 2.0, 1.0),
        (20, false, 0.0, 5.0, 1.0),
        (20, true, 0.0, 5.0, 1.0),
        (5, false, 0.0, 2.0, 10.0),
    ] {
        let (v, _, _) = strike(n, circles, 0.0, gap, u, m);
        let common = m * u / (m + n as f64);
        let worst = v.iter().map(|x| (x - common).abs()).fold(0.0, f64::max);
        println!(
            "inelastic n {n} circles {circles} gap {gap} striker {m}: expected {common:.6}, worst deviation {worst:.2e}"
        );
        // Each velocity is a sum of rounded impulse shares: same rounding
        // allowance as the sums above.
        assert!(worst <= SUM_ROUND);
    }
}

#[test]
fn elastic_collisions_one_per_step_pass_the_momentum_down_the_row() {
    // Gaps the striker needs more than one step to close (gap > u·h):
    // the collisions are separate and each is the two-body elastic one,
    // so equal masses exchange velocities down the row.
    for (n, circles, gap) in [
        (5, true, 0.05),
        (5, true, 0.1),
        (5, false, 0.1),
        (5, true, 0.5),
        (3, false, 0.3),
    ] {
        let u = 2.0;
        assert!(gap > u / HZ as f64);
        let (v, _, _) = strike(n, circles, 1.0, gap, u, 1.0);
        let mut expected = vec![0.0; n + 1];
        expected[n] = u;
        let worst = v
            .iter()
            .zip(&expected)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        println!(
            "elastic row n {n} circles {circles} gap {gap}: v {v:.4?}, worst deviation {worst:.2e}"
        );
        assert!(worst <= SUM_ROUND);
    }
    // One contact at a time with unequal masses: the two-body elastic
    // result v₁ = (M − m)/(M + m)·u, v₂ = 2M/(M + m)·u.
    for (circles, big) in [(false, 3.0), (true, 3.0), (false, 0.25), (true, 10.0)] {
        let u = 2.0;
        let (v, _, _) = strike(1, circles, 1.0, 0.0, u, big);
        let (v1, v2) = ((big - 1.0) / (big + 1.0) * u, 2.0 * big / (big + 1.0) * u);
        println!(
            "elastic pair striker {big} circles {circles}: v {v:.6?}, expected [{v1:.6}, {v2:.6}]"
        );
        assert!((v[0] - v1).abs() <= SUM_ROUND && (v[1] - v2).abs() <= SUM_ROUND);
    }
}

/// Worst overlap of any two of `ids` (unit boxes): both axes must overlap.
fn worst_box_overlap(world: &World, ids: &[BodyId]) -> f64 {
    let mut worst = 0.0f64;
    for (i, &a) in ids.iter().enumerate() {
        let pa = world.body(a).unwrap().position().to_f64();
        for &b in &ids[i + 1..] {
            let pb = world.body(b).unwrap().position().to_f64();
            worst = worst.max((1.0 - (pa.0 - pb.0).abs()).min(1.0 - (pa.1 - pb.1).abs()));
        }
    }
    worst
}

#[test]
fn heavy_bodies_dropped_on_a_stack_do_not_crush_it() {
    // (boxes, dropped shape is a box, mass, height above its rest, e)
    for (n, is_box, m, h, e) in [
        (30, false, 1000.0, 10.0, 0.0),
        (30, false, 1000.0, 10.0, 0.5),
        (10, true, 10_000.0, 5.0, 0.0),
        (10, true, 1000.0, 20.0, 0.0),
    ] {
        let mut world = World::new(WorldSettings::default());
        add_ground(&mut world);
        let mut bodies = unit_column(&mut world, n);
        let shape = if is_box {
            Shape::aabb(vec2(0.5, 0.5))
        } else {
            Shape::circle(fx(0.5))
        };
        let rest = n as f64 + 0.5;
        let dropped = world
            .add_body(
                BodyDef::dynamic(shape)
                    .mass(fx(m))
                    .restitution(fx(e))
                    .position(vec2(0.0, rest + h)),
            )
            .expect("dropped");
        bodies.push((dropped, rest));
        let ids: Vec<BodyId> = bodies.iter().map(|&(id, _)| id).collect();
        // Every contact in the column holds, at every tick, within one
        // slop (the column's boxes and the dropped body are unit sized,
        // so a neighbour overlap is 1 minus the centre distance).
        let mut worst = 0.0f64;
        for _ in 0..2 * HZ {
            world.step();
            worst = worst.max(worst_box_overlap(&world, &ids[..n]));
            let top = world.body(ids[n - 1]).unwrap().position().y.to_f64();
            let on = world.body(dropped).unwrap().position().y.to_f64();
            worst = worst.max(1.0 - (on - top));
        }
        let s = settle(&mut world, &bodies, 8 * HZ);
        println!(
            "{} of mass {m} dropped {h} (e {e}) on {n} unit boxes: worst overlap {worst:.2e}; then worst sink {:.2e}, x moved {}, asleep from {:?}",
            if is_box { "box" } else { "ball" },
            s.sink,
            s.moved_x,
            s.asleep_from
        );
        assert!(worst <= SLOP);
        assert!(s.sink <= (n + 1) as f64 * SLOP + ROUND);
        assert!(!s.moved_x);
        assert!(s.asleep_from.is_some());
    }
}

#[test]
fn a_ball_hitting_a_stack_from_the_side_never_adds_energy_nor_overlaps_boxes() {
    // A ball flying level (gravity scale 0) into box `row` of a 10-box
    // column. Energy: kinetic + gravitational of every body never rises
    // above its start. Measured from the stored velocities, which are the
    // integrator's chord velocities: under gravity they differ from the
    // velocity at the sample by up to g·h/2, so the measured kinetic
    // energy may exceed the true one by m·|v|·g·h/2 + m·(g·h/2)²/2 per
    // body; that is the allowance, evaluated at each tick.
    let g = 10.0;
    let h = 1.0 / HZ as f64;
    for (vx, m, row) in [
        (10.0, 1.0, 0),
        (10.0, 10.0, 0),
        (5.0, 1.0, 5),
        (30.0, 1.0, 9),
        (20.0, 100.0, 0),
    ] {
        let mut world = World::new(WorldSettings::default());
        add_ground(&mut world);
        let mut ids: Vec<BodyId> = unit_column(&mut world, 10)
            .into_iter()
            .map(|(id, _)| id)
            .collect();
        let ball = world
            .add_body(
                BodyDef::dynamic(Shape::circle(fx(0.4)))
                    .mass(fx(m))
                    .gravity_scale(fx(0.0))
                    .position(vec2(-3.0, 0.5 + row as f64))
                    .velocity(vec2(vx, 0.0)),
            )
            .expect("ball");
        ids.push(ball);
        let energy = |world: &World| {
            ids.iter().fold((0.0, 0.0), |(e, allowance), &id| {
                let b = world.body(id).unwrap();
                let mass = b.mass().to_f64();
                let (vx, vy) = b.velocity().to_f64();
                let y = b.position().y.to_f64();
                let gravity = g * b.gravity_scale().to_f64();
                let speed = vx.hypot(vy);
                (
                    e + 0.5 * mass * speed * speed + mass * gravity * y,
                    allowance
                        + mass * speed * gravity * h / 2.0
                        + mass * (gravity * h / 2.0).powi(2) / 2.0,
                )
            })
        };
        let (e0, _) = energy(&world);
        let (mut rise, mut overlap) = (f64::MIN, 0.0f64);
        for _ in 0..5 * HZ {
            world.step();
            let (e, allowance) = energy(&world);
            rise = rise.max(e - e0 - allowance);
            overlap = overlap.max(worst_box_overlap(&world, &ids[..10]));
        }
        println!(
            "ball of mass {m} at {vx} into box {row} of 10: energy above start beyond the allowance {rise:.2e} J, worst box overlap {overlap:.2e}; ball ends at {:.3?}, box {row} at {:.3?}",
            world.body(ball).unwrap().velocity().to_f64(),
            world.body(ids[row]).unwrap().position().to_f64()
        );
        assert!(rise <= SUM_ROUND);
        assert!(overlap <= SLOP);
    }
}
