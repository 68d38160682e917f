//! The `geometry_differential` target's input and checks: contacts, ray
//! casts and times of impact in `Fx` against the same generic code run with
//! the `f64` reference scalar, and against the geometry itself (signed
//! distance functions evaluated in `f64`).
//!
//! # Inputs
//!
//! Two shapes (circles or boxes) with centres within the world bounds
//! (±2¹⁵) and sizes in `[2⁻³², 4096]` (the engine's largest shape), a ray
//! (origin within the bounds, any nonzero direction, `max_distance ≤ 2¹⁷`)
//! and a displacement per shape within ±2¹⁵ per axis. Every `Fx` input is
//! exact in `f64` (at most 17 + 32 = 49 significant bits), so both scalars
//! see the same geometry.
//!
//! # Error bounds (derived; `u = 2⁻³²`, one `Fx` ulp)
//!
//! * `E` (the `f64` side): every `f64` quantity here is a handful of
//!   operations on numbers of magnitude at most `M` (the largest
//!   coordinate, size, displacement or ray length of the input, ≤ 2¹⁸);
//!   each rounds by `2⁻⁵³·M`, so `E = 64·2⁻⁵³·M` (≤ 2⁻²⁹ = 8 u) covers
//!   them with room. It is added to every bound below.
//! * Contacts. Box–box uses only exact additions: `Fx` and `f64` agree
//!   bit for bit. Circle–circle and circle–box (corner region) take one
//!   square root, floored: the separation is low by less than `u`, each
//!   normal component within `u·(1 + 1/L)` (`L` the centre distance, or
//!   the corner distance). Face and inside regions are exact. Swapping the
//!   shapes gives exactly the flipped contact, except the documented ties
//!   (coincident centres, a zero offset on the chosen axis).
//! * Ray casts. Box: every decision exact, the distance truncated (< 1 u),
//!   the point exactly on the face. Circle: the point within 4 u of the
//!   circle (the library's bound; +1 u for a grazing ray of radius up to
//!   2¹²), and `point − (origin + s·dir)` within 2 u per component (the
//!   foot point and the scaled step each round once). So the signed
//!   distance `φ(s)` of `origin + s·dir` to the shape is within
//!   `B_ray = 4 + 1 + 2√2 + 1 < 9 u` of zero at a reported hit, and the
//!   ray enters nowhere earlier by more than that. A miss passes at least
//!   `r − 3 u` from the centre (the library's bound): `min φ ≥ −B_ray`.
//! * Times of impact. The cast runs along `u = d/L` rounded (≤ `u` per
//!   component, so ≤ `√2·L·u` of position at the end of the step), `t` is
//!   truncated to `u` (≤ `|d|·u` of position) and the cast is within 4 u
//!   of the shape: at the reported `t` the shapes' signed distance is
//!   within `B_toi = (√2·L + |d| + 4) u ≤ (2.5|d| + 4) u` of zero
//!   (`L ≤ |d|`); the library documents "about (2|d| + 4) u". A miss
//!   keeps `min φ ≥ −B_toi`.
//! * Hit or miss against `f64`: the two may disagree only inside the
//!   grazing band, where the geometry is within the bound of touching:
//!   at the start (`|φ(0)| ≤ B`, inside or not), at the end of the range
//!   (`|φ(end)| ≤ B`) or at the closest approach (`|min φ| ≤ B`).
//! * Hit distance against `f64` (both hit, not from inside): box within
//!   `2u + 2⁻⁵⁰·s`; circle within `16 u·(1 + r/√(r² − h²))`, the
//!   conditioning of a line crossing a circle at distance `h` from its
//!   centre (a tangent has none: then only the point checks apply).

use arbitrary::{Arbitrary, Unstructured};
use clockwork2d::geometry::{
    Aabb, Circle, Contact, Ray, RayHit, Toi, contact_aabb_aabb, contact_aabb_circle,
    contact_circle_aabb, contact_circle_circle, ray_aabb, ray_circle, toi_aabb_aabb,
    toi_circle_aabb, toi_circle_circle,
};
use clockwork2d::prelude::{Fx, Scalar, Vec2};

