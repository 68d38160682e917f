//! The suite's scenarios: a world and a script each.
//!
//! Every number here is an integer or a ratio of integers converted by the
//! scalar (`from_int`, `from_ratio`): no float appears, so the inputs are
//! the same bits on every target by construction. Built-in scenes are
//! loaded from their RON text, whose decimal literals the scene loader
//! converts with correct rounding.

use super::{Built, Observer, Script};
use clockwork2d::constraints::{Anchor, Constraint, ConstraintId};
use clockwork2d::dynamics::{BodyDef, BodyId, BodyKind};
use clockwork2d::geometry::{Aabb, Shape};
use clockwork2d::math::{Fx, Scalar, Vec2};
use clockwork2d::world::{Command, CommandOutcome, QueryFilter, World, WorldError, WorldSettings};
use clockwork2d_scene::builtin;
use clockwork2d_scene::scripted_commands;

/// An integer as a scalar.
fn n(value: i32) -> Fx {
    <Fx as Scalar>::from_int(value)
}

/// `numerator / denominator` as a scalar.
fn r(numerator: i32, denominator: i32) -> Fx {
    <Fx as Scalar>::from_ratio(numerator, denominator)
}

/// A vector of two integers.
fn vi(x: i32, y: i32) -> Vec2<Fx> {
    Vec2::new(n(x), n(y))
}

/// A vector of two scalars.
fn vf(x: Fx, y: Fx) -> Vec2<Fx> {
    Vec2::new(x, y)
}

/// The ids of the world's bodies of one kind, in id order.
fn ids_of(world: &World, kind: BodyKind) -> Vec<BodyId> {
    world
        .bodies()
        .filter(|(_, b)| b.kind() == kind)
        .map(|(id, _)| id)
        .collect()
}

/// The `i`-th element of `ids`, or a never-issued id (commands naming it
/// are refused, never a panic).
fn nth(ids: &[BodyId], i: usize) -> BodyId {
    ids.get(i)
        .copied()
        .unwrap_or(BodyId::from_parts(u32::MAX, u32::MAX))
}

/// Ids spawned and constraints added by a tick's commands, in order.
fn outcomes(results: &[Result<CommandOutcome, WorldError>]) -> (Vec<BodyId>, Vec<ConstraintId>) {
    let mut bodies = Vec::new();
    let mut constraints = Vec::new();
    for result in results {
        match result {
            Ok(CommandOutcome::Spawned(id)) => bodies.push(*id),
            Ok(CommandOutcome::ConstraintAdded(id)) => constraints.push(*id),
            _ => {}
        }
    }
    (bodies, constraints)
}

/// The impulse that changes a body's velocity by `dv` (`dv · mass`).
fn impulse_for(world: &World, body: BodyId, dv: Vec2<Fx>) -> Command {
    let mass = world.body(body).map_or(<Fx as Scalar>::ONE, |b| b.mass());
    Command::ApplyImpulse {
        body,
        impulse: dv.scale(mass),
    }
}

// ---------------------------------------------------------------------------
// stack_sleep
// ---------------------------------------------------------------------------

struct StackSleep {
    boxes: Vec<BodyId>,
}

impl Script for StackSleep {
    fn commands(&mut self, world: &World, observer: &mut Observer<'_>) -> Vec<Command> {
        let tick = world.tick();
        if tick % 60 == 0 {
            // Which boxes are awake is in the state; the probe records what
            // a point query at the stack's top answers.
            let top = world.body(nth(&self.boxes, 9)).map(|b| b.position());
            if let Some(p) = top {
                observer
                    .probe
                    .ids(&world.query_point(p, &QueryFilter::default()));
            }
        }
        match tick {
            // The stack is asleep by now: a ball dropped on it wakes it.
            360 => vec![Command::Spawn(
                BodyDef::dynamic(Shape::circle(r(3, 10)))
                    .position(vf(r(1, 5), n(14)))
                    .restitution(r(1, 5)),
            )],
            // And a command wakes it again after it has settled.
            540 => vec![Command::Wake(nth(&self.boxes, 0))],
            _ => Vec::new(),
        }
    }
}

