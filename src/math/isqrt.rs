//! The exact integer square root of a `u64` with one division: the root of
//! every squared length the narrow phase normalises (contact normals).
//!
//! # Method
//!
//! `x` is shifted left by an even amount `2k` into `[2⁶², 2⁶⁴)`, so that
//! `⌊√x⌋ = ⌊√(x·4ᵏ)⌋ >> k` (a floor of a floor quotient). There:
//!
//! 1. **Table and interpolation.** The top [`INDEX_BITS`] bits pick an
//!    interval `[i, i + 1)·2⁵⁴`; the table holds `⌊√(i·2⁵⁴)⌋` at both ends
//!    and the next 32 bits interpolate linearly between them. √ is concave
//!    with `|f''| = ¼·u^(−3/2) ≤ 2⁻⁹⁵` there, so the chord over an interval
//!    of `Δ = 2⁵⁴` is below the curve by at most `Δ²/8·|f''| ≤ 2¹⁰`; with
//!    the truncations the guess `g` is within `2¹⁰ + 2` of `√x'`.
//! 2. **One Newton step** `r = ⌊(g + ⌊x'/g⌋)/2⌋`: in exact arithmetic
//!    `(g + x'/g)/2 = √x' + e²/(2g)` for `g = √x' + e`, and
//!    `e²/(2g) < 2²¹/2³² < 1`; the two truncations take off at most one
//!    more, so `r` is the root or one below it.
//! 3. **Exact correction**: `r` is moved until `r² ≤ x' < (r + 1)²`,
//!    checked with exact 128-bit squares. The loops make the result exact
//!    whatever the guess (they only cost more steps if it were poor), so
//!    exactness does not rest on the bounds above; the tests compare with
//!    the standard library's `u64::isqrt`.
//!
//! Why not `u64::isqrt`: the standard one takes three divisions in a
//! dependent chain; it was 5.8 % of the time of 500 ticks of `balls5000`.

/// Bits of `x'` that index the table (`x' ∈ [2⁶², 2⁶⁴)` has its top two
/// bits at least `01`, so indices run over `[2^(INDEX_BITS−2), 2^INDEX_BITS)`).
const INDEX_BITS: u32 = 10;
/// First index in use.
const FIRST: usize = 1 << (INDEX_BITS - 2);
/// Entries: one per index in use, and the end of the last interval.
const ENTRIES: usize = (1 << INDEX_BITS) - FIRST + 1;
/// Shift from `x'` to its index.
const INDEX_SHIFT: u32 = 64 - INDEX_BITS;

/// `⌊√(i·2^INDEX_SHIFT)⌋` for `i` in `FIRST..=2^INDEX_BITS` (the last is
/// `2³²`, the root of `2⁶⁴`), computed at compile time.
static ROOTS: [u64; ENTRIES] = {
    let mut roots = [0u64; ENTRIES];
    let mut k = 0;
    while k < ENTRIES {
        let value = ((FIRST + k) as u128) << INDEX_SHIFT;
        roots[k] = value.isqrt() as u64;
        k += 1;
    }
    roots
};

/// `⌊√x⌋`, exactly (the same value as `x.isqrt()`).
#[inline]
pub(crate) fn isqrt_u64(x: u64) -> u64 {
    if x < 4 {
        // 0 → 0; 1, 2, 3 → 1.
        return u64::from(x != 0);
    }
    let half_shift = x.leading_zeros() / 2;
    let scaled = x << (2 * half_shift);
    // scaled ≥ 2⁶², so the index is in FIRST..2^INDEX_BITS.
    let index = (scaled >> INDEX_SHIFT) as usize - FIRST;
    let low = ROOTS[index];
    let high = ROOTS[index + 1];
    // The position inside the interval, as a 32-bit fraction.
    let fraction = (scaled >> (INDEX_SHIFT - 32)) & 0xFFFF_FFFF;
    // high − low < 2²³ (the root's slope is below 2⁻³² per unit here), so
    // the product stays below 2⁵⁵.
    let guess = low + (((high - low) * fraction) >> 32);
    // guess ≥ 2³¹ > 0; guess + scaled/guess < 2³⁴.
    let mut root = (guess + scaled / guess) >> 1;
    let target = u128::from(scaled);
    while u128::from(root) * u128::from(root) > target {
        root -= 1;
    }
    while u128::from(root + 1) * u128::from(root + 1) <= target {
        root += 1;
    }
    root >> half_shift
}

#[cfg(test)]
mod tests {
    use super::isqrt_u64;
    use proptest::prelude::*;

    #[test]
    fn small_values_and_the_ends() {
        for x in 0..100_000u64 {
            assert_eq!(isqrt_u64(x), x.isqrt(), "{x}");
        }
        for x in [u64::MAX, u64::MAX - 1, 1 << 62, (1 << 62) - 1, 1 << 63] {
            assert_eq!(isqrt_u64(x), x.isqrt(), "{x}");
        }
    }

    /// Perfect squares and their neighbours, where a root off by one shows,
    /// over the whole range of roots (and every power of two and its
    /// neighbours: the shift and table edges).
    #[test]
    fn squares_and_neighbours() {
        let mut root = 1u64;
        while root < (1 << 32) {
            let square = root * root;
            for x in [square - 1, square, square + 1, square + 2 * root] {
                assert_eq!(isqrt_u64(x), x.isqrt(), "{x}");
            }
            // About 40 000 roots, denser at the small end.
            root += 1 + root / 2_000;
        }
        for bit in 0..64 {
            let p = 1u64 << bit;
            for x in [p - 1, p, p + 1] {
                assert_eq!(isqrt_u64(x), x.isqrt(), "{x}");
            }
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(20_000))]

        /// Random values of every magnitude.
        #[test]
        fn random_values_match_the_standard_root(x in any::<u64>(), shift in 0u32..64) {
            let x = x >> shift;
            prop_assert_eq!(isqrt_u64(x), x.isqrt());
        }
    }
}
