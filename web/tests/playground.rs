//! The playground's Rust side, natively: what the page's clicks, drags and
//! keys do to the world, checked against the physics they should cause, and
//! the determinism panel's run against the recorder the CLI uses.
#![allow(clippy::float_arithmetic)] // reference values in f64

use clockwork2d::prelude::{Scalar, World};
use clockwork2d::replay::Recorder;
use clockwork2d_scene::{BUILTIN_SCENES, builtin, scripted_commands};
use clockwork2d_web::grapple::HEIGHT;
use clockwork2d_web::{
    BODY_STRIDE, CONSTRAINT_STRIDE, GRAPPLE_SCENE, Playground, PlaygroundError, determinism_hash,
    scene_names,
};

const G: f64 = 10.0;
const DT: f64 = 1.0 / 60.0;

fn steps(p: &mut Playground, n: u32) {
    for _ in 0..n {
        p.step();
    }
}

fn player(p: &Playground) -> (f64, f64, f64, f64) {
    let id = p.grapple().expect("grapple arena").player();
    let b = p.world().body(id).expect("player");
    let (x, y) = b.position().to_f64();
    let (vx, vy) = b.velocity().to_f64();
    (x, y, vx, vy)
}

#[test]
fn every_scene_is_offered_and_the_playground_adds_nothing_to_it() {
    let names = scene_names();
    assert_eq!(names.len(), BUILTIN_SCENES.len() + 1);
    assert_eq!(names.last().map(String::as_str), Some(GRAPPLE_SCENE));
    // Each built-in scene steps exactly like the library's own build of it
    // (the page sends no hidden commands).
    for (name, _) in BUILTIN_SCENES {
        let mut page = Playground::new(name).unwrap();
        let mut direct: World = builtin(name).unwrap().build().unwrap();
        for _ in 0..5 {
            page.step();
            direct.step();
        }
        assert_eq!(
            page.hash(),
            format!("0x{:016x}", direct.state_hash()),
            "{name}"
        );
        assert_eq!(page.tick(), 5);
    }
    assert!(matches!(
        Playground::new("no such scene"),
        Err(PlaygroundError::UnknownScene(_))
    ));
}

#[test]
fn the_determinism_run_is_what_the_cli_records() {
    // `clockwork2d record SCENE --seed S` drives a Recorder with the same
    // scripted input; its final hash is the number the page shows.
    let (scene, seed, ticks) = ("stack", 16_u32, 200_u32);
    let world: World = builtin(scene).unwrap().build().unwrap();
    let mut recorder = Recorder::new(world, ticks);
    for _ in 0..ticks {
        let commands = scripted_commands(recorder.world(), u64::from(seed));
        recorder.step_with(&commands);
    }
    let recorded = format!("0x{:016x}", recorder.finish().final_hash());
    assert_eq!(determinism_hash(scene, seed, ticks).unwrap(), recorded);
    // The input matters (else the comparison would prove little).
    assert_ne!(determinism_hash(scene, seed + 1, ticks).unwrap(), recorded);
    assert!(determinism_hash("nope", seed, ticks).is_err());
}

#[test]
fn a_dropped_ball_falls_freely_then_rests_on_the_ground() {
    let mut p = Playground::new("stack").unwrap();
    let count = p.body_count();
    assert_eq!(p.drop_body(5.0, 8.0, "ball").unwrap(), count + 1);
    let id = p.world().bodies().last().unwrap().0;
    let y = |p: &Playground| p.world().body(id).unwrap().position().y.to_f64();
    assert_eq!(y(&p), 8.0);
    // Semi-implicit Euler from rest: v_n = -n g dt, y_n = y_0 - g dt² n(n+1)/2.
    // After 30 ticks the ball (radius 0.4) is at 6.71, far above the ground.
    steps(&mut p, 30);
    let expected = 8.0 - G * DT * DT * 30.0 * 31.0 / 2.0;
    assert!((y(&p) - expected).abs() < 1e-6, "{} vs {expected}", y(&p));
    // Resting on the ground's top (y = 0): centre at its radius, within the
    // linear slop (1e-4) and the solver's residual.
    steps(&mut p, 300);
    assert!((y(&p) - 0.4).abs() < 2e-3, "{}", y(&p));
    // A box drops too.
    assert_eq!(p.drop_body(-5.0, 3.0, "box").unwrap(), count + 2);
}

