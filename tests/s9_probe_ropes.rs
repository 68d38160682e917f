//! PROBE (not for landing).
#![allow(dead_code, clippy::all)]
use clockwork2d::prelude::*;

const H: f64 = 1.0 / 60.0;
const SLOP: f64 = 1e-4;
const END_R: f64 = 0.05;

fn zg() -> WorldSettings {
    WorldSettings {
        gravity: Vec2::ZERO,
        ..WorldSettings::default()
    }
}
fn fixed_box(w: &mut World, hx: f64, hy: f64, x: f64, y: f64) -> BodyId {
    w.add_body(BodyDef::fixed(Shape::aabb(vec2(hx, hy))).position(vec2(x, y)))
        .unwrap()
}
fn p(w: &World, id: BodyId) -> (f64, f64) {
    w.body(id).unwrap().position().to_f64()
}
fn v(w: &World, id: BodyId) -> (f64, f64) {
    w.body(id).unwrap().velocity().to_f64()
}

/// Bullet rebounding (e 1) inside a closed box of thin walls, gravity off and on.
#[test]
fn rebounding_bullets() {
    for &(thick, speed, angle_deg, grav, shape_box) in &[
        (0.1, 1000.0, 0.0, false, false),
        (0.1, 1000.0, 37.0, false, false),
        (0.1, 1000.0, 37.0, true, false),
        (0.02, 4000.0, 23.0, false, false),
        (0.1, 1000.0, 45.0, false, false),
        (0.1, 1000.0, 37.0, false, true),
        (0.01, 3000.0, 1.0, true, false),
        (0.1, 200.0, 60.0, true, false),
    ] {
        let mut w = World::new(if grav { WorldSettings::default() } else { zg() });
        let half = 5.0;
        let t = thick / 2.0;
        for (hx, hy, x, y) in [
            (half + thick, t, 0.0, -half - t),
            (half + thick, t, 0.0, half + t),
            (t, half, -half - t, 0.0),
            (t, half, half + t, 0.0),
        ] {
            fixed_box(&mut w, hx, hy, x, y);
        }
        let a = (angle_deg as f64).to_radians();
        let shape = if shape_box {
            Shape::aabb(vec2(0.05, 0.05))
        } else {
            Shape::circle(fx(0.05))
        };
        let b = w
            .add_body(
                BodyDef::dynamic(shape)
                    .restitution(fx(1.0))
                    .friction(fx(0.0))
                    .bullet(true)
                    .position(vec2(0.0, 0.0))
                    .velocity(vec2(speed * a.cos(), speed * a.sin())),
            )
            .unwrap();
        let mut worst: f64 = 0.0;
        let mut first_out = None;
        let mut vmax: f64 = 0.0;
        let mut bounces = 0;
        let mut prev = v(&w, b);
        for tk in 1..=600 {
            w.step();
            let (x, y) = p(&w, b);
            let o = x.abs().max(y.abs()) + 0.05 - half;
            worst = worst.max(o);
            if o > 0.001 && first_out.is_none() {
                first_out = Some(tk);
            }
            let vv = v(&w, b);
            if vv.0.signum() != prev.0.signum() || vv.1.signum() != prev.1.signum() {
                bounces += 1;
            }
            prev = vv;
            vmax = vmax.max(vv.0.hypot(vv.1));
        }
        let (x, y) = p(&w, b);
        let vv = v(&w, b);
        println!(
            "thick {thick} speed {speed} angle {angle_deg} grav {grav} box {shape_box}: worst past inner face {worst:.5} first_out {first_out:?} final ({x:.3},{y:.3}) v ({:.2},{:.2}) |v| {:.3} vmax {vmax:.3} bounces {bounces}",
            vv.0,
            vv.1,
            vv.0.hypot(vv.1)
        );
    }
}

/// Bullet onto the exact corner of a thin fixed box / thin dynamic box, grazing angles.
#[test]
fn bullets_at_corners_and_grazing() {
    for &(target_dyn, aim_dy, angle_deg, speed) in &[
        (false, 0.0, 0.0, 1000.0),
        (false, 0.0499, 0.0, 1000.0),
        (false, 0.05, 0.0, 1000.0),
        (false, 0.0999, 0.0, 1000.0),
        (false, 0.0, 1.0, 1000.0),
        (false, 0.0, 0.1, 1000.0),
        (true, 0.0, 0.0, 1000.0),
        (true, 0.0999, 0.0, 1000.0),
        (true, 0.0, 2.0, 4000.0),
    ] {
        // thin wall: 0.1 thick (x) and 2 tall at x = 10; corner at (9.95, 1.0)
        let mut w = World::new(zg());
        let wall = if target_dyn {
            w.add_body(
                BodyDef::dynamic(Shape::aabb(vec2(0.05, 1.0)))
                    .mass(fx(10.0))
                    .position(vec2(10.0, 0.0)),
            )
            .unwrap()
        } else {
            fixed_box(&mut w, 0.05, 1.0, 10.0, 0.0)
        };
        // aim so the bullet (r 0.05) edge at y = 1.0 + 0.05 - aim_dy -> overlap with corner in y by aim_dy
        let y0 = 1.0 + 0.05 - aim_dy;
        let a = (angle_deg as f64).to_radians();
        // start so that path passes x=9.95 at y0
        let x0 = 0.0;
        let start_y = y0 - (9.95 - x0) * a.tan();
        let b = w
            .add_body(
                BodyDef::dynamic(Shape::circle(fx(0.05)))
                    .bullet(true)
                    .position(vec2(x0, start_y))
                    .velocity(vec2(speed * a.cos(), speed * a.sin())),
            )
            .unwrap();
        let mut passed = None;
        let mut worst_pen: f64 = -1.0;
        for tk in 1..=60 {
            w.step();
            let (x, y) = p(&w, b);
            let (wx, wy) = p(&w, wall);
            // overlap with the wall (circle vs box)
            let dx = ((x - wx).abs() - 0.05).max(0.0);
            let dy = ((y - wy).abs() - 1.0).max(0.0);
            let pen = 0.05 - dx.hypot(dy);
            worst_pen = worst_pen.max(pen);
            if x > wx && (y - wy).abs() < 1.0 && passed.is_none() {
                passed = Some(tk);
            }
        }
        let (x, y) = p(&w, b);
        println!(
            "dyn {target_dyn} aim_dy {aim_dy} angle {angle_deg} speed {speed}: through {passed:?} worst pen {worst_pen:.5} final ({x:.3},{y:.3}) v {:?} wall v {:?}",
            v(&w, b),
            v(&w, wall)
        );
    }
}

/// Head-on e=1 collisions of two free bodies, gravity off: exact 1-D elastic answer.
#[test]
fn two_body_elastic() {
    for &(m2, u1, u2, shape_box, e) in &[
        (1.0, 2.0, 0.0, false, 1.0),
        (3.0, 2.0, 0.0, false, 1.0),
        (1000.0, 2.0, 0.0, false, 1.0),
        (0.001, 2.0, 0.0, false, 1.0),
        (1.0, 5.0, -5.0, true, 1.0),
        (10.0, 30.0, -1.0, true, 1.0),
        (1.0, 2.0, 0.0, false, 0.5),
        (4.0, 300.0, 0.0, false, 0.5),
        (1.0, 1.5, 0.0, false, 1.0),
        (1.0, 0.9, 0.0, false, 1.0),
    ] {
        let mut w = World::new(zg());
        let shape = if shape_box {
            Shape::aabb(vec2(0.5, 0.5))
        } else {
            Shape::circle(fx(0.5))
        };
        let a = w
            .add_body(
                BodyDef::dynamic(shape)
                    .mass(fx(1.0))
                    .restitution(fx(e))
                    .position(vec2(-3.0, 0.0))
                    .velocity(vec2(u1, 0.0)),
            )
            .unwrap();
        let b = w
            .add_body(
                BodyDef::dynamic(shape)
                    .mass(fx(m2))
                    .restitution(fx(e))
                    .position(vec2(3.0, 0.0))
                    .velocity(vec2(u2, 0.0)),
            )
            .unwrap();
        for _ in 0..600 {
            w.step();
        }
        let (m1, mm) = (1.0, m2);
        let rel = u1 - u2;
        let thr = 1.0;
        let ee = if rel > thr { e } else { 0.0 };
        let v1 = (m1 * u1 + mm * u2 - mm * ee * rel) / (m1 + mm);
        let v2 = (m1 * u1 + mm * u2 + m1 * ee * rel) / (m1 + mm);
        let (va, vb) = (v(&w, a).0, v(&w, b).0);
        let ke0 = 0.5 * (m1 * u1 * u1 + mm * u2 * u2);
        let ke = 0.5 * (m1 * va * va + mm * vb * vb);
        println!(
            "m2 {m2} u ({u1},{u2}) box {shape_box} e {e}: v ({va:.6},{vb:.6}) expected ({v1:.6},{v2:.6}) KE {ke:.6}/{ke0:.6} p {:.3e} vy ({:.2e},{:.2e})",
            m1 * va + mm * vb - (m1 * u1 + mm * u2),
            v(&w, a).1,
            v(&w, b).1
        );
    }
}

/// Ball falling past a ledge corner with clearance, gravity on: compare with an empty world.
#[test]
fn falling_past_corners_with_clearance() {
    let mut fails = 0;
    let mut runs = 0;
    for &clear in &[0.0002, 0.001, 0.01, 0.05] {
        for &vx in &[0.0, 0.5, 3.0] {
            for &drop in &[0.5, 5.0, 50.0] {
                for shape_box in [false, true] {
                    for bullet in [false, true] {
                        let make = |obst: bool| {
                            let mut w = World::new(WorldSettings {
                                sleep_enabled: false,
                                ..WorldSettings::default()
                            });
                            if obst {
                                // ledge: fixed box [-3,0]x[-1,0]; ball falls along x>= clear + r
                                fixed_box(&mut w, 1.5, 0.5, -1.5, -0.5);
                                // and a wall on the right whose left face is at 2r+2clear (a shaft)
                                fixed_box(&mut w, 1.0, 50.0, 0.1 + 2.0 * clear + 1.0, -40.0);
                            }
                            let shape = if shape_box {
                                Shape::aabb(vec2(0.05, 0.05))
                            } else {
                                Shape::circle(fx(0.05))
                            };
                            let id = w
                                .add_body(
                                    BodyDef::dynamic(shape)
                                        .bullet(bullet)
                                        .position(vec2(0.05 + clear, drop))
                                        .velocity(vec2(vx, 0.0)),
                                )
                                .unwrap();
                            (w, id)
                        };
                        let (mut a, ia) = make(true);
                        let (mut b, ib) = make(false);
                        // run until ball reaches y = -20 in free world
                        let mut diff = 0.0f64;
                        for _ in 0..400 {
                            a.step();
                            b.step();
                            if p(&b, ib).1 < -30.0 {
                                break;
                            }
                            let (pa, pb) = (p(&a, ia), p(&b, ib));
                            if vx != 0.0 {
                                // with vx, the ball moves into the shaft wall; only check until it would touch
                                if pb.0 + 0.05 > 0.1 + 2.0 * clear - 1e-9 {
                                    break;
                                }
                            }
                            diff = diff.max((pa.0 - pb.0).abs()).max((pa.1 - pb.1).abs());
                        }
                        runs += 1;
                        if diff > 0.0 {
                            fails += 1;
                            println!(
                                "clear {clear} vx {vx} drop {drop} box {shape_box} bullet {bullet}: deviates by {diff:.3e}"
                            );
                        }
                    }
                }
            }
        }
    }
    println!("falling past corners: {fails} of {runs} deviate");
}