/// One `Fx` ulp.
const U: f64 = 1.0 / 4_294_967_296.0;
/// Raw bits of 1.0.
const ONE: i64 = 1 << 32;
/// The world limit, 2¹⁵, in raw bits.
const LIMIT: i64 = ONE << 15;
/// The largest shape size, 4096, in raw bits.
const MAX_SIZE: i64 = ONE << 12;

/// A coordinate within ±2¹⁵: mostly physical values, often edge values,
/// sometimes any bits in the range.
#[derive(Clone, Copy, Debug)]
pub struct Coord(pub Fx);

impl<'a> Arbitrary<'a> for Coord {
    fn arbitrary(u: &mut Unstructured<'a>) -> arbitrary::Result<Self> {
        let tag: u8 = u.arbitrary()?;
        let bits = match tag % 8 {
            // Multiples of 1/256 within ±128.
            0..=2 => i64::from(u.arbitrary::<i16>()?) << 24,
            // Multiples of 2⁻¹⁶ within ±2¹⁵.
            3 => i64::from(u.arbitrary::<i32>()?) << 16,
            // Any bits within the bounds.
            4 => u.arbitrary::<i64>()? % (LIMIT + 1),
            // A physical value off by a few ulps.
            5 => (i64::from(u.arbitrary::<i16>()?) << 24) + i64::from(u.arbitrary::<i8>()?),
            // Edge values.
            _ => *u.choose(&[0, 1, -1, ONE, -ONE, LIMIT, -LIMIT, LIMIT - 1, 1 - LIMIT])?,
        };
        Ok(Coord(Fx::from_bits(bits)))
    }
}

/// A size (radius or half extent) in `[2⁻³², 4096]`.
#[derive(Clone, Copy, Debug)]
pub struct Size(pub Fx);

impl<'a> Arbitrary<'a> for Size {
    fn arbitrary(u: &mut Unstructured<'a>) -> arbitrary::Result<Self> {
        let tag: u8 = u.arbitrary()?;
        let bits = match tag % 8 {
            // Multiples of 1/256 up to 16.
            0..=3 => (i64::from(u.arbitrary::<u16>()? % 4096) + 1) << 24,
            // Multiples of 1/256 up to 4096.
            4 => (i64::from(u.arbitrary::<u32>()? % (4096 * 256)) + 1) << 24,
            // Any bits in range.
            5 => (u.arbitrary::<u64>()? % MAX_SIZE as u64) as i64 + 1,
            // Tiny: a few ulps.
            6 => i64::from(u.arbitrary::<u8>()?) + 1,
            // Edge values.
            _ => *u.choose(&[1, ONE, MAX_SIZE, ONE >> 8, ONE / 2])?,
        };
        Ok(Size(Fx::from_bits(bits)))
    }
}

/// A vector of [`Coord`]s.
#[derive(Clone, Copy, Debug, Arbitrary)]
pub struct CoordVec(pub Coord, pub Coord);

impl CoordVec {
    /// As an engine vector.
    #[must_use]
    pub fn get(self) -> Vec2<Fx> {
        Vec2::new(self.0.0, self.1.0)
    }
}

/// A shape placed in the world.
#[derive(Clone, Copy, Debug, Arbitrary)]
pub enum ShapeInput {
    /// A circle.
    Circle {
        /// Centre.
        center: CoordVec,
        /// Radius.
        radius: Size,
    },
    /// An axis-aligned box.
    Aabb {
        /// Centre.
        center: CoordVec,
        /// Half extents.
        half: (Size, Size),
    },
}

/// Everything one input checks.
#[derive(Clone, Copy, Debug, Arbitrary)]
pub struct GeometryInput {
    /// First shape.
    pub a: ShapeInput,
    /// Second shape.
    pub b: ShapeInput,
    /// Ray origin.
    pub origin: CoordVec,
    /// Ray direction (any length; a zero one skips the ray checks).
    pub direction: CoordVec,
    /// Ray length (`|value| mod 2¹⁷`).
    pub max_distance: Coord,
    /// First shape's displacement over the step.
    pub da: CoordVec,
    /// Second shape's displacement over the step.
    pub db: CoordVec,
}

/// A shape in both scalars.
#[derive(Clone, Copy, Debug)]
enum Solid {
    Circle(Circle<Fx>, Circle<f64>),
    Aabb(Aabb<Fx>, Aabb<f64>),
}

