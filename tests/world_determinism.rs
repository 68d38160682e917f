//! Determinism (issue 3): the same scene with the same commands, run twice,
//! gives the same state hash after every tick. Three scenes: the 10-box
//! stack, the 20-row pyramid, and a mixed scene of circles and boxes with
//! commands of every kind applied mid-run.
//!
//! Both runs happen in this process, so this checks that the engine has no
//! hidden nondeterminism (hash-map iteration order, addresses, uninitialised
//! or leftover scratch state, time): everything that decides a step is in
//! the world's state. Cross-machine identity is the golden-hash tests' job.
//! A third world is cloned from the first mid-run and must continue in step
//! with it (a clone carries the whole state).

mod common;

use clockwork2d::prelude::*;
use common::{Rng, add_ground, add_pyramid, add_stack};

/// A scene: how to build the world, and the commands for each tick.
trait Scene {
    fn build(&mut self) -> World;
    fn commands(&mut self, _tick: u64, _world: &World) -> Vec<Command> {
        Vec::new()
    }
}

/// Runs the scene twice side by side for `ticks`, comparing hashes, command
/// results and events after every tick; clones run A after tick `ticks / 3`
/// and steps the clone with A's commands, checking it too. Returns the
/// final hash.
fn run_twice<S: Scene>(name: &str, mut a_scene: S, mut b_scene: S, ticks: u64) -> u64 {
    let mut a = a_scene.build();
    let mut b = b_scene.build();
    assert_eq!(
        a.state_hash(),
        b.state_hash(),
        "{name}: hashes differ before the first step"
    );
    let mut clone: Option<World> = None;
    let (mut applied, mut refused) = (0usize, 0usize);
    for tick in 0..ticks {
        let ca = a_scene.commands(tick, &a);
        let cb = b_scene.commands(tick, &b);
        assert_eq!(
            ca, cb,
            "{name}: the scene produced different commands at tick {tick}"
        );
        let ra = a.step_with(&ca);
        let rb = b.step_with(&cb);
        applied += ra.iter().filter(|r| r.is_ok()).count();
        refused += ra.iter().filter(|r| r.is_err()).count();
        assert_eq!(
            ra,
            rb,
            "{name}: command results differ at tick {}",
            a.tick()
        );
        assert_eq!(
            a.events(),
            b.events(),
            "{name}: events differ at tick {}",
            a.tick()
        );
        let (ha, hb) = (a.state_hash(), b.state_hash());
        assert_eq!(ha, hb, "{name}: state hashes differ at tick {}", a.tick());
        if let Some(c) = clone.as_mut() {
            // The clone gets the commands run A got (ids are identical).
            c.step_with(&ca);
            assert_eq!(
                c.state_hash(),
                ha,
                "{name}: the clone diverged at tick {}",
                a.tick()
            );
        }
        if tick == ticks / 3 {
            clone = Some(a.clone());
        }
    }
    let h = a.state_hash();
    println!(
        "determinism: {name}: {ticks} ticks identical ({applied} commands applied, {refused} refused), final hash {h:#018x}"
    );
    h
}

#[derive(Clone)]
struct Stack;

impl Scene for Stack {
    fn build(&mut self) -> World {
        let mut w = World::new(WorldSettings::default());
        add_ground(&mut w);
        add_stack(&mut w, 10, 0.05);
        w
    }
}

#[derive(Clone)]
struct Pyramid;

impl Scene for Pyramid {
    fn build(&mut self) -> World {
        let mut w = World::new(WorldSettings::default());
        add_ground(&mut w);
        add_pyramid(&mut w, 20, 1.05);
        w
    }
}

/// 60 circles and 40 boxes of assorted sizes dropped into a walled pit with
/// a kinematic platform, and a command schedule exercising every command:
/// impulses, velocities (also on the platform), spawns, despawns (of
/// spawned and original bodies, so slots get reused), teleports, wakes, and
/// commands that are refused (stale ids, fixed bodies).
#[derive(Clone)]
struct Mixed {
    rng: Rng,
    dynamic: Vec<BodyId>,
    platform: Option<BodyId>,
    ground: Option<BodyId>,
    removed: Vec<BodyId>,
}

impl Mixed {
    fn new() -> Self {
        Mixed {
            rng: Rng(0xd37e_4a11),
            dynamic: Vec::new(),
            platform: None,
            ground: None,
            removed: Vec::new(),
        }
    }

