//! Contact between two circles.
//!
//! # The maths
//!
//! With `d = c_b − c_a` and `L = |d|`, the surfaces are `L − (r_a + r_b)`
//! apart along `n = d / L`. One square root (`try_normalize_with_length`
//! gives both `n` and `L`); `L²` is formed exactly in the wide type, so
//! there is no overflow for any centres inside the world bounds.
//!
//! # Accuracy (for `Fx`, inputs inside ±`WORLD_LIMIT`)
//!
//! * `L` is `floor(√(L²))` on the ulp grid: `L − 1 ulp < L_fx ≤ L`. The
//!   subtraction of the radii is exact, so
//!   `separation* − 1 ulp < separation ≤ separation*`.
//! * Each normal component is `d_i / L_fx` truncated toward zero:
//!   `|n_i − d_i/L| ≤ (|d_i|/L)·(ulp/L_fx) + ulp ≤ ulp·(1 + 1/L_fx)`, so the
//!   normal is unit length within `ulp·(1 + 1/L)·√2` (2.3e-7 for centres
//!   1e-3 apart, 7e-10 for centres ≥ 1 apart). Since `L_fx ≥ |d_i|`
//!   (`|d_i|` is on the grid and below `√(L²)`), `|n_i| ≤ 1`; an
//!   axis-aligned offset gives an exact axis normal.
//!
//! # Symmetry
//!
//! Swapping `a` and `b` negates `d` exactly, leaves `L²` (hence `L`)
//! unchanged, and the fixed-point division truncates toward zero, so the
//! result is **exactly** the flipped contact: same separation, normal
//! negated bit for bit. The one exception is coincident centres, where the
//! normal is `+Y` in both orders (there is nothing to orient it by).

use super::{Circle, Contact};
use crate::math::{Scalar, Vec2};

/// The contact between circles `a` and `b`: the unit normal from `a`'s centre
/// towards `b`'s, and the signed distance between the circles' surfaces
/// (negative when they overlap).
///
/// Coincident centres give the normal `+Y` `(0, 1)` and the separation
/// `−(r_a + r_b)` (pushing `b` up by `r_a + r_b` separates them).
/// Accuracy for `Fx`: separation within 1 ulp (rounded down), normal within
/// `ulp·(1 + 1/distance)` per component; see the module notes in `src/geometry/contact_circle_circle.rs`.
///
/// ```
/// use clockwork2d::geometry::*;
/// use clockwork2d::math::*;
/// use clockwork2d::prelude::*;
/// let a = Circle::new(Vec2::new(fx(0.0), fx(0.0)), fx(1.0));
/// let b = Circle::new(Vec2::new(fx(3.0), fx(4.0)), fx(2.0));
/// let c = contact_circle_circle(&a, &b);
/// assert_eq!(c.separation, fx(2.0)); // 5 − (1 + 2)
/// // 3/5 and 4/5, truncated to the ulp grid (within 1 ulp):
/// assert!(c.normal.x.sub(fx(0.6)).abs() <= Fx::DELTA);
/// assert!(c.normal.y.sub(fx(0.8)).abs() <= Fx::DELTA);
/// // Coincident centres: +Y by convention.
/// let c = contact_circle_circle(&a, &a);
/// assert_eq!((c.normal, c.separation), (Vec2::Y, fx(-2.0)));
/// ```
#[must_use]
pub fn contact_circle_circle<S: Scalar>(a: &Circle<S>, b: &Circle<S>) -> Contact<S> {
    let radii = a.radius.add(b.radius);
    match (b.center - a.center).try_normalize_with_length() {
        Some((normal, distance)) => Contact {
            normal,
            separation: distance.sub(radii),
        },
        None => Contact {
            normal: Vec2::Y,
            separation: radii.neg(),
        },
    }
}
