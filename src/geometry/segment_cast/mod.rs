//! Shared internals of the ray casts ([`ray_circle`](super::ray_circle),
//! [`ray_aabb`](super::ray_aabb)) and the time-of-impact queries
//! ([`toi`](super::toi)): a parametric segment
//!
//! ```text
//! P(s) = origin + s·dir,   0 ≤ s ≤ s_max
//! ```
//!
//! cast against a solid circle, a solid box and a solid rounded box (a box
//! grown by a radius, with round corners: the Minkowski sum of a box and a
//! circle).
//!
//! `dir` need not be a unit vector: `s` is measured in units of `|dir|`.
//! The precision statements assume `|dir|` between 1/2 and 2 (a ray's unit
//! direction, or a displacement divided by its max-norm, whose length is in
//! `[1, √2]`). A zero `dir` is allowed and never divides by zero: the cast
//! then only reports whether `origin` is inside.
//!
//! Every shape is closed: a point on the boundary is inside (the same rule
//! as [`Circle::contains_point`](super::Circle::contains_point) and
//! [`Aabb::contains_point`](super::Aabb::contains_point)).
//!
//! Error bounds below are for `Fx` (`I32F32`, one ulp `u = 2⁻³²`) with all
//! inputs inside the world bounds (coordinates within ±2¹⁵, `s_max ≤ 2¹⁷`).
//! Outside those bounds every operation still saturates to a defined,
//! deterministic result; it is just no longer accurate.

use crate::math::{Scalar, Vec2, WideScalar};

/// The outcome of a cast.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Cast<S: Scalar> {
    /// `origin` is inside the shape or on its boundary.
    Inside,
    /// The first point of the segment on the shape's boundary.
    Hit {
        /// The parameter, in `[0, s_max]`.
        s: S,
        /// The point on the boundary (close to `origin + s·dir`, see the
        /// function docs for which one is exact).
        point: Vec2<S>,
        /// The unit outward normal of the shape at `point`.
        normal: Vec2<S>,
    },
    /// The segment never touches the shape.
    Miss,
}

/// `-dir` as a unit vector, or `+Y` for a zero `dir`: the normal used where
/// the surface gives none (a circle of radius zero hit dead centre).
fn fallback_normal<S: Scalar>(dir: Vec2<S>) -> Vec2<S> {
    (-dir).try_normalize().unwrap_or(Vec2::Y)
}

/// The intersection of the whole line `origin + s·dir` with a circle, solved
/// in a numerically stable form.
///
/// # Derivation
///
/// With `m = origin − center`, `|m + s·dir|² = r²` is the quadratic
///
/// ```text
/// a s² + 2 b s + c = 0,   a = dir·dir,  b = m·dir,  c = m·m − r²
/// s = (−b ± √(b² − a c)) / a
/// ```
///
/// By Lagrange's identity `(m·m)(dir·dir) − (m·dir)² = (m × dir)²`, so the
/// discriminant is `b² − a c = a r² − h²` with `h = m × dir` (`|h| / √a` is
/// the distance from the centre to the line). This form needs no squares
/// of `b` or of `|m|`, which can reach 2³³ (beyond the narrow range, and
/// whose rounding would be amplified), and it is well conditioned: `h` is
/// formed exactly in the wide type and rounded once, and `a r²` is formed
/// as `|r·dir|²` (two products rounded once each), not from `a` rounded to
/// the narrow type, which would be off by `r²` ulps.
///
/// Two refinements make the hit point accurate at any distance and for any
/// radius:
///
/// 1. **Solve near the circle.** An error `δa` in `a` moves the foot of the
///    perpendicular `−b/a` by `|b|·δa`, up to 2¹⁷·2⁻³² = 2⁻¹⁵ for a far
///    circle. So the origin is first moved to (about) that foot,
///    `o' = origin + s_f·dir`, `s_f = −b/a`, and the quadratic is solved
///    again from `o'`, where `|b'|` is tiny and the local roots
///    `s' = (−b' ∓ √disc)/a` are about `±r`. `o'` is an actual point (its
///    rounding, ≤ 1 ulp per component, moves the line sideways by at most
///    √2 ulp, which does not take the hit point off the circle), and the
///    roots are `s = s_f + s'`.
/// 2. **One Newton step on the exact residual.** The division by `a`
///    (rounded to the narrow type: the wide `dir·dir` is exact but cannot
///    divide) still puts `s'` off by `|s'|·δa ≤ r` ulps, a radial error of
///    `(√disc/r)·r·δa ≤ √disc` ulps: up to `r` ulps head-on. For the point
///    `p₀ = o' + s'·dir`, the radial residual `ρ = |p₀ − c| − r` is known
///    to an ulp (the length is formed from the exact wide square), and
///    `g = (p₀ − c)·dir` gives the slope `g / |p₀ − c|`, so
///    `s' − ρ·|p₀ − c| / g` is the Newton step for the exact equation. It
///    is taken only when `8|ρ|·|p₀ − c| < g²` (decided exactly): then the
///    step is below `|g| / 8`, the curvature changes the slope by at most a
///    quarter along it, and the step reduces the radial error at least
///    sixfold — for any hit that is not grazing, to rounding. It is skipped
///    (no division by a small or zero `g`) only for grazing rays,
///    `|g| ≈ √disc < √(8|ρ| r)`; and there the error it would remove,
///    `√disc` ulps, is itself below `√(8 r·r ulp)` ≈ `r·2⁻¹⁴·⁵` ulps.
///
/// # Error (`Fx`)
///
/// The hit point is within about 4 ulps (1e-9) of the circle, for any hit
/// at any distance (up to `r·2⁻¹⁴·⁵` ulps more for a grazing ray, below an
/// ulp for `r < 2¹⁴`): `ρ` is known to an ulp, the Newton step's own
/// rounding costs about one ulp of radial error, and forming the point
/// rounds each component once. Hit-or-miss is decided on `disc`, whose
/// error is under 3 ulps of line-to-centre distance, so a miss passes at
/// least `r − 3` ulps from the centre. The parameter `s` is as
/// ill-conditioned as the geometry: near a tangent (`√disc → 0`) it moves a
/// lot for a tiny change in the input, while the point stays on the circle.
struct LineCircle<S: Scalar> {
    /// `s_f`: the parameter of the foot point `o'`.
    foot: S,
    /// `o' = origin + s_f·dir` (rounded).
    foot_point: Vec2<S>,
    /// `a = dir·dir`, rounded to the narrow type; positive.
    a: S,
    /// `b' = (o' − center)·dir`.
    b: S,
    /// `√(a r² − h'²)`, `h' = (o' − center) × dir`.
    root: S,
}