/// Box sliding on the floor under an overhang with clearance (gravity on, friction): compare with no overhang.
#[test]
fn sliding_under_overhang() {
    let mut fails = 0;
    let mut runs = 0;
    for &clear in &[0.0002, 0.001, 0.01] {
        for &speed in &[0.5, 5.0, 50.0, 500.0] {
            for shape_box in [false, true] {
                for bullet in [false, true] {
                    let make = |obst: bool| {
                        let mut w = World::new(WorldSettings {
                            sleep_enabled: false,
                            ..WorldSettings::default()
                        });
                        fixed_box(&mut w, 2000.0, 0.5, 0.0, -0.5);
                        if obst {
                            // overhang bottom face at 1.0 + clear, spanning x in [5, 8]
                            fixed_box(&mut w, 1.5, 0.5, 6.5, 1.5 + clear);
                        }
                        let shape = if shape_box {
                            Shape::aabb(vec2(0.5, 0.5))
                        } else {
                            Shape::circle(fx(0.5))
                        };
                        let id = w
                            .add_body(
                                BodyDef::dynamic(shape)
                                    .friction(fx(0.0))
                                    .bullet(bullet)
                                    .position(vec2(0.0, 0.5))
                                    .velocity(vec2(speed, 0.0)),
                            )
                            .unwrap();
                        (w, id)
                    };
                    let (mut a, ia) = make(true);
                    let (mut b, ib) = make(false);
                    let mut diff = 0.0f64;
                    let ticks = ((20.0 / (speed * H)).ceil() as usize).min(2400);
                    for _ in 0..ticks {
                        a.step();
                        b.step();
                        let (pa, pb) = (p(&a, ia), p(&b, ib));
                        diff = diff.max((pa.0 - pb.0).abs()).max((pa.1 - pb.1).abs());
                    }
                    runs += 1;
                    let (pa, pb) = (p(&a, ia), p(&b, ib));
                    if diff > 0.0 {
                        fails += 1;
                        println!(
                            "clear {clear} speed {speed} box {shape_box} bullet {bullet}: deviates by {diff:.3e}; final {pa:?} vs {pb:?} v {:?}",
                            v(&a, ia)
                        );
                    }
                }
            }
        }
    }
    println!("sliding under overhang: {fails} of {runs} deviate");
}

/// Oblique frictionless collision of two circles (gravity off, sleep off): exact answer.
#[test]
fn oblique_circles() {
    for &(m2, speed, bimp, e, r) in &[
        (1.0, 2.0, 0.5, 1.0, 0.5),
        (1.0, 2.0, 0.9, 1.0, 0.5),
        (1.0, 20.0, 0.5, 1.0, 0.5),
        (1.0, 60.0, 0.5, 1.0, 0.5),
        (1.0, 200.0, 0.5, 1.0, 0.5),
        (3.0, 30.0, 0.3, 1.0, 0.5),
        (1.0, 30.0, 0.99, 1.0, 0.5),
        (1.0, 30.0, 0.5, 0.5, 0.5),
        (1.0, 100.0, 0.5, 1.0, 0.05),
    ] {
        let mut w = World::new(WorldSettings {
            gravity: Vec2::ZERO,
            sleep_enabled: false,
            ..WorldSettings::default()
        });
        let a = w
            .add_body(
                BodyDef::dynamic(Shape::circle(fx(r)))
                    .mass(fx(1.0))
                    .friction(fx(0.0))
                    .restitution(fx(e))
                    .position(vec2(-(speed * 0.5).max(5.0 * r), bimp * 2.0 * r))
                    .velocity(vec2(speed, 0.0)),
            )
            .unwrap();
        let b = w
            .add_body(
                BodyDef::dynamic(Shape::circle(fx(r)))
                    .mass(fx(m2))
                    .friction(fx(0.0))
                    .restitution(fx(e))
                    .position(vec2(0.0, 0.0)),
            )
            .unwrap();
        for _ in 0..120 {
            w.step();
        }
        // exact: at contact, centre offset d = (-sqrt(4r^2 - (2rb)^2), 2rb) from b to a; n = d/|d| pointing b->a
        let s = 2.0 * r * bimp;
        let nx = -(4.0 * r * r - s * s).sqrt() / (2.0 * r);
        let ny = s / (2.0 * r);
        // relative normal velocity of a wrt b: speed*nx (negative: approaching)
        let vn = speed * nx;
        let j = -(1.0 + e) * vn / (1.0 + 1.0 / m2);
        let va = (speed + j * nx, j * ny);
        let vb = (-j * nx / m2, -j * ny / m2);
        let ga = v(&w, a);
        let gb = v(&w, b);
        let ke0 = 0.5 * speed * speed;
        let ke = 0.5 * (ga.0 * ga.0 + ga.1 * ga.1) + 0.5 * m2 * (gb.0 * gb.0 + gb.1 * gb.1);
        let err = (ga.0 - va.0)
            .abs()
            .max((ga.1 - va.1).abs())
            .max((gb.0 - vb.0).abs())
            .max((gb.1 - vb.1).abs());
        println!(
            "m2 {m2} speed {speed} b {bimp} e {e} r {r}: a ({:.4},{:.4}) exp ({:.4},{:.4}); b ({:.4},{:.4}) exp ({:.4},{:.4}); err {:.2e} ({:.2e} of speed) KE {ke:.4}/{ke0:.4}",
            ga.0,
            ga.1,
            va.0,
            va.1,
            gb.0,
            gb.1,
            vb.0,
            vb.1,
            err,
            err / speed
        );
    }
}

/// Energy of an e=1 bullet bouncing between floor and ceiling with gravity.
#[test]
fn vertical_rebounds_gravity() {
    for &(room_h, speed, bullet, ceiling, angle) in &[
        (10.0, 1000.0, true, true, 90.0),
        (10.0, 1000.0, false, true, 90.0),
        (10.0, 100.0, true, true, 90.0),
        (10.0, 100.0, false, true, 90.0),
        (10.0, 30.0, true, true, 90.0),
        (10.0, 30.0, false, true, 90.0),
        (100.0, 1000.0, true, true, 90.0),
        (10.0, 1000.0, true, true, 37.0),
        (1000.0, 0.0, true, false, 90.0),
        (1000.0, 0.0, false, false, 90.0),
        (10.0, 0.0, true, false, 90.0),
        (10.0, 0.0, false, false, 90.0),
    ] {
        let mut w = World::new(WorldSettings {
            sleep_enabled: false,
            ..WorldSettings::default()
        });
        fixed_box(&mut w, 1000.0, 0.05, 0.0, -0.05);
        if ceiling {
            fixed_box(&mut w, 1000.0, 0.05, 0.0, room_h + 0.05);
        }
        let a = (angle as f64).to_radians();
        let y0 = if ceiling { room_h / 2.0 } else { room_h };
        let b = w
            .add_body(
                BodyDef::dynamic(Shape::circle(fx(0.05)))
                    .restitution(fx(1.0))
                    .friction(fx(0.0))
                    .bullet(bullet)
                    .position(vec2(0.0, y0))
                    .velocity(vec2(speed * a.cos(), speed * a.sin())),
            )
            .unwrap();
        let g = 10.0;
        let sh = |w: &World| {
            let (x, y) = p(w, b);
            let vv = v(w, b);
            let _ = x;
            0.5 * vv.1 * vv.1 + g * y - 0.5 * g * H * vv.1
        };
        let e0 = sh(&w);
        let mut emax = e0;
        let mut trace = vec![];
        for tk in 1..=600 {
            w.step();
            let e = sh(&w);
            emax = emax.max(e);
            if tk % 100 == 0 {
                trace.push(format!("{:.1}", e - e0));
            }
        }
        println!(
            "room {room_h} speed {speed} bullet {bullet} ceiling {ceiling} angle {angle}: E0 {e0:.2} max rise {:.3} ({:.3}%) trace {:?} final v {:?}",
            emax - e0,
            100.0 * (emax - e0) / e0,
            trace,
            v(&w, b)
        );
    }
}

/// Trace of the 4-wall room with gravity.
#[test]
fn room_gravity_trace() {
    for &(speed, angle, bullet, wall, ticks) in &[
        (1000.0, 37.0, true, 0.1, 3600),
        (1000.0, 37.0, true, 2.0, 3600),
        (300.0, 37.0, true, 2.0, 3600),
        (300.0, 37.0, false, 2.0, 3600),
        (100.0, 37.0, false, 2.0, 3600),
        (100.0, 37.0, true, 2.0, 3600),
        (30.0, 37.0, true, 2.0, 3600),
        (30.0, 37.0, false, 2.0, 3600),
    ] {
        let mut w = World::new(WorldSettings {
            sleep_enabled: false,
            ..WorldSettings::default()
        });
        let half = 5.0;
        let t = wall / 2.0;
        for (hx, hy, x, y) in [
            (half + wall, t, 0.0, -half - t),
            (half + wall, t, 0.0, half + t),
            (t, half, -half - t, 0.0),
            (t, half, half + t, 0.0),
        ] {
            fixed_box(&mut w, hx, hy, x, y);
        }
        let a = (angle as f64).to_radians();
        let b = w
            .add_body(
                BodyDef::dynamic(Shape::circle(fx(0.05)))
                    .restitution(fx(1.0))
                    .friction(fx(0.0))
                    .bullet(bullet)
                    .position(vec2(0.0, 0.0))
                    .velocity(vec2(speed * a.cos(), speed * a.sin())),
            )
            .unwrap();
        let g = 10.0;
        let sh = |w: &World| {
            let (_, y) = p(w, b);
            let vv = v(w, b);
            0.5 * (vv.0 * vv.0 + vv.1 * vv.1) + g * y - 0.5 * g * H * vv.1
        };
        let e0 = sh(&w);
        let mut trace = vec![];
        let mut emax = e0;
        for tk in 1..=ticks {
            w.step();
            emax = emax.max(sh(&w));
            if tk % 600 == 0 {
                trace.push(format!("{:.2}%", 100.0 * (sh(&w) - e0) / e0));
            }
        }
        println!(
            "speed {speed} angle {angle} bullet {bullet} wall {wall}: E0 {e0:.1} max {:.3}% trace {:?} v {:?}",
            100.0 * (emax - e0) / e0,
            trace,
            v(&w, b)
        );
    }
}

/// Where does the ball escape the room?
#[test]
fn room_escape_trace() {
    for &(speed, angle, bullet, wall, e, r) in &[
        (30.0, 37.0, false, 2.0, 1.0, 0.05),
        (100.0, 37.0, false, 2.0, 1.0, 0.05),
        (100.0, 37.0, true, 2.0, 1.0, 0.05),
        (30.0, 37.0, false, 2.0, 0.5, 0.05),
        (30.0, 37.0, false, 2.0, 1.0, 0.5),
        (10.0, 37.0, false, 2.0, 1.0, 0.05),
    ] {
        let mut w = World::new(WorldSettings {
            sleep_enabled: false,
            ..WorldSettings::default()
        });
        let half = 5.0;
        let t = wall / 2.0;
        for (hx, hy, x, y) in [
            (half + wall, t, 0.0, -half - t),
            (half + wall, t, 0.0, half + t),
            (t, half, -half - t, 0.0),
            (t, half, half + t, 0.0),
        ] {
            fixed_box(&mut w, hx, hy, x, y);
        }
        let a = (angle as f64).to_radians();
        let b = w
            .add_body(
                BodyDef::dynamic(Shape::circle(fx(r)))
                    .restitution(fx(e))
                    .friction(fx(0.0))
                    .bullet(bullet)
                    .position(vec2(0.0, 0.0))
                    .velocity(vec2(speed * a.cos(), speed * a.sin())),
            )
            .unwrap();
        let mut hist: Vec<((f64, f64), (f64, f64))> = vec![];
        let mut out = None;
        for tk in 1..=3600 {
            w.step();
            let pp = p(&w, b);
            hist.push((pp, v(&w, b)));
            if pp.0.abs().max(pp.1.abs()) + r - half > 0.01 {
                out = Some(tk);
                break;
            }
        }
        println!("speed {speed} bullet {bullet} e {e} r {r}: out at {out:?}");
        if out.is_some() {
            for h in hist.iter().rev().take(5).rev() {
                println!(
                    "   p ({:.5},{:.5}) v ({:.4},{:.4})",
                    h.0.0, h.0.1, h.1.0, h.1.1
                );
            }
        }
    }
}

