//! The structured input of the `world_commands` target: world settings and
//! a stream of commands, steps and restore checkpoints, with hostile values
//! and stale ids mixed in; and [`run`], which plays it and checks the
//! engine's invariants as it goes.
//!
//! # Invariants checked
//!
//! * Settings: `World::try_new` refuses exactly the settings that
//!   `validate` refuses (with a typed error), and accepts the rest.
//! * After every command: a refused command left the world unchanged (its
//!   snapshot bytes are identical to those before the command).
//! * After every step: every body that is not frozen has its centre inside
//!   the world bounds, and every body frozen during the step has its
//!   `Frozen` event in that step; no body's velocity has a component above
//!   `max_speed`.
//! * After every step: no overlap deeper than the documented bound persists
//!   between a dynamic and a fixed body (see [`crate::overlap`]).
//! * At the script's restore points, the world is snapshotted and restored
//!   into a copy (the round trip must give the same hash and bytes), and the
//!   copy replays every later command and step alongside: the same command
//!   results and the same state hash after every step, to the end.

use arbitrary::{Arbitrary, Unstructured};
use clockwork2d::prelude::*;

use crate::numbers::{FuzzFx, FuzzVec, SmallVec};
use crate::overlap::OverlapWatch;
use crate::roundtrip::assert_roundtrip;

/// Most operations played from one input.
pub const MAX_OPS: usize = 200;
/// Most steps played from one input (bounds the time per input).
pub const MAX_STEPS: u32 = 240;
/// Most live bodies (spawns beyond are skipped).
pub const MAX_BODIES: usize = 24;
/// Most restored copies running alongside the original.
pub const MAX_COPIES: usize = 2;

/// Settings as the fuzzer gives them. The raw values go through
/// `World::try_new` / `World::new` (anything at all); the world that is
/// stepped uses them clamped to a cost the fuzzer can afford (iterations
/// and substeps bounded), every field still inside its documented range.
#[derive(Arbitrary, Debug, Clone)]
pub struct SettingsInput {
    /// Gravity (physical range).
    pub gravity: SmallVec,
    /// Index into [`DTS`], or any value.
    pub dt: Choice<FuzzFx>,
    /// Solver iterations (stepped world: 1..=16).
    pub velocity_iterations: u8,
    /// Position iterations (stepped world: 0..=8).
    pub position_iterations: u8,
    /// Substeps (stepped world: 1..=4).
    pub substeps: u8,
    /// Sleeping on or off.
    pub sleep_enabled: bool,
    /// Optional overrides of the other fields (default when `None`).
    pub sleep_linear_threshold: Option<FuzzFx>,
    /// As above.
    pub time_to_sleep: Option<FuzzFx>,
    /// As above.
    pub restitution_threshold: Option<FuzzFx>,
    /// As above.
    pub linear_slop: Option<FuzzFx>,
    /// As above.
    pub position_correction: Option<FuzzFx>,
    /// As above.
    pub max_correction: Option<FuzzFx>,
    /// As above.
    pub speculative_margin: Option<FuzzFx>,
    /// As above.
    pub max_speed: Option<FuzzFx>,
    /// Bounds: centre and half extents (small values: bodies reach them).
    pub bounds: Option<(SmallVec, SmallVec)>,
}

/// Time steps of the stepped world (seconds).
pub const DTS: [(i32, i32); 5] = [(1, 60), (1, 30), (1, 120), (1, 240), (1, 10)];

/// Either an index into a table of sensible values or a raw value.
#[derive(Arbitrary, Debug, Clone, Copy)]
pub enum Choice<T> {
    /// The table entry `index % len`.
    Table(u8),
    /// A raw value.
    Raw(T),
}

/// A body reference: one issued before (live or stale), or raw parts.
#[derive(Arbitrary, Debug, Clone, Copy)]
pub enum IdRef {
    /// The `n % count`-th body id ever issued in this run.
    Issued(u8),
    /// Any index and generation.
    Raw(u32, u32),
}

/// A constraint reference, like [`IdRef`].
#[derive(Arbitrary, Debug, Clone, Copy)]
pub enum ConstraintRef {
    /// The `n % count`-th constraint id ever issued in this run.
    Issued(u8),
    /// Any index and generation.
    Raw(u32, u32),
}

