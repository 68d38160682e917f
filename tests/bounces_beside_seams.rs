//! A circle landing beside the seam of two flush fixed tiles bounces as off
//! one flat face: straight back, to `e²·h`, with no sideways motion — and
//! a real corner still deflects.
//!
//! The physics: two tiles whose faces lie in one plane make one flat face.
//! Their seam is a line in that plane; the corner of the tile the ball is
//! not over lies on the other tile's face, so the ball (held above that
//! face) can never touch it. Dropped from rest, the ball meets the plane
//! with a vertical normal: the bounce is vertical (no impulse along the
//! face, so the velocity along it stays zero and the centre keeps its
//! coordinate along the face), and the apex of the rebound is `e²·h`.
//!
//! Tolerances:
//! - Along the face: every row the ball takes is along the face's normal,
//!   exactly `(0, ±1)` or `(±1, 0)` in fixed point, so no impulse has a
//!   component along the face and the velocity along it stays exactly 0;
//!   we allow `1e-9` (a few units of the last place of I32F32, 2.3e-10).
//!   Before the fix the ball took a row from the other tile's corner,
//!   tilted by `atan(dx/r)`, and left with up to `(1 + e)·v·dx/r`
//!   sideways: 0.025 units/s at dx 0.001 off a 0.25 ball at 6.3 units/s.
//! - The apex: as tests/bounces_on_pegs_edges_seams.rs derives, within
//!   `(1 + e²)·g·h_t²/8 + slop` of `e²·h` (semi-implicit Euler samples the
//!   parabolas at most `g·h_t²/8` below their vertices; the contact settles
//!   within the slop).
//!
//! The family: circles of radius 0.05, 0.25 and 1 (the largest spans
//! several seams of tiles 0.25 wide), tiles 1 and 0.25 wide, the seam
//! under the ball's centre offset by ±1e-4 .. ±0.8 r, e 1 and 0.5, drops
//! of 0.5 and 2, gravity down onto a floor, sideways onto a wall of stacked
//! tiles and up onto a ceiling, at the origin and near the world's bounds
//! (30 000). A neighbour lower by 0.01 (a step down: its corner is behind
//! the face the ball lands on) changes nothing either.
//!
//! Controls that must still deflect (a real corner): the ball landing with
//! its centre beyond the edge of a lone tile, or beside a neighbour higher
//! by 0.01, leaves sideways, away from the corner.

use clockwork2d::prelude::*;

const G: f64 = 10.0;
const TICK: f64 = 1.0 / 60.0;
const SLOP: f64 = 1e-4;
/// Velocity and position along the face: exact up to rounding.
const ALONG: f64 = 1e-9;

/// The direction of gravity, and so the face the ball lands on.
#[derive(Clone, Copy, Debug)]
enum Face {
    /// Gravity −y onto a floor.
    Floor,
    /// Gravity +x onto a wall of stacked tiles.
    Wall,
    /// Gravity +y onto a ceiling.
    Ceiling,
}

impl Face {
    /// World coordinates of a point given along the face (`u`) and out of
    /// it towards the ball (`w`), the face's plane through `origin`.
    fn at(self, origin: (f64, f64), u: f64, w: f64) -> (f64, f64) {
        match self {
            Face::Floor => (origin.0 + u, origin.1 + w),
            Face::Wall => (origin.0 - w, origin.1 + u),
            Face::Ceiling => (origin.0 + u, origin.1 - w),
        }
    }

    /// Along-face and out-of-face components of a world vector.
    fn split(self, v: (f64, f64)) -> (f64, f64) {
        match self {
            Face::Floor => (v.0, v.1),
            Face::Wall => (v.1, -v.0),
            Face::Ceiling => (v.0, -v.1),
        }
    }

    fn gravity(self) -> Vec2 {
        match self {
            Face::Floor => vec2(0.0, -G),
            Face::Wall => vec2(G, 0.0),
            Face::Ceiling => vec2(0.0, G),
        }
    }

