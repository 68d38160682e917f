//! Found by the `world_commands` fuzz target (a long local run): a body
//! spawned deep inside immovable bodies. The input is kept in
//! `tests/data/fuzz/world_commands/` (and among the target's seeds);
//! `cargo run --manifest-path fuzz/Cargo.toml --example show_script --
//! FILE` prints it. What mattered, as plain Rust, is the first test.
//!
//! A dynamic circle of radius 4 was spawned at the centre of two fixed
//! circles of radius 1/16, with 1 velocity and 1 position iteration,
//! gravity 0, `sleep_linear_threshold` 0 and `time_to_sleep` 0. The
//! projection out of immovable bodies (the last word on positions) removed
//! each row's whole depth along its normal, 7.6 units in one substep, far
//! beyond the region the broad phase had searched for the body's partners;
//! the body landed 0.47 deep in a fixed box it had no row with, and, at
//! rest, fell asleep there for good.
//!
//! # What is expected, and the bounds
//!
//! A body pushed out of an overlap has no velocity from it (position
//! corrections leave velocities alone), so its broad-phase region is its
//! box grown by the speculative margin `m` (0.1 at the defaults). The
//! position pass moves it at most `m/2` per axis and substep, and the
//! projection keeps it within that region: **at most `m` per axis per
//! substep** (plus the rounding of the displacements, far below 1e-9).
//! So a deep overlap takes about `depth/m` substeps, and meanwhile:
//!
//! * the body never ends a tick deeper than the slop in a fixed body it
//!   started the tick clear of (its every partner within reach has a row);
//! * it is never asleep while deeper than the slop in a fixed body
//!   (nothing would ever move it again: a sleeping body and a fixed one
//!   have no rows);
//! * once out, it rests (asleep, within the slop of everything).

use clockwork2d::prelude::*;

const SLOP: f64 = 1e-4;
const MARGIN: f64 = 0.1;
/// Rounding allowance on a displacement: a few ulps of `Fx` (2⁻³²) per
/// operation, a handful of operations per substep.
const ROUNDING: f64 = 1e-9;

/// Penetration depth of two bodies (negative: their gap), exact for circle
/// pairs and box pairs, and for a circle against a box.
fn depth(a: &Body, b: &Body) -> f64 {
    let (pa, pb) = (a.position().to_f64(), b.position().to_f64());
    let half = |s: Shape| match s {
        Shape::Circle { radius } => (true, radius.to_f64(), radius.to_f64()),
        Shape::Aabb { half_extents } => {
            let h = half_extents.to_f64();
            (false, h.0, h.1)
        }
    };
    let (ca, ax, ay) = half(a.shape());
    let (cb, bx, by) = half(b.shape());
    let (dx, dy) = (pb.0 - pa.0, pb.1 - pa.1);
    match (ca, cb) {
        (true, true) => ax + bx - dx.hypot(dy),
        (false, false) => (ax + bx - dx.abs()).min(ay + by - dy.abs()),
        _ => {
            // Circle of radius r at c against a box of half extents h at o.
            let (r, c, h, o) = if ca {
                (ax, pa, (bx, by), pb)
            } else {
                (bx, pb, (ax, ay), pa)
            };
            let (qx, qy) = ((c.0 - o.0).abs() - h.0, (c.1 - o.1).abs() - h.1);
            if qx <= 0.0 && qy <= 0.0 {
                r - qx.max(qy)
            } else {
                r - qx.max(0.0).hypot(qy.max(0.0))
            }
        }
    }
}

/// Settings of the finding: no gravity, one iteration each, instant sleep.
fn finding_settings() -> WorldSettings {
    WorldSettings {
        gravity: vec2(0.0, 0.0),
        velocity_iterations: 1,
        position_iterations: 1,
        sleep_linear_threshold: fx(0.0),
        time_to_sleep: fx(0.0),
        ..WorldSettings::default()
    }
}