#[test]
fn bad_drops_are_refused_and_change_nothing() {
    let mut p = Playground::new("stack").unwrap();
    steps(&mut p, 10);
    let (hash, count) = (p.hash(), p.body_count());
    for (x, y, shape) in [
        (f64::NAN, 1.0, "ball"),
        (1.0, f64::INFINITY, "ball"),
        (1e12, 1.0, "box"),
        // Inside the number range, outside the world bounds (±32768).
        (40_000.0, 1.0, "ball"),
        (1.0, 1.0, "triangle"),
    ] {
        let e = p.drop_body(x, y, shape).unwrap_err();
        assert!(!e.to_string().is_empty());
        assert_eq!((p.hash(), p.body_count()), (hash.clone(), count), "{e}");
    }
    assert!(p.push(f64::NAN, 0.0, 1.0, 1.0).is_err());
    assert!(p.push(0.0, 0.0, f64::NEG_INFINITY, 1.0).is_err());
    assert_eq!(p.hash(), hash);
}

#[test]
fn a_push_changes_the_velocity_by_what_the_drag_asked() {
    let mut p = Playground::new("stack").unwrap();
    steps(&mut p, 120);
    // The top box of the stack (the highest body).
    let (id, top) = p
        .world()
        .bodies()
        .map(|(id, b)| (id, b.position().to_f64()))
        .max_by(|a, b| a.1.1.total_cmp(&b.1.1))
        .unwrap();
    let before = p.world().body(id).unwrap().velocity().to_f64();
    assert!(p.push(top.0, top.1, 2.0, 1.5).unwrap());
    let after = p.world().body(id).unwrap().velocity().to_f64();
    // impulse = m·dv then Δv = impulse / m: exact up to a few ulps (2^-32).
    assert!((after.0 - before.0 - 2.0).abs() < 1e-8);
    assert!((after.1 - before.1 - 1.5).abs() < 1e-8);
    // Empty air and the fixed ground are not pushed; nothing changes.
    let hash = p.hash();
    assert!(!p.push(15.0, 10.0, 5.0, 5.0).unwrap());
    assert!(!p.push(15.0, -0.5, 5.0, 5.0).unwrap());
    assert_eq!(p.hash(), hash);
}

#[test]
fn a_shot_straight_up_hangs_a_rope_from_the_ceiling() {
    let mut p = Playground::new(GRAPPLE_SCENE).unwrap();
    steps(&mut p, 30);
    let (x, y, _, _) = player(&p);
    assert!(p.aim(x, y).unwrap().is_empty(), "no direction, no hit");
    let hit = p.aim(x, y + 1.0).unwrap();
    assert!(p.fire(x, y + 1.0).unwrap());
    let rope = p.grapple().unwrap().rope().unwrap();
    let (ax, ay) = rope.anchor.to_f64();
    // Nothing hangs over the start: the ray meets the ceiling's underside.
    let ceiling = f64::from(HEIGHT);
    assert!(
        (ax - x).abs() < 1e-8 && (ay - ceiling).abs() < 1e-8,
        "({ax}, {ay})"
    );
    assert!((rope.length.to_f64() - (ceiling - y)).abs() < 1e-8);
    assert_eq!(hit, vec![ax as f32, ay as f32]);
    assert_eq!(p.constraint_count(), 1);
    assert_eq!(p.grapple_state().len(), 5);
}

#[test]
fn reeling_moves_a_tenth_per_tick_within_its_limits() {
    let mut p = Playground::new(GRAPPLE_SCENE).unwrap();
    steps(&mut p, 30);
    let (x, y, _, _) = player(&p);
    assert!(p.fire(x, y + 1.0).unwrap());
    let length = |p: &Playground| p.grapple().unwrap().rope().unwrap().length.to_f64();
    let start = length(&p);
    p.set_controls(false, false, true, false).unwrap();
    steps(&mut p, 10);
    assert!((start - length(&p) - 1.0).abs() < 1e-8);
    p.set_controls(false, false, false, true).unwrap();
    steps(&mut p, 4);
    assert!((start - length(&p) - 0.6).abs() < 1e-8);
    // Reeled all the way in: the rope stops at half a unit and still holds
    // (one rope, the player hangs within its length).
    p.set_controls(false, false, true, false).unwrap();
    steps(&mut p, 400);
    assert_eq!(length(&p), 0.5);
    assert_eq!(p.constraint_count(), 1);
    steps(&mut p, 60);
    let (px, py, _, _) = player(&p);
    let rope = p.grapple().unwrap().rope().unwrap();
    let (ax, ay) = rope.anchor.to_f64();
    assert!(((px - ax).hypot(py - ay) - 0.5).abs() < 0.01);
}