    fn pick(&mut self) -> BodyId {
        let k = (self.rng.next_u64() % self.dynamic.len() as u64) as usize;
        self.dynamic[k]
    }
}

impl Scene for Mixed {
    fn build(&mut self) -> World {
        let mut w = World::new(WorldSettings::default());
        self.ground = Some(add_ground(&mut w));
        for x in [-12.0, 12.0] {
            w.add_body(BodyDef::fixed(Shape::aabb(vec2(0.5, 10.0))).position(vec2(x, 10.0)))
                .unwrap();
        }
        self.platform = Some(
            w.add_body(BodyDef::kinematic(Shape::aabb(vec2(2.0, 0.25))).position(vec2(0.0, 6.0)))
                .unwrap(),
        );
        for k in 0..100 {
            let x = self.rng.range(-10.0, 10.0);
            let y = self.rng.range(8.0, 30.0);
            let def = if k % 5 < 3 {
                BodyDef::dynamic(Shape::circle(fx(self.rng.range(0.15, 0.5))))
                    .restitution(fx(self.rng.range(0.0, 0.6)))
            } else {
                BodyDef::dynamic(Shape::aabb(vec2(
                    self.rng.range(0.2, 0.6),
                    self.rng.range(0.2, 0.6),
                )))
                .friction(fx(self.rng.range(0.1, 0.9)))
            };
            self.dynamic
                .push(w.add_body(def.position(vec2(x, y))).unwrap());
        }
        w
    }

    fn commands(&mut self, tick: u64, world: &World) -> Vec<Command> {
        let mut out = Vec::new();
        let platform = self.platform.unwrap();
        // The platform oscillates: 1.5 units/s, reversing every second.
        if tick.is_multiple_of(60) {
            let s = if (tick / 60).is_multiple_of(2) {
                1.5
            } else {
                -1.5
            };
            out.push(Command::SetVelocity {
                body: platform,
                velocity: vec2(s, 0.0),
            });
        }
        match tick % 50 {
            7 => {
                let body = self.pick();
                let impulse = vec2(self.rng.range(-3.0, 3.0), self.rng.range(0.0, 6.0));
                out.push(Command::ApplyImpulse { body, impulse });
            }
            13 => {
                let body = self.pick();
                out.push(Command::SetVelocity {
                    body,
                    velocity: vec2(self.rng.range(-4.0, 4.0), 2.0),
                });
            }
            21 => {
                let def = BodyDef::dynamic(Shape::circle(fx(0.3)))
                    .position(vec2(self.rng.range(-8.0, 8.0), 25.0));
                out.push(Command::Spawn(def));
            }
            29 if self.dynamic.len() > 20 => {
                let k = (self.rng.next_u64() % self.dynamic.len() as u64) as usize;
                let body = self.dynamic.remove(k);
                self.removed.push(body);
                out.push(Command::Despawn(body));
            }
            37 => {
                let body = self.pick();
                out.push(Command::SetPosition {
                    body,
                    position: vec2(self.rng.range(-9.0, 9.0), 20.0),
                });
                out.push(Command::Wake(self.pick()));
            }
            43 => {
                // Refused commands: a stale id and an impulse on a fixed body.
                if let Some(&stale) = self.removed.last() {
                    out.push(Command::Wake(stale));
                }
                out.push(Command::ApplyImpulse {
                    body: self.ground.unwrap(),
                    impulse: vec2(1.0, 0.0),
                });
            }
            _ => {}
        }
        // Spawned ids are learnt from the world (deterministic too): every
        // live dynamic body not yet known is added to the pool.
        for (id, body) in world.bodies() {
            if body.kind() == BodyKind::Dynamic
                && !self.dynamic.contains(&id)
                && !self.removed.contains(&id)
            {
                self.dynamic.push(id);
            }
        }
        out
    }
}

#[test]
fn stack_runs_identically_twice() {
    run_twice("stack", Stack, Stack, 600);
}

#[test]
fn pyramid_runs_identically_twice() {
    run_twice("pyramid", Pyramid, Pyramid, 600);
}

#[test]
fn mixed_scene_with_commands_runs_identically_twice() {
    run_twice("mixed", Mixed::new(), Mixed::new(), 900);
}
