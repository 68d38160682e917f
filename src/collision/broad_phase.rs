//! Broad phase: sweep and prune along x over swept bounding boxes.
//!
//! Cost: a sort of the proxies by `min_x` (the order changes little between
//! steps, so the sort is close to linear) plus one pass whose work is the
//! number of x-overlaps. Pairs come out sorted by `(a, b)` slot index.

use crate::math::Scalar;

/// How a proxy takes part in pairing.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum ProxyClass {
    /// Fixed bodies, and kinematic bodies at rest.
    Still,
    /// A sleeping dynamic body.
    Sleeping,
    /// A kinematic body with a velocity.
    MovingKinematic,
    /// An awake dynamic body.
    Dynamic,
}

impl ProxyClass {
    /// Whether a pair of these classes needs a contact: something must be
    /// able to respond (an awake dynamic body), or a moving kinematic body
    /// must be able to wake a sleeper.
    #[inline]
    fn pairs_with(self, other: ProxyClass) -> bool {
        use ProxyClass::{Dynamic, MovingKinematic, Sleeping};
        matches!(
            (self, other),
            (Dynamic, _) | (_, Dynamic) | (MovingKinematic, Sleeping) | (Sleeping, MovingKinematic)
        )
    }
}

/// A body's swept bounding box for this substep.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct Proxy<S: Scalar> {
    pub(crate) min_x: S,
    pub(crate) max_x: S,
    pub(crate) min_y: S,
    pub(crate) max_y: S,
    pub(crate) index: u32,
    pub(crate) class: Option<ProxyClass>,
}

/// Sorts `proxies` along x and writes the overlapping pairs, sorted by
/// `(a, b)` with `a < b`, into `pairs`.
pub(crate) fn find_pairs<S: Scalar>(proxies: &mut [Proxy<S>], pairs: &mut Vec<(u32, u32)>) {
    pairs.clear();
    // Ties on min_x are broken by slot index, so the order is total and the
    // same on every machine.
    proxies.sort_unstable_by(|p, q| {
        p.min_x
            .partial_cmp(&q.min_x)
            .unwrap_or(core::cmp::Ordering::Equal)
            .then(p.index.cmp(&q.index))
    });
    for (i, p) in proxies.iter().enumerate() {
        let Some(pc) = p.class else { continue };
        for q in &proxies[i + 1..] {
            if q.min_x > p.max_x {
                break;
            }
            let Some(qc) = q.class else { continue };
            if !pc.pairs_with(qc) || q.min_y > p.max_y || p.min_y > q.max_y {
                continue;
            }
            let pair = if p.index < q.index {
                (p.index, q.index)
            } else {
                (q.index, p.index)
            };
            pairs.push(pair);
        }
    }
    pairs.sort_unstable();
}
