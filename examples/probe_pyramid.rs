use clockwork2d::prelude::*;
fn main() {
    let a: Vec<f64> = std::env::args().skip(1).map(|x| x.parse().unwrap()).collect();
    let mut s = WorldSettings::default();
    if a.len() >= 4 { s.linear_slop = fx(a[0]); s.position_correction = fx(a[1]); s.velocity_iterations = a[2] as u32; s.position_iterations = a[3] as u32; }
    let rows = if a.len() >= 5 { a[4] as usize } else { 20 };
    let mut w: World = World::new(s);
    w.add_body(BodyDef::fixed(Shape::aabb(Vec2::new(fx(40.0), fx(0.5)))).position(Vec2::new(fx(0.0), fx(-0.5)))).unwrap();
    let mut top = None;
    for r in 0..rows {
        let n = rows - r;
        for i in 0..n {
            let x = (i as f64 - (n as f64 - 1.0) / 2.0) * 1.05;
            let y = 0.5 + r as f64 * 1.0;
            top = Some(w.add_body(BodyDef::dynamic(Shape::aabb(Vec2::new(fx(0.5), fx(0.5)))).position(Vec2::new(fx(x), fx(y)))).unwrap());
        }
    }
    let top = top.unwrap();
    let y0 = rows as f64 - 0.5;
    let t0 = std::time::Instant::now();
    for t in 0..600 {
        w.step();
        if t % 60 == 0 || t == 599 {
            let b = w.body(top).unwrap();
            let awake = w.bodies().filter(|(_, b)| b.is_awake()).count();
            println!("{t}: top sag {:.5} dx {:.6} awake {awake}", y0 - b.position().y.to_f64(), b.position().x.to_f64());
        }
    }
    println!("ms/step {:.3}", t0.elapsed().as_secs_f64() * 1000.0 / 600.0);
}