impl Solid {
    fn new(input: ShapeInput) -> Self {
        match input {
            ShapeInput::Circle { center, radius } => {
                let c = Circle::new(center.get(), radius.0);
                Solid::Circle(c, Circle::new(c.center.cast(), c.radius.to_f64()))
            }
            ShapeInput::Aabb { center, half } => {
                let b = Aabb::new(center.get(), Vec2::new(half.0.0, half.1.0));
                Solid::Aabb(b, Aabb::new(b.center.cast(), b.half_extents.cast()))
            }
        }
    }

    fn center(&self) -> (f64, f64) {
        match self {
            Solid::Circle(_, c) => (c.center.x, c.center.y),
            Solid::Aabb(_, b) => (b.center.x, b.center.y),
        }
    }

    /// Largest magnitude involved (for `E`).
    fn magnitude(&self) -> f64 {
        let (x, y) = self.center();
        let size = match self {
            Solid::Circle(_, c) => c.radius,
            Solid::Aabb(_, b) => b.half_extents.x.max(b.half_extents.y),
        };
        x.abs().max(y.abs()) + size
    }

    /// Signed distance from `(px, py)` to the solid (negative inside).
    fn sdf(&self, px: f64, py: f64) -> f64 {
        match self {
            Solid::Circle(_, c) => (px - c.center.x).hypot(py - c.center.y) - c.radius,
            Solid::Aabb(_, b) => box_sdf(
                px - b.center.x,
                py - b.center.y,
                b.half_extents.x,
                b.half_extents.y,
            ),
        }
    }
}

/// Signed distance from `(qx, qy)` (relative to the centre) to a box of
/// half extents `(hx, hy)`.
fn box_sdf(qx: f64, qy: f64, hx: f64, hy: f64) -> f64 {
    let (ox, oy) = (qx.abs() - hx, qy.abs() - hy);
    let outside = ox.max(0.0).hypot(oy.max(0.0));
    outside + ox.max(oy).min(0.0)
}

/// The minimum of a convex function on `[lo, hi]` (golden-section search;
/// 120 steps shrink the interval by 0.618¹²⁰ ≈ 1e-25, far below `f64`'s
/// resolution for any interval here).
fn convex_min(f: impl Fn(f64) -> f64, lo: f64, hi: f64) -> f64 {
    let (mut lo, mut hi) = (lo, hi);
    let g = 0.618_033_988_749_895;
    for _ in 0..120 {
        let m1 = hi - g * (hi - lo);
        let m2 = lo + g * (hi - lo);
        if f(m1) <= f(m2) {
            hi = m2;
        } else {
            lo = m1;
        }
    }
    f(lo).min(f(hi)).min(f(0.5 * (lo + hi)))
}

fn fx_vec(v: Vec2<Fx>) -> (f64, f64) {
    (v.x.to_f64(), v.y.to_f64())
}

/// Runs every check on one input.
///
/// # Panics
/// On any violation: that is the finding.
pub fn check(input: &GeometryInput) {
    let a = Solid::new(input.a);
    let b = Solid::new(input.b);
    check_contact(&a, &b);
    let ray = Ray::new(
        input.origin.get(),
        input.direction.get(),
        Fx::from_bits(input.max_distance.0.to_bits().rem_euclid((ONE << 17) + 1)),
    );
    if let Some(ray) = ray {
        check_ray(&ray, &a);
        check_ray(&ray, &b);
    }
    let (da, db) = (input.da.get(), input.db.get());
    check_toi(&a, da, &b, db);
    check_toi(&b, db, &a, da);
}

/// The contact of two solids in `Fx` and in `f64`.
fn contact(a: &Solid, b: &Solid) -> (Contact<Fx>, Contact<f64>) {
    match (a, b) {
        (Solid::Circle(p, p64), Solid::Circle(q, q64)) => {
            (contact_circle_circle(p, q), contact_circle_circle(p64, q64))
        }
        (Solid::Circle(p, p64), Solid::Aabb(q, q64)) => {
            (contact_circle_aabb(p, q), contact_circle_aabb(p64, q64))
        }
        (Solid::Aabb(p, p64), Solid::Circle(q, q64)) => {
            (contact_aabb_circle(p, q), contact_aabb_circle(p64, q64))
        }
        (Solid::Aabb(p, p64), Solid::Aabb(q, q64)) => {
            (contact_aabb_aabb(p, q), contact_aabb_aabb(p64, q64))
        }
    }
}