/// Ball into an L corner (floor + left wall), both contacts in one tick.
#[test]
fn corner_hits() {
    let mut fails = 0;
    let mut runs = 0;
    let mut worst_case = (0.0, String::new());
    for &grav in &[false, true] {
        for &e in &[0.0, 0.5, 1.0] {
            for &speed in &[5.0, 24.0, 60.0, 150.0] {
                for &bullet in &[false, true] {
                    for &sq in &[false, true] {
                        for k in 0..20 {
                            let mut w = World::new(WorldSettings {
                                sleep_enabled: false,
                                gravity: if grav { vec2(0.0, -10.0) } else { Vec2::ZERO },
                                ..WorldSettings::default()
                            });
                            // floor top y=0 spanning x in [-2, 10]; wall right face x=0 spanning y in [0, 10]
                            fixed_box(&mut w, 6.0, 1.0, 4.0, -1.0);
                            fixed_box(&mut w, 1.0, 5.0, -1.0, 5.0);
                            let r = 0.05;
                            let shape = if sq {
                                Shape::aabb(vec2(r, r))
                            } else {
                                Shape::circle(fx(r))
                            };
                            // aim at the corner point (r, r) from direction 45deg-ish with offset
                            let ang = (200.0 + 5.0 * k as f64 / 2.0).to_radians();
                            let d = 3.0 + 0.0137 * k as f64;
                            let (cx, cy) = (r - d * ang.cos(), r - d * ang.sin());
                            let id = w
                                .add_body(
                                    BodyDef::dynamic(shape)
                                        .restitution(fx(e))
                                        .friction(fx(0.0))
                                        .bullet(bullet)
                                        .position(vec2(cx, cy))
                                        .velocity(vec2(speed * ang.cos(), speed * ang.sin())),
                                )
                                .unwrap();
                            let mut worst: f64 = 0.0;
                            for _ in 0..((6.0 / (speed * H)) as usize + 60) {
                                w.step();
                                let (x, y) = p(&w, id);
                                let pen = (r - x).max(r - y);
                                worst = worst.max(pen);
                            }
                            runs += 1;
                            if worst > 0.001 {
                                fails += 1;
                                let s = format!(
                                    "grav {grav} e {e} speed {speed} bullet {bullet} square {sq} k {k}: worst pen {worst:.4} final {:?} v {:?}",
                                    p(&w, id),
                                    v(&w, id)
                                );
                                if worst > worst_case.0 {
                                    worst_case = (worst, s.clone());
                                }
                                if fails < 40 {
                                    println!("{s}");
                                }
                            }
                        }
                    }
                }
            }
        }
    }
    println!(
        "corner hits: {fails} of {runs} go > 0.001 into a wall; worst: {}",
        worst_case.1
    );
}

#[test]
fn corner_trace() {
    for &(k, speed) in &[(1usize, 24.0), (6, 24.0), (1, 23.0), (1, 25.0), (1, 30.0)] {
        let mut w = World::new(WorldSettings {
            sleep_enabled: false,
            ..WorldSettings::default()
        });
        fixed_box(&mut w, 6.0, 1.0, 4.0, -1.0);
        fixed_box(&mut w, 1.0, 5.0, -1.0, 5.0);
        let r = 0.05;
        let ang = (200.0 + 5.0 * k as f64 / 2.0).to_radians();
        let d = 3.0 + 0.0137 * k as f64;
        let (cx, cy) = (r - d * ang.cos(), r - d * ang.sin());
        let id = w
            .add_body(
                BodyDef::dynamic(Shape::circle(fx(r)))
                    .friction(fx(0.0))
                    .position(vec2(cx, cy))
                    .velocity(vec2(speed * ang.cos(), speed * ang.sin())),
            )
            .unwrap();
        println!(
            "k {k} speed {speed} start ({cx:.5},{cy:.5}) v ({:.4},{:.4})",
            speed * ang.cos(),
            speed * ang.sin()
        );
        for tk in 1..=14 {
            w.step();
            let (x, y) = p(&w, id);
            let vv = v(&w, id);
            if x < 0.6 || y < 0.6 {
                println!(
                    "  tick {tk}: p ({x:.5},{y:.5}) v ({:.4},{:.4}) touching {}",
                    vv.0,
                    vv.1,
                    w.touching_pairs().count()
                );
            }
        }
    }
}

#[test]
fn corner_sweep() {
    for &flush in &[true, false] {
        for &grav in &[false, true] {
            for &(r, sq) in &[(0.05, false), (0.5, false), (0.05, true), (0.5, true)] {
                let (mut through, mut deep, mut runs) = (0, 0, 0);
                let mut worst: f64 = 0.0;
                let mut example = String::new();
                for &speed in &[3.0, 10.0, 24.0, 50.0, 100.0] {
                    for ai in 0..15 {
                        for k in 0..7 {
                            let mut w = World::new(WorldSettings {
                                sleep_enabled: false,
                                gravity: if grav { vec2(0.0, -10.0) } else { Vec2::ZERO },
                                ..WorldSettings::default()
                            });
                            fixed_box(&mut w, 6.0, 1.0, 4.0, -1.0);
                            if flush {
                                fixed_box(&mut w, 1.0, 5.0, -1.0, 5.0);
                            } else {
                                fixed_box(&mut w, 1.0, 6.0, -1.0, 4.0);
                            }
                            let shape = if sq {
                                Shape::aabb(vec2(r, r))
                            } else {
                                Shape::circle(fx(r))
                            };
                            let ang = (190.0 + 5.0 * ai as f64).to_radians();
                            let d = 3.0 + 0.0371 * k as f64;
                            let (cx, cy) = (r - d * ang.cos(), r - d * ang.sin());
                            let id = w
                                .add_body(
                                    BodyDef::dynamic(shape)
                                        .friction(fx(0.0))
                                        .position(vec2(cx, cy))
                                        .velocity(vec2(speed * ang.cos(), speed * ang.sin())),
                                )
                                .unwrap();
                            let mut wp: f64 = 0.0;
                            for _ in 0..((6.0 / (speed * H)) as usize + 30) {
                                w.step();
                                let (x, y) = p(&w, id);
                                wp = wp.max((r - x).max(r - y));
                            }
                            runs += 1;
                            let (x, y) = p(&w, id);
                            if x < -r || y < -r {
                                through += 1;
                                if example.is_empty() {
                                    example = format!(
                                        "speed {speed} angle {} k {k} final ({x:.3},{y:.3})",
                                        190 + 5 * ai
                                    );
                                }
                            } else if wp > 0.01 {
                                deep += 1;
                            }
                            if !(x < -r || y < -r) {
                                worst = worst.max(wp);
                            }
                        }
                    }
                }
                println!(
                    "flush {flush} grav {grav} r {r} square {sq}: {through} through, {deep} deeper than 0.01 (worst of the rest {worst:.4}) of {runs}; e.g. {example}"
                );
            }
        }
    }
}

#[test]
fn room_energy_events() {
    for &(speed, bullet, wall, grav) in &[
        (300.0, true, 2.0, true),
        (1000.0, true, 0.1, true),
        (300.0, true, 2.0, false),
        (100.0, true, 2.0, true),
    ] {
        let mut w = World::new(WorldSettings {
            sleep_enabled: false,
            gravity: if grav { vec2(0.0, -10.0) } else { Vec2::ZERO },
            ..WorldSettings::default()
        });
        let half = 5.0;
        let t = wall / 2.0;
        for (hx, hy, x, y) in [
            (half + wall, t, 0.0, -half - t),
            (half + wall, t, 0.0, half + t),
            (t, half, -half - t, 0.0),
            (t, half, half + t, 0.0),
        ] {
            fixed_box(&mut w, hx, hy, x, y);
        }
        let a = (37.0f64).to_radians();
        let b = w
            .add_body(
                BodyDef::dynamic(Shape::circle(fx(0.05)))
                    .restitution(fx(1.0))
                    .friction(fx(0.0))
                    .bullet(bullet)
                    .position(vec2(0.0, 0.0))
                    .velocity(vec2(speed * a.cos(), speed * a.sin())),
            )
            .unwrap();
        let g = if grav { 10.0 } else { 0.0 };
        let sh = |w: &World| {
            let (_, y) = p(w, b);
            let vv = v(w, b);
            0.5 * (vv.0 * vv.0 + vv.1 * vv.1) + g * y - 0.5 * g * H * vv.1
        };
        let mut prev = sh(&w);
        let e0 = prev;
        let mut shown = 0;
        let mut pp = (p(&w, b), v(&w, b));
        let mut sum_gain = 0.0;
        let mut nj = 0;
        for tk in 1..=1200 {
            w.step();
            let e = sh(&w);
            let allowed = g * H * 2.0 * speed;
            if (e - prev).abs() > allowed.max(1e-3 * e0) {
                nj += 1;
                sum_gain += e - prev;
                if shown < 6 {
                    shown += 1;
                    println!(
                        "speed {speed} grav {grav} tick {tk}: dE {:.2} from p ({:.4},{:.4}) v ({:.3},{:.3}) to p ({:.4},{:.4}) v ({:.3},{:.3})",
                        e - prev,
                        pp.0.0,
                        pp.0.1,
                        pp.1.0,
                        pp.1.1,
                        p(&w, b).0,
                        p(&w, b).1,
                        v(&w, b).0,
                        v(&w, b).1
                    );
                }
            }
            prev = e;
            pp = (p(&w, b), v(&w, b));
        }
        println!(
            "speed {speed} grav {grav}: {nj} jumps, sum {sum_gain:.1} of E0 {e0:.1}, final {:.1}",
            prev
        );
    }
}

struct Rng(u64);
impl Rng {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E3779B97F4A7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58476D1CE4E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D049BB133111EB);
        z ^= z >> 31;
        (z >> 11) as f64 / (1u64 << 53) as f64
    }
    fn range(&mut self, a: f64, b: f64) -> f64 {
        a + (b - a) * self.next()
    }
}

