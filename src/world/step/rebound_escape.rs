//! Phase "rebound escape" (part of the rebound sweep): the bodies a bounce
//! sends beyond their broad-phase region are paired with what lies there.
//!
//! Why: the rebound sweep ([`World::sweep_rebounds`]) stops a rebound at
//! the first partner it meets, but its partners are the broad-phase pairs,
//! found with the body's box swept by its velocity *before* the solve,
//! grown by the speculative margin. A bounce can launch a body far beyond
//! that: a ball at 50 units/s striking a resting box of its own mass stops
//! and the box leaves at 50 units/s; the box's proxy (at rest: its box
//! grown by 0.1) did not reach a wall 0.3 away, the sweep knew no wall, and
//! the box ended 0.57 along, through a 0.02 wall (292 units through at
//! 2000 units/s; a box 100× lighter than the ball leaves at twice its
//! speed).
//!
//! What: each rebounding body whose rebound path (its box where the
//! rebound starts ∪ its box where it ends) leaves its proxy takes that
//! path joined with its proxy into a second broad-phase query, against
//! every other proxy (fixed, kinematic, asleep or awake: a rebound stops at
//! anything it meets). The pairs found there and not among the substep's
//! pairs are the body's extra partners for the sweep. No rebound leaves its
//! proxy in most substeps (a fast body's proxy covers its speed in every
//! direction, `step/broad_phase.rs`): the rebounds are checked first, and
//! only when one escapes is the proxy list copied and queried.

use crate::collision::{Proxy, ProxyClass};
use crate::math::{Scalar, Vec2};
use crate::solver::StepContext;
use crate::solver::restitution::Rebound;
use crate::world::{Slot, World};

/// The corners `(min, max)` of a rebounding body's path (its box where the
/// rebound starts ∪ its box where it ends) when that path leaves the
/// body's proxy; `None` when the proxy covers it (or the body is gone).
fn path_beyond_proxy<S: Scalar>(
    slots: &[Slot<S>],
    displacements: &[Vec2<S>],
    proxy: &Proxy<S>,
    rebound: &Rebound<S>,
) -> Option<(Vec2<S>, Vec2<S>)> {
    let body = slots[proxy.index as usize].body.as_ref()?;
    let start = body.shape.bounding_aabb_at(body.position + rebound.start);
    let end = body
        .shape
        .bounding_aabb_at(body.position + displacements[proxy.index as usize]);
    let path = start.union(&end);
    let (lo, hi) = (path.min(), path.max());
    (!proxy.covers(lo, hi)).then_some((lo, hi))
}

impl<S: Scalar> World<S> {
    /// Fills `rebound_escape_pairs` with `(rebounding slot, other slot)`
    /// for every body beyond a rebounding body's proxy that its rebound
    /// path reaches (by bounding boxes), sorted, none of them in `pairs`.
    /// Expects `rebounds` sorted by slot without repeats.
    pub(super) fn find_rebound_escapes(&mut self) {
        let context = &mut self.step_context;
        context.rebound_escape_pairs.clear();
        context.escape_proxies.clear();
        // `proxies` is in slot order, one per slot at most.
        let proxy_of = |slot: u32| {
            context
                .proxies
                .binary_search_by_key(&slot, |p| p.index)
                .ok()
                .map(|k| &context.proxies[k])
                .filter(|proxy| proxy.class.is_some())
        };
        let any_escapes = context.rebounds.iter().any(|rebound| {
            proxy_of(rebound.slot).is_some_and(|proxy| {
                path_beyond_proxy(&self.slots, &context.displacements, proxy, rebound).is_some()
            })
        });
        if !any_escapes {
            return;
        }
        let mut next = 0;
        for proxy in &context.proxies {
            if proxy.class.is_none() {
                continue;
            }
            // `rebounds` and `proxies` are both in slot order.
            while next < context.rebounds.len() && context.rebounds[next].slot < proxy.index {
                next += 1;
            }
            let path = context
                .rebounds
                .get(next)
                .filter(|r| r.slot == proxy.index)
                .and_then(|rebound| {
                    path_beyond_proxy(&self.slots, &context.displacements, proxy, rebound)
                });
            // An escaping body is the only class that pairs here
            // (`Dynamic`); every other proxy is `Still`, which pairs with
            // it only.
            context.escape_proxies.push(match path {
                Some((lo, hi)) => proxy.escaping_over(lo, hi),
                None => Proxy {
                    class: Some(ProxyClass::Still),
                    ..*proxy
                },
            });
        }
        let StepContext {
            rebound_broad_phase,
            escape_proxies,
            escape_found,
            pairs,
            rebound_escape_pairs,
            ..
        } = &mut self.step_context;
        rebound_broad_phase.find_pairs(escape_proxies, escape_found);
        let escaping = |slot: u32| {
            escape_proxies
                .binary_search_by_key(&slot, |p| p.index)
                .is_ok_and(|k| escape_proxies[k].class == Some(ProxyClass::Dynamic))
        };
        for &(a, b) in escape_found.iter() {
            if pairs.binary_search(&(a, b)).is_ok() {
                continue;
            }
            for (mover, other) in [(a, b), (b, a)] {
                if escaping(mover) {
                    rebound_escape_pairs.push((mover, other));
                }
            }
        }
        rebound_escape_pairs.sort_unstable();
    }
}