/// A shape: mostly small, sometimes any value.
#[derive(Arbitrary, Debug, Clone, Copy)]
pub enum ShapeInput {
    /// A circle of this radius.
    Circle(Size),
    /// A box of these half extents.
    Aabb(Size, Size),
}

/// A size: mostly 1/16..=4 units, sometimes any value.
#[derive(Arbitrary, Debug, Clone, Copy)]
pub enum Size {
    /// `(1 + n % 64) / 16` units.
    Small(u8),
    /// Any value (mostly refused).
    Raw(FuzzFx),
}

impl Size {
    fn get(self) -> Fx {
        match self {
            Size::Small(n) => Fx::from_ratio(1 + i32::from(n % 64), 16),
            Size::Raw(v) => v.0,
        }
    }
}

/// A body definition.
#[derive(Arbitrary, Debug, Clone, Copy)]
pub struct BodyInput {
    /// 0 fixed, 1 kinematic, otherwise dynamic.
    pub kind: u8,
    /// The shape.
    pub shape: ShapeInput,
    /// Position: small or any.
    pub position: Choice<FuzzVec>,
    /// Velocity.
    pub velocity: Option<FuzzVec>,
    /// Mass or density (true = mass).
    pub mass: Option<(bool, FuzzFx)>,
    /// Restitution.
    pub restitution: Option<FuzzFx>,
    /// Friction.
    pub friction: Option<FuzzFx>,
    /// Gravity scale.
    pub gravity_scale: Option<FuzzFx>,
    /// Bullet flag.
    pub bullet: bool,
}

/// An anchor of a constraint.
#[derive(Arbitrary, Debug, Clone, Copy)]
pub enum AnchorInput {
    /// A world point.
    Point(SmallVec),
    /// A body's centre.
    Body(IdRef),
    /// A point fixed to a body.
    BodyOffset(IdRef, FuzzVec),
}

/// A constraint definition.
#[derive(Arbitrary, Debug, Clone, Copy)]
pub enum ConstraintInput {
    /// A bendy spring.
    Bendy(AnchorInput, AnchorInput, FuzzVec, FuzzFx, Option<FuzzVec>),
    /// A radial spring.
    Radial(AnchorInput, AnchorInput, FuzzFx, FuzzFx, FuzzFx),
    /// A rope.
    Rope(AnchorInput, AnchorInput, FuzzFx, Option<FuzzFx>),
}

/// One operation of the script.
#[derive(Arbitrary, Debug, Clone)]
pub enum Op {
    /// `Command::Spawn`.
    Spawn(BodyInput),
    /// `Command::Despawn`.
    Despawn(IdRef),
    /// `Command::ApplyImpulse`.
    Impulse(IdRef, FuzzVec),
    /// `Command::SetVelocity`.
    Velocity(IdRef, FuzzVec),
    /// `Command::SetPosition` (a teleport).
    Teleport(IdRef, Choice<FuzzVec>),
    /// `Command::Wake`.
    Wake(IdRef),
    /// `Command::AddConstraint`.
    AddConstraint(ConstraintInput),
    /// `Command::RemoveConstraint`.
    RemoveConstraint(ConstraintRef),
    /// `1 + n % 16` steps.
    Step(u8),
    /// A snapshot → restore copy that runs alongside from here on.
    Restore,
}

/// A whole input.
#[derive(Debug, Clone)]
pub struct Script {
    /// The world's settings.
    pub settings: SettingsInput,
    /// The operations, at most [`MAX_OPS`].
    pub ops: Vec<Op>,
}

impl<'a> Arbitrary<'a> for Script {
    fn arbitrary(u: &mut Unstructured<'a>) -> arbitrary::Result<Self> {
        let settings = u.arbitrary()?;
        let mut ops = Vec::new();
        while ops.len() < MAX_OPS && !u.is_empty() {
            ops.push(u.arbitrary()?);
        }
        Ok(Script { settings, ops })
    }
}