pub(super) fn stack_sleep() -> Built {
    let world: World = builtin("stack")?.build()?;
    let boxes = ids_of(&world, BodyKind::Dynamic);
    Ok((world, Box::new(StackSleep { boxes })))
}

// ---------------------------------------------------------------------------
// pyramid
// ---------------------------------------------------------------------------

struct Pyramid;

impl Script for Pyramid {
    fn commands(&mut self, world: &World, _observer: &mut Observer<'_>) -> Vec<Command> {
        if world.tick() == 420 {
            // A ball dropped on the apex (row 20, top at y = 20).
            vec![Command::Spawn(
                BodyDef::dynamic(Shape::circle(r(2, 5)))
                    .position(vf(r(3, 10), n(26)))
                    .density(n(2)),
            )]
        } else {
            Vec::new()
        }
    }
}

pub(super) fn pyramid() -> Built {
    let world: World = builtin("pyramid")?.build()?;
    Ok((world, Box::new(Pyramid)))
}

// ---------------------------------------------------------------------------
// bullets_toi
// ---------------------------------------------------------------------------

struct Bullets {
    bullets: Vec<BodyId>,
}

impl Script for Bullets {
    fn commands(&mut self, world: &World, observer: &mut Observer<'_>) -> Vec<Command> {
        let tick = world.tick();
        if tick % 60 == 30 {
            // Where is the first bullet's next wall? (ray along its path)
            if let Some(b) = world.body(nth(&self.bullets, 0)) {
                let filter = QueryFilter {
                    exclude: Some(nth(&self.bullets, 0)),
                    ..QueryFilter::default()
                };
                let hit = world.raycast_filtered(b.position(), b.velocity(), n(100), &filter);
                observer.ray(hit.as_ref());
            }
        }
        let bullet = |shape: Shape<Fx>, position: Vec2<Fx>, velocity: Vec2<Fx>| {
            Command::Spawn(
                BodyDef::dynamic(shape)
                    .position(position)
                    .velocity(velocity)
                    .bullet(true)
                    .restitution(n(1))
                    .friction(n(0)),
            )
        };
        match tick {
            // 33 units per tick against 0.1-thick walls 40 apart (one
            // impact per tick at most).
            100 => vec![bullet(
                Shape::circle(r(1, 20)),
                vf(n(-19), r(1, 2)),
                vi(2000, 0),
            )],
            200 => vec![Command::SetVelocity {
                body: nth(&self.bullets, 0),
                velocity: vi(-1500, 30),
            }],
            // A box bullet (time of impact of a box, i.e. a rounded-box sweep).
            300 => vec![bullet(
                Shape::aabb(vf(r(1, 20), r(1, 20))),
                vf(n(15), r(-3, 2)),
                vi(-3000, 1),
            )],
            // A fast body that is not a bullet (speculative contacts only).
            400 => vec![Command::Spawn(
                BodyDef::dynamic(Shape::circle(r(1, 5)))
                    .position(vi(0, 2))
                    .velocity(vi(900, 0))
                    .restitution(r(1, 2)),
            )],
            _ => Vec::new(),
        }
    }
}

pub(super) fn bullets_toi() -> Built {
    let world: World = builtin("bullets")?.build()?;
    let bullets = world
        .bodies()
        .filter(|(_, b)| b.is_bullet())
        .map(|(id, _)| id)
        .collect();
    Ok((world, Box::new(Bullets { bullets })))
}

// ---------------------------------------------------------------------------
// springs
// ---------------------------------------------------------------------------

struct Springs {
    bodies: Vec<BodyId>,
    added: Vec<ConstraintId>,
}

