//! Chains of ropes that fall onto themselves under a heavy end (issue 13).
//!
//! A chain of `n` light links (mass 0.1, radius 0.01) joined by ropes of
//! length 0.1 from a fixed point is stacked straight up above it, each link
//! half a rope above the one before, the last one `ratio` times a link;
//! exactly upright, or leaning by 1e-4 per link. Released at rest, the
//! chain falls past its anchor; the lower ropes come taut first and stop
//! their links, the links above fall onto them, and the heavy end lands on
//! that pile of links (held by the ropes above the anchor) before its own
//! ropes catch it. A pile of light links carrying the heavy end, with
//! slack ropes between the same links, is where a warm-started contact
//! fought a slack rope: when the pile shifted, a contact between two
//! links kept last tick's impulse (214 at 10⁴×, the heavy end's load)
//! while the contacts around it lost theirs, the exact tree solve of the
//! ropes held it with the slack rope between the same two links, the
//! rope's sideways stiffness was then raised from that impulse, and the
//! links left the velocity solve at 100–6000 units/s: ropes 345 % to
//! 10⁶ % long (`world::step::energy_guard`, "Ropes and contacts").
//!
//! Bounds, at every tick:
//! * every rope within the slop (1e-4, 0.1 % of a rope) plus the rounding
//!   of the last rope settling round (`ROUNDING`, derived in
//!   `tests/chains_snapping_taut.rs`: `δ²/(2ℓ)` for a correction `δ` of the
//!   order of the slop, 5e-7 of stretch);
//! * no link faster than the speed a body reaches by falling from its start
//!   to the lowest point the chain allows (`n` ropes below the anchor)
//!   plus the rope's speed budget below: a solve that conserves or loses
//!   energy cannot give one link more than the whole chain's fall, and the
//!   chain's potential energy `Σ m_k·g·Δy_k` spread over one link of mass
//!   0.1 is the strict bound `√(2·Σ m_k·g·Δy_k / 0.1)`.
//!
//! Figures print with `--nocapture`.

use clockwork2d::prelude::*;

mod common;
use common::chain_stretch::worst_stretch;
use common::oscillators::{pos, vel};

const LINK_MASS: f64 = 0.1;
const SEGMENT: f64 = 0.1;
const SLOP: f64 = 1e-4;
const G: f64 = 10.0;
/// See the module notes.
const ROUNDING: f64 = 1e-6;
/// 10 s in release, 4 s in the slower debug profile (the chains land
/// within the first second).
const TICKS: usize = if cfg!(debug_assertions) { 240 } else { 600 };

#[derive(Clone, Copy, Debug)]
struct Fall {
    links: usize,
    ratio: f64,
    substeps: u32,
    lean: f64,
}

/// Runs one chain; returns its worst stretch, its fastest link and the
/// speed bound of the module notes.
fn run(fall: Fall) -> (f64, f64, f64) {
    let Fall {
        links,
        ratio,
        substeps,
        lean,
    } = fall;
    let mut world = World::new(WorldSettings {
        substeps,
        ..WorldSettings::default()
    });
    let mut ids: Vec<BodyId> = Vec::new();
    let mut drop_energy = 0.0;
    for k in 1..=links {
        let mass = if k == links {
            LINK_MASS * ratio
        } else {
            LINK_MASS
        };
        let y = 0.5 * SEGMENT * k as f64;
        let id = world
            .add_body(
                BodyDef::dynamic(Shape::circle(fx(0.01)))
                    .mass(fx(mass))
                    .position(vec2(lean * k as f64, y)),
            )
            .expect("link");
        let anchor = match ids.last() {
            Some(&previous) => Anchor::Body(previous),
            None => Anchor::Point(vec2(0.0, 0.0)),
        };
        world
            .add_constraint(Constraint::rope(anchor, Anchor::Body(id), fx(SEGMENT)))
            .expect("rope");
        ids.push(id);
        // The lowest a link can go is `links` ropes below the anchor.
        drop_energy += mass * G * (y + SEGMENT * links as f64);
    }
    let speed_bound = (2.0 * drop_energy / LINK_MASS).sqrt();
    let (mut worst, mut fastest) = (0.0f64, 0.0f64);
    for _ in 0..TICKS {
        world.step();
        worst = worst.max(worst_stretch(&world, (0.0, 0.0), &ids, SEGMENT));
        for &id in &ids {
            let v = vel(&world, id);
            fastest = fastest.max(v.0.hypot(v.1));
        }
        assert!(pos(&world, ids[0]).1.is_finite());
    }
    (worst, fastest, speed_bound)
}

fn family() -> Vec<Fall> {
    let mut falls = Vec::new();
    for links in [5, 10, 15, 20, 25, 30, 40] {
        for ratio in [100.0, 1000.0, 3000.0, 10000.0, 30000.0] {
            for substeps in [1, 2, 4] {
                for lean in [0.0, 1e-4] {
                    falls.push(Fall {
                        links,
                        ratio,
                        substeps,
                        lean,
                    });
                }
            }
        }
    }
    falls
}

/// Every chain of the family keeps every rope within the slop at every
/// tick, and no link outruns the chain's whole fall. Debug runs take every
/// 9th chain.
#[test]
fn chains_falling_onto_themselves_under_heavy_ends_keep_their_length() {
    let step = if cfg!(debug_assertions) { 9 } else { 1 };
    let slop_fraction = SLOP / SEGMENT;
    let mut failures = Vec::new();
    let mut checked = 0;
    for fall in family().into_iter().step_by(step) {
        let (worst, fastest, bound) = run(fall);
        checked += 1;
        if worst > slop_fraction + ROUNDING || fastest > bound {
            failures.push(format!(
                "{fall:?}: worst stretch {:.4} % (slop {:.4} %), fastest link {fastest:.2} (bound {bound:.2})",
                worst * 100.0,
                slop_fraction * 100.0
            ));
        }
    }
    println!("{checked} chains, {} beyond a bound", failures.len());
    for failure in &failures {
        println!("  {failure}");
    }
    assert!(
        failures.is_empty(),
        "{} chains beyond a bound",
        failures.len()
    );
}
