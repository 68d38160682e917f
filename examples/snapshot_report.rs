use clockwork2d::World;
use clockwork2d::scene::builtin;
fn main() {
    for (name, ticks) in [
        ("pyramid", 600u64),
        ("balls", 120),
        ("mixed", 300),
        ("stack", 600),
    ] {
        let mut w: World = builtin(name).unwrap().build().unwrap();
        for _ in 0..ticks {
            w.step();
        }
        let bytes = w.snapshot();
        let r: World = World::restore(&bytes).unwrap();
        assert_eq!(r.state_hash(), w.state_hash());
        println!(
            "{name}: {} bodies, {} bytes, {} per body, contacts {}",
            w.body_count(),
            bytes.len(),
            bytes.len() / w.body_count(),
            w.touching_pairs().count()
        );
    }
}
