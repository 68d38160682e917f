//! Ropes against contacts (issue 12 regression): a body on an ideal rope
//! that contacts push, press or pin never ends a tick farther from its
//! anchor than the rope's length plus the tolerance below, and never ends
//! inside a fixed body deeper than the linear slop.
//!
//! # Why these scenes
//!
//! The contact phases after the position pass move bodies without looking
//! at ropes: the bound on position corrections (0.05 per axis per substep)
//! capped a rope's pull like a crowd's push, the projection out of fixed
//! bodies moves a body along a contact normal that may point away from the
//! anchor, and a bounce launches it along that normal. Each scene puts one
//! of those against a taut rope: steering into a fixed box (gentle to
//! brutal pushes, light and heavy bodies, circle and box), swinging into
//! it at speed with and without restitution, reeling the rope in while
//! pushing (the playground's grapple), a rope pulling a body into the top
//! of a box over its corner, a stack standing on a roped body, a heavy
//! body pinning a roped one against a wall, and a rope that could only be
//! honoured inside a fixed body (where the fixed body must win).
//!
//! # The tolerance
//!
//! An ideal rope's length is a hard bound. The engine restores it after
//! every other position change (`World::settle_ropes`): the stretch beyond
//! the linear slop is removed exactly along the rope, so a feasible
//! configuration ends each substep within `linear_slop` (1e-4) of the
//! length plus rounding (a few ulps of 2.3e-10 per operation), unless the
//! fixed body the rope pulls the body into pushes it back out along a
//! normal at an angle to the rope: the two projections alternate four times,
//! and each round leaves at most `cos²` of the angle between the rope and the
//! surface of what it had. `STRETCH_TOLERANCE` = 2·slop covers the slop
//! and that remainder for the scenes here (the measured worst case is
//! printed); the playground test allows ten times the slop. Penetration
//! into a fixed body: `linear_slop` plus rounding (`PENETRATION_TOLERANCE`).
#![allow(clippy::float_arithmetic)] // reference values in f64

mod common;
use clockwork2d::geometry::Shape;
use clockwork2d::prelude::*;
use common::depth::shape_depth;

/// The engine's default linear slop.
const SLOP: f64 = 1e-4;
/// See the module notes.
const STRETCH_TOLERANCE: f64 = 2.0 * SLOP;
/// See the module notes.
const PENETRATION_TOLERANCE: f64 = SLOP + 1e-8;

fn v(x: f64, y: f64) -> Vec2 {
    Vec2::new(fx(x), fx(y))
}

fn pos(world: &World, id: BodyId) -> (f64, f64) {
    world.body(id).expect("live body").position().to_f64()
}

fn dist(a: (f64, f64), b: (f64, f64)) -> f64 {
    (b.0 - a.0).hypot(b.1 - a.1)
}

/// Whether the straight rope from `a` to `b` passes through the inside of
/// a fixed box (the box shrunk by 1e-3, so an anchor on its surface and a
/// rope leaving it outwards do not count): slab test in f64. Circles are
/// not needed here.
fn rope_through_box(a: (f64, f64), b: (f64, f64), shape: Shape, centre: (f64, f64)) -> bool {
    let Shape::Aabb { half_extents } = shape else {
        return false;
    };
    let half = half_extents.to_f64();
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, d, c, e) in [
        (a.0, b.0 - a.0, centre.0, half.0 - 1e-3),
        (a.1, b.1 - a.1, centre.1, half.1 - 1e-3),
    ] {
        let (lo, hi) = (c - e, c + e);
        if d == 0.0 {
            if p <= lo || p >= hi {
                return false;
            }
        } else {
            let (mut u, mut w) = ((lo - p) / d, (hi - p) / d);
            if u > w {
                std::mem::swap(&mut u, &mut w);
            }
            t0 = t0.max(u);
            t1 = t1.min(w);
        }
    }
    t0 < t1
}

