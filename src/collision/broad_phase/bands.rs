//! Horizontal bands: y cut into runs of one height so each band is swept
//! on its own (see the broad phase's docs, step 3).

use super::item::{Item, y_span};

/// Most bands (a power of two). Bounds the per-call band tables (two
/// `usize` per band) and, with the `4n` bound on band copies, the memory of
/// the phase. 4096 bands of the median proxy height is far more than any
/// pile needs; a world taller than that gets taller bands. Also keeps a
/// band number within `u16` ([`Item::band_min`]).
pub(super) const MAX_BANDS: usize = 1 << 12;

/// The band layout of one call: band `k` holds y keys in
/// `[bottom + k·2^shift, bottom + (k+1)·2^shift)`.
#[derive(Clone, Copy, Debug)]
pub(super) struct Bands {
    /// The lowest y key of any item.
    pub(super) bottom: i64,
    /// The highest y key of any item.
    pub(super) top: i64,
    /// `log2` of the band height in key units; 64 means one band.
    pub(super) shift: u32,
}

impl Bands {
    /// Chooses the band height for `items`: the power of two just above
    /// the median proxy height (a proxy then meets one or two bands, and
    /// the sweep's work, ~(bands per proxy) × (B + h), is near its
    /// minimum at B ≈ h), raised if needed so that the copies stay below
    /// `4n` and the bands below [`MAX_BANDS`]. One pass, integers only.
    pub(super) fn choose(items: &[Item]) -> Bands {
        let mut bottom = i64::MAX;
        let mut top = i64::MIN;
        // Proxies by the bit length of their height (0..=64).
        let mut by_bits = [0usize; 65];
        let mut height_sum = 0u128;
        for item in items {
            let (low, high) = y_span(item);
            bottom = bottom.min(low);
            top = top.max(high);
            let height = high.abs_diff(low);
            by_bits[(u64::BITS - height.leading_zeros()) as usize] += 1;
            height_sum += u128::from(height);
        }
        if items.is_empty() {
            return Bands {
                bottom: 0,
                top: 0,
                shift: 64,
            };
        }
        let n = items.len();
        // Bit length j of the median height h: 2^j > h ≥ 2^(j-1).
        let mut seen = 0usize;
        let mut median_bits = 64u32;
        for (bits, &count) in (0u32..).zip(&by_bits) {
            seen += count;
            if 2 * seen >= n {
                median_bits = bits;
                break;
            }
        }
        // Copies: a proxy of height h meets at most h/B + 2 bands, so the
        // total is at most 2n + Σh/B; B > Σh/(2n) keeps it below 4n.
        let per_band = height_sum / (2 * n as u128);
        let copies_bits = u128::BITS - per_band.leading_zeros();
        // Band count: the y range shifted right by `shift` stays below
        // MAX_BANDS.
        let range_bits = u64::BITS - top.abs_diff(bottom).leading_zeros();
        let shift = median_bits
            .max(copies_bits)
            .max(range_bits.saturating_sub(MAX_BANDS.trailing_zeros()));
        Bands { bottom, top, shift }
    }

    /// The band of a y key in `[bottom, top]`.
    #[inline]
    pub(super) fn band(&self, y: i64) -> usize {
        // y ≥ bottom, so the difference is exact as u64; the result is
        // below MAX_BANDS by the choice of shift.
        y.abs_diff(self.bottom).checked_shr(self.shift).unwrap_or(0) as usize
    }

    /// The first and last band an item's y range meets.
    #[inline]
    pub(super) fn range(&self, item: &Item) -> (usize, usize) {
        let (low, high) = y_span(item);
        (self.band(low), self.band(high))
    }
}