impl Script for Springs {
    fn commands(&mut self, world: &World, _observer: &mut Observer<'_>) -> Vec<Command> {
        let b = |i: usize| nth(&self.bodies, i);
        match world.tick() {
            // A radial spring between the two free balls, off-centre anchors.
            120 => vec![Command::AddConstraint(Constraint::radial_spring(
                Anchor::BodyOffset(b(0), vf(r(1, 10), n(0))),
                Anchor::BodyOffset(b(1), vf(r(-1, 10), n(0))),
                n(4),
                n(30),
                r(1, 5),
            ))],
            // A bendy spring between two hanging boxes, with a rest offset.
            240 => vec![Command::AddConstraint(
                Constraint::bendy_spring(
                    Anchor::Body(b(2)),
                    Anchor::Body(b(3)),
                    vi(80, 120),
                    r(1, 2),
                )
                .with_rest_offset(vf(r(12, 5), n(0))),
            )],
            360 => self
                .added
                .first()
                .map(|&id| vec![Command::RemoveConstraint(id)])
                .unwrap_or_default(),
            // A kick to the box on the 10^6 spring.
            420 => vec![impulse_for(world, b(7), vi(0, 50))],
            // The box on the 5000 spring is let go (constraint slot 6 of the
            // scene) and falls to the ground.
            480 => vec![Command::RemoveConstraint(ConstraintId::from_parts(6, 0))],
            // The stiffest spring accepted (2^24), undamped, on another box.
            500 => vec![Command::AddConstraint(Constraint::radial_spring(
                Anchor::Point(vf(r(-6, 5), n(5))),
                Anchor::Body(b(4)),
                n(1),
                n(1 << 24),
                n(0),
            ))],
            _ => Vec::new(),
        }
    }

    fn after_step(
        &mut self,
        _world: &World,
        results: &[Result<CommandOutcome, WorldError>],
        _observer: &mut Observer<'_>,
    ) {
        self.added.extend(outcomes(results).1);
    }
}

pub(super) fn springs() -> Built {
    let world: World = builtin("springs")?.build()?;
    let bodies = ids_of(&world, BodyKind::Dynamic);
    Ok((
        world,
        Box::new(Springs {
            bodies,
            added: Vec::new(),
        }),
    ))
}

// ---------------------------------------------------------------------------
// ropes_chain
// ---------------------------------------------------------------------------

struct Ropes {
    bodies: Vec<BodyId>,
}

impl Script for Ropes {
    fn commands(&mut self, world: &World, _observer: &mut Observer<'_>) -> Vec<Command> {
        // Dynamic bodies: 0 pendulum bob, 1 heavy ball, 2..=11 chain links.
        let b = |i: usize| nth(&self.bodies, i);
        match world.tick() {
            150 => vec![Command::SetVelocity {
                body: b(11),
                velocity: vi(0, 6),
            }],
            // A middle link goes, and its two ropes with it: the chain splits.
            300 => vec![Command::Despawn(b(6))],
            // A bouncy rope between the pendulum bob and the heavy ball.
            400 => vec![Command::AddConstraint(
                Constraint::rope(Anchor::Body(b(0)), Anchor::Body(b(1)), n(14))
                    .with_restitution(r(1, 2)),
            )],
            // The fallen end of the chain is hoisted by a short rope.
            450 => vec![Command::AddConstraint(Constraint::rope(
                Anchor::Point(vi(-2, 10)),
                Anchor::BodyOffset(b(11), vf(r(1, 20), n(0))),
                n(3),
            ))],
            _ => Vec::new(),
        }
    }
}

pub(super) fn ropes_chain() -> Built {
    let world: World = builtin("rope")?.build()?;
    let bodies = ids_of(&world, BodyKind::Dynamic);
    Ok((world, Box::new(Ropes { bodies })))
}

// ---------------------------------------------------------------------------
// grapple_rays
// ---------------------------------------------------------------------------

/// The grapple's state machine.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Grapple {
    /// Waiting for the next throw.
    Idle,
    /// The rope was requested this tick; its id comes with the results.
    Attaching,
    /// Swinging on the rope since the given tick.
    Swinging(ConstraintId, u64),
}

struct GrappleRays {
    player: BodyId,
    state: Grapple,
    /// Directions tried in turn when a throw misses.
    attempt: usize,
}

