//! The broad phase's work item: a classed proxy with its coordinates as
//! integer order keys.

use super::proxy::{Proxy, ProxyClass};
use crate::math::Scalar;

/// A proxy as the phase works on it: coordinates as order keys (see
/// [`order_key`]), 40 bytes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(super) struct Item {
    pub(super) min_x: i64,
    pub(super) max_x: i64,
    pub(super) min_y: i64,
    pub(super) max_y: i64,
    /// Slot index of the body.
    pub(super) index: u32,
    /// The band holding `min_y` (set when the item is copied into bands).
    pub(super) band_min: u16,
    /// [`ProxyClass::code`].
    pub(super) class: u8,
}

/// An item's y range as `(low, high)`, also for an inverted proxy
/// (`min_y > max_y`, which the pair test treats asymmetrically: its pairs
/// have `max(p.min_y, q.min_y)` inside this range all the same).
#[inline]
pub(super) fn y_span(item: &Item) -> (i64, i64) {
    (item.min_y.min(item.max_y), item.min_y.max(item.max_y))
}

/// The work item of a classed proxy.
#[inline]
pub(super) fn item_of<S: Scalar>(proxy: &Proxy<S>) -> Item {
    Item {
        min_x: order_key(proxy.min_x),
        max_x: order_key(proxy.max_x),
        min_y: order_key(proxy.min_y),
        max_y: order_key(proxy.max_y),
        index: proxy.index,
        band_min: 0,
        class: proxy.class.map_or(0, ProxyClass::code),
    }
}

/// An `i64` ordered like the scalar: `a < b` ⇔ `order_key(a) <
/// order_key(b)` and `a == b` ⇔ equal keys (for floats: apart from NaN,
/// which gets some key and is then ordered by it, where IEEE comparisons
/// would have made the original sweep's order undefined).
///
/// Fixed point: the raw two's complement value, which
/// [`Scalar::to_hash_bits`] gives sign-extended to 64 bits. Float reference
/// types: the IEEE bits made monotone (negatives flipped, the sign bit set
/// on positives), with −0 taken as +0 since they compare equal.
#[inline]
pub(super) fn order_key<S: Scalar>(value: S) -> i64 {
    if !S::IS_REFERENCE {
        // Reinterpreting the sign-extended raw value.
        return value.to_hash_bits() as i64;
    }
    let value = if value == S::ZERO { S::ZERO } else { value };
    // The sign bit of the type's own width (bit 31 for f32, 63 for f64).
    let sign = S::ONE.to_hash_bits() ^ S::ONE.neg().to_hash_bits();
    let width_mask = (sign << 1).wrapping_sub(1);
    let bits = value.to_hash_bits();
    let unsigned = if bits & sign != 0 {
        !bits & width_mask
    } else {
        bits | sign
    };
    // Unsigned order → signed order.
    (unsigned ^ (1 << 63)) as i64
}