    /// A tile's half extents: `along` the face, `depth` out of it.
    fn half(self, along: f64, depth: f64) -> Vec2 {
        match self {
            Face::Floor | Face::Ceiling => vec2(along, depth),
            Face::Wall => vec2(depth, along),
        }
    }
}

/// What is beside the tile the ball lands over.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Neighbour {
    /// A flush tile: one flat face.
    Flush,
    /// A tile whose face is 0.01 farther from the ball (a step down).
    Lower,
    /// Nothing (a lone tile's edge): a real corner.
    None,
    /// A tile whose face is 0.01 nearer the ball (a step up): a real corner.
    Higher,
}

struct Drop {
    face: Face,
    origin: (f64, f64),
    tile: f64,
    radius: f64,
    /// The ball's centre along the face from the seam (positive: over the
    /// tile the ball lands on).
    offset: f64,
    neighbour: Neighbour,
    e: f64,
    height: f64,
}

/// After the first bounce: velocity along the face, displacement along the
/// face, and the first apex above the face.
fn drop(d: &Drop) -> (f64, f64, f64) {
    let mut world = World::new(WorldSettings {
        gravity: d.face.gravity(),
        ..WorldSettings::default()
    });
    let depth = 0.5;
    let half = d.face.half(d.tile / 2.0, depth);
    // The landing tile spans [0, tile] along the face from the seam; the
    // neighbour [-tile, 0]; a row of tiles on each side beyond, so the
    // largest ball (r 1 over tiles 0.25) lands over several seams.
    let tiles = (2.0 * d.radius / d.tile).ceil() as i32 + 1;
    let mut fixed = |u: f64, face_at: f64| {
        let (x, y) = d.face.at(d.origin, u, face_at - depth);
        world
            .add_body(BodyDef::fixed(Shape::aabb(half)).position(vec2(x, y)))
            .expect("tile");
    };
    for k in 0..tiles {
        fixed((k as f64 + 0.5) * d.tile, 0.0);
    }
    let neighbour_face = match d.neighbour {
        Neighbour::Flush => Some(0.0),
        Neighbour::Lower => Some(-0.01),
        Neighbour::Higher => Some(0.01),
        Neighbour::None => None,
    };
    if let Some(level) = neighbour_face {
        for k in 0..tiles {
            fixed(-(k as f64 + 0.5) * d.tile, level);
        }
    }
    let start = d.face.at(d.origin, d.offset, d.radius + d.height);
    let ball = world
        .add_body(
            BodyDef::dynamic(Shape::circle(fx(d.radius)))
                .restitution(fx(d.e))
                .position(vec2(start.0, start.1)),
        )
        .expect("ball");
    let (mut bounced, mut apex, mut previous_out) = (false, f64::MIN, 0.0);
    let (mut along_v, mut along_x) = (0.0, 0.0);
    let ticks = (2.5 * (2.0 * d.height / G).sqrt() / TICK) as usize + 20;
    for _ in 0..ticks {
        world.step();
        let b = world.body(ball).unwrap();
        let (v_along, v_out) = d.face.split(b.velocity().to_f64());
        let p = b.position().to_f64();
        let (u, w) = d.face.split((p.0 - d.origin.0, p.1 - d.origin.1));
        if !bounced && v_out > 0.0 && previous_out < 0.0 {
            bounced = true;
        }
        if bounced {
            apex = apex.max(w - d.radius);
            if along_v.abs() < v_along.abs() {
                along_v = v_along;
            }
            if along_x.abs() < (u - d.offset).abs() {
                along_x = u - d.offset;
            }
            if v_out < 0.0 && previous_out >= 0.0 {
                break;
            }
        }
        previous_out = v_out;
    }
    assert!(bounced, "no bounce");
    (along_v, along_x, apex)
}