impl SettingsInput {
    /// The settings exactly as given (possibly invalid).
    #[must_use]
    pub fn raw(&self) -> WorldSettings<Fx> {
        let d = WorldSettings::<Fx>::default();
        let pick = |v: Option<FuzzFx>, default: Fx| v.map_or(default, |v| v.0);
        WorldSettings {
            gravity: self.gravity.get(),
            dt: match self.dt {
                Choice::Table(i) => {
                    let (n, m) = DTS[usize::from(i) % DTS.len()];
                    Fx::from_ratio(n, m)
                }
                Choice::Raw(v) => v.0,
            },
            velocity_iterations: u32::from(self.velocity_iterations),
            position_iterations: u32::from(self.position_iterations),
            substeps: u32::from(self.substeps),
            sleep_enabled: self.sleep_enabled,
            sleep_linear_threshold: pick(self.sleep_linear_threshold, d.sleep_linear_threshold),
            time_to_sleep: pick(self.time_to_sleep, d.time_to_sleep),
            restitution_threshold: pick(self.restitution_threshold, d.restitution_threshold),
            linear_slop: pick(self.linear_slop, d.linear_slop),
            position_correction: pick(self.position_correction, d.position_correction),
            max_correction: pick(self.max_correction, d.max_correction),
            speculative_margin: pick(self.speculative_margin, d.speculative_margin),
            max_speed: pick(self.max_speed, d.max_speed),
            bounds: self.bounds.map_or(d.bounds, |(c, h)| {
                Aabb::new(c.get(), Vec2::new(h.0.0.abs(), h.1.0.abs()))
            }),
        }
    }

    /// The settings of the stepped world: the raw ones with the work per
    /// step bounded, and every field that would make them invalid replaced
    /// by its default (see [`repair`]).
    #[must_use]
    pub fn affordable(&self) -> WorldSettings<Fx> {
        let mut s = self.raw();
        s.velocity_iterations = 1 + u32::from(self.velocity_iterations % 16);
        s.position_iterations = u32::from(self.position_iterations % 9);
        s.substeps = 1 + u32::from(self.substeps % 4);
        if let Choice::Raw(_) = self.dt {
            // Any valid dt, but not so small that nothing happens: at least
            // 1/1024 s.
            if s.dt < Fx::from_ratio(1, 1024) {
                s.dt = Fx::from_ratio(1, 60);
            }
        }
        repair(s)
    }
}

/// `wanted` with every field that makes it invalid replaced by the default:
/// starting from the (valid) defaults, each field in turn takes the wanted
/// value if the settings stay valid. Deterministic, and the result always
/// validates (`World::new` refuses invalid settings with a panic).
#[must_use]
pub fn repair(wanted: WorldSettings<Fx>) -> WorldSettings<Fx> {
    type Setter = fn(&mut WorldSettings<Fx>, &WorldSettings<Fx>);
    const FIELDS: [Setter; 15] = [
        |s, w| s.gravity = w.gravity,
        |s, w| s.dt = w.dt,
        |s, w| s.velocity_iterations = w.velocity_iterations,
        |s, w| s.position_iterations = w.position_iterations,
        |s, w| s.substeps = w.substeps,
        |s, w| s.sleep_enabled = w.sleep_enabled,
        |s, w| s.sleep_linear_threshold = w.sleep_linear_threshold,
        |s, w| s.time_to_sleep = w.time_to_sleep,
        |s, w| s.restitution_threshold = w.restitution_threshold,
        |s, w| s.linear_slop = w.linear_slop,
        |s, w| s.position_correction = w.position_correction,
        |s, w| s.max_correction = w.max_correction,
        |s, w| s.speculative_margin = w.speculative_margin,
        |s, w| s.max_speed = w.max_speed,
        |s, w| s.bounds = w.bounds,
    ];
    let mut settings = WorldSettings::<Fx>::default();
    for set in FIELDS {
        let mut candidate = settings;
        set(&mut candidate, &wanted);
        if candidate.validate().is_ok() {
            settings = candidate;
        }
    }
    settings
}

/// Everything a run needs to remember.
struct Run {
    world: World<Fx>,
    copies: Vec<World<Fx>>,
    bodies: Vec<BodyId>,
    constraints: Vec<ConstraintId>,
    overlap: OverlapWatch,
    steps: u32,
}