/// Integer directions of the grapple's throws (any length: ray casts take
/// any non-zero direction).
const THROWS: [(i32, i32); 6] = [(1, 2), (2, 3), (-1, 3), (1, 1), (3, 4), (-2, 3)];
/// Ticks at which a throw starts.
const THROW_TICKS: [u64; 4] = [30, 170, 310, 450];
/// Ticks the player swings before letting go.
const SWING_TICKS: u64 = 100;

impl GrappleRays {
    /// The every-60-ticks query battery.
    fn queries(world: &World, observer: &mut Observer<'_>) {
        let origin = vi(0, 5);
        let fan: [(i32, i32); 12] = [
            (1, 0),
            (2, 1),
            (1, 1),
            (1, 2),
            (0, 1),
            (-1, 2),
            (-1, 1),
            (-2, 1),
            (-1, 0),
            (-1, -1),
            (0, -1),
            (1, -1),
        ];
        for (x, y) in fan {
            let hit = world.raycast(origin, vi(x, y), n(50));
            observer.ray(hit.as_ref());
            let all = world.raycast_all(origin, vi(x, y), n(50), &QueryFilter::default());
            observer.probe.rays(&all);
        }
        let dynamic_only = QueryFilter {
            fixed: false,
            kinematic: false,
            ..QueryFilter::default()
        };
        let hit = world.raycast_filtered(vi(-20, 1), vi(1, 0), n(60), &dynamic_only);
        observer.ray(hit.as_ref());
        // Degenerate rays have defined answers: none.
        observer.ray(world.raycast(origin, Vec2::ZERO, n(10)).as_ref());
        observer.ray(world.raycast(origin, vi(1, 0), n(-1)).as_ref());
        let area = Aabb::new(vi(4, 1), vi(3, 2));
        observer
            .probe
            .ids(&world.query_aabb(&area, &QueryFilter::default()));
        observer
            .probe
            .ids(&world.query_point(vi(4, 0), &dynamic_only));
    }
}

impl Script for GrappleRays {
    fn commands(&mut self, world: &World, observer: &mut Observer<'_>) -> Vec<Command> {
        let tick = world.tick();
        if tick % 60 == 0 {
            Self::queries(world, observer);
        }
        let Some(player) = world.body(self.player) else {
            return Vec::new();
        };
        let position = player.position();
        match self.state {
            Grapple::Idle => {
                let due = THROW_TICKS
                    .iter()
                    .any(|&t| tick >= t && tick < t.saturating_add(20));
                if !due {
                    return Vec::new();
                }
                let (x, y) = THROWS
                    .get(self.attempt % THROWS.len())
                    .copied()
                    .unwrap_or((1, 2));
                self.attempt += 1;
                let filter = QueryFilter {
                    dynamic: false,
                    exclude: Some(self.player),
                    ..QueryFilter::default()
                };
                let hit = world.raycast_filtered(position, vi(x, y), n(30), &filter);
                observer.ray(hit.as_ref());
                let Some(hit) = hit else {
                    return Vec::new();
                };
                let Some(target) = world.body(hit.body) else {
                    return Vec::new();
                };
                // Attach at the hit point, in the target's frame, with the
                // hit distance as the rope length; swing sideways.
                let offset = hit.hit.point - target.position();
                self.state = Grapple::Attaching;
                let side = if x >= 0 { 6 } else { -6 };
                vec![
                    Command::AddConstraint(Constraint::rope(
                        Anchor::BodyOffset(hit.body, offset),
                        Anchor::Body(self.player),
                        hit.hit.distance,
                    )),
                    Command::SetVelocity {
                        body: self.player,
                        velocity: vi(side, 0),
                    },
                ]
            }
            Grapple::Attaching => Vec::new(),
            Grapple::Swinging(rope, since) => {
                // Line of sight from the player to the rope's anchor.
                if let Some(Constraint::Rope { a, .. }) = world.constraint(rope).copied() {
                    let anchor = match a {
                        Anchor::Point(p) => p,
                        Anchor::Body(id) => world.body(id).map_or(Vec2::ZERO, |b| b.position()),
                        Anchor::BodyOffset(id, o) => {
                            world.body(id).map_or(Vec2::ZERO, |b| b.position()) + o
                        }
                    };
                    let filter = QueryFilter {
                        exclude: Some(self.player),
                        ..QueryFilter::default()
                    };
                    let hit = world.raycast_filtered(position, anchor - position, n(40), &filter);
                    observer.ray(hit.as_ref());
                }
                if tick.saturating_sub(since) < SWING_TICKS {
                    return Vec::new();
                }
                self.state = Grapple::Idle;
                vec![
                    Command::RemoveConstraint(rope),
                    impulse_for(world, self.player, vi(2, 5)),
                ]
            }
        }
    }

