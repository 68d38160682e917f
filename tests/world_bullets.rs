//! Bullets (issue 3): a circle of radius 0.05 at 1000 units/s never passes
//! through a fixed wall 0.1 thick, nor through a thin free dynamic box.
//!
//! Gravity is **off** in every scene here (the shot is then a straight line
//! and "the near side" is a fixed half-plane; with gravity on the bullet
//! drops only g·t²/2 ≈ 0.0014 over the 1/60 s of flight anyway).
//!
//! At 1000 units/s and 60 Hz the bullet moves 16.7 units per step, 167
//! times its diameter and 167 times the wall's thickness: without
//! continuous collision nothing stops it from jumping over. The check is
//! made after **every** step: the bullet's centre must be strictly on the
//! near side of the obstacle's near face (a centre past the near face is
//! inside or beyond a 0.1 thick obstacle, i.e. through it). The same shots
//! without the bullet flag are run and only reported.

mod common;

use clockwork2d::prelude::*;

const SPEED: f64 = 1000.0;
const RADIUS: f64 = 0.05;
/// Half thickness of the wall and of the thin box (0.1 thick).
const HALF_THICKNESS: f64 = 0.05;

fn zero_gravity() -> World {
    World::new(WorldSettings {
        gravity: Vec2::ZERO,
        ..WorldSettings::default()
    })
}

/// What happened to one shot.
struct Shot {
    /// Largest `centre - near face` over the run along the shot's x axis
    /// (negative: the centre stayed that far in front of the face).
    worst_centre_past_face: f64,
    /// Largest overlap of the bullet's surface with the near face.
    max_surface_penetration: f64,
    /// The first tick at which the centre was past the near face, if any.
    passed_at: Option<u64>,
    /// Bullet x at the end.
    final_x: f64,
}

/// Fires a bullet from `start` with `velocity` at `target` for `ticks`
/// ticks, checking after each step that the bullet's centre is in front of
/// the target's near (left) face, `target.x - HALF_THICKNESS`.
fn fire(
    world: &mut World,
    target: BodyId,
    start: Vec2,
    velocity: Vec2,
    bullet: bool,
    ticks: u32,
) -> Shot {
    let b = world
        .add_body(
            BodyDef::dynamic(Shape::circle(fx(RADIUS)))
                .position(start)
                .velocity(velocity)
                .bullet(bullet),
        )
        .unwrap();
    let mut shot = Shot {
        worst_centre_past_face: f64::NEG_INFINITY,
        max_surface_penetration: 0.0,
        passed_at: None,
        final_x: 0.0,
    };
    for _ in 0..ticks {
        world.step();
        let x = world.body(b).unwrap().position().x.to_f64();
        let face = world.body(target).unwrap().position().x.to_f64() - HALF_THICKNESS;
        let past = x - face;
        shot.worst_centre_past_face = shot.worst_centre_past_face.max(past);
        shot.max_surface_penetration = shot.max_surface_penetration.max(past + RADIUS);
        if past >= 0.0 && shot.passed_at.is_none() {
            shot.passed_at = Some(world.tick());
        }
        shot.final_x = x;
    }
    shot
}

fn wall_scene() -> (World, BodyId) {
    let mut world = zero_gravity();
    // Near face at x = 49.95, 3 steps of flight away; 0.1 thick, 40 tall.
    let wall = world
        .add_body(BodyDef::fixed(Shape::aabb(vec2(HALF_THICKNESS, 20.0))).position(vec2(50.0, 0.0)))
        .unwrap();
    (world, wall)
}

fn thin_box_scene() -> (World, BodyId) {
    let mut world = zero_gravity();
    // A free 0.1 × 2 box (mass 0.2), at rest, near face at x = 49.95.
    let thin = world
        .add_body(
            BodyDef::dynamic(Shape::aabb(vec2(HALF_THICKNESS, 1.0))).position(vec2(50.0, 0.0)),
        )
        .unwrap();
    (world, thin)
}

/// The shots: straight along +x, and along the 3-4-5 direction (speed
/// exactly 1000: (800, 600)), aimed so it hits the obstacle at y ≈ 0.5.
fn shots() -> [(&'static str, Vec2, Vec2); 2] {
    [
        ("straight", vec2(0.0, 0.0), vec2(SPEED, 0.0)),
        (
            "angled 3-4-5",
            vec2(0.0, 0.5 - 50.0 * 0.75),
            vec2(800.0, 600.0),
        ),
    ]
}

#[test]
fn bullet_never_passes_a_fixed_wall() {
    for (name, start, velocity) in shots() {
        let (mut world, wall) = wall_scene();
        let shot = fire(&mut world, wall, start, velocity, true, 120);
        println!(
            "bullet vs wall ({name}): centre stays {:.6} in front of the near face (surface penetration {:.6}), final x {:.4}",
            -shot.worst_centre_past_face, shot.max_surface_penetration, shot.final_x
        );
        assert!(
            shot.passed_at.is_none(),
            "{name}: bullet centre past the wall's near face at tick {:?} (by {})",
            shot.passed_at,
            shot.worst_centre_past_face
        );
    }
}

#[test]
fn bullet_never_passes_a_thin_dynamic_box() {
    for (name, start, velocity) in shots() {
        let (mut world, thin) = thin_box_scene();
        let shot = fire(&mut world, thin, start, velocity, true, 120);
        let box_v = world.body(thin).unwrap().velocity().to_f64();
        println!(
            "bullet vs thin box ({name}): centre stays {:.6} in front of the box's near face (surface penetration {:.6}); box velocity after ({:.3}, {:.3})",
            -shot.worst_centre_past_face, shot.max_surface_penetration, box_v.0, box_v.1
        );
        assert!(
            shot.passed_at.is_none(),
            "{name}: bullet centre past the box's near face at tick {:?} (by {})",
            shot.passed_at,
            shot.worst_centre_past_face
        );
        // Momentum went into the box: it moves away from the shooter. (The
        // bullet's momentum is 1000 · π·0.05² ≈ 7.85; the box has mass 0.2.)
        assert!(box_v.0 > 0.0, "{name}: the box was not pushed");
    }
}

#[test]
fn without_the_bullet_flag_report_only() {
    for (name, start, velocity) in shots() {
        let (mut world, wall) = wall_scene();
        let shot = fire(&mut world, wall, start, velocity, false, 120);
        println!(
            "non-bullet vs wall ({name}): tunnels {} (first past the face at tick {:?}), final x {:.4}",
            shot.passed_at.is_some(),
            shot.passed_at,
            shot.final_x
        );
        let (mut world, thin) = thin_box_scene();
        let shot = fire(&mut world, thin, start, velocity, false, 120);
        println!(
            "non-bullet vs thin box ({name}): tunnels {} (first past the face at tick {:?}), final x {:.4}",
            shot.passed_at.is_some(),
            shot.passed_at,
            shot.final_x
        );
    }
}