/// What a scene measured over its ticks.
#[derive(Debug, Default)]
struct Report {
    /// Largest `distance − length` at the end of a tick, over the ticks
    /// whose straight rope does not pass through a fixed body.
    stretch: f64,
    /// Ticks that ended with the straight rope through a fixed body (a
    /// real rope would wrap round it; an ideal straight rope cannot be
    /// honoured there without entering the body, and the body wins).
    wrapped: u32,
    /// Deepest overlap of the roped body with a fixed body at a tick's end.
    penetration: f64,
    /// Ticks that ended with the rope taut (within 1e-3 of its length).
    taut: u32,
    /// Ticks that ended with the roped body within 1e-3 of a fixed body.
    touching: u32,
    /// Ticks that ended with the rope taut and the body touching a fixed
    /// body: the two constraints acting together.
    both: u32,
}

/// A world with one roped body: the rope's id, its fixed anchor point and
/// its length (which reeling changes).
struct Roped {
    world: World,
    body: BodyId,
    rope: ConstraintId,
    anchor: (f64, f64),
    length: f64,
}

impl Roped {
    fn new(world: World, body: BodyId, anchor: (f64, f64), length: f64) -> Roped {
        let mut world = world;
        let rope = world
            .add_constraint(Constraint::rope(
                Anchor::Point(v(anchor.0, anchor.1)),
                Anchor::Body(body),
                fx(length),
            ))
            .expect("rope");
        Roped {
            world,
            body,
            rope,
            anchor,
            length,
        }
    }

    /// Steps `ticks` times; `commands(tick, world, body)` gives each tick's
    /// commands; `reel` shortens the rope by that much each tick (down to
    /// `shortest`) by replacing it, as a game does.
    fn run(
        &mut self,
        ticks: u32,
        reel: Option<(f64, f64)>,
        mut commands: impl FnMut(u32, &World, BodyId) -> Vec<Command>,
    ) -> Report {
        let mut report = Report::default();
        let fixed: Vec<(Shape, (f64, f64))> = self
            .world
            .bodies()
            .filter(|(_, b)| b.kind() == BodyKind::Fixed)
            .map(|(_, b)| (b.shape(), b.position().to_f64()))
            .collect();
        let shape = self.world.body(self.body).unwrap().shape();
        for tick in 0..ticks {
            let mut list = commands(tick, &self.world, self.body);
            if let Some((step, shortest)) = reel {
                let next = (self.length - step).max(shortest);
                if next != self.length {
                    list.push(Command::RemoveConstraint(self.rope));
                    list.push(Command::AddConstraint(Constraint::rope(
                        Anchor::Point(v(self.anchor.0, self.anchor.1)),
                        Anchor::Body(self.body),
                        fx(next),
                    )));
                    self.length = fx(next).to_f64();
                }
            }
            let results = self.world.step_with(&list);
            for result in results {
                if let Ok(CommandOutcome::ConstraintAdded(id)) = result {
                    self.rope = id;
                }
                assert!(result.is_ok(), "command refused at tick {tick}: {result:?}");
            }
            let p = pos(&self.world, self.body);
            let stretch = dist(self.anchor, p) - self.length;
            if fixed
                .iter()
                .any(|&(s, q)| rope_through_box(self.anchor, p, s, q))
            {
                report.wrapped += 1;
            } else {
                report.stretch = report.stretch.max(stretch);
            }
            let deepest = fixed
                .iter()
                .map(|&(s, q)| shape_depth(shape, p, s, q))
                .fold(f64::NEG_INFINITY, f64::max);
            report.penetration = report.penetration.max(deepest);
            let taut = stretch > -1e-3;
            let touching = deepest > -1e-3;
            report.taut += u32::from(taut);
            report.touching += u32::from(touching);
            report.both += u32::from(taut && touching);
        }
        report
    }
}

fn check(name: &str, r: &Report) {
    println!(
        "{name}: worst stretch {:+.3e}, deepest in a fixed body {:+.3e}, ticks taut {}, \
         touching {}, both {}, rope through a fixed body {}",
        r.stretch, r.penetration, r.taut, r.touching, r.both, r.wrapped
    );
    assert!(
        r.stretch <= STRETCH_TOLERANCE,
        "{name}: the rope stretched by {} (> {STRETCH_TOLERANCE})",
        r.stretch
    );
    assert!(
        r.penetration <= PENETRATION_TOLERANCE,
        "{name}: {} deep in a fixed body",
        r.penetration
    );
}