    fn after_step(
        &mut self,
        world: &World,
        results: &[Result<CommandOutcome, WorldError>],
        _observer: &mut Observer<'_>,
    ) {
        if self.state == Grapple::Attaching {
            self.state = match outcomes(results).1.first() {
                Some(&id) => Grapple::Swinging(id, world.tick()),
                None => Grapple::Idle,
            };
        }
    }
}

pub(super) fn grapple_rays() -> Built {
    let mut world = World::new(WorldSettings::default());
    world.add_body(BodyDef::fixed(Shape::aabb(vi(40, 1))).position(vi(0, -1)))?;
    for (x, y) in [(-8, 10), (0, 11), (8, 10), (16, 12)] {
        world.add_body(BodyDef::fixed(Shape::aabb(vf(r(3, 2), r(1, 4)))).position(vi(x, y)))?;
    }
    world.add_body(BodyDef::fixed(Shape::circle(n(1))).position(vi(-14, 6)))?;
    world.add_body(
        BodyDef::kinematic(Shape::aabb(vf(n(1), r(1, 4))))
            .position(vi(-4, 6))
            .velocity(vf(n(1), n(0))),
    )?;
    world.add_body(
        BodyDef::dynamic(Shape::aabb(vf(r(1, 2), r(1, 2)))).position(vf(n(4), r(1, 2))),
    )?;
    world.add_body(
        BodyDef::dynamic(Shape::aabb(vf(r(1, 2), r(1, 2)))).position(vf(r(26, 5), r(1, 2))),
    )?;
    world.add_body(BodyDef::dynamic(Shape::circle(r(1, 2))).position(vf(n(12), r(1, 2))))?;
    let player = world.add_body(
        BodyDef::dynamic(Shape::circle(r(2, 5)))
            .position(vf(n(-12), r(2, 5)))
            .friction(r(1, 5)),
    )?;
    Ok((
        world,
        Box::new(GrappleRays {
            player,
            state: Grapple::Idle,
            attempt: 0,
        }),
    ))
}

// ---------------------------------------------------------------------------
// commands_churn
// ---------------------------------------------------------------------------

struct Churn {
    ground: BodyId,
    bodies: Vec<BodyId>,
    spawned: Vec<BodyId>,
    constraints: Vec<ConstraintId>,
    kinematic: Option<BodyId>,
}