/// A root of [`LineCircle`], refined.
struct Root<S: Scalar> {
    /// The parameter along the line from the original origin.
    s: S,
    /// The point on the circle.
    point: Vec2<S>,
    /// `point − center`.
    rel: Vec2<S>,
}

impl<S: Scalar> LineCircle<S> {
    /// The root `s' = (−b' + sign·√disc) / a` measured from `o'` (the
    /// first for `far == false`), with one guarded Newton step on the exact
    /// residual (see [`LineCircle`]).
    fn root(&self, far: bool, dir: Vec2<S>, center: Vec2<S>, radius: S) -> Root<S> {
        let minus_b = self.b.neg();
        let num = if far {
            minus_b.add(self.root)
        } else {
            minus_b.sub(self.root)
        };
        // a > 0 (checked when solving).
        let local = num.div(self.a);
        let point = self.foot_point + dir.scale(local);
        let rel = point - center;
        // Newton on f(s) = |rel(s)| − r: f' = g / len with g = rel·dir, so
        // the step is −(len − r)·(len / g). `len` is rounded down by less
        // than an ulp, so ρ = len − r is the radial error to an ulp, and
        // forming ρ·(len/g) (|len/g| ≥ 1/|dir|) costs about one ulp of
        // radial error whatever the radius (unlike narrowing |rel|² − r²,
        // whose ulp would be divided by 2r).
        let len = rel.length();
        let rho = len.sub(radius.abs());
        let g = rel.dot(dir);
        // Guard, exact in the wide type: 8|ρ|·len < g², i.e. the step
        // |ρ|·len/|g| is below |g|/8; f'' ≤ a/len ≤ 2/len changes the slope
        // g/len by at most a quarter over it, so the step reduces the error
        // at least sixfold (to rounding, for any hit that is not grazing).
        // It also proves g ≠ 0 when ρ ≠ 0.
        let guard = rho.abs().mul_int(8).wide_mul(len) < g.wide_mul(g);
        if rho != S::ZERO && guard {
            // g ≠ 0 (guard), so the division is defined.
            let step = rho.mul(len.div(g)).neg();
            let local = local.add(step);
            let point = self.foot_point + dir.scale(local);
            return Root {
                s: self.foot.add(local),
                point,
                rel: point - center,
            };
        }
        Root {
            s: self.foot.add(local),
            point,
            rel,
        }
    }
}