/// Stacks of mixed boxes, on the ground, on one circle, on two circles in a slot.
#[test]
fn stacks_on_circles_and_mixed() {
    for &(n, base, mixed, seed, gap) in &[
        (30usize, 0u8, true, 1u64, 0.0),
        (50, 0, true, 2, 0.0),
        (100, 0, true, 3, 0.0),
        (50, 0, true, 4, 0.05),
        (30, 1, false, 0, 0.0),
        (50, 1, false, 0, 0.0),
        (30, 1, true, 5, 0.0),
        (100, 1, false, 0, 0.0),
        (30, 2, false, 0, 0.0),
        (50, 2, true, 6, 0.0),
        (30, 1, false, 0, 0.05),
        (30, 3, false, 0, 0.0),
        (30, 4, false, 0, 0.0),
    ] {
        let mut w = World::new(WorldSettings::default());
        fixed_box(&mut w, 50.0, 0.5, 0.0, -0.5);
        let mut rng = Rng(seed);
        let mut top = 0.0;
        let mut ideal = vec![];
        let mut depth = 0usize;
        // base: 0 ground, 1 one dynamic circle r 0.5, 2 two circles r 0.5 in a slot (walls), 3 circle r 0.5 x1000 heavy stack? no: fixed circle, 4 circle of mass 0.01 (light)
        match base {
            1 | 4 => {
                let mut d = BodyDef::dynamic(Shape::circle(fx(0.5))).position(vec2(0.0, 0.5));
                if base == 4 {
                    d = d.mass(fx(0.01));
                }
                let c = w.add_body(d).unwrap();
                ideal.push((c, 0.0, 0.5, 1usize));
                top = 1.0;
                depth = 1;
            }
            2 => {
                // slot walls at |x| = 1, circles at x = ±0.5
                fixed_box(&mut w, 0.5, 0.6, -1.5, 0.6);
                fixed_box(&mut w, 0.5, 0.6, 1.5, 0.6);
                for x in [-0.5, 0.5] {
                    let c = w
                        .add_body(BodyDef::dynamic(Shape::circle(fx(0.5))).position(vec2(x, 0.5)))
                        .unwrap();
                    ideal.push((c, x, 0.5, 1));
                }
                top = 1.0;
                depth = 1;
            }
            3 => {
                w.add_body(BodyDef::fixed(Shape::circle(fx(0.5))).position(vec2(0.0, 0.5)))
                    .unwrap();
                top = 1.0;
            }
            _ => {}
        }
        for i in 0..n {
            let (hx, hy) = if mixed {
                (rng.range(0.2, 1.5), rng.range(0.1, 1.0))
            } else {
                (0.5, 0.5)
            };
            let hx = if base == 2 { 1.0 } else { hx };
            let y = top + hy;
            let id = w
                .add_body(
                    BodyDef::dynamic(Shape::aabb(vec2(hx, hy)))
                        .position(vec2(0.0, y + gap * (i + 1) as f64)),
                )
                .unwrap();
            depth += 1;
            ideal.push((id, 0.0, y, depth));
            top += 2.0 * hy;
        }
        let (mut worst_excess, mut drift, mut asleep, mut last_err) = (f64::MIN, 0.0f64, None, 0.0);
        let ticks = 600;
        for tk in 1..=ticks {
            w.step();
            let mut err = 0.0f64;
            let mut exc = f64::MIN;
            let mut all = true;
            for &(id, x, y, d) in &ideal {
                let (px, py) = p(&w, id);
                let e = (py - y).abs();
                err = err.max(e);
                if tk > 60 || gap == 0.0 {
                    exc = exc.max(e - d as f64 * SLOP);
                }
                drift = drift.max((px - x).abs());
                all &= !w.body(id).unwrap().is_awake();
            }
            worst_excess = worst_excess.max(exc);
            last_err = err;
            if all && asleep.is_none() {
                asleep = Some(tk);
            }
            if !all {
                asleep = None;
            }
        }
        println!(
            "n {n} base {base} mixed {mixed} gap {gap}: worst excess over depth*slop {worst_excess:.6}, final err {last_err:.6} (bound {:.4}), drift {drift:.2e}, asleep {asleep:?}",
            depth as f64 * SLOP
        );
    }
}

/// 200-link chain, end x1000, released horizontal, swinging into fixed pegs / a box stack.
#[test]
fn chain_hits_obstacles() {
    for &(links, ratio, obstacle) in &[
        (200usize, 1000.0, 0u8),
        (200, 1000.0, 1),
        (200, 100.0, 1),
        (200, 1000.0, 2),
        (50, 1000.0, 1),
        (50, 1000.0, 2),
        (200, 1000.0, 3),
    ] {
        let mut w = World::new(WorldSettings::default());
        let seg = 0.1;
        match obstacle {
            1 => {
                // a fixed peg box below the anchor, in the swing path
                fixed_box(&mut w, 0.5, 0.5, 0.0, -8.0);
            }
            2 => {
                // a stack of 10 unit boxes standing on a ground below, in the swing path
                fixed_box(&mut w, 50.0, 0.5, 0.0, -21.5);
                for i in 0..10 {
                    w.add_body(
                        BodyDef::dynamic(Shape::aabb(vec2(0.5, 0.5)))
                            .position(vec2(-3.0, -21.0 + 0.5 + i as f64)),
                    )
                    .unwrap();
                }
            }
            3 => {
                // a fixed ground right under the hanging end: the heavy end hits it
                fixed_box(&mut w, 50.0, 0.5, 0.0, -15.5);
            }
            _ => {}
        }
        let mut ids = vec![];
        for i in 0..links {
            let mass = if i + 1 == links { 0.1 * ratio } else { 0.1 };
            let r = if i + 1 == links { END_R } else { 0.02 };
            let id = w
                .add_body(
                    BodyDef::dynamic(Shape::circle(fx(r)))
                        .mass(fx(mass))
                        .position(vec2(seg * (i + 1) as f64, 0.0)),
                )
                .unwrap();
            let above = ids
                .last()
                .map_or(Anchor::Point(Vec2::ZERO), |&q| Anchor::Body(q));
            w.add_constraint(Constraint::rope(above, Anchor::Body(id), fx(seg)))
                .unwrap();
            ids.push(id);
        }
        let (mut worst, mut last, mut worst_tick) = (0.0f64, 0.0f64, 0);
        let ticks = 1200;
        let mut max_pen: f64 = 0.0;
        for tk in 1..=ticks {
            w.step();
            let mut prev = (0.0, 0.0);
            let mut st = 0.0f64;
            for &id in &ids {
                let q = p(&w, id);
                st = st.max(((q.0 - prev.0).hypot(q.1 - prev.1) - seg) / seg);
                prev = q;
            }
            if st > worst {
                worst = st;
                worst_tick = tk;
            }
            if tk + 60 > ticks {
                last = last.max(st);
            }
            if obstacle == 1 {
                for &id in &ids {
                    let (x, y) = p(&w, id);
                    let r = w.body(id).unwrap().shape();
                    let rr = if let Shape::Circle { radius } = r {
                        radius.to_f64()
                    } else {
                        0.0
                    };
                    let dx = (x.abs() - 0.5).max(0.0);
                    let dy = ((y + 8.0).abs() - 0.5).max(0.0);
                    max_pen = max_pen.max(rr - dx.hypot(dy));
                }
            }
        }
        let end = p(&w, *ids.last().unwrap());
        println!(
            "links {links} ratio {ratio} obstacle {obstacle}: worst stretch {:.4}% at tick {worst_tick}, last second {:.4}%, peg penetration {max_pen:.4}, end at ({:.3},{:.3})",
            100.0 * worst,
            100.0 * last,
            end.0,
            end.1
        );
    }
}

/// Crowd of mixed bodies in a closed box with thin walls; also at the world bounds.
#[test]
fn crowds_in_thin_boxes() {
    for &(n, wall, cx, cy, g, heavy, seed) in &[
        (300usize, 0.1, 0.0, 0.0, 10.0, false, 1u64),
        (300, 0.1, 0.0, 0.0, 100.0, false, 2),
        (300, 0.1, 0.0, 0.0, 10.0, true, 3),
        (300, 0.02, 0.0, 0.0, 10.0, false, 4),
        (300, 0.1, 32700.0, 32700.0, 10.0, false, 5),
        (300, 0.1, -32700.0, -32700.0, 10.0, true, 6),
    ] {
        let mut w = World::new(WorldSettings {
            gravity: vec2(0.0, -g),
            ..WorldSettings::default()
        });
        let (hw, hh) = (4.0, 8.0); // interior half sizes
        let t = wall / 2.0;
        for (hx, hy, x, y) in [
            (hw + wall, t, 0.0, -hh - t),
            (hw + wall, t, 0.0, hh + t),
            (t, hh, -hw - t, 0.0),
            (t, hh, hw + t, 0.0),
        ] {
            fixed_box(&mut w, hx, hy, cx + x, cy + y);
        }
        let mut rng = Rng(seed);
        let mut ids = vec![];
        // fill: grid of slots 0.5 apart, random shapes up to 0.24
        let mut k = 0;
        'outer: for row in 0..32 {
            for col in 0..16 {
                if k >= n {
                    break 'outer;
                }
                let x = -hw + 0.25 + 0.5 * col as f64;
                let y = -hh + 0.25 + 0.5 * row as f64;
                let s = rng.range(0.05, 0.24);
                let shape = if rng.next() < 0.5 {
                    Shape::circle(fx(s))
                } else {
                    Shape::aabb(vec2(s, rng.range(0.05, 0.24)))
                };
                let mut d = BodyDef::dynamic(shape).position(vec2(cx + x, cy + y));
                if heavy && k % 10 == 0 {
                    d = d.mass(fx(1000.0 * 0.1));
                }
                ids.push(w.add_body(d).unwrap());
                k += 1;
            }
        }
        let mut worst_out: f64 = f64::MIN;
        let mut asleep = None;
        let mut last_out: f64 = f64::MIN;
        let mut vlast: f64 = 0.0;
        let mut awake_last = 0;
        for tk in 1..=1200 {
            w.step();
            let mut out = f64::MIN;
            let mut all = true;
            for &id in &ids {
                let b = w.body(id).unwrap();
                let (x, y) = b.position().to_f64();
                let (x, y) = (x - cx, y - cy);
                let (ex, ey) = match b.shape() {
                    Shape::Circle { radius } => (radius.to_f64(), radius.to_f64()),
                    Shape::Aabb { half_extents } => half_extents.to_f64(),
                };
                out = out.max((x.abs() + ex - hw).max(y.abs() + ey - hh));
                all &= !b.is_awake();
                if tk > 1140 {
                    let (vx, vy) = b.velocity().to_f64();
                    vlast = vlast.max(vx.hypot(vy));
                }
                if tk == 1200 && b.is_awake() {
                    awake_last += 1;
                }
            }
            worst_out = worst_out.max(out);
            if tk > 1140 {
                last_out = last_out.max(out);
            }
            if all && asleep.is_none() {
                asleep = Some(tk);
            }
            if !all {
                asleep = None;
            }
        }
        println!(
            "n {n} wall {wall} at ({cx},{cy}) g {g} heavy {heavy}: worst past a wall {worst_out:.5}, last second {last_out:.5}, asleep {asleep:?}, v max last second {vlast:.4}, awake at the end {awake_last}"
        );
    }
}