impl Script for Churn {
    fn commands(&mut self, world: &World, _observer: &mut Observer<'_>) -> Vec<Command> {
        let tick = world.tick();
        // The replay module's seeded input: impulses, spawns, despawns,
        // velocities, wakes and a stale despawn, on their own periods.
        let mut out = scripted_commands(world, 0x00C1_0C4B);
        let b = |i: usize| nth(&self.bodies, i);
        match tick {
            10 => {
                out.push(Command::AddConstraint(Constraint::rope(
                    Anchor::Body(b(0)),
                    Anchor::Body(b(1)),
                    n(2),
                )));
                out.push(Command::AddConstraint(Constraint::bendy_spring(
                    Anchor::Body(b(2)),
                    Anchor::Body(b(3)),
                    vi(40, 40),
                    r(1, 2),
                )));
            }
            // A body with a rope goes (the rope with it); its stale handle
            // is refused; the next spawn reuses its slot, one generation up.
            50 => out.push(Command::Despawn(b(0))),
            51 => {
                out.push(impulse_for(world, b(0), vi(1, 0)));
                out.push(Command::Spawn(
                    BodyDef::dynamic(Shape::aabb(vf(r(3, 10), r(3, 10)))).position(vi(-3, 7)),
                ));
            }
            100 => {
                out.push(Command::SetPosition {
                    body: b(4),
                    position: vi(3, 6),
                });
                out.push(Command::ApplyImpulse {
                    body: self.ground,
                    impulse: vi(1, 0),
                });
                out.push(Command::SetVelocity {
                    body: self.ground,
                    velocity: vi(1, 0),
                });
            }
            // Invalid definitions, each refused with its own error.
            150 => {
                out.push(Command::Spawn(BodyDef::dynamic(Shape::circle(n(0)))));
                out.push(Command::Spawn(
                    BodyDef::dynamic(Shape::circle(n(1))).restitution(n(2)),
                ));
                out.push(Command::Spawn(
                    BodyDef::dynamic(Shape::circle(n(1))).mass(n(0)),
                ));
                out.push(Command::Spawn(BodyDef::dynamic(Shape::circle(n(5000)))));
            }
            200 => {
                // A constraint attached to no body, and a rope of negative
                // length: both refused.
                out.push(Command::AddConstraint(Constraint::rope(
                    Anchor::Point(vi(0, 1)),
                    Anchor::Point(vi(0, 2)),
                    n(1),
                )));
                out.push(Command::AddConstraint(Constraint::rope(
                    Anchor::Point(vi(0, 1)),
                    Anchor::Body(self.spawned.first().copied().unwrap_or(b(5))),
                    n(-1),
                )));
                out.push(Command::RemoveConstraint(ConstraintId::from_parts(0, 9)));
                // The spring between 2 and 3 goes.
                if let Some(&id) = self.constraints.get(1) {
                    out.push(Command::RemoveConstraint(id));
                }
            }
            250 => out.push(Command::Spawn(
                BodyDef::kinematic(Shape::aabb(vf(r(3, 2), r(1, 4))))
                    .position(vi(-8, 3))
                    .velocity(vi(2, 0)),
            )),
            // A burst of spawns in one tick; three of them go the next tick.
            300 => {
                for i in 0..5 {
                    out.push(Command::Spawn(
                        BodyDef::dynamic(Shape::circle(r(1, 4))).position(vf(n(i - 2), n(9))),
                    ));
                }
            }
            301 => {
                for &id in self.spawned.iter().rev().take(3) {
                    out.push(Command::Despawn(id));
                }
            }
            350 => {
                if let Some(k) = self.kinematic {
                    out.push(Command::SetVelocity {
                        body: k,
                        velocity: vi(-2, 0),
                    });
                }
            }
            450 => {
                if let Some(k) = self.kinematic {
                    out.push(Command::Despawn(k));
                }
            }
            500 => {
                for (id, body) in world.bodies() {
                    if body.kind() == BodyKind::Dynamic {
                        out.push(Command::Wake(id));
                    }
                }
            }
            _ => {}
        }
        out
    }

    fn after_step(
        &mut self,
        world: &World,
        results: &[Result<CommandOutcome, WorldError>],
        _observer: &mut Observer<'_>,
    ) {
        let (bodies, constraints) = outcomes(results);
        if world.tick() == 251 {
            self.kinematic = bodies.iter().copied().find(|&id| {
                world
                    .body(id)
                    .is_some_and(|b| b.kind() == BodyKind::Kinematic)
            });
        }
        self.spawned.extend(bodies);
        self.constraints.extend(constraints);
    }
}

