//! Phase "broad phase": swept bounding boxes (proxies) of the bodies, then
//! the candidate pairs ([`crate::collision::BroadPhase`]).

use crate::collision::{Proxy, ProxyClass};
use crate::dynamics::BodyKind;
use crate::math::{Scalar, Vec2};
use crate::world::World;

impl<S: Scalar> World<S> {
    /// Swept bounding boxes: the box now ∪ the box after moving `v·h`,
    /// grown by the speculative margin for bodies that move.
    pub(super) fn build_proxies(&mut self, h: S) {
        let margin = self.settings.speculative_margin;
        let context = &mut self.step_context;
        context.proxies.clear();
        for (i, slot) in self.slots.iter().enumerate() {
            let Some(body) = &slot.body else { continue };
            if body.frozen {
                continue;
            }
            let velocity = context.velocities[i];
            let class = match body.kind {
                BodyKind::Dynamic if body.awake => ProxyClass::Dynamic,
                BodyKind::Dynamic => ProxyClass::Sleeping,
                BodyKind::Kinematic if velocity != Vec2::ZERO => ProxyClass::MovingKinematic,
                _ => ProxyClass::Still,
            };
            let now = body.aabb();
            let swept = if matches!(class, ProxyClass::Dynamic | ProxyClass::MovingKinematic) {
                // A body may bounce within the substep and travel the rest
                // of its path `|v|·h` in another direction (a bullet: in
                // several), so a fast dynamic body's box is every point
                // within `(|v_x| + |v_y|)·h ≥ |v|·h` of where it starts: the
                // rebound sweep then knows every partner it can reach. A
                // slow one's path is within the margin already.
                let reach = velocity.x.abs().add(velocity.y.abs()).mul(h);
                if class == ProxyClass::Dynamic && reach > margin {
                    now.expanded(reach.add(margin))
                } else {
                    let later = body
                        .shape
                        .bounding_aabb_at(body.position + velocity.scale(h));
                    now.union(&later).expanded(margin)
                }
            } else {
                now
            };
            let (lo, hi) = (swept.min(), swept.max());
            context.proxies.push(Proxy {
                min_x: lo.x,
                max_x: hi.x,
                min_y: lo.y,
                max_y: hi.y,
                index: u32::try_from(i).unwrap_or(u32::MAX),
                class: Some(class),
            });
        }
    }

    /// Candidate pairs of the proxies into `context.pairs`, sorted.
    pub(super) fn find_pairs(&mut self) {
        let context = &mut self.step_context;
        context
            .broad_phase
            .find_pairs(&context.proxies, &mut context.pairs);
    }
}
