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
//! direction, `step/broad_phase.rs`), and then nothing is queried.

use crate::collision::{Proxy, ProxyClass};
use crate::math::Scalar;
use crate::solver::StepContext;
use crate::world::World;

impl<S: Scalar> World<S> {
    /// Fills `rebound_escape_pairs` with `(rebounding slot, other slot)`
    /// for every body beyond a rebounding body's proxy that its rebound
    /// path reaches (by bounding boxes), sorted, none of them in `pairs`.
    /// Expects `rebounds` sorted by slot without repeats.
    pub(super) fn find_rebound_escapes(&mut self) {
        let context = &mut self.step_context;
        context.rebound_escape_pairs.clear();
        context.escape_proxies.clear();
        let mut any = false;
        let mut next = 0;
        for proxy in &context.proxies {
            if proxy.class.is_none() {
                continue;
            }
            // `rebounds` and `proxies` are both in slot order.
            while next < context.rebounds.len() && context.rebounds[next].slot < proxy.index {
                next += 1;
            }
            let rebound = context.rebounds.get(next).filter(|r| r.slot == proxy.index);
            let body = self.slots[proxy.index as usize].body.as_ref();
            let path = match (rebound, body) {
                (Some(rebound), Some(body)) => {
                    let start = body.shape.bounding_aabb_at(body.position + rebound.start);
                    let end = body.shape.bounding_aabb_at(
                        body.position + context.displacements[proxy.index as usize],
                    );
                    let path = start.union(&end);
                    let (lo, hi) = (path.min(), path.max());
                    (!proxy.covers(lo, hi)).then_some((lo, hi))
                }
                _ => None,
            };
            // An escaping body is the only class that pairs here
            // (`Dynamic`); every other proxy is `Still`, which pairs with
            // it only.
            context.escape_proxies.push(match path {
                Some((lo, hi)) => {
                    any = true;
                    proxy.escaping_over(lo, hi)
                }
                None => Proxy {
                    class: Some(ProxyClass::Still),
                    ..*proxy
                },
            });
        }
        if !any {
            return;
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