pub(super) fn commands_churn() -> Built {
    let mut world = World::new(WorldSettings::default());
    let ground = world
        .add_body(BodyDef::fixed(Shape::aabb(vf(n(12), r(1, 2)))).position(vf(n(0), r(-1, 2))))?;
    for x in [-25, 25] {
        world
            .add_body(BodyDef::fixed(Shape::aabb(vf(r(1, 2), n(8)))).position(vf(r(x, 2), n(8))))?;
    }
    let mut bodies = Vec::new();
    for i in 0..12 {
        let x = r(i * 3 - 16, 2);
        let y = n(1 + (i % 3) * 2);
        let def = if i % 2 == 0 {
            BodyDef::dynamic(Shape::circle(r(3 + i % 3, 10)))
        } else {
            BodyDef::dynamic(Shape::aabb(vf(r(2 + i % 4, 10), r(3, 10))))
        };
        bodies.push(world.add_body(def.position(vf(x, y)).restitution(r(i % 4, 8)))?);
    }
    Ok((
        world,
        Box::new(Churn {
            ground,
            bodies,
            spawned: Vec::new(),
            constraints: Vec::new(),
            kinematic: None,
        }),
    ))
}

// ---------------------------------------------------------------------------
// bounds_extreme
// ---------------------------------------------------------------------------

struct Bounds {
    b: Vec<BodyId>,
}

impl Script for Bounds {
    fn commands(&mut self, world: &World, observer: &mut Observer<'_>) -> Vec<Command> {
        let b = |i: usize| nth(&self.b, i);
        let max = <Fx as Scalar>::MAX;
        let min = <Fx as Scalar>::MIN;
        if world.tick() % 60 == 0 {
            // Rays across the whole world, and one of unbounded length.
            let rays = [
                (vi(-32768, -32600), vi(1, 0), n(1 << 16)),
                (vi(32768, 32768), vi(-1, -1), n(1 << 17)),
                (vi(0, 0), vi(0, -1), max),
                (vi(-32768, 32768), vi(32767, -1), max),
            ];
            for (origin, direction, length) in rays {
                let hit = world.raycast(origin, direction, length);
                observer.ray(hit.as_ref());
            }
        }
        match world.tick() {
            3 => vec![
                // Δv = 1000 · 1024 units/s on the 1/1024-mass body: refused.
                Command::ApplyImpulse {
                    body: b(5),
                    impulse: vi(1000, 0),
                },
                // The most negative impulses there are: refused, nothing overflows.
                Command::ApplyImpulse {
                    body: b(4),
                    impulse: vf(min, min),
                },
                // On the heaviest body the largest impulse is a change of
                // 2048 units/s: accepted, and saturates nothing.
                Command::ApplyImpulse {
                    body: b(4),
                    impulse: vf(max, n(0)),
                },
                Command::ApplyImpulse {
                    body: b(6),
                    impulse: vf(min, n(0)),
                },
            ],
            5 => vec![
                Command::SetVelocity {
                    body: b(7),
                    velocity: vi(0, 4097),
                },
                Command::SetVelocity {
                    body: b(1),
                    velocity: vi(4096, 0),
                },
            ],
            // b1 is frozen at x = +32768 by now.
            20 => vec![
                impulse_for(world, b(1), vi(-1, 0)),
                Command::SetVelocity {
                    body: b(1),
                    velocity: vi(-10, 0),
                },
                Command::SetPosition {
                    body: b(1),
                    position: vi(32767, 0),
                },
                Command::SetVelocity {
                    body: b(1),
                    velocity: vi(-4096, 0),
                },
            ],
            25 => vec![
                Command::SetPosition {
                    body: b(2),
                    position: vi(40000, 0),
                },
                Command::SetPosition {
                    body: b(2),
                    position: vf(max, min),
                },
                Command::Spawn(BodyDef::dynamic(Shape::circle(n(1))).position(vi(32769, 0))),
                Command::Spawn(BodyDef::dynamic(Shape::circle(n(1))).position(vi(32768, -32768))),
                Command::Spawn(BodyDef::dynamic(Shape::circle(n(1))).velocity(vi(4097, 0))),
                Command::Spawn(BodyDef::dynamic(Shape::circle(n(1))).mass(n(1 << 21))),
                Command::Spawn(BodyDef::dynamic(Shape::circle(n(1))).mass(r(1, 2048))),
            ],
            // The largest shape, heaviest mass, at max speed toward a corner.
            60 => vec![Command::Spawn(
                BodyDef::dynamic(Shape::circle(n(4096)))
                    .position(vi(28000, 28000))
                    .velocity(vi(4096, 4096))
                    .mass(n(1 << 20)),
            )],
            // A rope of the largest length between bodies half a world apart.
            120 => vec![Command::AddConstraint(Constraint::rope(
                Anchor::Body(b(1)),
                Anchor::Body(b(9)),
                n(32768),
            ))],
            300 => vec![Command::Despawn(b(2))],
            _ => Vec::new(),
        }
    }
}