/// Solves the line–circle quadratic; `None` when the line misses the circle
/// (or `dir` is zero, or so short that `dir·dir` rounds to zero).
fn line_circle<S: Scalar>(
    origin: Vec2<S>,
    dir: Vec2<S>,
    center: Vec2<S>,
    radius: S,
) -> Option<LineCircle<S>> {
    let a = dir.length_squared_wide().narrow();
    if !a.is_positive() {
        return None;
    }
    let m = origin - center;
    // s_f = −(m·dir)/a; a > 0 was checked.
    let foot = m.dot(dir).neg().div(a);
    let foot_point = origin + dir.scale(foot);
    let rel = foot_point - center;
    let b = rel.dot(dir);
    let h = rel.cross(dir);
    // disc = a r² − h², with a r² = |r·dir|²: the products r·dir are
    // rounded once each (< 1 ulp), so disc is off by less than about
    // 2√2·r ulps (plus 2|h| ulps from h), an error of under 3 ulps in the
    // distance |h|/√a it is compared with. (Using the narrowed a instead
    // would be off by r²·ulp.)
    let rd = dir.scale(radius);
    let disc = rd.length_squared_wide().sub(h.wide_mul(h));
    if disc.is_negative() {
        return None;
    }
    Some(LineCircle {
        foot,
        foot_point,
        a,
        b,
        root: disc.sqrt_narrow(),
    })
}

/// Both parameters where the line `origin + s·dir` crosses the circle,
/// `s0 ≤ s1`, not limited to any range; `None` when the line misses it (a
/// tangent line gives `s0 == s1`) or `dir` is zero.
#[must_use]
pub(crate) fn circle_roots<S: Scalar>(
    origin: Vec2<S>,
    dir: Vec2<S>,
    center: Vec2<S>,
    radius: S,
) -> Option<(S, S)> {
    let lc = line_circle(origin, dir, center, radius)?;
    let s0 = lc.root(false, dir, center, radius).s;
    let s1 = lc.root(true, dir, center, radius).s;
    // The Newton steps move each root by rounding-sized amounts; keep the
    // documented order even if they cross on a tangent.
    Some((s0.min(s1), s0.max(s1)))
}

/// Casts the segment against the solid circle (`|radius|` is used).
///
/// `Inside` when `|origin − center| ≤ r` (decided exactly in the wide
/// type). Otherwise a hit needs the segment to approach the centre
/// (`m·dir < 0`, exact) and the line to cross the circle; the first root is
/// then positive in exact arithmetic, and a computed value rounded below
/// zero (origin within a few ulps of the circle) is clamped to `s = 0`,
/// `point = origin`. The returned `point` is the refined root's (within
/// about 4 ulps of the circle, see [`LineCircle`]), within a few ulps of
/// `origin + s·dir`.
#[must_use]
pub(crate) fn cast_circle<S: Scalar>(
    origin: Vec2<S>,
    dir: Vec2<S>,
    s_max: S,
    center: Vec2<S>,
    radius: S,
) -> Cast<S> {
    let m = origin - center;
    let c = m.length_squared_wide().sub(radius.wide_mul(radius));
    if c <= S::Wide::ZERO {
        return Cast::Inside;
    }
    if m.dot_wide(dir) >= S::Wide::ZERO {
        // Outside and moving away (or sideways, or not at all): the
        // distance to the centre never decreases.
        return Cast::Miss;
    }
    let Some(lc) = line_circle(origin, dir, center, radius) else {
        return Cast::Miss;
    };
    let root = lc.root(false, dir, center, radius);
    let (s, point, rel_hit) = if root.s.is_negative() {
        (S::ZERO, origin, m)
    } else {
        (root.s, root.point, root.rel)
    };
    if s > s_max {
        return Cast::Miss;
    }
    let normal = rel_hit
        .try_normalize()
        .unwrap_or_else(|| fallback_normal(dir));
    Cast::Hit { s, point, normal }
}

/// One axis of the slab test.
#[derive(Clone, Copy)]
enum Slab<S: Scalar> {
    /// `dir` has no component on this axis and the origin is within the
    /// slab: the axis imposes no limit.
    Free,
    /// The segment crosses the slab's planes at `s = enter / speed` and
    /// `s = exit / speed`, `enter ≤ exit`, `speed > 0`.
    Span {
        /// Signed distance to the entry plane along the motion.
        enter: S,
        /// Signed distance to the exit plane along the motion.
        exit: S,
        /// `|dir|` on this axis, positive.
        speed: S,
        /// The entry plane's coordinate.
        face: S,
        /// `true` if moving towards −∞ on this axis (entering through the
        /// max face, whose outward normal is +axis).
        negative: bool,
    },
}

