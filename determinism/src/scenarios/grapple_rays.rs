//! The `grapple_rays` scenario: scripted grapple (ray cast, attach rope,
//! swing, release) and ray / box / point queries.

use super::*;

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

pub(crate) fn grapple_rays() -> Built {
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