pub(super) fn bounds_extreme() -> Built {
    let mut world = World::new(WorldSettings::default());
    let heavy = n(1 << 20);
    let tiny = r(1, 1024);
    let defs = [
        // 0: the largest fixed box, near the bottom bound.
        BodyDef::fixed(Shape::aabb(vi(4096, 16))).position(vi(0, -32700)),
        // 1: at 4000 units/s toward x = +32768, 768 units away.
        BodyDef::dynamic(Shape::circle(r(1, 2)))
            .position(vi(32000, 0))
            .velocity(vi(4000, 0))
            .gravity_scale(n(0)),
        // 2: toward the bottom-left corner.
        BodyDef::dynamic(Shape::aabb(vi(1, 1)))
            .position(vi(-32000, -32000))
            .velocity(vi(-4000, -4000))
            .gravity_scale(n(0)),
        // 3: at max speed, 68 units under the top bound.
        BodyDef::dynamic(Shape::circle(n(1)))
            .position(vi(0, 32700))
            .velocity(vi(0, 4096)),
        // 4 and 5: the heaviest and the lightest body, head on at 8000.
        BodyDef::dynamic(Shape::aabb(vi(2, 2)))
            .position(vi(30000, 100))
            .velocity(vi(-4000, 0))
            .mass(heavy)
            .gravity_scale(n(0)),
        BodyDef::dynamic(Shape::circle(r(1, 4)))
            .position(vi(29000, 100))
            .velocity(vi(4000, 0))
            .mass(tiny)
            .gravity_scale(n(0)),
        // 6: 1000 g of gravity: clamped to max_speed, lands on body 0.
        BodyDef::dynamic(Shape::circle(n(1)))
            .position(vi(1000, 30000))
            .gravity_scale(n(1000)),
        // 7: a bullet at max speed between a wall and the open world.
        BodyDef::dynamic(Shape::circle(r(1, 10)))
            .position(vi(0, -32600))
            .velocity(vi(4096, 0))
            .bullet(true)
            .restitution(n(1))
            .gravity_scale(n(0)),
        BodyDef::fixed(Shape::aabb(vf(r(1, 10), n(100)))).position(vi(3000, -32600)),
        // 9: on the stiffest, most damped radial spring to the far corner.
        BodyDef::dynamic(Shape::circle(r(1, 2)))
            .position(vi(20000, 20000))
            .gravity_scale(n(0)),
        // 10 and 11: a 2^24 bendy spring between opposite corners.
        BodyDef::dynamic(Shape::circle(r(1, 2))).position(vi(-32000, 32000)),
        BodyDef::dynamic(Shape::circle(r(1, 2))).position(vi(32000, -32000)),
        // 12: hanging on a long rope from the top-right corner.
        BodyDef::dynamic(Shape::circle(r(1, 2))).position(vi(32000, 32000)),
    ];
    let mut b = Vec::new();
    for def in defs {
        b.push(world.add_body(def)?);
    }
    let k = n(1 << 24);
    world.add_constraint(Constraint::radial_spring(
        Anchor::Point(vi(-32768, -32768)),
        Anchor::Body(nth(&b, 9)),
        n(0),
        k,
        k,
    ))?;
    world.add_constraint(Constraint::bendy_spring(
        Anchor::Body(nth(&b, 10)),
        Anchor::Body(nth(&b, 11)),
        vf(k, k),
        n(0),
    ))?;
    world.add_constraint(Constraint::rope(
        Anchor::Point(vi(32768, 32768)),
        Anchor::Body(nth(&b, 12)),
        n(2000),
    ))?;
    Ok((world, Box::new(Bounds { b })))
}
