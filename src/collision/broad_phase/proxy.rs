//! Proxies: what a body brings to the broad phase (its swept bounding box
//! and how it takes part in pairing).

use crate::math::{Scalar, Vec2};

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
    /// All classes, in the order of their codes (see [`Self::code`]).
    pub(super) const ALL: [ProxyClass; 4] = [
        ProxyClass::Still,
        ProxyClass::Sleeping,
        ProxyClass::MovingKinematic,
        ProxyClass::Dynamic,
    ];

    /// Whether a pair of these classes needs a contact: something must be
    /// able to respond (an awake dynamic body), or a moving kinematic body
    /// must be able to wake a sleeper.
    #[inline]
    pub(super) const fn pairs_with(self, other: ProxyClass) -> bool {
        use ProxyClass::{Dynamic, MovingKinematic, Sleeping};
        matches!(
            (self, other),
            (Dynamic, _) | (_, Dynamic) | (MovingKinematic, Sleeping) | (Sleeping, MovingKinematic)
        )
    }

    /// A small code, `0..4`, indexing [`PAIR_TABLE`].
    #[inline]
    pub(super) const fn code(self) -> u8 {
        match self {
            ProxyClass::Still => 0,
            ProxyClass::Sleeping => 1,
            ProxyClass::MovingKinematic => 2,
            ProxyClass::Dynamic => 3,
        }
    }
}

/// [`ProxyClass::pairs_with`] as a bit table: bit `4·a + b` is set when the
/// classes with codes `a` and `b` pair. One shift and mask in the sweep's
/// inner loop instead of a match.
pub(super) const PAIR_TABLE: u16 = {
    let mut table = 0u16;
    let mut a = 0;
    while a < 4 {
        let mut b = 0;
        while b < 4 {
            if ProxyClass::ALL[a].pairs_with(ProxyClass::ALL[b]) {
                table |= 1 << (4 * a + b);
            }
            b += 1;
        }
        a += 1;
    }
    table
};

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

impl<S: Scalar> Proxy<S> {
    /// Whether the box `lo..hi` lies inside this proxy: a body whose motion
    /// stays inside its proxy was paired with everything it can reach.
    pub(crate) fn covers(&self, lo: Vec2<S>, hi: Vec2<S>) -> bool {
        lo.x >= self.min_x && lo.y >= self.min_y && hi.x <= self.max_x && hi.y <= self.max_y
    }

    /// This proxy grown over the box `lo..hi`, as the `Dynamic` proxy of a
    /// body whose motion leaves it (a rebound, a punched body): a second
    /// broad-phase query pairs it with what lies in the region it reaches.
    pub(crate) fn escaping_over(&self, lo: Vec2<S>, hi: Vec2<S>) -> Self {
        Self {
            min_x: lo.x.min(self.min_x),
            max_x: hi.x.max(self.max_x),
            min_y: lo.y.min(self.min_y),
            max_y: hi.y.max(self.max_y),
            index: self.index,
            class: Some(ProxyClass::Dynamic),
        }
    }
}