/// Steps `world` for `ticks`, checking the rules of the module notes for
/// the dynamic body `id` against the fixed bodies `fixed`; returns the
/// tick by which it was out of every fixed body (within the slop) for
/// good, and asleep if `must_sleep`.
fn watch(
    world: &mut World,
    id: BodyId,
    fixed: &[BodyId],
    ticks: u32,
    must_sleep: bool,
    label: &str,
) -> u32 {
    let substeps = f64::from(world.settings().substeps);
    let mut settled_at = None;
    for tick in 1..=ticks {
        let before_p = world.body(id).unwrap().position().to_f64();
        // The region is swept by the body's own motion: grown by
        // `(|v_x| + |v_y|)·h` when that exceeds the margin (broad phase),
        // so per tick up to `(|v_x| + |v_y| + |g|·dt)·dt` more on an axis
        // (gravity adds `|g|·h` per substep); at rest this is 0.
        let (vx, vy) = world.body(id).unwrap().velocity().to_f64();
        let dt = world.settings().dt.to_f64();
        let (gx, gy) = world.settings().gravity.to_f64();
        let motion = (vx.abs() + vy.abs() + gx.hypot(gy) * dt) * dt;
        let before: Vec<f64> = fixed
            .iter()
            .map(|&f| depth(world.body(id).unwrap(), world.body(f).unwrap()))
            .collect();
        world.step();
        let body = world.body(id).unwrap();
        let p = body.position().to_f64();
        let step_bound = MARGIN * substeps + ROUNDING;
        assert!(
            (p.0 - before_p.0).abs() <= step_bound + motion
                && (p.1 - before_p.1).abs() <= step_bound + motion,
            "{label}: tick {tick}: moved ({:.6}, {:.6}) in one tick from rest (bound {step_bound} per axis)",
            p.0 - before_p.0,
            p.1 - before_p.1
        );
        let mut deepest: f64 = f64::NEG_INFINITY;
        for (k, &f) in fixed.iter().enumerate() {
            let d = depth(body, world.body(f).unwrap());
            assert!(
                before[k] > SLOP || d <= SLOP + ROUNDING,
                "{label}: tick {tick}: ended {d:.6} deep in fixed body {k}, clear of it before the tick"
            );
            deepest = deepest.max(d);
        }
        assert!(
            body.is_awake() || deepest <= SLOP + ROUNDING,
            "{label}: tick {tick}: asleep {deepest:.6} deep in a fixed body"
        );
        if deepest <= SLOP + ROUNDING && !(must_sleep && body.is_awake()) {
            settled_at.get_or_insert(tick);
        } else {
            settled_at = None;
        }
    }
    settled_at.unwrap_or_else(|| panic!("{label}: not out and asleep after {ticks} ticks"))
}

#[test]
fn circle_spawned_inside_two_coincident_fixed_circles_is_not_thrown_into_a_box() {
    let mut w = World::new(finding_settings());
    let mut fixed = Vec::new();
    let mut add_fixed = |w: &mut World, shape: Shape, x: f64, y: f64| {
        let id = w
            .add_body(BodyDef::fixed(shape).position(vec2(x, y)))
            .unwrap();
        fixed.push(id);
    };
    add_fixed(&mut w, Shape::aabb(vec2(0.8125, 0.8125)), -1.5, -0.75);
    add_fixed(&mut w, Shape::circle(fx(0.0625)), 4.5, -7.75);
    add_fixed(&mut w, Shape::aabb(vec2(4.0, 1.25)), -95.984375, 0.171875);
    for _ in 0..4 {
        add_fixed(&mut w, Shape::circle(fx(0.0625)), -7.5, -7.75);
    }
    add_fixed(&mut w, Shape::circle(fx(0.0625)), 4.5, -7.75);
    add_fixed(&mut w, Shape::circle(fx(0.8125)), -7.5, -7.75);
    let id = w
        .add_body(BodyDef::dynamic(Shape::circle(fx(4.0))).position(vec2(4.5, -7.75)))
        .unwrap();
    // Depth 4 + 1/16 at m per axis per tick along a diagonal or an axis:
    // at most ceil(4.0625/0.1) = 41 ticks; 240 is the script's length.
    let settled = watch(&mut w, id, &fixed, 240, true, "finding");
    assert!(settled <= 41 + 1, "settled only at tick {settled}");
}

