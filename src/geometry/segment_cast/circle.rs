//! A segment cast against a solid circle, and the two roots of a line and a
//! circle (see the [module notes](super) for the segment's parametrisation
//! and the error conventions).

use super::Cast;
use crate::math::{Scalar, Vec2, WideScalar};

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