/// Spring chains and pairs: energy.
#[test]
fn spring_energy_variants() {
    // pair of masses 1 and M on a bendy spring, gravity off, kicked
    for &(m2, wh) in &[
        (1000.0, 0.3),
        (1000.0, 1.0),
        (1000.0, 3.0),
        (1000.0, 10.0),
        (0.001, 1.0),
        (1.0, 30.0),
    ] {
        let mut w = World::new(WorldSettings {
            gravity: Vec2::ZERO,
            sleep_enabled: false,
            ..WorldSettings::default()
        });
        let a = w
            .add_body(
                BodyDef::dynamic(Shape::circle(fx(0.1)))
                    .mass(fx(1.0))
                    .position(vec2(0.0, 0.0))
                    .velocity(vec2(1.0, 0.5)),
            )
            .unwrap();
        let b = w
            .add_body(
                BodyDef::dynamic(Shape::circle(fx(0.1)))
                    .mass(fx(m2))
                    .position(vec2(1.0, 0.0)),
            )
            .unwrap();
        // omega^2 = k (1/m1 + 1/m2)
        let k = wh * wh / (H * H) / (1.0 + 1.0 / m2);
        w.add_constraint(
            Constraint::bendy_spring(Anchor::Body(a), Anchor::Body(b), vec2(k, k), fx(0.0))
                .with_rest_offset(vec2(1.0, 0.0)),
        )
        .unwrap();
        let en = |w: &World| {
            let (pa, pb, va, vb) = (p(w, a), p(w, b), v(w, a), v(w, b));
            let dx = pb.0 - pa.0 - 1.0;
            let dy = pb.1 - pa.1;
            0.5 * (va.0 * va.0 + va.1 * va.1)
                + 0.5 * m2 * (vb.0 * vb.0 + vb.1 * vb.1)
                + 0.5 * k * (dx * dx + dy * dy)
        };
        let e0 = en(&w);
        let p0 = (v(&w, a).0 + m2 * v(&w, b).0, v(&w, a).1 + m2 * v(&w, b).1);
        let mut emax: f64 = 0.0;
        let mut emin: f64 = f64::MAX;
        for _ in 0..3600 {
            w.step();
            let e = en(&w) / e0;
            emax = emax.max(e);
            emin = emin.min(e);
        }
        let p1 = (v(&w, a).0 + m2 * v(&w, b).0, v(&w, a).1 + m2 * v(&w, b).1);
        println!(
            "spring pair m2 {m2} omega*h {wh}: E/E0 in [{emin:.5}, {emax:.5}], momentum change ({:.2e},{:.2e})",
            p1.0 - p0.0,
            p1.1 - p0.1
        );
    }
    // hanging chain of radial springs with heavy end, released horizontal, gravity on
    for &(n, ratio, wh) in &[
        (50usize, 1000.0, 0.3),
        (50, 1000.0, 1.0),
        (20, 100.0, 3.0),
        (50, 1.0, 1.0),
    ] {
        let mut w = World::new(WorldSettings {
            sleep_enabled: false,
            ..WorldSettings::default()
        });
        let seg = 0.2;
        let mut ids = vec![];
        let mut ks = vec![];
        for i in 0..n {
            let m = if i + 1 == n { ratio * 0.1 } else { 0.1 };
            let id = w
                .add_body(
                    BodyDef::dynamic(Shape::circle(fx(0.02)))
                        .mass(fx(m))
                        .position(vec2(seg * (i + 1) as f64, 0.0)),
                )
                .unwrap();
            let above = ids
                .last()
                .map_or(Anchor::Point(Vec2::ZERO), |&q| Anchor::Body(q));
            // omega^2 = k (w_a + w_b) with w = 1/m
            let wsum = 1.0 / m + if i == 0 { 0.0 } else { 1.0 / 0.1 };
            let k = wh * wh / (H * H) / wsum;
            w.add_constraint(Constraint::radial_spring(
                above,
                Anchor::Body(id),
                fx(seg),
                fx(k),
                fx(0.0),
            ))
            .unwrap();
            ks.push(k);
            ids.push(id);
        }
        let masses: Vec<f64> = ids
            .iter()
            .map(|&id| w.body(id).unwrap().mass().to_f64())
            .collect();
        let en = |w: &World| {
            let mut e = 0.0;
            let mut prev = (0.0, 0.0);
            for (i, &id) in ids.iter().enumerate() {
                let (x, y) = p(w, id);
                let (vx, vy) = v(w, id);
                e += 0.5 * masses[i] * (vx * vx + vy * vy) + masses[i] * 10.0 * y
                    - 0.5 * masses[i] * 10.0 * H * vy;
                let l = (x - prev.0).hypot(y - prev.1);
                e += 0.5 * ks[i] * (l - seg) * (l - seg);
                prev = (x, y);
            }
            e
        };
        let e0 = en(&w);
        let scale = masses.iter().sum::<f64>() * 10.0 * seg * n as f64; // potential energy scale
        let mut rise: f64 = f64::MIN;
        for _ in 0..1200 {
            w.step();
            rise = rise.max(en(&w) - e0);
        }
        println!(
            "radial chain n {n} ratio {ratio} omega*h {wh}: max energy rise {rise:.4} ({:.3}% of the PE scale {scale:.1})",
            100.0 * rise / scale
        );
    }
}

/// Sleeping and waking.
#[test]
fn sleep_wake_variants() {
    // W1: stack asleep on a kinematic platform that then moves down
    {
        let mut w = World::new(WorldSettings::default());
        let plat = w
            .add_body(BodyDef::kinematic(Shape::aabb(vec2(2.0, 0.25))).position(vec2(0.0, -0.25)))
            .unwrap();
        let ids: Vec<BodyId> = (0..5)
            .map(|i| {
                w.add_body(
                    BodyDef::dynamic(Shape::aabb(vec2(0.5, 0.5)))
                        .position(vec2(0.0, 0.5 + i as f64)),
                )
                .unwrap()
            })
            .collect();
        let mut t_sleep = None;
        for tk in 1..=300 {
            w.step();
            if ids.iter().all(|&i| !w.body(i).unwrap().is_awake()) {
                t_sleep = Some(tk);
                break;
            }
        }
        w.apply(Command::SetVelocity {
            body: plat,
            velocity: vec2(0.0, -2.0),
        })
        .unwrap();
        let mut worst_gap: f64 = 0.0;
        for _ in 0..120 {
            w.step();
            let top_plat = p(&w, plat).1 + 0.25;
            let bottom = p(&w, ids[0]).1 - 0.5;
            worst_gap = worst_gap.max(bottom - top_plat);
        }
        println!(
            "W1 kinematic platform moves down under a sleeping stack (asleep at {t_sleep:?}): worst gap bottom box - platform {worst_gap:.4}; platform y {:.3} box0 y {:.3} awake {}",
            p(&w, plat).1,
            p(&w, ids[0]).1,
            w.body(ids[0]).unwrap().is_awake()
        );
    }
    // W1b: kinematic platform moves sideways under a sleeping stack (friction should carry it)
    {
        let mut w = World::new(WorldSettings::default());
        let plat = w
            .add_body(BodyDef::kinematic(Shape::aabb(vec2(20.0, 0.25))).position(vec2(0.0, -0.25)))
            .unwrap();
        let ids: Vec<BodyId> = (0..5)
            .map(|i| {
                w.add_body(
                    BodyDef::dynamic(Shape::aabb(vec2(0.5, 0.5)))
                        .position(vec2(0.0, 0.5 + i as f64)),
                )
                .unwrap()
            })
            .collect();
        for _ in 1..=300 {
            w.step();
        }
        let asleep = ids.iter().all(|&i| !w.body(i).unwrap().is_awake());
        w.apply(Command::SetVelocity {
            body: plat,
            velocity: vec2(1.0, 0.0),
        })
        .unwrap();
        for _ in 0..120 {
            w.step();
        }
        println!(
            "W1b platform sideways 1 u/s under a sleeping stack (asleep {asleep}): after 2 s platform x {:.3}, box0 x {:.3} box4 x {:.3}",
            p(&w, plat).0,
            p(&w, ids[0]).0,
            p(&w, ids[4]).0
        );
    }
    // W2: rope pulls a sleeping box
    {
        let mut w = World::new(WorldSettings::default());
        fixed_box(&mut w, 50.0, 0.5, 0.0, -0.5);
        let bx = w
            .add_body(BodyDef::dynamic(Shape::aabb(vec2(0.5, 0.5))).position(vec2(0.0, 0.5)))
            .unwrap();
        let ball = w
            .add_body(BodyDef::dynamic(Shape::circle(fx(0.25))).position(vec2(2.0, 0.25)))
            .unwrap();
        w.add_constraint(Constraint::rope(
            Anchor::Body(bx),
            Anchor::Body(ball),
            fx(3.0),
        ))
        .unwrap();
        for _ in 0..120 {
            w.step();
        }
        let asleep = !w.body(bx).unwrap().is_awake() && !w.body(ball).unwrap().is_awake();
        w.apply(Command::SetVelocity {
            body: ball,
            velocity: vec2(10.0, 0.0),
        })
        .unwrap();
        for _ in 0..60 {
            w.step();
        }
        let d = (p(&w, ball).0 - p(&w, bx).0).hypot(p(&w, ball).1 - p(&w, bx).1);
        println!(
            "W2 rope yanks a sleeping box (both asleep {asleep}): box x {:.3}, ball x {:.3}, rope length {d:.4} (max 3)",
            p(&w, bx).0,
            p(&w, ball).0
        );
    }
    // W3: fixed ground teleported away under a sleeping stack
    {
        let mut w = World::new(WorldSettings::default());
        let g = fixed_box(&mut w, 50.0, 0.5, 0.0, -0.5);
        let ids: Vec<BodyId> = (0..5)
            .map(|i| {
                w.add_body(
                    BodyDef::dynamic(Shape::aabb(vec2(0.5, 0.5)))
                        .position(vec2(0.0, 0.5 + i as f64)),
                )
                .unwrap()
            })
            .collect();
        for _ in 0..300 {
            w.step();
        }
        let asleep = ids.iter().all(|&i| !w.body(i).unwrap().is_awake());
        let r = w.apply(Command::SetPosition {
            body: g,
            position: vec2(0.0, -10.5),
        });
        for _ in 0..60 {
            w.step();
        }
        println!(
            "W3 ground moved 10 down under a sleeping stack (asleep {asleep}, command {r:?}): box0 y after 1 s {:.3} (free fall from 0.5: {:.3})",
            p(&w, ids[0]).1,
            0.5 - 0.5 * 10.0 * 1.0
        );
    }
    // W4: slow ball into a floating sleeping box, gravity off
    {
        let mut w = World::new(WorldSettings {
            gravity: Vec2::ZERO,
            ..WorldSettings::default()
        });
        let bx = w
            .add_body(BodyDef::dynamic(Shape::aabb(vec2(0.5, 0.5))).position(vec2(0.0, 0.0)))
            .unwrap();
        for _ in 0..60 {
            w.step();
        }
        let asleep = !w.body(bx).unwrap().is_awake();
        let ball = w
            .add_body(
                BodyDef::dynamic(Shape::circle(fx(0.5)))
                    .mass(fx(1.0))
                    .position(vec2(-1.5, 0.0))
                    .velocity(vec2(0.2, 0.0)),
            )
            .unwrap();
        for _ in 0..600 {
            w.step();
        }
        println!(
            "W4 ball 0.2 u/s into a sleeping floating box (asleep {asleep}): box v {:?} x {:.3}, ball v {:?} x {:.3}; momentum {:.4} of 0.2",
            v(&w, bx),
            p(&w, bx).0,
            v(&w, ball),
            p(&w, ball).0,
            v(&w, bx).0 + v(&w, ball).0
        );
    }
    // W5: despawn the middle of a sleeping stack
    {
        let mut w = World::new(WorldSettings::default());
        fixed_box(&mut w, 50.0, 0.5, 0.0, -0.5);
        let ids: Vec<BodyId> = (0..10)
            .map(|i| {
                w.add_body(
                    BodyDef::dynamic(Shape::aabb(vec2(0.5, 0.5)))
                        .position(vec2(0.0, 0.5 + i as f64)),
                )
                .unwrap()
            })
            .collect();
        for _ in 0..300 {
            w.step();
        }
        w.remove_body(ids[4]).unwrap();
        for _ in 0..120 {
            w.step();
        }
        println!(
            "W5 middle box removed from a sleeping 10-stack: box5 y {:.4} (ideal 4.5), top y {:.4} (ideal 8.5)",
            p(&w, ids[5]).1,
            p(&w, ids[9]).1
        );
    }
}

