//! Contacts of bodies whose centres coincide: the geometry gives no normal,
//! so one is chosen from the pair's slot indices.
//!
//! # Why from the ids
//!
//! Two shapes with the same centre overlap symmetrically: every direction
//! separates them equally well. The shape functions return a fixed
//! fallback (`+Y`), which is fine for one pair but not for a crowd spawned
//! at one point: every pair would be pushed apart along the same axis, the
//! crowd would become a column, and the column would be forced through
//! whatever fixed body caps it. Choosing the direction from the pair's
//! indices instead spreads a crowd in many directions at once, and stays
//! deterministic (the indices are part of the state, the same on every
//! peer and after a restore).
//!
//! The directions are the 16 unit vectors of rational coordinates
//! `(±1, 0)`, `(0, ±1)`, `(±4/5, ±3/5)`, `(±3/5, ±4/5)`, `(±12/13, ±5/13)`
//! (Pythagorean triples: unit length up to one rounding per component, no
//! square root, no trigonometry); boxes take the axis directions only, as
//! their contact normals are always face normals.

use crate::geometry::{Contact, Shape};
use crate::math::{Scalar, Vec2};

/// A well-mixed 32-bit value of the pair `(a, b)` (a multiply-xorshift
/// hash; fixed, so the same on every target).
fn pair_hash(a: u32, b: u32) -> u32 {
    let mut x = a.wrapping_mul(0x9E37_79B1) ^ b.wrapping_mul(0x85EB_CA77).rotate_left(13);
    x ^= x >> 15;
    x = x.wrapping_mul(0x2C1B_3C6D);
    x ^= x >> 12;
    x
}

/// The unit direction number `k` (mod 16) of the table in the module notes.
fn direction<S: Scalar>(k: u32) -> Vec2<S> {
    // The first quadrant's four directions (by angle: 0°, 22.6°, 36.9°,
    // 53.1°); the other quadrants are their quarter turns.
    let (x, y) = match k % 4 {
        0 => (S::ONE, S::ZERO),
        1 => (S::from_ratio(12, 13), S::from_ratio(5, 13)),
        2 => (S::from_ratio(4, 5), S::from_ratio(3, 5)),
        _ => (S::from_ratio(3, 5), S::from_ratio(4, 5)),
    };
    let base = Vec2::new(x, y);
    // Quarter turn: (x, y) → (−y, x).
    (0..(k / 4) % 4).fold(base, |v, _| Vec2::new(v.y.neg(), v.x))
}

/// The contact of shapes `a` (slot `ia`) and `b` (slot `ib`) with the same
/// centre: the pair's direction, and the separation along it (the negated
/// sum of the shapes' extents along that direction: the distance either
/// body must move to separate them).
pub(crate) fn coincident_contact<S: Scalar>(
    ia: u32,
    a: &Shape<S>,
    ib: u32,
    b: &Shape<S>,
) -> Contact<S> {
    let hash = pair_hash(ia, ib);
    let any_box = matches!(a, Shape::Aabb { .. }) || matches!(b, Shape::Aabb { .. });
    // Boxes: an axis direction (every fourth entry of the table).
    let normal = if any_box {
        direction::<S>((hash % 4) * 4)
    } else {
        direction::<S>(hash % 16)
    };
    // Extent of a shape along an axis direction or (circles) any direction.
    let extent = |shape: &Shape<S>| match *shape {
        Shape::Circle { radius } => radius,
        Shape::Aabb { half_extents } => {
            if normal.x == S::ZERO {
                half_extents.y
            } else {
                half_extents.x
            }
        }
    };
    Contact {
        normal,
        separation: extent(a).add(extent(b)).neg(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::{Fx, WideScalar};

    #[test]
    fn directions_are_unit_and_distinct() {
        let all: Vec<Vec2<Fx>> = (0..16).map(direction).collect();
        for (i, d) in all.iter().enumerate() {
            let len = d.length_squared_wide().narrow();
            assert!(
                (len.to_f64() - 1.0).abs() < 1e-8,
                "direction {i} has |d|² = {len:?}"
            );
            for e in &all[..i] {
                assert_ne!(d, e);
            }
        }
    }

    #[test]
    fn pairs_of_a_crowd_use_every_direction() {
        let mut seen = [0u32; 16];
        for a in 0..40 {
            for b in a + 1..40 {
                seen[(pair_hash(a, b) % 16) as usize] += 1;
            }
        }
        // 780 pairs over 16 directions: 48.75 each on average; each is used
        // (a fair hash puts fewer than 20 in one with negligible odds).
        assert!(seen.iter().all(|&n| n >= 20), "{seen:?}");
    }

    #[test]
    fn separation_is_the_extent_along_the_normal() {
        let circle = Shape::<Fx>::Circle {
            radius: Fx::from_f64(0.5),
        };
        let boxy = Shape::<Fx>::Aabb {
            half_extents: Vec2::new(Fx::from_f64(0.25), Fx::from_f64(0.75)),
        };
        for ia in 0..8 {
            let c = coincident_contact(ia, &circle, ia + 1, &circle);
            assert_eq!(c.separation, Fx::from_f64(-1.0));
            let c = coincident_contact(ia, &circle, ia + 1, &boxy);
            let expected = if c.normal.x == Fx::ZERO { -1.25 } else { -0.75 };
            assert_eq!(c.separation, Fx::from_f64(expected));
            assert!(c.normal.x == Fx::ZERO || c.normal.y == Fx::ZERO);
        }
    }
}
