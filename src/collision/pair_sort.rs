//! Sorting of the broad phase's packed pair keys.
//!
//! A pair `(a, b)` is the key `(a << bits) | b`, so sorting keys sorts
//! pairs by `(a, b)`. With n bodies the keys have `2·⌈log2 n⌉` bits (26 for
//! 5000 bodies). An LSD radix sort does that in one counting pass and
//! `⌈bits / 13⌉` scatter passes (two for 26 bits), against ~`log2 p`
//! comparisons per key (≈14 for 16 000 pairs) for a comparison sort;
//! measured on the pairs of `balls5000`, it takes ~0.4 of `sort_unstable`'s
//! time.

/// Widest digit: 2¹³ `u32` counters (32 KiB) per pass stay in the L1/L2
/// cache. The digits of one sort are equal and as narrow as the pass count
/// allows (26 bits: two 13-bit passes; 30 bits: three 10-bit passes).
const MAX_DIGIT_BITS: u32 = 13;
/// Below this many keys a comparison sort is cheaper than clearing and
/// scanning the counters.
const SMALL: usize = 256;

/// Sorts `keys` ascending. Every key must be below `2^key_bits`
/// (`key_bits <= 64`). `scratch` and `histogram` are working buffers,
/// reused between calls.
///
/// Cost: O(len · ⌈key_bits / 13⌉ + 2¹³ · ⌈key_bits / 13⌉); memory one more
/// buffer of `len` keys. A pass whose digit is the same for every key is
/// skipped.
pub(crate) fn sort_keys(
    keys: &mut [u64],
    scratch: &mut Vec<u64>,
    histogram: &mut Vec<u32>,
    key_bits: u32,
) {
    // Counters are u32: longer inputs (never met: 2³² pairs) take the
    // comparison sort.
    if keys.len() <= SMALL || u32::try_from(keys.len()).is_err() {
        keys.sort_unstable();
        return;
    }
    let key_bits = key_bits.clamp(1, u64::BITS);
    let passes = key_bits.div_ceil(MAX_DIGIT_BITS);
    let digit_bits = key_bits.div_ceil(passes);
    let radix = 1usize << digit_bits;
    let mask = (1u64 << digit_bits) - 1;
    // All digit histograms in one read of the keys.
    histogram.clear();
    histogram.resize(passes as usize * radix, 0);
    for &key in keys.iter() {
        let mut shift = 0;
        for counts in histogram.chunks_exact_mut(radix) {
            counts[((key >> shift) & mask) as usize] += 1;
            shift += digit_bits;
        }
    }
    scratch.clear();
    scratch.resize(keys.len(), 0);
    // Where the current order lives: `keys` or `scratch`.
    let mut in_scratch = false;
    for (pass, counts) in (0u32..).zip(histogram.chunks_exact_mut(radix)) {
        if counts.iter().any(|&count| count as usize == keys.len()) {
            // Every key has the same digit here: the pass moves nothing.
            continue;
        }
        let mut total = 0;
        for count in counts.iter_mut() {
            let here = *count;
            *count = total;
            total += here;
        }
        // Stable scatter by this digit keeps the lower digits' order.
        let shift = pass * digit_bits;
        let (from, to): (&[u64], &mut [u64]) = if in_scratch {
            (scratch, keys)
        } else {
            (keys, scratch)
        };
        for &key in from {
            let slot = &mut counts[((key >> shift) & mask) as usize];
            to[*slot as usize] = key;
            *slot += 1;
        }
        in_scratch = !in_scratch;
    }
    if in_scratch {
        keys.copy_from_slice(scratch);
    }
}

#[cfg(test)]
mod tests {
    use super::sort_keys;
    use proptest::prelude::*;

    proptest! {
        #[test]
        fn sorts_like_the_standard_sort(
            mut keys in proptest::collection::vec(any::<u64>(), 0..2000),
            bits in 1u32..=64,
        ) {
            let mask = u64::MAX >> (64 - bits);
            for key in &mut keys {
                *key &= mask;
            }
            let mut expected = keys.clone();
            expected.sort_unstable();
            let (mut scratch, mut histogram) = (Vec::new(), Vec::new());
            sort_keys(&mut keys, &mut scratch, &mut histogram, bits);
            prop_assert_eq!(keys, expected);
        }
    }

    #[test]
    fn constant_digits_and_large_inputs_are_sorted() {
        // Keys sharing their high digits (skipped passes), many repeats,
        // and pass counts of both parities.
        for bits in [12, 26, 39, 64] {
            let mut keys: Vec<u64> = (0..10_000u64)
                .map(|i| ((i * 7919) % 3001) | (1 << (bits - 1)))
                .collect();
            let mut expected = keys.clone();
            expected.sort_unstable();
            let (mut scratch, mut histogram) = (Vec::new(), Vec::new());
            sort_keys(&mut keys, &mut scratch, &mut histogram, bits);
            assert_eq!(keys, expected);
        }
    }
}