/// Ray casts against analytic answers.
#[test]
fn ray_variants() {
    let mut rng = Rng(7);
    let mut worst: f64 = 0.0;
    let mut wrong_body = 0;
    let mut misses = 0;
    let mut n = 0;
    for (cx, cy) in [(0.0, 0.0), (32000.0, -32000.0), (-32700.0, 32700.0)] {
        let mut w = World::new(WorldSettings::default());
        let mut shapes = vec![];
        for _ in 0..40 {
            let (x, y) = (cx + rng.range(-20.0, 20.0), cy + rng.range(-20.0, 20.0));
            if rng.next() < 0.5 {
                let r = rng.range(0.05, 2.0);
                let id = w
                    .add_body(BodyDef::fixed(Shape::circle(fx(r))).position(vec2(x, y)))
                    .unwrap();
                let (x, y) = p(&w, id);
                shapes.push((id, true, x, y, r, r));
            } else {
                let (hx, hy) = (rng.range(0.01, 2.0), rng.range(0.01, 2.0));
                let id = w
                    .add_body(BodyDef::fixed(Shape::aabb(vec2(hx, hy))).position(vec2(x, y)))
                    .unwrap();
                let (x, y) = p(&w, id);
                let Shape::Aabb { half_extents } = w.body(id).unwrap().shape() else {
                    unreachable!()
                };
                let (hx, hy) = half_extents.to_f64();
                shapes.push((id, false, x, y, hx, hy));
            }
        }
        for _ in 0..2000 {
            let (ox, oy) = (cx + rng.range(-40.0, 40.0), cy + rng.range(-40.0, 40.0));
            let a = rng.range(0.0, std::f64::consts::TAU);
            let len = rng.range(0.001, 100.0);
            let (dx, dy) = (len * a.cos(), len * a.sin());
            let o = vec2(ox, oy);
            let d = vec2(dx, dy);
            let (ox, oy) = o.to_f64();
            let (dx, dy) = d.to_f64();
            let l = dx.hypot(dy);
            let (ux, uy) = (dx / l, dy / l);
            let maxd = 200.0;
            // analytic nearest
            let mut best: Option<(f64, BodyId)> = None;
            for &(id, circ, x, y, hx, hy) in &shapes {
                let t = if circ {
                    let (fx_, fy_) = (ox - x, oy - y);
                    let b = fx_ * ux + fy_ * uy;
                    let c = fx_ * fx_ + fy_ * fy_ - hx * hx;
                    if c <= 0.0 {
                        Some(0.0)
                    } else {
                        let disc = b * b - c;
                        if disc < 0.0 {
                            None
                        } else {
                            let t = -b - disc.sqrt();
                            if t >= 0.0 { Some(t) } else { None }
                        }
                    }
                } else {
                    let (mut t0, mut t1) = (0.0f64, f64::MAX);
                    let mut ok = true;
                    for (o, u, lo, hi) in [(ox, ux, x - hx, x + hx), (oy, uy, y - hy, y + hy)] {
                        if u.abs() < 1e-15 {
                            if o < lo || o > hi {
                                ok = false;
                            }
                        } else {
                            let (a, b) = ((lo - o) / u, (hi - o) / u);
                            t0 = t0.max(a.min(b));
                            t1 = t1.min(a.max(b));
                        }
                    }
                    if ok && t0 <= t1 { Some(t0) } else { None }
                };
                if let Some(t) = t {
                    if t <= maxd && best.map_or(true, |(bt, _)| t < bt) {
                        best = Some((t, id));
                    }
                }
            }
            let got = w.raycast(o, d, fx(maxd));
            n += 1;
            match (best, got) {
                (None, None) => {}
                (Some((t, id)), Some(h)) => {
                    let e = (h.hit.distance.to_f64() - t).abs();
                    worst = worst.max(e);
                    if h.body != id {
                        // tie?
                        wrong_body += 1;
                        if wrong_body < 5 {
                            println!("wrong body: analytic {t} got {}", h.hit.distance.to_f64());
                        }
                    }
                    if e > 1e-5 && misses < 10 {
                        misses += 1;
                        println!("ray error {e:.3e}: origin ({ox},{oy}) dir ({dx},{dy}) t {t}");
                    }
                }
                (a, b) => {
                    misses += 1;
                    if misses < 10 {
                        println!(
                            "ray disagreement: analytic {a:?} got {:?} origin ({ox},{oy}) dir ({dx},{dy})",
                            b.map(|h| h.hit.distance.to_f64())
                        );
                    }
                }
            }
        }
    }
    println!(
        "rays: {n} cast, worst distance error {worst:.3e}, {wrong_body} different bodies, {misses} disagreements"
    );
}

/// Radial spring chains: where do they blow up?
#[test]
fn radial_chain_grid() {
    for &(n, ratio, wh, grav, horizontal) in &[
        (20usize, 100.0, 3.0, true, true),
        (20, 100.0, 3.0, true, false),
        (20, 100.0, 3.0, false, true),
        (20, 1.0, 3.0, true, true),
        (20, 100.0, 1.5, true, true),
        (20, 100.0, 1.0, true, true),
        (5, 100.0, 3.0, true, true),
        (2, 100.0, 3.0, true, true),
        (1, 100.0, 3.0, true, true),
        (20, 10.0, 3.0, true, true),
        (50, 1000.0, 3.0, true, true),
        (50, 1000.0, 1.5, true, true),
        (20, 1.0, 10.0, true, true),
        (20, 1.0, 30.0, true, true),
        (2, 1.0, 3.0, true, true),
        (2, 1.0, 1.0, true, true),
        (2, 1.0, 0.3, true, true),
        (2, 100.0, 1.0, true, true),
        (2, 100.0, 0.3, true, true),
        (1, 1.0, 30.0, true, true),
        (1, 1.0, 100.0, true, true),
        (2, 1.0, 10.0, false, true),
    ] {
        let g = if grav { 10.0 } else { 0.0 };
        let mut w = World::new(WorldSettings {
            sleep_enabled: false,
            gravity: vec2(0.0, -g),
            ..WorldSettings::default()
        });
        let seg = 0.2;
        let mut ids = vec![];
        let mut ks = vec![];
        for i in 0..n {
            let m = if i + 1 == n { ratio * 0.1 } else { 0.1 };
            let pos = if horizontal {
                vec2(seg * (i + 1) as f64, 0.0)
            } else {
                vec2(0.0, -seg * (i + 1) as f64)
            };
            let vel = if grav {
                Vec2::ZERO
            } else {
                vec2(0.0, if i + 1 == n { 1.0 } else { 0.0 })
            };
            let id = w
                .add_body(
                    BodyDef::dynamic(Shape::circle(fx(0.02)))
                        .mass(fx(m))
                        .position(pos)
                        .velocity(vel),
                )
                .unwrap();
            let above = ids
                .last()
                .map_or(Anchor::Point(Vec2::ZERO), |&q| Anchor::Body(q));
            let wsum = 1.0 / m + if i == 0 { 0.0 } else { 1.0 / 0.1 };
            let k = wh * wh / (H * H) / wsum;
            w.add_constraint(Constraint::radial_spring(
                above,
                Anchor::Body(id),
                fx(seg),
                fx(k),
                fx(0.0),
            ))
            .unwrap();
            ks.push(k);
            ids.push(id);
        }
        let masses: Vec<f64> = ids
            .iter()
            .map(|&id| w.body(id).unwrap().mass().to_f64())
            .collect();
        let en = |w: &World| {
            let mut e = 0.0;
            let mut prev = (0.0, 0.0);
            for (i, &id) in ids.iter().enumerate() {
                let (x, y) = p(w, id);
                let (vx, vy) = v(w, id);
                e += 0.5 * masses[i] * (vx * vx + vy * vy) + masses[i] * g * y
                    - 0.5 * masses[i] * g * H * vy;
                let l = (x - prev.0).hypot(y - prev.1);
                e += 0.5 * ks[i] * (l - seg) * (l - seg);
                prev = (x, y);
            }
            e
        };
        let e0 = en(&w);
        let mut rise: f64 = f64::MIN;
        let mut first_bad = None;
        let mut maxstretch: f64 = 0.0;
        for tk in 1..=1200 {
            w.step();
            let r = en(&w) - e0;
            rise = rise.max(r);
            if r > 1.0 && first_bad.is_none() {
                first_bad = Some(tk);
            }
            let mut prev = (0.0, 0.0);
            for &id in &ids {
                let q = p(&w, id);
                maxstretch = maxstretch.max(((q.0 - prev.0).hypot(q.1 - prev.1) - seg) / seg);
                prev = q;
            }
        }
        println!(
            "n {n} ratio {ratio} omega*h {wh} gravity {grav} horizontal {horizontal}: E0 {e0:.3} max rise {rise:.4e}, first > 1 J at {first_bad:?}, max stretch {:.1}%",
            100.0 * maxstretch
        );
    }
}

#[test]
fn radial_pair_trace() {
    for &(horizontal, still) in &[(true, false), (false, false), (false, true)] {
        let mut w = World::new(WorldSettings {
            sleep_enabled: false,
            ..WorldSettings::default()
        });
        let seg = 0.2;
        let (m0, m1) = (0.1, 10.0);
        let k1 = 9.0 / (H * H) / (1.0 / m0);
        let k2 = 9.0 / (H * H) / (1.0 / m0 + 1.0 / m1);
        // static hanging equilibrium: spring 2 carries m1 g, spring 1 carries (m0+m1) g
        let (s1, s2) = if still {
            ((m0 + m1) * 10.0 / k1, m1 * 10.0 / k2)
        } else {
            (0.0, 0.0)
        };
        let p0 = if horizontal {
            vec2(seg, 0.0)
        } else {
            vec2(0.0, -(seg + s1))
        };
        let p1 = if horizontal {
            vec2(2.0 * seg, 0.0)
        } else {
            vec2(0.0, -(2.0 * seg + s1 + s2))
        };
        let a = w
            .add_body(
                BodyDef::dynamic(Shape::circle(fx(0.02)))
                    .mass(fx(m0))
                    .position(p0),
            )
            .unwrap();
        let b = w
            .add_body(
                BodyDef::dynamic(Shape::circle(fx(0.02)))
                    .mass(fx(m1))
                    .position(p1),
            )
            .unwrap();
        w.add_constraint(Constraint::radial_spring(
            Anchor::Point(Vec2::ZERO),
            Anchor::Body(a),
            fx(seg),
            fx(k1),
            fx(0.0),
        ))
        .unwrap();
        w.add_constraint(Constraint::radial_spring(
            Anchor::Body(a),
            Anchor::Body(b),
            fx(seg),
            fx(k2),
            fx(0.0),
        ))
        .unwrap();
        println!("horizontal {horizontal} still {still}: k1 {k1:.1} k2 {k2:.1}");
        for tk in 1..=40 {
            w.step();
            if tk % 4 == 0 || tk < 4 {
                let (pa, pb) = (p(&w, a), p(&w, b));
                let l1 = pa.0.hypot(pa.1);
                let l2 = (pb.0 - pa.0).hypot(pb.1 - pa.1);
                println!(
                    "  tick {tk}: a ({:.4},{:.4}) b ({:.4},{:.4}) l1 {l1:.4} l2 {l2:.4} va {:?}",
                    pa.0,
                    pa.1,
                    pb.0,
                    pb.1,
                    v(&w, a)
                );
            }
        }
    }
}