/// The slab `[lo, hi]` of one axis for a segment starting at `o` with
/// component `d`; `None` if the segment can never be inside the slab.
fn slab<S: Scalar>(o: S, d: S, lo: S, hi: S) -> Option<Slab<S>> {
    if d.is_positive() {
        Some(Slab::Span {
            enter: lo.sub(o),
            exit: hi.sub(o),
            speed: d,
            face: lo,
            negative: false,
        })
    } else if d.is_negative() {
        Some(Slab::Span {
            enter: o.sub(hi),
            exit: o.sub(lo),
            speed: d.neg(),
            face: hi,
            negative: true,
        })
    } else if lo <= o && o <= hi {
        Some(Slab::Free)
    } else {
        None
    }
}

/// Casts the segment against the solid box (`|half|` is used).
///
/// # Method: exact slab test without division
///
/// On an axis with `dir_i ≠ 0` the segment is between the box's two planes
/// for `s ∈ [enter_i / speed_i, exit_i / speed_i]` (`speed_i = |dir_i|`,
/// `enter_i`, `exit_i` the signed distances to the entry and exit planes
/// along the motion). On an axis with `dir_i = 0` there is no division at
/// all: if the origin's coordinate is within the slab, the axis imposes no
/// limit, otherwise the segment misses.
///
/// The segment enters the box at the larger entry parameter and leaves it at
/// the smaller exit parameter. These fractions are compared by cross
/// multiplication in the wide type (`enter_x·speed_y` vs `enter_y·speed_x`,
/// products of narrow values, exact for `Fx` and `I48F16`), and the reach
/// test `enter_k ≤ s_max·speed_k` likewise, so every decision (hit or miss,
/// which face) is exact. Only the reported `s = enter_k / speed_k` is
/// divided, once, after the reach test has proved it at most `s_max`: the
/// quotient cannot overflow however small `speed_k` is, and it is truncated
/// by less than one ulp.
///
/// Ties: when the entry parameters of both axes are exactly equal (the
/// segment enters exactly through a corner), the **y** face is reported,
/// the rule of the rest of the geometry module.
///
/// The returned `point` lies exactly on the entered face: its coordinate on
/// the entry axis is the face's, and the other one is
/// `origin + s·dir` (one rounding) clamped to the face's extent.
#[must_use]
pub(crate) fn cast_box<S: Scalar>(
    origin: Vec2<S>,
    dir: Vec2<S>,
    s_max: S,
    center: Vec2<S>,
    half: Vec2<S>,
) -> Cast<S> {
    let half = half.abs();
    let lo = center - half;
    let hi = center + half;
    if lo.x <= origin.x && origin.x <= hi.x && lo.y <= origin.y && origin.y <= hi.y {
        return Cast::Inside;
    }
    let (Some(sx), Some(sy)) = (
        slab(origin.x, dir.x, lo.x, hi.x),
        slab(origin.y, dir.y, lo.y, hi.y),
    ) else {
        return Cast::Miss;
    };
    // The entering axis (`true` = x) and its slab, and the other slab.
    let (x_enters, enter_slab, other) = match (sx, sy) {
        // Both free means the origin is in both slabs, i.e. inside (handled
        // above); kept as a defined answer.
        (Slab::Free, Slab::Free) => return Cast::Miss,
        (Slab::Span { .. }, Slab::Free) => (true, sx, sy),
        (Slab::Free, Slab::Span { .. }) => (false, sy, sx),
        (
            Slab::Span {
                enter: ex,
                speed: vx,
                ..
            },
            Slab::Span {
                enter: ey,
                speed: vy,
                ..
            },
        ) => {
            // enter_x / vx > enter_y / vy  ⇔  enter_x·vy > enter_y·vx (both
            // speeds positive). Ties go to y.
            if ex.wide_mul(vy) > ey.wide_mul(vx) {
                (true, sx, sy)
            } else {
                (false, sy, sx)
            }
        }
    };
    let Slab::Span {
        enter,
        exit,
        speed,
        face,
        negative,
    } = enter_slab
    else {
        return Cast::Miss;
    };
    // The box must not be behind the origin on the entering axis...
    if exit.is_negative() {
        return Cast::Miss;
    }
    // ...nor on the other one, and the entry must come before the other
    // axis's exit: enter / speed ≤ exit_o / speed_o.
    if let Slab::Span {
        exit: exit_o,
        speed: speed_o,
        ..
    } = other
        && (exit_o.is_negative() || enter.wide_mul(speed_o) > exit_o.wide_mul(speed))
    {
        return Cast::Miss;
    }
    // Reach: enter / speed ≤ s_max. A negative `enter` cannot happen for an
    // origin outside the box (the axis on which it is outside has a
    // positive entry distance, or a negative exit distance and was
    // rejected), but is clamped to zero all the same.
    let enter = enter.max(S::ZERO);
    if S::Wide::from_narrow(enter) > s_max.wide_mul(speed) {
        return Cast::Miss;
    }
    // 0 ≤ enter ≤ s_max·speed, so the quotient is in [0, s_max]: no
    // overflow. (`min` only matters for the float references, whose
    // division rounds to nearest.)
    let s = enter.div(speed).min(s_max);
    let sign = if negative { S::ONE } else { S::ONE.neg() };
    let (point, normal) = if x_enters {
        let y = origin.y.add(dir.y.mul(s)).clamp(lo.y, hi.y);
        (Vec2::new(face, y), Vec2::new(sign, S::ZERO))
    } else {
        let x = origin.x.add(dir.x.mul(s)).clamp(lo.x, hi.x);
        (Vec2::new(x, face), Vec2::new(S::ZERO, sign))
    };
    Cast::Hit { s, point, normal }
}