fn check_contact(a: &Solid, b: &Solid) {
    let (c, c64) = contact(a, b);
    let (swapped, _) = contact(b, a);
    let e = 64.0 * f64::EPSILON / 2.0 * a.magnitude().max(b.magnitude()).max(1.0);
    let (ax, ay) = a.center();
    let (bx, by) = b.center();
    let coincident = ax == bx && ay == by;
    // Swap symmetry: exactly the flipped contact, but for the documented
    // ties, where the separation is the same and the normal is the
    // positive axis in both orders.
    match (a, b) {
        (Solid::Circle(..), Solid::Circle(..)) if coincident => {
            assert_eq!(swapped, c, "coincident circles: same contact both ways");
        }
        (Solid::Aabb(..), Solid::Aabb(..))
            if (c.normal.x != Fx::ZERO && ax == bx) || (c.normal.y != Fx::ZERO && ay == by) =>
        {
            assert_eq!(swapped, c, "boxes with a zero offset on the contact axis");
        }
        _ => assert_eq!(swapped, c.flipped(), "swapping the shapes"),
    }
    let (sep, sep64) = (c.separation.to_f64(), c64.separation);
    let (nx, ny) = fx_vec(c.normal);
    match (a, b) {
        (Solid::Aabb(..), Solid::Aabb(..)) => {
            // Only exact additions: bit for bit.
            assert_eq!(sep, sep64, "box-box separation, Fx vs f64");
            assert_eq!((nx, ny), (c64.normal.x, c64.normal.y), "box-box normal");
        }
        _ => {
            // One floored square root: low by less than an ulp.
            assert!(
                (sep - sep64).abs() <= U + e,
                "separation {sep} vs f64 {sep64} (more than 1 ulp)"
            );
            // The separation is the signed distance between the shapes.
            let (circle, other, flip) = match (a, b) {
                (Solid::Circle(_, p), _) => (p, b, 1.0),
                (_, Solid::Circle(_, p)) => (p, a, -1.0),
                _ => unreachable!(),
            };
            let truth = other.sdf(circle.center.x, circle.center.y) - circle.radius;
            assert!(
                (sep - truth).abs() <= U + e,
                "separation {sep} vs the geometry {truth}"
            );
            // Normal: each component within u·(1 + 1/L), L the distance
            // whose square root was taken (centre to centre, or centre to
            // the box's nearest point); exact when L is not taken.
            let l = match other {
                Solid::Circle(_, q) => {
                    (q.center.x - circle.center.x).hypot(q.center.y - circle.center.y)
                }
                Solid::Aabb(..) => other.sdf(circle.center.x, circle.center.y).abs(),
            }
            .max(U);
            let tol = U * (1.0 + 1.0 / l) + e;
            assert!(
                (nx - c64.normal.x).abs() <= 2.0 * tol && (ny - c64.normal.y).abs() <= 2.0 * tol,
                "normal ({nx}, {ny}) vs f64 ({}, {}) beyond {tol} (flip {flip})",
                c64.normal.x,
                c64.normal.y
            );
        }
    }
}

/// Outcome of a cast, as a category.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Outcome {
    Inside,
    Hit,
    Miss,
}

fn ray_outcome<S: Scalar>(ray: &Ray<S>, hit: &Option<RayHit<S>>) -> Outcome {
    match hit {
        None => Outcome::Miss,
        // The solid convention for an origin inside; a hit at distance 0
        // from outside has the surface's normal instead.
        Some(h) if h.distance == S::ZERO && h.point == ray.origin && h.normal == -ray.direction => {
            Outcome::Inside
        }
        Some(_) => Outcome::Hit,
    }
}