fn settings() -> WorldSettings {
    WorldSettings {
        // A body pinned still by rope and wall may fall asleep: sleeping
        // bodies do not move, which would make the later ticks vacuous.
        sleep_enabled: false,
        ..WorldSettings::default()
    }
}

fn roped_shape(box_shaped: bool) -> Shape {
    if box_shaped {
        Shape::aabb(v(0.3, 0.3))
    } else {
        Shape::circle(fx(0.3))
    }
}

/// A sideways push of `dv` (units/s) per tick, as an impulse.
fn push(world: &World, body: BodyId, dv: (f64, f64)) -> Command {
    let mass = world.body(body).unwrap().mass().to_f64();
    Command::ApplyImpulse {
        body,
        impulse: v(dv.0 * mass, dv.1 * mass),
    }
}

/// The box every "into a box" scene presses against: fixed, left face at
/// x = 1, from y = −3 to 3.
fn wall(world: &mut World) {
    world
        .add_body(BodyDef::fixed(Shape::aabb(v(1.0, 3.0))).position(v(2.0, 0.0)))
        .unwrap();
}

/// Hanging at rest from (0, 5) on a rope of 5, pushed right by `dv` per
/// tick into the box's face at x = 1 for 4 s. The rope and the face meet
/// where the body is both taut and touching: it must stay there, the rope
/// pulling up and left, the face pushing left, the push pressing right.
#[test]
fn a_roped_body_steered_into_a_fixed_box_never_outruns_its_rope() {
    for box_shaped in [false, true] {
        for mass in [1.0, 100.0] {
            for dv in [0.2, 1.0, 5.0, 20.0] {
                let mut world = World::new(settings());
                wall(&mut world);
                let body = world
                    .add_body(
                        BodyDef::dynamic(roped_shape(box_shaped))
                            .mass(fx(mass))
                            .position(v(0.0, 0.0)),
                    )
                    .unwrap();
                let mut roped = Roped::new(world, body, (0.0, 5.0), 5.0);
                let report = roped.run(240, None, |_, w, b| vec![push(w, b, (dv, 0.0))]);
                let name = format!("steer box={box_shaped} mass={mass} dv={dv}/tick");
                check(&name, &report);
                assert!(
                    report.both > 100,
                    "{name}: never pressed with the rope taut"
                );
            }
        }
    }
}

/// Swinging into the box's face from the bottom of the swing at 1 to 60
/// units/s, restitution 0, 0.5 and 1, still pushed gently: the impact, the
/// bounce and the rebound must not carry the body beyond the rope.
#[test]
fn a_roped_body_swinging_into_a_fixed_box_at_speed_never_outruns_its_rope() {
    for box_shaped in [false, true] {
        for speed in [1.0, 5.0, 20.0, 60.0] {
            for e in [0.0, 0.5, 1.0] {
                let mut world = World::new(settings());
                wall(&mut world);
                let body = world
                    .add_body(
                        BodyDef::dynamic(roped_shape(box_shaped))
                            .mass(fx(1.0))
                            .restitution(fx(e))
                            .position(v(-0.5, 5.0 - (25.0f64 - 0.25).sqrt()))
                            .velocity(v(speed, 0.0)),
                    )
                    .unwrap();
                let mut roped = Roped::new(world, body, (0.0, 5.0), 5.0);
                let report = roped.run(240, None, |_, w, b| vec![push(w, b, (0.2, 0.0))]);
                let name = format!("swing box={box_shaped} speed={speed} e={e}");
                check(&name, &report);
                // Came within a tick's travel of the face (a bounce with
                // e = 1 leaves before the tick ends).
                assert!(report.penetration > -0.05, "{name}: never reached the box");
            }
        }
    }
}

