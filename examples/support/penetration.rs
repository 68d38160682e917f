//! Geometric penetration of a set of circles and axis-aligned boxes, measured
//! from positions alone (in `f64`), so the same measure applies to
//! clockwork2d worlds of any scalar and to rapier2d worlds.
//!
//! Shared by the `peer_comparison` and `accuracy` examples (included with
//! `#[path]`; this folder has no `main.rs`, so cargo does not take it for an
//! example of its own).

/// The shape of a piece, in world units.
#[derive(Clone, Copy, Debug)]
pub enum PieceShape {
    /// A circle of this radius.
    Circle(f64),
    /// An axis-aligned box of these half extents.
    Box(f64, f64),
}

/// One body as seen by the measure: centre, shape, and whether it can move
/// (overlaps between two fixed bodies, such as wall corners, are ignored).
#[derive(Clone, Copy, Debug)]
pub struct Piece {
    pub x: f64,
    pub y: f64,
    pub shape: PieceShape,
    pub dynamic: bool,
}

impl Piece {
    fn half_extents(&self) -> (f64, f64) {
        match self.shape {
            PieceShape::Circle(r) => (r, r),
            PieceShape::Box(hx, hy) => (hx, hy),
        }
    }
}

/// Penetration depth of a box and a circle (0 if apart): the circle's
/// radius minus the distance from its centre to the box, or, for a centre
/// inside the box, the radius plus the distance to the nearest face.
fn box_circle(bx: f64, by: f64, hx: f64, hy: f64, cx: f64, cy: f64, r: f64) -> f64 {
    let (dx, dy) = (cx - bx, cy - by);
    if dx.abs() <= hx && dy.abs() <= hy {
        return r + (hx - dx.abs()).min(hy - dy.abs());
    }
    let qx = dx.clamp(-hx, hx);
    let qy = dy.clamp(-hy, hy);
    let d = (dx - qx).hypot(dy - qy);
    (r - d).max(0.0)
}

/// Penetration depth of two pieces (0 if apart or just touching).
pub fn depth(a: &Piece, b: &Piece) -> f64 {
    match (a.shape, b.shape) {
        (PieceShape::Circle(ra), PieceShape::Circle(rb)) => {
            (ra + rb - (b.x - a.x).hypot(b.y - a.y)).max(0.0)
        }
        (PieceShape::Box(hxa, hya), PieceShape::Box(hxb, hyb)) => {
            let ox = hxa + hxb - (b.x - a.x).abs();
            let oy = hya + hyb - (b.y - a.y).abs();
            if ox > 0.0 && oy > 0.0 {
                ox.min(oy)
            } else {
                0.0
            }
        }
        (PieceShape::Box(hx, hy), PieceShape::Circle(r)) => {
            box_circle(a.x, a.y, hx, hy, b.x, b.y, r)
        }
        (PieceShape::Circle(r), PieceShape::Box(hx, hy)) => {
            box_circle(b.x, b.y, hx, hy, a.x, a.y, r)
        }
    }
}

/// The largest penetration depth over all pairs with at least one movable
/// piece. Sweep and prune along x: O(n log n + overlapping pairs).
pub fn max_penetration(pieces: &[Piece]) -> f64 {
    let mut order: Vec<usize> = (0..pieces.len()).collect();
    let min_x = |i: usize| pieces[i].x - pieces[i].half_extents().0;
    order.sort_by(|&i, &j| min_x(i).total_cmp(&min_x(j)));
    let mut worst: f64 = 0.0;
    for (k, &i) in order.iter().enumerate() {
        let a = &pieces[i];
        let (ahx, ahy) = a.half_extents();
        let max_x = a.x + ahx;
        for &j in &order[k + 1..] {
            if min_x(j) > max_x {
                break;
            }
            let b = &pieces[j];
            if !(a.dynamic || b.dynamic) {
                continue;
            }
            let bhy = b.half_extents().1;
            if (b.y - a.y).abs() >= ahy + bhy {
                continue;
            }
            worst = worst.max(depth(a, b));
        }
    }
    worst
}