fn check_ray(ray: &Ray<Fx>, solid: &Solid) {
    let ray64 = Ray {
        origin: ray.origin.cast::<f64>(),
        direction: ray.direction.cast::<f64>(),
        max_distance: ray.max_distance.to_f64(),
    };
    let (hit, hit64) = match solid {
        Solid::Circle(c, c64) => (ray_circle(ray, c), ray_circle(&ray64, c64)),
        Solid::Aabb(b, b64) => (ray_aabb(ray, b), ray_aabb(&ray64, b64)),
    };
    let (ox, oy) = (ray64.origin.x, ray64.origin.y);
    let (dx, dy) = (ray64.direction.x, ray64.direction.y);
    let max = ray64.max_distance;
    let e = 64.0 * f64::EPSILON / 2.0 * (solid.magnitude() + ox.abs().max(oy.abs()) + max).max(1.0);
    let bound = 9.0 * U + e;
    let phi = |s: f64| solid.sdf(ox + s * dx, oy + s * dy);
    let outcome = ray_outcome(ray, &hit);
    let outcome64 = ray_outcome(&ray64, &hit64);
    match (&hit, outcome) {
        (_, Outcome::Inside) => assert!(
            phi(0.0) <= e,
            "ray inside, but its origin is {} outside",
            phi(0.0)
        ),
        (Some(h), Outcome::Hit) => {
            let s = h.distance.to_f64();
            let (px, py) = fx_vec(h.point);
            assert!(s <= max && s >= 0.0, "hit distance {s} outside [0, {max}]");
            // The point is on the surface and on the ray at s.
            let on_surface = match solid {
                Solid::Circle(..) => 5.0 * U + e,
                Solid::Aabb(..) => e,
            };
            assert!(
                solid.sdf(px, py).abs() <= on_surface,
                "hit point {} off the surface",
                solid.sdf(px, py)
            );
            assert!(
                (px - (ox + s * dx)).abs() <= 2.0 * U + e
                    && (py - (oy + s * dy)).abs() <= 2.0 * U + e,
                "hit point ({px}, {py}) not at distance {s} along the ray"
            );
            // Nothing earlier: the ray was outside until s.
            assert!(phi(0.0) >= -e, "hit at {s} from an origin inside");
            let earlier = convex_min(phi, 0.0, s);
            assert!(
                earlier >= -bound,
                "the ray entered the shape (depth {earlier}) before the reported hit at {s}"
            );
            check_ray_normal(solid, h);
        }
        (None, _) => {
            let closest = convex_min(phi, 0.0, max);
            assert!(
                closest >= -bound,
                "a miss, but the ray goes {closest} deep into the shape"
            );
        }
        _ => unreachable!(),
    }
    if outcome != outcome64 {
        let near = phi(0.0).abs() <= bound
            || phi(max).abs() <= bound
            || convex_min(phi, 0.0, max).abs() <= bound;
        assert!(
            near,
            "Fx {outcome:?} vs f64 {outcome64:?} outside the grazing band: φ(0) {}, φ(max) {}, min {}",
            phi(0.0),
            phi(max),
            convex_min(phi, 0.0, max)
        );
    } else if let (Outcome::Hit, Some(h), Some(h64)) = (outcome, hit, hit64) {
        let (s, s64) = (h.distance.to_f64(), h64.distance);
        let tol = match solid {
            Solid::Aabb(..) => 2.0 * U + s64 * 4.0 * f64::EPSILON + e,
            Solid::Circle(_, c) => {
                let (mx, my) = (ox - c.center.x, oy - c.center.y);
                let len = dx.hypot(dy);
                let h = (mx * dy - my * dx).abs() / len;
                let chord = (c.radius * c.radius - h * h).max(0.0).sqrt();
                if chord > 0.0 {
                    16.0 * U * (1.0 + c.radius / chord) + e
                } else {
                    f64::INFINITY
                }
            }
        };
        assert!(
            (s - s64).abs() <= tol,
            "hit distance {s} vs f64 {s64} beyond {tol}"
        );
    }
}