#[test]
fn chain_peg_trace() {
    for &(links, ratio, peg_circle, ticks) in &[
        (200usize, 1000.0, false, 1100usize),
        (200, 1.0, false, 1200),
        (100, 1000.0, false, 1200),
        (200, 1000.0, true, 1200),
    ] {
        let mut w = World::new(WorldSettings::default());
        let seg = 0.1;
        if peg_circle {
            w.add_body(BodyDef::fixed(Shape::circle(fx(0.5))).position(vec2(0.0, -8.0)))
                .unwrap();
        } else {
            fixed_box(&mut w, 0.5, 0.5, 0.0, -8.0);
        }
        let mut ids = vec![];
        for i in 0..links {
            let mass = if i + 1 == links { 0.1 * ratio } else { 0.1 };
            let r = if i + 1 == links { END_R } else { 0.02 };
            let id = w
                .add_body(
                    BodyDef::dynamic(Shape::circle(fx(r)))
                        .mass(fx(mass))
                        .position(vec2(seg * (i + 1) as f64, 0.0)),
                )
                .unwrap();
            let above = ids
                .last()
                .map_or(Anchor::Point(Vec2::ZERO), |&q| Anchor::Body(q));
            w.add_constraint(Constraint::rope(above, Anchor::Body(id), fx(seg)))
                .unwrap();
            ids.push(id);
        }
        let mut over = vec![];
        let mut worst = (0.0f64, 0usize, 0usize);
        for tk in 1..=ticks {
            w.step();
            let mut prev = (0.0, 0.0);
            let mut st = (0.0f64, 0usize);
            for (i, &id) in ids.iter().enumerate() {
                let q = p(&w, id);
                let s = ((q.0 - prev.0).hypot(q.1 - prev.1) - seg) / seg;
                if s > st.0 {
                    st = (s, i);
                }
                prev = q;
            }
            if st.0 > 0.01 {
                over.push(tk);
            }
            if st.0 > worst.0 {
                worst = (st.0, tk, st.1);
            }
        }
        let first = over.first().copied();
        println!(
            "links {links} ratio {ratio} circle peg {peg_circle}: {} ticks over 1 % (first {first:?}, last {:?}); worst {:.2}% at tick {} in segment {}",
            over.len(),
            over.last(),
            100.0 * worst.0,
            worst.1,
            worst.2
        );
    }
}

/// Bounce apexes: e^2 h bound in new placements.
#[test]
fn bounce_apex_variants() {
    // (label, target, e, drop height, ball offset x, world offset)
    for &(target, e, h, dx, off) in &[
        (0u8, 1.0, 2.0, 0.0, 0.0),
        (0, 0.5, 2.0, 0.0, 0.0),
        (0, 1.0, 2.0, 0.0, -32000.0),
        (0, 0.8, 200.0, 0.0, 0.0),
        (1, 1.0, 2.0, 0.0, 0.0),  // fixed circle peg top
        (1, 0.7, 2.0, 0.3, 0.0),  // fixed circle peg off-centre
        (2, 1.0, 2.0, 0.49, 0.0), // fixed box, ball lands near the corner (on top)
        (2, 1.0, 2.0, 0.55, 0.0), // ball lands on the corner itself
        (2, 0.5, 2.0, 0.55, 0.0),
        (3, 1.0, 2.0, 0.0, 0.0), // seam between two flush fixed tiles, exactly on the seam
        (3, 1.0, 2.0, 0.02, 0.0),
        (4, 1.0, 2.0, 0.0, 0.0), // box e=1 (not ball) onto the ground
        (5, 1.0, 2.0, 0.0, 0.0), // box e=1 onto the seam of two tiles
        (6, 1.0, 2.0, 0.0, 0.0), // ball onto a 1000x heavy dynamic box resting on ground
    ] {
        let mut w = World::new(WorldSettings::default());
        let (gx, gy) = (0.0, off);
        let r = 0.25;
        let mut top = 0.0;
        match target {
            0 | 4 => {
                fixed_box(&mut w, 50.0, 0.5, gx, gy - 0.5);
            }
            1 => {
                w.add_body(BodyDef::fixed(Shape::circle(fx(0.5))).position(vec2(gx, gy - 0.5)))
                    .unwrap();
            }
            2 => {
                fixed_box(&mut w, 0.5, 0.5, gx, gy - 0.5);
            }
            3 | 5 => {
                fixed_box(&mut w, 1.0, 0.5, gx - 1.0, gy - 0.5);
                fixed_box(&mut w, 1.0, 0.5, gx + 1.0, gy - 0.5);
            }
            6 => {
                fixed_box(&mut w, 50.0, 0.5, gx, gy - 0.5);
                w.add_body(
                    BodyDef::dynamic(Shape::aabb(vec2(0.5, 0.5)))
                        .mass(fx(1000.0))
                        .position(vec2(gx, gy + 0.5)),
                )
                .unwrap();
                top = 1.0;
            }
            _ => {}
        }
        let shape = if target == 4 || target == 5 {
            Shape::aabb(vec2(r, r))
        } else {
            Shape::circle(fx(r))
        };
        let y0 = gy + top + r + h;
        let b = w
            .add_body(
                BodyDef::dynamic(shape)
                    .restitution(fx(e))
                    .position(vec2(gx + dx, y0)),
            )
            .unwrap();
        // track apex after first bounce: E_shadow
        let en = |w: &World| {
            let (_, y) = p(w, b);
            let vv = v(w, b);
            0.5 * (vv.0 * vv.0 + vv.1 * vv.1) + 10.0 * (y - y0) - 0.5 * 10.0 * H * vv.1
        };
        let e0 = en(&w);
        let mut emax = f64::MIN;
        let mut bounced = false;
        let mut apex = f64::MIN;
        let mut prev_vy = 0.0;
        for _ in 0..240 {
            w.step();
            let vy = v(&w, b).1;
            if !bounced && vy > 0.0 && prev_vy < 0.0 {
                bounced = true;
            }
            if bounced {
                apex = apex.max(p(&w, b).1);
                emax = emax.max(en(&w) - e0);
            }
            if bounced && vy < 0.0 && prev_vy >= 0.0 {
                break;
            }
            prev_vy = vy;
        }
        // apex height above the contact height: the contact height depends on target; use drop height ratio via energy:
        let rise = apex - (y0 - h);
        println!(
            "target {target} e {e} h {h} dx {dx} off {off}: first apex {rise:.4} above the start level minus h (e^2 h = {:.4}), shadow energy rise {emax:.3e}",
            e * e * h
        );
    }
}

#[test]
fn crowd_unrest() {
    for &(wall, g, seed) in &[
        (0.02, 10.0, 4u64),
        (0.1, 10.0, 4),
        (0.02, 10.0, 1),
        (0.1, 100.0, 2),
        (0.1, 100.0, 1),
        (2.0, 10.0, 4),
    ] {
        let mut w = World::new(WorldSettings {
            gravity: vec2(0.0, -g),
            ..WorldSettings::default()
        });
        let (hw, hh) = (4.0, 8.0);
        let t = wall / 2.0;
        for (hx, hy, x, y) in [
            (hw + wall, t, 0.0, -hh - t),
            (hw + wall, t, 0.0, hh + t),
            (t, hh, -hw - t, 0.0),
            (t, hh, hw + t, 0.0),
        ] {
            fixed_box(&mut w, hx, hy, x, y);
        }
        let mut rng = Rng(seed);
        let mut ids = vec![];
        for k in 0..300 {
            let (row, col) = (k / 16, k % 16);
            let x = -hw + 0.25 + 0.5 * col as f64;
            let y = -hh + 0.25 + 0.5 * row as f64;
            let s = rng.range(0.05, 0.24);
            let shape = if rng.next() < 0.5 {
                Shape::circle(fx(s))
            } else {
                Shape::aabb(vec2(s, rng.range(0.05, 0.24)))
            };
            ids.push(
                w.add_body(BodyDef::dynamic(shape).position(vec2(x, y)))
                    .unwrap(),
            );
        }
        let mut trace = vec![];
        for tk in 1..=1200 {
            w.step();
            if tk % 150 == 0 {
                let mut best = (0.0f64, 0usize);
                let mut ke = 0.0;
                for (i, &id) in ids.iter().enumerate() {
                    let b = w.body(id).unwrap();
                    let (vx, vy) = b.velocity().to_f64();
                    ke += 0.5 * b.mass().to_f64() * (vx * vx + vy * vy);
                    if vx.hypot(vy) > best.0 {
                        best = (vx.hypot(vy), i);
                    }
                }
                let (px, py) = p(&w, ids[best.1]);
                trace.push(format!(
                    "t{tk}: KE {ke:.3} vmax {:.2} (#{} at ({px:.2},{py:.2}) {:?})",
                    best.0,
                    best.1,
                    w.body(ids[best.1]).unwrap().shape()
                ));
            }
        }
        println!("wall {wall} g {g} seed {seed}:");
        for s in trace {
            println!("   {s}");
        }
    }
}

#[test]
fn crowd_unrest_body() {
    let (wall, g, seed) = (0.1, 10.0, 4u64);
    let mut w = World::new(WorldSettings {
        gravity: vec2(0.0, -g),
        ..WorldSettings::default()
    });
    let (hw, hh) = (4.0, 8.0);
    let t = wall / 2.0;
    for (hx, hy, x, y) in [
        (hw + wall, t, 0.0, -hh - t),
        (hw + wall, t, 0.0, hh + t),
        (t, hh, -hw - t, 0.0),
        (t, hh, hw + t, 0.0),
    ] {
        fixed_box(&mut w, hx, hy, x, y);
    }
    let mut rng = Rng(seed);
    let mut ids = vec![];
    for k in 0..300 {
        let (row, col) = (k / 16, k % 16);
        let x = -hw + 0.25 + 0.5 * col as f64;
        let y = -hh + 0.25 + 0.5 * row as f64;
        let s = rng.range(0.05, 0.24);
        let shape = if rng.next() < 0.5 {
            Shape::circle(fx(s))
        } else {
            Shape::aabb(vec2(s, rng.range(0.05, 0.24)))
        };
        ids.push(
            w.add_body(BodyDef::dynamic(shape).position(vec2(x, y)))
                .unwrap(),
        );
    }
    for tk in 1..=600 {
        w.step();
        if tk >= 590 {
            let b = w.body(ids[117]).unwrap();
            println!(
                "tick {tk}: #117 p {:?} v {:?} awake {}",
                b.position().to_f64(),
                b.velocity().to_f64(),
                b.is_awake()
            );
        }
    }
    // neighbours of 117
    let (x0, y0) = p(&w, ids[117]);
    for (i, &id) in ids.iter().enumerate() {
        let (x, y) = p(&w, id);
        if (x - x0).abs() < 0.6 && (y - y0).abs() < 0.6 && i != 117 {
            let b = w.body(id).unwrap();
            println!(
                "  neighbour #{i} p ({x:.4},{y:.4}) v {:?} {:?} mass {:.4}",
                b.velocity().to_f64(),
                b.shape(),
                b.mass().to_f64()
            );
        }
    }
    let b = w.body(ids[117]).unwrap();
    println!("  #117 shape {:?} mass {:.4}", b.shape(), b.mass().to_f64());
}

fn crowd_world(seed: u64) -> (World, Vec<BodyId>) {
    let (wall, g) = (0.1, 10.0);
    let mut w = World::new(WorldSettings {
        gravity: vec2(0.0, -g),
        ..WorldSettings::default()
    });
    let (hw, hh) = (4.0, 8.0);
    let t = wall / 2.0;
    for (hx, hy, x, y) in [
        (hw + wall, t, 0.0, -hh - t),
        (hw + wall, t, 0.0, hh + t),
        (t, hh, -hw - t, 0.0),
        (t, hh, hw + t, 0.0),
    ] {
        fixed_box(&mut w, hx, hy, x, y);
    }
    let mut rng = Rng(seed);
    let mut ids = vec![];
    for k in 0..300 {
        let (row, col) = (k / 16, k % 16);
        let x = -hw + 0.25 + 0.5 * col as f64;
        let y = -hh + 0.25 + 0.5 * row as f64;
        let s = rng.range(0.05, 0.24);
        let shape = if rng.next() < 0.5 {
            Shape::circle(fx(s))
        } else {
            Shape::aabb(vec2(s, rng.range(0.05, 0.24)))
        };
        ids.push(
            w.add_body(BodyDef::dynamic(shape).position(vec2(x, y)))
                .unwrap(),
        );
    }
    (w, ids)
}