impl Run {
    fn body(&self, r: IdRef) -> BodyId {
        match r {
            IdRef::Issued(n) if !self.bodies.is_empty() => {
                self.bodies[usize::from(n) % self.bodies.len()]
            }
            IdRef::Issued(n) => BodyId::from_parts(u32::from(n), 0),
            IdRef::Raw(i, g) => BodyId::from_parts(i, g),
        }
    }

    fn constraint(&self, r: ConstraintRef) -> ConstraintId {
        match r {
            ConstraintRef::Issued(n) if !self.constraints.is_empty() => {
                self.constraints[usize::from(n) % self.constraints.len()]
            }
            ConstraintRef::Issued(n) => ConstraintId::from_parts(u32::from(n), 0),
            ConstraintRef::Raw(i, g) => ConstraintId::from_parts(i, g),
        }
    }

    fn anchor(&self, a: AnchorInput) -> Anchor<Fx> {
        match a {
            AnchorInput::Point(p) => Anchor::Point(p.get()),
            AnchorInput::Body(r) => Anchor::Body(self.body(r)),
            AnchorInput::BodyOffset(r, o) => Anchor::BodyOffset(self.body(r), o.get()),
        }
    }

    fn body_def(b: &BodyInput) -> BodyDef<Fx> {
        let shape = match b.shape {
            ShapeInput::Circle(r) => Shape::circle(r.get()),
            ShapeInput::Aabb(x, y) => Shape::aabb(Vec2::new(x.get(), y.get())),
        };
        let mut def = match b.kind % 8 {
            0 => BodyDef::fixed(shape),
            1 => BodyDef::kinematic(shape),
            _ => BodyDef::dynamic(shape),
        };
        def = def.position(match b.position {
            // Within ±8 units of the origin, on a 1/32 grid.
            Choice::Table(n) => {
                let x = i32::from(n % 16) - 8;
                let y = i32::from(n / 16) - 8;
                Vec2::new(Fx::from_int(x), Fx::from_int(y)) + Vec2::new(fx(0.5), fx(0.25))
            }
            Choice::Raw(v) => v.get(),
        });
        if let Some(v) = b.velocity {
            def = def.velocity(v.get());
        }
        if let Some((is_mass, m)) = b.mass {
            def = if is_mass {
                def.mass(m.0)
            } else {
                def.density(m.0)
            };
        }
        if let Some(e) = b.restitution {
            def = def.restitution(e.0);
        }
        if let Some(f) = b.friction {
            def = def.friction(f.0);
        }
        if let Some(g) = b.gravity_scale {
            def = def.gravity_scale(g.0);
        }
        def.bullet(b.bullet)
    }

    fn command(&self, op: &Op) -> Option<Command<Fx>> {
        Some(match op {
            Op::Spawn(b) => Command::Spawn(Self::body_def(b)),
            Op::Despawn(r) => Command::Despawn(self.body(*r)),
            Op::Impulse(r, j) => Command::ApplyImpulse {
                body: self.body(*r),
                impulse: j.get(),
            },
            Op::Velocity(r, v) => Command::SetVelocity {
                body: self.body(*r),
                velocity: v.get(),
            },
            Op::Teleport(r, p) => Command::SetPosition {
                body: self.body(*r),
                position: match p {
                    Choice::Table(n) => {
                        let x = i32::from(n % 16) - 8;
                        let y = i32::from(n / 16) - 8;
                        Vec2::new(Fx::from_int(x), Fx::from_int(y))
                    }
                    Choice::Raw(v) => v.get(),
                },
            },
            Op::Wake(r) => Command::Wake(self.body(*r)),
            Op::AddConstraint(c) => Command::AddConstraint(match *c {
                ConstraintInput::Bendy(a, b, k, c, offset) => {
                    let s = Constraint::bendy_spring(self.anchor(a), self.anchor(b), k.get(), c.0);
                    match offset {
                        Some(o) => s.with_rest_offset(o.get()),
                        None => s,
                    }
                }
                ConstraintInput::Radial(a, b, l, k, c) => {
                    Constraint::radial_spring(self.anchor(a), self.anchor(b), l.0, k.0, c.0)
                }
                ConstraintInput::Rope(a, b, l, e) => {
                    let r = Constraint::rope(self.anchor(a), self.anchor(b), l.0);
                    match e {
                        Some(e) => r.with_restitution(e.0),
                        None => r,
                    }
                }
            }),
            Op::RemoveConstraint(r) => Command::RemoveConstraint(self.constraint(*r)),
            Op::Step(_) | Op::Restore => return None,
        })
    }