/// Casts the segment against the solid rounded box: the box `(center,
/// half)` grown by `radius` (`|half|`, `|radius|` are used), i.e. the set of
/// points within `radius` of the box. It is the Minkowski sum used for a
/// moving circle against a box: four flat faces pushed out by `radius` and
/// four quarter circles of radius `radius` around the box's corners.
///
/// # Method
///
/// 1. Inside test, exact: with `q = |origin − center|` per axis, the
///    distance to the box is `|(max(q.x − h.x, 0), max(q.y − h.y, 0))|`,
///    compared squared with `r²` in the wide type.
/// 2. Cast against the box grown by `r` on each axis (it contains the
///    rounded box, so a miss there is a miss). If the entry point is within
///    the inner box's extent on the other axis, it is on a flat face: done.
/// 3. Otherwise the entry point is in a corner square `[h, h + r]²` (up to
///    signs), and the answer is the cast against that corner's circle: from
///    inside the corner square the segment can only leave it through the
///    two outer sides (leaving the grown box for good, as it is convex) or
///    through the two inner sides, which lie inside the corner circle; so
///    it either hits that circle first or misses the rounded box.
///
///    If the origin itself is inside the grown box but outside the rounded
///    box, it is in a corner square, and step 3 applies from there.
///
/// At the face/corner boundary both answers agree (the circle's normal
/// there is the face normal), so classifying a point one ulp off that
/// boundary changes the result by rounding only.
#[must_use]
pub(crate) fn cast_rounded_box<S: Scalar>(
    origin: Vec2<S>,
    dir: Vec2<S>,
    s_max: S,
    center: Vec2<S>,
    half: Vec2<S>,
    radius: S,
) -> Cast<S> {
    let half = half.abs();
    let radius = radius.abs();
    let q = (origin - center).abs();
    let outside = Vec2::new(q.x.sub(half.x).max(S::ZERO), q.y.sub(half.y).max(S::ZERO));
    if outside.length_squared_wide() <= radius.wide_mul(radius) {
        return Cast::Inside;
    }
    let grown = half + Vec2::new(radius, radius);
    // The corner of the inner box on the side of `p`.
    let corner_near = |p: Vec2<S>| {
        let rel = p - center;
        Vec2::new(
            if rel.x.is_negative() {
                center.x.sub(half.x)
            } else {
                center.x.add(half.x)
            },
            if rel.y.is_negative() {
                center.y.sub(half.y)
            } else {
                center.y.add(half.y)
            },
        )
    };
    let hit = match cast_box(origin, dir, s_max, center, grown) {
        Cast::Miss => return Cast::Miss,
        // Inside the grown box but not the rounded box: in a corner square.
        Cast::Inside => return cast_circle(origin, dir, s_max, corner_near(origin), radius),
        Cast::Hit { s, point, normal } => (s, point, normal),
    };
    let (_, point, normal) = hit;
    let rel = point - center;
    // The coordinate along the face (the axis the normal is not on).
    let on_face = if normal.x == S::ZERO {
        rel.x.abs() <= half.x
    } else {
        rel.y.abs() <= half.y
    };
    if on_face {
        return Cast::Hit {
            s: hit.0,
            point,
            normal,
        };
    }
    cast_circle(origin, dir, s_max, corner_near(point), radius)
}
