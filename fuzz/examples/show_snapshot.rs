//! Prints what a `snapshot_restore` input holds and what stepping it costs:
//! the settings, the bodies and constraints, the pair estimate of
//! `cost::pairs_near`, then every tick the target would step (raw bytes,
//! then the repaired frame) with its wall time and touching pairs:
//! `cargo run --release --manifest-path fuzz/Cargo.toml --example show_snapshot -- FILE`.

use clockwork2d::prelude::{Fx, World};
use clockwork2d_fuzz::cost::pairs_near;
use clockwork2d_fuzz::frame::{Kind, repaired};
use std::time::Instant;

fn show(label: &str, bytes: &[u8]) {
    let mut world = match World::<Fx>::restore(bytes) {
        Ok(world) => world,
        Err(error) => {
            println!("{label}: refused: {error}");
            return;
        }
    };
    println!(
        "{label}: {} bodies, {} constraints",
        world.body_count(),
        world.constraints().count()
    );
    println!("{:#?}", world.settings());
    let mut kinds = std::collections::BTreeMap::<String, usize>::new();
    for (_, constraint) in world.constraints() {
        let name = format!("{constraint:?}");
        let kind = name
            .split(['(', ' ', '{'])
            .next()
            .unwrap_or("?")
            .to_string();
        *kinds.entry(kind).or_default() += 1;
    }
    println!("constraints by kind: {kinds:?}");
    let mut shapes = std::collections::BTreeMap::<String, usize>::new();
    for (_, body) in world.bodies() {
        let key = format!(
            "{:?} {:?} m {} e {} mu {} g {}",
            body.kind(),
            body.shape(),
            body.mass(),
            body.restitution(),
            body.friction(),
            body.gravity_scale()
        );
        *shapes.entry(key).or_default() += 1;
    }
    let mut census: Vec<_> = shapes.into_iter().collect();
    census.sort_by_key(|(_, n)| std::cmp::Reverse(*n));
    for (key, n) in census.iter().take(12) {
        println!("{n:6} x {key}");
    }
    println!("({} distinct bodies)", census.len());
    println!("pairs_near: {}", pairs_near(&world, u64::MAX));
    let mut fast: Vec<(f64, String)> = world
        .bodies()
        .map(|(id, body)| {
            let v = body.velocity();
            (
                v.x.to_num::<f64>().hypot(v.y.to_num::<f64>()),
                format!("{id:?} at {:?} v {:?}", body.position(), v),
            )
        })
        .collect();
    fast.sort_by(|a, b| b.0.total_cmp(&a.0));
    for (speed, what) in fast.iter().take(5) {
        println!("fast at start: {speed:.1} u/s {what}");
    }
    for tick in 1..=10 {
        let start = Instant::now();
        world.step();
        let elapsed = start.elapsed().as_secs_f64() * 1e3;
        let (mut fastest, mut lo, mut hi) = (0.0f64, [f64::MAX; 2], [f64::MIN; 2]);
        for (_, body) in world.bodies() {
            let v = body.velocity();
            fastest = fastest.max(v.x.to_num::<f64>().hypot(v.y.to_num::<f64>()));
            let p = body.position();
            for (axis, value) in [p.x.to_num::<f64>(), p.y.to_num::<f64>()]
                .into_iter()
                .enumerate()
            {
                lo[axis] = lo[axis].min(value);
                hi[axis] = hi[axis].max(value);
            }
        }
        println!(
            "tick {tick}: {elapsed:.1} ms, {} touching pairs, pairs_near {}, fastest {fastest:.1} u/s, positions x {:.1}..{:.1} y {:.1}..{:.1}",
            world.touching_pairs().count(),
            pairs_near(&world, u64::MAX),
            lo[0],
            hi[0],
            lo[1],
            hi[1]
        );
    }
}

fn main() {
    let path = std::env::args().nth(1).expect("usage: show_snapshot FILE");
    let bytes = std::fs::read(&path).expect("readable input");
    show("raw", &bytes);
    let fixed = repaired(&bytes, Kind::Snapshot);
    if let Some(fixed) = &fixed {
        show("repaired", fixed);
    }
    // A second file: what differs from it (e.g. the seed an input grew from).
    if let Some(reference) = std::env::args().nth(2) {
        let reference = std::fs::read(&reference).expect("readable reference");
        let input = fixed.as_deref().unwrap_or(&bytes);
        match clockwork2d::diff::diff_snapshots(&reference, input) {
            Ok(differences) => {
                for d in differences {
                    println!("differs: {}: {}", d.part, d.description);
                }
            }
            Err(error) => println!("no diff: {error}"),
        }
    }
}