/// The playground's grapple in engine terms: a body standing on the
/// floor, a rope to a point up and to the right, reeled in by `step` per
/// tick (a new, shorter rope each tick) while the body is pushed right
/// into a ledge. Reeling at up to 0.2 per tick (12 units/s) the body keeps
/// up with the rope.
#[test]
fn a_reeled_in_rope_pulls_its_body_along_while_it_is_pushed_into_a_ledge() {
    for step in [0.02, 0.1, 0.2] {
        for dv in [0.2, 1.0] {
            let mut world = World::new(settings());
            // Floor (top at y = 0) and a ledge right of the anchor.
            world
                .add_body(BodyDef::fixed(Shape::aabb(v(20.0, 0.5))).position(v(0.0, -0.5)))
                .unwrap();
            world
                .add_body(BodyDef::fixed(Shape::aabb(v(1.5, 0.2))).position(v(0.5, 7.5)))
                .unwrap();
            let body = world
                .add_body(
                    BodyDef::dynamic(Shape::circle(fx(0.3)))
                        .mass(fx(1.0))
                        .position(v(-3.5, 0.3)),
                )
                .unwrap();
            let anchor = (-1.0, 7.3);
            let length = dist(anchor, (-3.5, 0.3));
            let mut roped = Roped::new(world, body, anchor, length);
            let report = roped.run(240, Some((step, 1.0)), |_, w, b| {
                vec![push(w, b, (dv, 0.0))]
            });
            let name = format!("reel {step}/tick push {dv}/tick");
            check(&name, &report);
            // The rope pulls while it is being reeled in (until it reaches
            // its shortest, 1.0).
            let reeling = ((length - 1.0) / step).floor().min(240.0) as u32;
            assert!(
                report.taut >= reeling * 9 / 10,
                "{name}: the rope was not pulling ({} of {reeling} ticks)",
                report.taut
            );
        }
    }
}

/// A rope that passes over a box's corner: the anchor (−1, −1.5) is left of
/// the box and below its top (y = 0), the body stands on the top and is
/// pushed right (away from the anchor) until the rope is taut. The rope
/// then pulls down and to the left, into the top: the body must end every
/// tick on the top (not in it) and within the rope. A shallow variant has
/// the anchor far away just below the top's level.
#[test]
fn a_rope_pulling_a_body_into_the_top_of_a_box_over_its_corner() {
    for (anchor, start, length) in [
        ((-1.0, -1.5), (1.0, 0.3), 2.8),
        ((-8.0, -0.2), (1.0, 0.3), 9.5),
    ] {
        for box_shaped in [false, true] {
            for dv in [0.2, 1.0, 5.0] {
                let mut world = World::new(settings());
                world
                    .add_body(BodyDef::fixed(Shape::aabb(v(4.0, 1.0))).position(v(4.0, -1.0)))
                    .unwrap();
                let body = world
                    .add_body(
                        BodyDef::dynamic(roped_shape(box_shaped))
                            .mass(fx(1.0))
                            .position(v(start.0, start.1)),
                    )
                    .unwrap();
                let mut roped = Roped::new(world, body, anchor, length);
                let report = roped.run(240, None, |_, w, b| vec![push(w, b, (dv, 0.0))]);
                let name = format!("corner anchor={anchor:?} box={box_shaped} dv={dv}/tick");
                check(&name, &report);
                assert!(
                    report.both > 100,
                    "{name}: rope and top never acted together"
                );
            }
        }
    }
}

