use clockwork2d::prelude::*;
fn main() {
    let scene = clockwork2d::scene::builtin("balls").unwrap();
    let mut w: World = scene.build().unwrap();
    for t in 0..600 {
        w.step();
        let fast: Vec<(BodyId, f64)> = w.bodies().filter(|(_, b)| b.velocity().length().to_f64() > 0.05).map(|(i, b)| (i, b.velocity().length().to_f64())).collect();
        if t >= 300 && t < 320 { println!("{t}: fast {} {:?} awake {}", fast.len(), fast.iter().take(3).collect::<Vec<_>>(), w.bodies().filter(|(_, b)| b.is_awake()).count()); }
    }
}
