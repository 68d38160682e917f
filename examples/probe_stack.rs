use clockwork2d::prelude::*;
fn main() {
    let mut s = WorldSettings::default(); let a: Vec<f64> = std::env::args().skip(1).map(|x| x.parse().unwrap()).collect(); if a.len() == 4 { s.linear_slop = fx(a[0]); s.position_correction = fx(a[1]); s.velocity_iterations = a[2] as u32; s.position_iterations = a[3] as u32; } let mut w: World = World::new(s);
    w.add_body(BodyDef::fixed(Shape::aabb(Vec2::new(fx(20.0), fx(0.5)))).position(Vec2::new(fx(0.0), fx(-0.5)))).unwrap();
    let mut ids = vec![];
    for i in 0..10 {
        ids.push(w.add_body(BodyDef::dynamic(Shape::aabb(Vec2::new(fx(0.5), fx(0.5)))).position(Vec2::new(fx(0.0), fx(0.5 + 1.05 * i as f64)))).unwrap());
    }
    for t in 0..600 {
        w.step();
        if t % 30 == 0 || t == 599 {
            let ys: Vec<String> = ids.iter().map(|&id| { let b = w.body(id).unwrap(); format!("{:.5}{}", b.position().y.to_f64() - (0.5 + ids.iter().position(|x| *x == id).unwrap() as f64), if b.is_awake() {"*"} else {""}) }).collect();
            println!("{t}: {}", ys.join(" "));
        }
    }
}