fn check_ray_normal(solid: &Solid, hit: &RayHit<Fx>) {
    let (nx, ny) = fx_vec(hit.normal);
    let (px, py) = fx_vec(hit.point);
    match solid {
        Solid::Circle(_, c) => {
            let (rx, ry) = (px - c.center.x, py - c.center.y);
            let len = rx.hypot(ry).max(U);
            // The point is within 5 u of the circle, so its direction is
            // within 5u/r of the true normal; normalising rounds ~1 u.
            let tol = 8.0 * U * (1.0 + 1.0 / len);
            assert!(
                (nx - rx / len).abs() <= tol && (ny - ry / len).abs() <= tol,
                "circle hit normal ({nx}, {ny}) vs ({}, {})",
                rx / len,
                ry / len
            );
        }
        Solid::Aabb(_, b) => {
            let on_face = match (nx, ny) {
                (1.0, 0.0) => px == b.center.x + b.half_extents.x,
                (-1.0, 0.0) => px == b.center.x - b.half_extents.x,
                (0.0, 1.0) => py == b.center.y + b.half_extents.y,
                (0.0, -1.0) => py == b.center.y - b.half_extents.y,
                _ => false,
            };
            assert!(
                on_face,
                "box hit normal ({nx}, {ny}) is not the face of ({px}, {py})"
            );
        }
    }
}

fn toi_outcome<S: Scalar>(toi: &Toi<S>) -> Outcome {
    match toi {
        Toi::Overlapping => Outcome::Inside,
        Toi::Hit { .. } => Outcome::Hit,
        Toi::Miss => Outcome::Miss,
    }
}

/// Time of impact of `a` moving by `da` and `b` by `db`, both scalars (a
/// box against a circle is the circle against the box, normal negated).
fn check_toi(a: &Solid, da: Vec2<Fx>, b: &Solid, db: Vec2<Fx>) {
    let (da64, db64) = (da.cast::<f64>(), db.cast::<f64>());
    let (toi, toi64) = match (a, b) {
        (Solid::Circle(p, p64), Solid::Circle(q, q64)) => (
            toi_circle_circle(p, da, q, db),
            toi_circle_circle(p64, da64, q64, db64),
        ),
        (Solid::Aabb(p, p64), Solid::Aabb(q, q64)) => (
            toi_aabb_aabb(p, da, q, db),
            toi_aabb_aabb(p64, da64, q64, db64),
        ),
        (Solid::Circle(p, p64), Solid::Aabb(q, q64)) => (
            toi_circle_aabb(p, da, q, db),
            toi_circle_aabb(p64, da64, q64, db64),
        ),
        (Solid::Aabb(p, p64), Solid::Circle(q, q64)) => (
            negated(toi_circle_aabb(q, db, p, da)),
            negated(toi_circle_aabb(q64, db64, p64, da64)),
        ),
    };
    // Relative position of a's centre from b's at time t, and the signed
    // distance of the Minkowski shape (b grown by a) at it.
    let (ax, ay) = a.center();
    let (bx, by) = b.center();
    let (dx, dy) = (da64.x - db64.x, da64.y - db64.y);
    let at = |t: f64| (ax - bx + t * dx, ay - by + t * dy);
    let minkowski = |(px, py): (f64, f64)| match (a, b) {
        (Solid::Circle(_, p), Solid::Circle(_, q)) => px.hypot(py) - (p.radius + q.radius),
        (Solid::Aabb(_, p), Solid::Aabb(_, q)) => box_sdf(
            px,
            py,
            p.half_extents.x + q.half_extents.x,
            p.half_extents.y + q.half_extents.y,
        ),
        (Solid::Circle(_, p), Solid::Aabb(_, q)) => {
            box_sdf(px, py, q.half_extents.x, q.half_extents.y) - p.radius
        }
        (Solid::Aabb(_, p), Solid::Circle(_, q)) => {
            box_sdf(px, py, p.half_extents.x, p.half_extents.y) - q.radius
        }
    };
    let phi = |t: f64| minkowski(at(t));
    let d = dx.hypot(dy);
    let e = 64.0 * f64::EPSILON / 2.0 * (a.magnitude() + b.magnitude() + 2.0 * d).max(1.0);
    let bound = (2.5 * d + 4.0) * U + e;
    let outcome = toi_outcome(&toi);
    match toi {
        Toi::Overlapping => assert!(phi(0.0) <= e, "overlapping, but {} apart", phi(0.0)),
        Toi::Hit { t, normal } => {
            let t = t.to_f64();
            assert!((0.0..=1.0).contains(&t), "t = {t}");
            assert!(phi(0.0) >= -e, "a hit at {t}, but overlapping at 0");
            assert!(
                phi(t).abs() <= bound,
                "at the reported t = {t} the shapes are {} apart (bound {bound})",
                phi(t)
            );
            let earlier = convex_min(phi, 0.0, t);
            assert!(
                earlier >= -bound,
                "the shapes overlap by {earlier} before the reported t = {t}"
            );
            check_toi_normal(a, b, at(t), normal, bound);
        }
        Toi::Miss => {
            let closest = convex_min(phi, 0.0, 1.0);
            assert!(
                closest >= -bound,
                "a miss, but the shapes overlap by {closest} during the step"
            );
        }
    }
    let outcome64 = toi_outcome(&toi64);
    if outcome != outcome64 {
        let near = phi(0.0).abs() <= bound
            || phi(1.0).abs() <= bound
            || convex_min(phi, 0.0, 1.0).abs() <= bound;
        assert!(
            near,
            "TOI Fx {outcome:?} vs f64 {outcome64:?} outside the grazing band: φ(0) {}, φ(1) {}, min {}",
            phi(0.0),
            phi(1.0),
            convex_min(phi, 0.0, 1.0)
        );
    }
}