#[test]
fn crowd_column_dump() {
    let (mut w, ids) = crowd_world(4);
    for _ in 0..600 {
        w.step();
    }
    for (i, &id) in ids.iter().enumerate() {
        if i % 16 == 5 {
            let b = w.body(id).unwrap();
            println!(
                "#{i} p {:?} v {:?} {:?} awake {}",
                b.position().to_f64(),
                b.velocity().to_f64(),
                b.shape(),
                b.is_awake()
            );
        }
    }
    // column alone on a floor
    let col: Vec<(Shape, f64)> = ids
        .iter()
        .enumerate()
        .filter(|(i, _)| i % 16 == 5)
        .map(|(_, &id)| {
            let b = w.body(id).unwrap();
            (b.shape(), b.position().to_f64().1)
        })
        .collect();
    for variant in 0..3 {
        let mut w2 = World::new(WorldSettings::default());
        fixed_box(&mut w2, 4.1, 0.05, 0.0, -8.05);
        if variant >= 1 {
            // walls close to the column
            fixed_box(
                &mut w2,
                0.05,
                8.0,
                -0.25 - 0.05 - if variant == 2 { 0.0 } else { 0.3 },
                0.0,
            );
            fixed_box(
                &mut w2,
                0.05,
                8.0,
                0.25 + 0.05 + if variant == 2 { 0.0 } else { 0.3 },
                0.0,
            );
        }
        let mut cids = vec![];
        for (k, &(shape, _)) in col.iter().enumerate() {
            let y = -8.0 + 0.25 + 0.5 * (k * 16 + 5) as f64 / 16.0 * 0.0 + 0.5 * k as f64;
            cids.push(
                w2.add_body(BodyDef::dynamic(shape).position(vec2(0.0, y)))
                    .unwrap(),
            );
        }
        let mut vmax: f64 = 0.0;
        for tk in 0..600 {
            w2.step();
            if tk > 540 {
                for &id in &cids {
                    vmax = vmax.max(v(&w2, id).1.abs());
                }
            }
        }
        let asleep = cids.iter().all(|&id| !w2.body(id).unwrap().is_awake());
        println!("column alone variant {variant}: vmax last second {vmax:.3}, asleep {asleep}");
    }
}

#[test]
fn crowd_squeeze_grid() {
    for &(wall, g, heavy, seed) in &[
        (0.02, 100.0, true, 5u64),
        (0.1, 100.0, true, 5),
        (2.0, 100.0, true, 5),
        (0.02, 10.0, true, 5),
        (0.1, 100.0, true, 8),
        (0.1, 100.0, true, 9),
        (2.0, 10.0, true, 5),
    ] {
        let mut w = World::new(WorldSettings {
            gravity: vec2(0.0, -g),
            ..WorldSettings::default()
        });
        let (hw, hh) = (4.0, 8.0);
        let t = wall / 2.0;
        for (hx, hy, x, y) in [
            (hw + wall, t, 0.0, -hh - t),
            (hw + wall, t, 0.0, hh + t),
            (t, hh, -hw - t, 0.0),
            (t, hh, hw + t, 0.0),
        ] {
            fixed_box(&mut w, hx, hy, x, y);
        }
        let mut rng = Rng(seed);
        let mut ids = vec![];
        for k in 0..300 {
            let x = -hw + 0.25 + 0.5 * (k % 16) as f64;
            let y = -hh + 0.25 + 0.5 * (k / 16) as f64;
            let s = rng.range(0.05, 0.24);
            let shape = if rng.next() < 0.5 {
                Shape::circle(fx(s))
            } else {
                Shape::aabb(vec2(s, rng.range(0.05, 0.24)))
            };
            let mut d = BodyDef::dynamic(shape).position(vec2(x, y));
            if heavy && k % 10 == 0 {
                d = d.density(fx(1000.0));
            }
            ids.push(w.add_body(d).unwrap());
        }
        let mut worst = (f64::MIN, 0usize, 0usize);
        let mut outside_end = 0;
        let mut over = 0;
        for tk in 1..=1200 {
            w.step();
            for (i, &id) in ids.iter().enumerate() {
                let b = w.body(id).unwrap();
                let (x, y) = b.position().to_f64();
                let (ex, ey) = match b.shape() {
                    Shape::Circle { radius } => (radius.to_f64(), radius.to_f64()),
                    Shape::Aabb { half_extents } => half_extents.to_f64(),
                };
                let r = (x.abs() + ex - hw).max(y.abs() + ey - hh);
                if r > worst.0 {
                    worst = (r, tk, i);
                }
                if r > 0.001 {
                    over += 1;
                }
                if tk == 1200 && (x.abs() > hw || y.abs() > hh) {
                    outside_end += 1;
                }
            }
        }
        let b = w.body(ids[worst.2]).unwrap();
        println!(
            "wall {wall} g {g} heavy {heavy} seed {seed}: worst reach {:.4} at tick {} by #{} ({:?}, mass {:.3}); body-ticks over 0.001: {over}; centres outside at the end: {outside_end}",
            worst.0,
            worst.1,
            worst.2,
            b.shape(),
            b.mass().to_f64()
        );
    }
}

#[test]
fn corner_sweep_bullets_and_seam_bounces() {
    for &bullet in &[true, false] {
        let (mut through, mut deep, mut runs) = (0, 0, 0);
        let mut worst: f64 = 0.0;
        for &speed in &[3.0, 10.0, 24.0, 50.0, 100.0] {
            for ai in 0..15 {
                for k in 0..7 {
                    let mut w = World::new(WorldSettings {
                        sleep_enabled: false,
                        ..WorldSettings::default()
                    });
                    fixed_box(&mut w, 6.0, 1.0, 4.0, -1.0);
                    fixed_box(&mut w, 1.0, 5.0, -1.0, 5.0);
                    let r = 0.05;
                    let ang = (190.0 + 5.0 * ai as f64).to_radians();
                    let d = 3.0 + 0.0371 * k as f64;
                    let (cx, cy) = (r - d * ang.cos(), r - d * ang.sin());
                    let id = w
                        .add_body(
                            BodyDef::dynamic(Shape::circle(fx(r)))
                                .bullet(bullet)
                                .friction(fx(0.0))
                                .position(vec2(cx, cy))
                                .velocity(vec2(speed * ang.cos(), speed * ang.sin())),
                        )
                        .unwrap();
                    let mut wp: f64 = 0.0;
                    for _ in 0..((6.0 / (speed * H)) as usize + 30) {
                        w.step();
                        let (x, y) = p(&w, id);
                        wp = wp.max((r - x).max(r - y));
                    }
                    runs += 1;
                    let (x, y) = p(&w, id);
                    if x < -r || y < -r {
                        through += 1;
                    } else if wp > 0.01 {
                        deep += 1;
                        worst = worst.max(wp);
                    }
                }
            }
        }
        println!(
            "corner sweep bullet {bullet}: {through} through, {deep} deeper than 0.01 (worst {worst:.4}) of {runs}"
        );
    }
    for &square in &[false, true] {
        for &dx in &[0.0, 0.001, 0.005, 0.02, 0.1, 0.2, 0.24] {
            let mut w = World::new(WorldSettings::default());
            fixed_box(&mut w, 1.0, 0.5, -1.0, -0.5);
            fixed_box(&mut w, 1.0, 0.5, 1.0, -0.5);
            let shape = if square {
                Shape::aabb(vec2(0.25, 0.25))
            } else {
                Shape::circle(fx(0.25))
            };
            let b = w
                .add_body(
                    BodyDef::dynamic(shape)
                        .restitution(fx(1.0))
                        .position(vec2(dx, 2.25)),
                )
                .unwrap();
            let (mut bounced, mut apex, mut pv) = (false, f64::MIN, 0.0);
            let mut vx_after = 0.0;
            for _ in 0..150 {
                w.step();
                let vy = v(&w, b).1;
                if !bounced && vy > 0.0 && pv < 0.0 {
                    bounced = true;
                    vx_after = v(&w, b).0;
                }
                if bounced {
                    apex = apex.max(p(&w, b).1 - 0.25);
                    if vy < 0.0 && pv >= 0.0 {
                        break;
                    }
                }
                pv = vy;
            }
            println!(
                "seam bounce square {square} dx {dx}: apex {apex:.4} of 2.0, vx after the bounce {vx_after:.4}"
            );
        }
    }
}

#[test]
fn radial_pair_substeps_and_bendy() {
    for &(substeps, bendy, wh, ratio) in &[
        (1u32, false, 3.0, 100.0),
        (2, false, 3.0, 100.0),
        (4, false, 3.0, 100.0),
        (1, true, 3.0, 100.0),
        (1, true, 10.0, 100.0),
        (1, true, 3.0, 1.0),
        (8, false, 3.0, 100.0),
    ] {
        let mut w = World::new(WorldSettings {
            sleep_enabled: false,
            substeps,
            ..WorldSettings::default()
        });
        let seg = 0.2;
        let (m0, m1) = (0.1, 0.1 * ratio);
        let k1 = wh * wh / (H * H) / (1.0 / m0);
        let k2 = wh * wh / (H * H) / (1.0 / m0 + 1.0 / m1);
        let a = w
            .add_body(
                BodyDef::dynamic(Shape::circle(fx(0.02)))
                    .mass(fx(m0))
                    .position(vec2(seg, 0.0)),
            )
            .unwrap();
        let b = w
            .add_body(
                BodyDef::dynamic(Shape::circle(fx(0.02)))
                    .mass(fx(m1))
                    .position(vec2(2.0 * seg, 0.0)),
            )
            .unwrap();
        if bendy {
            w.add_constraint(
                Constraint::bendy_spring(
                    Anchor::Point(Vec2::ZERO),
                    Anchor::Body(a),
                    vec2(k1, k1),
                    fx(0.0),
                )
                .with_rest_offset(vec2(seg, 0.0)),
            )
            .unwrap();
            w.add_constraint(
                Constraint::bendy_spring(Anchor::Body(a), Anchor::Body(b), vec2(k2, k2), fx(0.0))
                    .with_rest_offset(vec2(seg, 0.0)),
            )
            .unwrap();
        } else {
            w.add_constraint(Constraint::radial_spring(
                Anchor::Point(Vec2::ZERO),
                Anchor::Body(a),
                fx(seg),
                fx(k1),
                fx(0.0),
            ))
            .unwrap();
            w.add_constraint(Constraint::radial_spring(
                Anchor::Body(a),
                Anchor::Body(b),
                fx(seg),
                fx(k2),
                fx(0.0),
            ))
            .unwrap();
        }
        let en = |w: &World| {
            let (pa, pb, va, vb) = (p(w, a), p(w, b), v(w, a), v(w, b));
            let (l1, l2) = if bendy {
                (
                    ((pa.0 - seg).powi(2) + pa.1 * pa.1).sqrt(),
                    ((pb.0 - pa.0 - seg).powi(2) + (pb.1 - pa.1).powi(2)).sqrt(),
                )
            } else {
                (
                    pa.0.hypot(pa.1) - seg,
                    (pb.0 - pa.0).hypot(pb.1 - pa.1) - seg,
                )
            };
            0.5 * m0 * (va.0 * va.0 + va.1 * va.1)
                + 0.5 * m1 * (vb.0 * vb.0 + vb.1 * vb.1)
                + 10.0 * (m0 * pa.1 + m1 * pb.1)
                - 0.5 * 10.0 * H / substeps as f64 * (m0 * va.1 + m1 * vb.1)
                + 0.5 * k1 * l1 * l1
                + 0.5 * k2 * l2 * l2
        };
        let e0 = en(&w);
        let mut rise: f64 = f64::MIN;
        for _ in 0..1200 {
            w.step();
            rise = rise.max(en(&w) - e0);
        }
        println!(
            "pair substeps {substeps} bendy {bendy} omega*h {wh} ratio {ratio}: max energy rise {rise:.4e} J (PE scale {:.2})",
            10.0 * (m0 + m1) * 2.0 * seg
        );
    }
}