    fn apply(&mut self, command: Command<Fx>) {
        if matches!(command, Command::Spawn(_)) && self.world.body_count() >= MAX_BODIES {
            return;
        }
        let before = self.world.snapshot();
        let result = self.world.apply(command.clone());
        match &result {
            Ok(CommandOutcome::Spawned(id)) => self.bodies.push(*id),
            Ok(CommandOutcome::ConstraintAdded(id)) => self.constraints.push(*id),
            Ok(CommandOutcome::Applied) => {}
            Err(e) => {
                assert!(
                    self.world.snapshot() == before,
                    "refused command {command:?} ({e}) changed the world"
                );
            }
        }
        self.overlap.command_applied(&command, &result);
        for (i, copy) in self.copies.iter_mut().enumerate() {
            let copied = copy.apply(command.clone());
            assert_eq!(
                copied, result,
                "restored copy {i} answered {command:?} differently"
            );
        }
    }

    fn step(&mut self) {
        let frozen_before: Vec<BodyId> = self
            .world
            .bodies()
            .filter(|(_, b)| b.is_frozen())
            .map(|(id, _)| id)
            .collect();
        self.world.step();
        self.steps += 1;
        let bounds = self.world.settings().bounds;
        let max_speed = self.world.settings().max_speed;
        for (id, b) in self.world.bodies() {
            let v = b.velocity();
            assert!(
                v.x.abs() <= max_speed && v.y.abs() <= max_speed,
                "{id} left tick {} at {v:?}, above max_speed {max_speed}",
                self.world.tick()
            );
            if b.is_frozen() {
                if !frozen_before.contains(&id) {
                    assert!(
                        self.world.events().contains(&Event::Frozen(id)),
                        "{id} was frozen at tick {} without a Frozen event",
                        self.world.tick()
                    );
                }
            } else {
                assert!(
                    bounds.contains_point(b.position()),
                    "{id} is outside the world bounds and not frozen at tick {}: {:?}",
                    self.world.tick(),
                    b.position()
                );
            }
        }
        self.overlap.after_step(&self.world);
        let hash = self.world.state_hash();
        for (i, copy) in self.copies.iter_mut().enumerate() {
            copy.step();
            assert_eq!(
                copy.state_hash(),
                hash,
                "restored copy {i} diverged at tick {}",
                self.world.tick()
            );
        }
    }
}

/// Plays a script and checks the invariants (see the module docs).
///
/// # Panics
/// On any violated invariant: that is the finding.
pub fn run(script: &Script) {
    let raw = script.settings.raw();
    match (World::<Fx>::try_new(raw), raw.validate()) {
        (Ok(world), Ok(())) => assert_eq!(world.settings(), &raw, "try_new changed settings"),
        (Err(made), Err(checked)) => assert_eq!(made, checked, "try_new and validate disagree"),
        (made, checked) => panic!(
            "try_new ({}) and validate ({checked:?}) disagree on {raw:?}",
            made.is_ok()
        ),
    }

    let world = World::<Fx>::new(script.settings.affordable());
    let overlap = OverlapWatch::new(world.settings());
    let mut run = Run {
        world,
        copies: Vec::new(),
        bodies: Vec::new(),
        constraints: Vec::new(),
        overlap,
        steps: 0,
    };
    for op in &script.ops {
        if run.steps >= MAX_STEPS {
            break;
        }
        match op {
            Op::Step(n) => {
                for _ in 0..=(n % 16) {
                    if run.steps >= MAX_STEPS {
                        break;
                    }
                    run.step();
                }
            }
            Op::Restore => {
                let copy = assert_roundtrip(&run.world, "restore point");
                if run.copies.len() < MAX_COPIES {
                    run.copies.push(copy);
                }
            }
            _ => {
                if let Some(command) = run.command(op) {
                    run.apply(command);
                }
            }
        }
    }
}