/// A box hanging from (0, 10) on a rope of 5 carries a stack of five boxes
/// (each 1, 10 or 100 times its mass), pushed sideways into a fixed wall
/// by a steady push on the roped box: the stack's weight and the wall act
/// on the roped body through contacts, the rope alone holds it up.
#[test]
fn a_roped_body_carrying_a_stack_against_a_wall_never_outruns_its_rope() {
    for ratio in [1.0, 10.0, 100.0] {
        for dv in [0.0, 0.5] {
            let mut world = World::new(settings());
            // The wall's left face at x = 0.6.
            world
                .add_body(BodyDef::fixed(Shape::aabb(v(0.5, 8.0))).position(v(1.1, 5.0)))
                .unwrap();
            let body = world
                .add_body(
                    BodyDef::dynamic(Shape::aabb(v(0.5, 0.5)))
                        .mass(fx(1.0))
                        .position(v(0.0, 5.0)),
                )
                .unwrap();
            for k in 1..=5 {
                world
                    .add_body(
                        BodyDef::dynamic(Shape::aabb(v(0.5, 0.5)))
                            .mass(fx(ratio))
                            .position(v(0.0, 5.0 + f64::from(k))),
                    )
                    .unwrap();
            }
            let mut roped = Roped::new(world, body, (0.0, 10.0), 5.0);
            let report = roped.run(240, None, |_, w, b| vec![push(w, b, (dv, 0.0))]);
            let name = format!("stack mass ratio {ratio} push {dv}/tick");
            check(&name, &report);
            assert!(
                report.taut > 200,
                "{name}: the rope was not holding the stack"
            );
        }
    }
}

/// A heavy free box (1000 times the roped body's mass, no gravity) flies at
/// 1, 5 or 20 units/s into a roped body that rests taut against the box's
/// face at x = 1, and pins it there: the contact between the two dynamic
/// bodies pushes the roped body into the fixed one, away from nothing the
/// rope can give.
#[test]
fn a_heavy_body_pinning_a_roped_body_against_a_wall() {
    for speed in [1.0, 5.0, 20.0] {
        let mut world = World::new(settings());
        wall(&mut world);
        // Taut and touching the face: x = 0.7, on the circle of 5 round (0, 5).
        let y = 5.0 - (25.0f64 - 0.49).sqrt();
        let body = world
            .add_body(
                BodyDef::dynamic(Shape::circle(fx(0.3)))
                    .mass(fx(1.0))
                    .position(v(0.7, y)),
            )
            .unwrap();
        world
            .add_body(
                BodyDef::dynamic(Shape::aabb(v(0.4, 0.4)))
                    .mass(fx(1000.0))
                    .gravity_scale(fx(0.0))
                    .position(v(-1.0, y))
                    .velocity(v(speed, 0.0)),
            )
            .unwrap();
        let mut roped = Roped::new(world, body, (0.0, 5.0), 5.0);
        let report = roped.run(180, None, |_, _, _| Vec::new());
        let name = format!("heavy pinning at {speed} u/s");
        check(&name, &report);
        assert!(
            report.taut > 150 && report.touching > 0,
            "{name}: not pinned with the rope taut"
        );
    }
}

/// A rope that could only be honoured inside a fixed body: the anchor is
/// 2 below a box's bottom and the body stands on its top (3.3 from the
/// anchor) on a rope of 2. Ropes do not wrap round bodies, so no position
/// satisfies both: the fixed body wins (the body stays on the top, never in
/// the box, never through it) and nothing blows up; the rope stays long
/// by the box's height.
#[test]
fn a_rope_that_only_fits_through_a_fixed_body_loses_to_it() {
    for box_shaped in [false, true] {
        let mut world = World::new(settings());
        let floor = world
            .add_body(BodyDef::fixed(Shape::aabb(v(2.0, 1.0))).position(v(0.0, -1.0)))
            .unwrap();
        let body = world
            .add_body(
                BodyDef::dynamic(roped_shape(box_shaped))
                    .mass(fx(1.0))
                    .position(v(0.3, 0.3)),
            )
            .unwrap();
        let mut roped = Roped::new(world, body, (0.0, -3.0), 2.0);
        let report = roped.run(240, None, |_, _, _| Vec::new());
        let p = pos(&roped.world, body);
        let speed = {
            let (vx, vy) = roped.world.body(body).unwrap().velocity().to_f64();
            vx.hypot(vy)
        };
        println!(
            "infeasible box={box_shaped}: deepest {:+.3e}, end ({:.4}, {:.4}), speed {speed:.3e}",
            report.penetration, p.0, p.1
        );
        assert!(report.penetration <= PENETRATION_TOLERANCE, "{report:?}");
        let top = pos(&roped.world, floor).1 + 1.0;
        assert!(p.1 > top, "went through the box: {p:?}");
        assert!(speed < 20.0, "flung: {speed}");
    }
}
