use clockwork2d::prelude::*;

#[test]
fn explore_radial_angular_momentum() {
    let mut s = WorldSettings::default();
    s.gravity = Vec2::ZERO;
    s.sleep_enabled = false;
    let mut w: World = World::new(s);
    let b = w.add_body(BodyDef::dynamic(Shape::circle(fx(0.1))).mass(fx(1.0))
        .position(Vec2::new(fx(2.0), fx(0.0))).velocity(Vec2::new(fx(0.0), fx(3.0)))).unwrap();
    w.add_constraint(Constraint::radial_spring(Anchor::Point(Vec2::ZERO), Anchor::Body(b), fx(2.0), fx(16.0), fx(0.0))).unwrap();
    for n in 0..6001 {
        let body = w.body(b).unwrap();
        let (p, v) = (body.position(), body.velocity());
        let q = p.x.to_f64() * v.y.to_f64() - p.y.to_f64() * v.x.to_f64();
        if n % 600 == 0 { println!("{n} L={q} d={}", (p.x.to_f64().hypot(p.y.to_f64()))); }
        w.step();
    }
}