#[test]
fn circles_beside_flush_seams_bounce_straight_back() {
    // Release: the whole family; debug (`cargo test`): a spread subset.
    let stride = if cfg!(debug_assertions) { 7 } else { 1 };
    let (mut runs, mut worst_v, mut worst_x, mut worst_apex) = (0usize, 0.0f64, 0.0f64, 0.0f64);
    let mut case = 0usize;
    for face in [Face::Floor, Face::Wall, Face::Ceiling] {
        for origin in [(0.0, 0.0), (30_000.0, -30_000.0)] {
            for tile in [1.0, 0.25] {
                for radius in [0.05, 0.25, 1.0] {
                    for fraction in [1e-4, 1e-3, 5e-3, 0.02, 0.1, 0.3, 0.8] {
                        for sign in [1.0, -1.0] {
                            for neighbour in [Neighbour::Flush, Neighbour::Lower] {
                                for (e, height) in [(1.0, 2.0), (0.5, 0.5)] {
                                    case += 1;
                                    if !case.is_multiple_of(stride) {
                                        continue;
                                    }
                                    // The ball over the landing tile; with
                                    // a lower neighbour only (a flush one
                                    // is symmetric: negative offsets land
                                    // over it).
                                    let offset = sign * fraction * radius;
                                    if neighbour == Neighbour::Lower && offset < 0.0 {
                                        continue;
                                    }
                                    let d = Drop {
                                        face,
                                        origin,
                                        tile,
                                        radius,
                                        offset,
                                        neighbour,
                                        e,
                                        height,
                                    };
                                    let (v, x, apex) = drop(&d);
                                    runs += 1;
                                    let expected = e * e * height;
                                    let tolerance = (1.0 + e * e) * G * TICK * TICK / 8.0 + SLOP;
                                    let what = format!(
                                        "{face:?} at {origin:?}, tiles {tile}, r {radius}, offset {offset}, \
                                         {neighbour:?}, e {e}, drop {height}"
                                    );
                                    assert!(
                                        v.abs() <= ALONG && x.abs() <= ALONG,
                                        "{what}: moved along the face after the bounce: v {v:.3e}, x {x:.3e}"
                                    );
                                    assert!(
                                        (apex - expected).abs() <= tolerance,
                                        "{what}: apex {apex:.6} against {expected} (tolerance {tolerance:.1e})"
                                    );
                                    worst_v = worst_v.max(v.abs());
                                    worst_x = worst_x.max(x.abs());
                                    worst_apex = worst_apex.max((apex - expected).abs());
                                }
                            }
                        }
                    }
                }
            }
        }
    }
    println!(
        "{runs} drops beside seams: along the face |v| <= {worst_v:.2e}, |x| <= {worst_x:.2e}; \
         apex off by <= {worst_apex:.2e}"
    );
}

#[test]
fn real_corners_still_deflect() {
    for face in [Face::Floor, Face::Wall, Face::Ceiling] {
        for radius in [0.05, 0.25] {
            for neighbour in [Neighbour::None, Neighbour::Higher] {
                // Over a lone tile's edge the centre is just beyond it (the
                // ball meets the corner only); beside a higher neighbour the
                // centre is over the landing tile, its corner reachable.
                let offset = match neighbour {
                    Neighbour::None => -0.1 * radius,
                    _ => 0.1 * radius,
                };
                let d = Drop {
                    face,
                    origin: (0.0, 0.0),
                    tile: 1.0,
                    radius,
                    offset,
                    neighbour,
                    e: 1.0,
                    height: 1.0,
                };
                let (v, _, _) = drop(&d);
                // Away from the corner (its normal points from the corner
                // to the centre): a lone tile's corner at u = 0 with the
                // centre at u < 0 throws the ball to −u; a higher
                // neighbour's corner at u = 0 with the centre at u > 0, to
                // +u.
                let away = match neighbour {
                    Neighbour::None => v < 0.0,
                    _ => v > 0.0,
                };
                assert!(
                    away && v.abs() > 1e-3,
                    "{face:?} r {radius} {neighbour:?}: left with {v:.3e} along the face"
                );
            }
        }
    }
}