#[test]
fn the_rope_holds_a_swinging_player_and_letting_go_is_free_fall() {
    let mut p = Playground::new(GRAPPLE_SCENE).unwrap();
    steps(&mut p, 30);
    let (x, y, _, _) = player(&p);
    // Up and to the right: the ledge or the ceiling.
    assert!(p.fire(x + 3.0, y + 6.0).unwrap());
    p.set_controls(false, true, true, false).unwrap();
    steps(&mut p, 40);
    p.set_controls(false, true, false, false).unwrap();
    let rope = p.grapple().unwrap().rope().unwrap();
    let (ax, ay) = rope.anchor.to_f64();
    let length = rope.length.to_f64();
    let mut farthest = 0.0_f64;
    let mut lowest_speed = f64::INFINITY;
    for _ in 0..120 {
        p.step();
        let (px, py, vx, vy) = player(&p);
        farthest = farthest.max((px - ax).hypot(py - ay));
        lowest_speed = lowest_speed.min(vx.hypot(vy));
    }
    // An ideal rope never stretches: the player stays within its length
    // (the position solver's slop is 1e-4; allow ten times that).
    assert!(farthest <= length + 1e-3, "{farthest} > {length}");
    // And the player did swing (not hang still).
    assert!(farthest > length - 0.05 && lowest_speed < 20.0);
    assert!(p.release().unwrap());
    assert!(!p.release().unwrap());
    assert_eq!(p.constraint_count(), 0);
    // Let go in the air: gravity alone, Δv_y = -g·dt per tick.
    p.set_controls(false, false, false, false).unwrap();
    let (_, y0, _, vy0) = player(&p);
    assert!(y0 > 2.0, "released in the air ({y0})");
    p.step();
    let (_, _, _, vy1) = player(&p);
    assert!((vy1 - (vy0 - G * DT)).abs() < 1e-8, "{vy0} -> {vy1}");
}

#[test]
fn jumping_needs_the_ground() {
    let mut p = Playground::new(GRAPPLE_SCENE).unwrap();
    steps(&mut p, 30);
    p.set_controls(false, false, true, false).unwrap();
    p.step();
    // SetVelocity (0, 7) before the tick, then one tick of gravity.
    let (_, _, _, vy) = player(&p);
    assert!((vy - (7.0 - G * DT)).abs() < 1e-8, "{vy}");
    // Still holding up in the air: no second jump, just gravity.
    p.step();
    let (_, _, _, vy2) = player(&p);
    assert!((vy2 - (vy - G * DT)).abs() < 1e-8);
}

#[test]
fn grapple_controls_are_refused_outside_the_arena() {
    let mut p = Playground::new("stack").unwrap();
    assert_eq!(p.fire(0.0, 5.0), Err(PlaygroundError::NotGrapple));
    assert_eq!(p.release(), Err(PlaygroundError::NotGrapple));
    assert!(p.aim(0.0, 5.0).is_err());
    assert!(p.set_controls(true, false, false, false).is_err());
    assert!(p.grapple_state().is_empty());
    let mut g = Playground::new(GRAPPLE_SCENE).unwrap();
    let hash = g.hash();
    assert!(g.fire(f64::NAN, 0.0).is_err());
    assert_eq!(g.hash(), hash);
}

#[test]
fn draw_lists_carry_every_body_and_constraint() {
    let mut p = Playground::new("rope").unwrap();
    steps(&mut p, 10);
    let bodies = p.bodies();
    assert_eq!(bodies.len(), p.body_count() as usize * BODY_STRIDE);
    for ((_, body), record) in p.world().bodies().zip(bodies.chunks(BODY_STRIDE)) {
        let (x, y) = body.position().to_f64();
        assert_eq!((record[1], record[2]), (x as f32, y as f32));
    }
    let constraints = p.constraints();
    assert_eq!(
        constraints.len(),
        p.constraint_count() as usize * CONSTRAINT_STRIDE
    );
    assert!(p.constraint_count() > 0);
    assert!(
        constraints
            .chunks(CONSTRAINT_STRIDE)
            .all(|c| (0.0..=2.0).contains(&c[0]))
    );
    assert_eq!(p.contacts().len() % 4, 0);
}