fn negated<S: Scalar>(toi: Toi<S>) -> Toi<S> {
    match toi {
        Toi::Hit { t, normal } => Toi::Hit { t, normal: -normal },
        other => other,
    }
}

/// The normal at a hit points from `a` to `b`: along `−p` (p = a's centre
/// relative to b's) for two circles, the axis of the faces that meet for
/// two boxes, and the direction into the grown box for a circle and a box.
fn check_toi_normal(a: &Solid, b: &Solid, p: (f64, f64), normal: Vec2<Fx>, bound: f64) {
    let (nx, ny) = fx_vec(normal);
    let (px, py) = p;
    // The outward gradient of the Minkowski shape at p, pointing from b
    // towards a; the normal is its negation. For boxes only the axis and
    // sign are checked (at a corner either face may be reported).
    match (a, b) {
        (Solid::Aabb(_, p_), Solid::Aabb(_, q)) => {
            let (hx, hy) = (
                p_.half_extents.x + q.half_extents.x,
                p_.half_extents.y + q.half_extents.y,
            );
            let ok = match (nx, ny) {
                (x, 0.0) if x.abs() == 1.0 => (px.abs() - hx).abs() <= bound && px * x <= bound,
                (0.0, y) if y.abs() == 1.0 => (py.abs() - hy).abs() <= bound && py * y <= bound,
                _ => false,
            };
            assert!(
                ok,
                "box-box TOI normal ({nx}, {ny}) at relative ({px}, {py})"
            );
        }
        _ => {
            let radius = match (a, b) {
                (Solid::Circle(_, p_), Solid::Circle(_, q)) => p_.radius + q.radius,
                (Solid::Circle(_, p_), _) => p_.radius,
                (_, Solid::Circle(_, q)) => q.radius,
                _ => unreachable!(),
            };
            // Nearest point of the inner shape (b's centre for circles, the
            // box for a circle against a box) to p.
            let (gx, gy) = match (a, b) {
                (Solid::Circle(..), Solid::Circle(..)) => (px, py),
                _ => {
                    let h = match (a, b) {
                        (_, Solid::Aabb(_, q)) | (Solid::Aabb(_, q), _) => q.half_extents,
                        _ => unreachable!(),
                    };
                    (px - px.clamp(-h.x, h.x), py - py.clamp(-h.y, h.y))
                }
            };
            // The normal is the cast's hit point minus the circle's centre
            // over the radius R: the point is within `bound` of the surface
            // and rounded by an ulp per component, so the normal is within
            // (bound + 2u)/R of the true one and unit within that (plus an
            // ulp per component for the division): for R of a few ulps it
            // is only roughly unit, as for the contact normals.
            let tol = 2.0 * (bound + 2.0 * U) / radius.max(U) + 8.0 * U;
            let unit = (nx.hypot(ny) - 1.0).abs();
            assert!(unit <= tol, "TOI normal ({nx}, {ny}) not unit within {tol}");
            let len = gx.hypot(gy);
            if len > 0.0 {
                assert!(
                    (nx + gx / len).abs() <= tol && (ny + gy / len).abs() <= tol,
                    "TOI normal ({nx}, {ny}) vs ({}, {}) beyond {tol}",
                    -gx / len,
                    -gy / len
                );
            }
        }
    }
}
