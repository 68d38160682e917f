//! Proptest strategies for full-precision `Fx` values.

use clockwork2d::prelude::*;
use proptest::prelude::*;

/// Full-precision `Fx` in `[-2^e, 2^e]` (raw bits), `e` drawn from a range:
/// every magnitude from tiny to large, every fraction bit live.
pub fn scaled(exps: core::ops::Range<i32>) -> impl Strategy<Value = Fx> {
    (exps, -(1i64 << 32)..=(1i64 << 32)).prop_map(|(e, m)| {
        let raw = if e >= 0 { m << e } else { m >> -e };
        Fx::from_bits(raw)
    })
}

/// A positive full-precision `Fx` around `2^e`.
pub fn positive(exps: core::ops::Range<i32>) -> impl Strategy<Value = Fx> {
    (exps, (1i64 << 31)..=(1i64 << 32)).prop_map(|(e, m)| {
        let raw = if e >= 0 { m << e } else { m >> -e };
        Fx::from_bits(raw.max(1))
    })
}