#[test]
fn bodies_spawned_deep_in_immovable_bodies_leave_at_a_bounded_rate_and_stay_awake_until_out() {
    // (dynamic shape, fixed shapes spawned at the same centre, settings)
    let mut cases = 0;
    for dynamic in [
        Shape::circle(fx(0.05)),
        Shape::circle(fx(0.5)),
        Shape::circle(fx(4.0)),
        Shape::aabb(vec2(0.5, 0.5)),
        Shape::aabb(vec2(3.0, 0.25)),
    ] {
        for fixed_shapes in [
            vec![Shape::circle(fx(0.0625))],
            vec![Shape::circle(fx(0.0625)), Shape::circle(fx(0.0625))],
            vec![
                Shape::circle(fx(0.0625)),
                Shape::circle(fx(0.8)),
                Shape::circle(fx(0.0625)),
            ],
            vec![Shape::aabb(vec2(0.3, 0.3))],
            vec![Shape::aabb(vec2(0.3, 0.3)), Shape::circle(fx(0.2))],
        ] {
            for (settings_name, settings, substeps) in [
                ("finding", finding_settings(), 1),
                (
                    "defaults, no gravity",
                    WorldSettings {
                        gravity: vec2(0.0, 0.0),
                        ..WorldSettings::default()
                    },
                    1,
                ),
                (
                    "finding, substeps 2",
                    WorldSettings {
                        substeps: 2,
                        ..finding_settings()
                    },
                    2,
                ),
            ] {
                // Also at the world's bounds (where `Fx` is coarsest
                // relative to the positions).
                for centre in [(3.0, -2.0), (32_700.0, -32_700.0)] {
                    let mut w = World::new(settings);
                    let fixed: Vec<BodyId> = fixed_shapes
                        .iter()
                        .map(|&s| {
                            w.add_body(BodyDef::fixed(s).position(vec2(centre.0, centre.1)))
                                .unwrap()
                        })
                        .collect();
                    let id = w
                        .add_body(BodyDef::dynamic(dynamic).position(vec2(centre.0, centre.1)))
                        .unwrap();
                    // Deepest start: the sum of the largest extents (≤ 4 +
                    // 0.8), left at ≥ m/2 per axis per substep along any
                    // direction (the slowest: the position pass alone),
                    // i.e. within 2·4.8/0.05 = 192 substeps; 240 ticks
                    // are ample and leave time to fall asleep (0.5 s).
                    let label =
                        format!("{dynamic:?} in {fixed_shapes:?}, {settings_name}, at {centre:?}");
                    let settled = watch(&mut w, id, &fixed, 240, true, &label);
                    assert!(
                        settled <= 192 / substeps + 31,
                        "{label}: settled only at tick {settled}"
                    );
                    cases += 1;
                }
            }
        }
    }
    assert_eq!(cases, 5 * 5 * 3 * 2);
}

/// The second finding (a run after the fix above): a dynamic circle of
/// radius 58 spawned around a fixed circle of radius 1.1875, at the
/// defaults (gravity on). The fix resolves it at the rate the position
/// pass documents (`m/2` per axis per substep at least), 52.5 deep: at
/// most 52.5/0.05 = 1050 ticks, where the fuzz target's overlap watch had
/// assumed the old all-at-once projection. Here: the rules of `watch`
/// with gravity on, and out within that bound (it then falls freely:
/// nothing is below it, so it is not asked to sleep).
#[test]
fn huge_circle_spawned_around_a_fixed_circle_is_pushed_out_at_the_documented_rate() {
    let mut w = World::new(WorldSettings::default());
    let fixed = w
        .add_body(BodyDef::fixed(Shape::circle(fx(1.1875))).position(vec2(-7.5, -7.75)))
        .unwrap();
    let id = w
        .add_body(BodyDef::dynamic(Shape::circle(fx(58.0))).position(vec2(-1.5, -4.75)))
        .unwrap();
    let settled = watch(&mut w, id, &[fixed], 1200, false, "huge circle");
    assert!(settled <= 1050, "out only at tick {settled}");
}

/// The third finding (CI's run on the fix above): a dynamic circle of
/// radius 1/16 spawned at the centre of a fixed circle of radius 13/16 and
/// four of radius 1/16, thrown upwards at 48 units/s, with the finding's
/// settings. The projection moved it along the rows' normals, which the
/// coincidence rule had chosen where it started; by the true geometry it
/// was still 0.257 deep, and with `time_to_sleep` 0 it fell asleep there.
/// A body the projection moves may not fall asleep that tick, so the next
/// substep's rows see the true depth: the rules of `watch` hold.
#[test]
fn circle_projected_along_coincident_normals_does_not_sleep_deep() {
    for (vx, vy) in [(0.0, 48.0), (0.0, 0.0), (-40.0, 48.0), (30.0, -30.0)] {
        let mut w = World::new(finding_settings());
        let id = w
            .add_body(
                BodyDef::dynamic(Shape::circle(fx(0.0625)))
                    .position(vec2(-7.5, -7.75))
                    .velocity(vec2(vx, vy)),
            )
            .unwrap();
        let mut fixed = vec![
            w.add_body(BodyDef::fixed(Shape::circle(fx(0.8125))).position(vec2(-7.5, -7.75)))
                .unwrap(),
        ];
        for _ in 0..4 {
            fixed.push(
                w.add_body(BodyDef::fixed(Shape::circle(fx(0.0625))).position(vec2(-7.5, -7.75)))
                    .unwrap(),
            );
        }
        // Depth at most 0.875 at ≥ m/2 = 0.05 per tick: 18 ticks; the
        // body then flies on (no gravity), so it is not asked to sleep.
        let settled = watch(&mut w, id, &fixed, 120, false, &format!("v ({vx}, {vy})"));
        assert!(settled <= 18, "v ({vx}, {vy}): out only at tick {settled}");
    }
}
