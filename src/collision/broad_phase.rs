//! Broad phase: sweep and prune along x over swept bounding boxes, run
//! separately in horizontal bands.
//!
//! # What it computes
//!
//! The pair set is defined by a plain sweep and prune along x: order the
//! proxies by `(min_x, index)`; a proxy `q` later in that order pairs with an
//! earlier `p` when `q.min_x <= p.max_x`, the y ranges overlap
//! (`q.min_y <= p.max_y && p.min_y <= q.max_y`) and the classes pair
//! ([`ProxyClass::pairs_with`]); proxies with no class take no part. Pairs
//! come out as `(a, b)` slot indices, `a < b`, sorted, without repeats.
//! Everything below is an exact, faster way to get that set; the set itself
//! (and with it every later step of the simulation) does not depend on any
//! of the speed-ups, nor on the history kept between calls.
//!
//! # How, and what it costs
//!
//! 1. **Integer keys.** Each coordinate becomes an `i64` whose order is the
//!    scalar's order ([`order_key`]): for fixed point that is the raw value,
//!    so all later work is plain integer comparisons and shifts.
//! 2. **x order kept between calls.** Bodies move little per substep, so the
//!    last call's order (slot indices, [`BroadPhase::order`]) is a nearly
//!    sorted start: the proxies are laid out in that order and finished with
//!    an insertion sort, linear when almost nothing moved. Its work is
//!    capped; past the cap (a first call, a restored world, many spawns)
//!    a full `O(n log n)` sort takes over. Added proxies are appended,
//!    removed ones skipped.
//! 3. **Bands.** A single sweep along x visits every pair of proxies that
//!    overlap in x, which in a pile 16 balls high is ~75 per ball for ~3
//!    real pairs. So y is cut into bands of one height `B` (a power of two
//!    ≥ the median proxy height, so a proxy is in one or two bands), each
//!    proxy is copied into every band its y range meets (a stable counting
//!    sort, so each band stays in x order), and each band is swept on its
//!    own. The x overlaps seen drop by about the pile height over `2B`
//!    (`balls5000`: from ~75 to ~7.5 per ball, for ~3.2 pairs per ball).
//!    A pair is seen in every band both proxies are in; it is reported only
//!    in the band of `max(p.min_y, q.min_y)`, a value inside both y ranges,
//!    so exactly once. `B` is also raised so that the copies stay under
//!    `4n` and the band count under [`MAX_BANDS`], which bounds time and
//!    memory for any input (a proxy spanning the world, saturated
//!    coordinates, everything in one spot).
//! 4. **Pair sort.** Pairs are packed into `u64` keys and sorted by an LSD
//!    radix sort ([`super::pair_sort`]): a few linear passes instead of
//!    `O(p log p)` comparisons.
//!
//! All buffers live in [`BroadPhase`], kept in the step scratch, so a world
//! in steady state allocates nothing here.

use super::pair_sort::sort_keys;
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
    /// All classes, in the order of their codes (see [`Self::code`]).
    const ALL: [ProxyClass; 4] = [
        ProxyClass::Still,
        ProxyClass::Sleeping,
        ProxyClass::MovingKinematic,
        ProxyClass::Dynamic,
    ];

    /// Whether a pair of these classes needs a contact: something must be
    /// able to respond (an awake dynamic body), or a moving kinematic body
    /// must be able to wake a sleeper.
    #[inline]
    const fn pairs_with(self, other: ProxyClass) -> bool {
        use ProxyClass::{Dynamic, MovingKinematic, Sleeping};
        matches!(
            (self, other),
            (Dynamic, _) | (_, Dynamic) | (MovingKinematic, Sleeping) | (Sleeping, MovingKinematic)
        )
    }

    /// A small code, `0..4`, indexing [`PAIR_TABLE`].
    #[inline]
    const fn code(self) -> u8 {
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
const PAIR_TABLE: u16 = {
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

/// Most bands (a power of two). Bounds the per-call band tables (two
/// `usize` per band) and, with the `4n` bound on band copies, the memory of
/// the phase. 4096 bands of the median proxy height is far more than any
/// pile needs; a world taller than that gets taller bands. Also keeps a
/// band number within `u16` ([`Item::band_min`]).
const MAX_BANDS: usize = 1 << 12;

/// Marks a slot with no proxy in [`BroadPhase::slot_position`].
const ABSENT: u32 = u32::MAX;
/// Marks a slot whose proxy was already placed in the x order.
const TAKEN: u32 = u32::MAX - 1;

/// A proxy as the phase works on it: coordinates as order keys (see
/// [`order_key`]), 40 bytes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
struct Item {
    min_x: i64,
    max_x: i64,
    min_y: i64,
    max_y: i64,
    /// Slot index of the body.
    index: u32,
    /// The band holding `min_y` (set when the item is copied into bands).
    band_min: u16,
    /// [`ProxyClass::code`].
    class: u8,
}

/// The broad phase's working memory, kept from call to call. None of it is
/// state: results never depend on it (a fresh one gives the same pairs), it
/// only makes the next call faster.
#[derive(Clone, Debug, Default)]
pub(crate) struct BroadPhase {
    /// Slot indices in the x order of the last call: the starting order of
    /// the next sort.
    order: Vec<u32>,
    /// Slot index → position of its proxy in the input, or [`ABSENT`] /
    /// [`TAKEN`]. Used only while the slot indices are dense enough (see
    /// [`Self::lay_out_in_last_order`]) so its size stays `O(n)`.
    slot_position: Vec<u32>,
    /// The classed proxies in `(min_x, index)` order.
    items: Vec<Item>,
    /// Offset of each band's run in `banded`; `bands + 1` entries.
    band_start: Vec<usize>,
    /// Write cursor of each band while copying.
    band_cursor: Vec<usize>,
    /// The items copied into their bands: band by band, each in x order.
    banded: Vec<Item>,
    /// Found pairs as `(a << bits) | b` keys in `keys[..key_count]`; the
    /// rest is room the sweep writes into (see [`sweep`]).
    keys: Vec<u64>,
    /// How many keys the last sweep found.
    key_count: usize,
    /// Second buffer of the radix sort.
    keys_scratch: Vec<u64>,
    /// Digit histograms of the radix sort.
    histogram: Vec<u32>,
}

impl BroadPhase {
    /// Writes the overlapping pairs of `proxies`, sorted by `(a, b)` with
    /// `a < b`, into `pairs` (see the [module docs](self) for the exact
    /// predicate). Slot indices must be distinct among classed proxies
    /// (repeats give an unspecified, but still panic-free, result).
    pub(crate) fn find_pairs<S: Scalar>(
        &mut self,
        proxies: &[Proxy<S>],
        pairs: &mut Vec<(u32, u32)>,
    ) {
        pairs.clear();
        self.sort_along_x(proxies);
        if !self.any_pair_possible() {
            return;
        }
        self.fill_bands();
        let index_bits = self.sweep_bands();
        let keys = &mut self.keys[..self.key_count];
        sort_keys(
            keys,
            &mut self.keys_scratch,
            &mut self.histogram,
            2 * index_bits,
        );
        let low_mask = (1u64 << index_bits) - 1;
        pairs.extend(keys.iter().map(|&key| {
            // Both halves are slot indices (< 2³²), so the casts are exact.
            ((key >> index_bits) as u32, (key & low_mask) as u32)
        }));
    }

    /// Fills `items` with the classed proxies in `(min_x, index)` order and
    /// records that order for the next call.
    fn sort_along_x<S: Scalar>(&mut self, proxies: &[Proxy<S>]) {
        self.items.clear();
        let appended = self.lay_out_in_last_order(proxies);
        // The insertion sort's work is the items' total displacement from
        // the last order, small when bodies move little per substep. Past
        // a few moves per item the order was not a good start (first call,
        // restore, many spawns) and a full sort is cheaper.
        let budget = 8 * self.items.len() + 64;
        let nearly_sorted = appended <= self.items.len() / 8 + 16
            && insertion_sort_bounded(&mut self.items, budget);
        if !nearly_sorted {
            self.items
                .sort_unstable_by_key(|item| (item.min_x, item.index));
        }
        self.order.clear();
        self.order.extend(self.items.iter().map(|item| item.index));
    }

    /// Pushes the classed proxies into `items`: first those in the last
    /// call's order, then the new ones. Returns how many were new (all of
    /// them when the slot indices are too sparse or repeat, which turns the
    /// history off for this call).
    fn lay_out_in_last_order<S: Scalar>(&mut self, proxies: &[Proxy<S>]) -> usize {
        let classed = proxies.iter().filter(|p| p.class.is_some());
        let max_index = classed.clone().map(|p| p.index).max().unwrap_or(0);
        let count = classed.clone().count();
        // The map from slot index to input position costs O(max index) per
        // call; use it only while that is O(n). Positions must also fit
        // below the two markers.
        let dense = u64::from(max_index) <= 8 * count as u64 + 4096;
        let fits = u32::try_from(proxies.len()).is_ok_and(|len| len < TAKEN);
        if !(dense && fits && !self.order.is_empty()) {
            self.items.extend(classed.map(item_of));
            return self.items.len();
        }
        self.slot_position.clear();
        self.slot_position.resize(max_index as usize + 1, ABSENT);
        for (position, proxy) in proxies.iter().enumerate() {
            if proxy.class.is_none() {
                continue;
            }
            let slot = &mut self.slot_position[proxy.index as usize];
            if *slot != ABSENT {
                // A repeated slot index: no well-defined history.
                self.items
                    .extend(proxies.iter().filter(|p| p.class.is_some()).map(item_of));
                return self.items.len();
            }
            // `fits` above: the position is below both markers.
            *slot = position as u32;
        }
        for &slot in &self.order {
            let Some(position) = self.slot_position.get_mut(slot as usize) else {
                continue;
            };
            if *position >= TAKEN {
                continue;
            }
            self.items.push(item_of(&proxies[*position as usize]));
            *position = TAKEN;
        }
        let kept = self.items.len();
        for proxy in proxies {
            if proxy.class.is_some() && self.slot_position[proxy.index as usize] != TAKEN {
                self.items.push(item_of(proxy));
            }
        }
        self.items.len() - kept
    }

    /// Whether any two classes present can pair (a world with nothing awake
    /// and nothing kinematic moving has no pairs, whatever overlaps).
    fn any_pair_possible(&self) -> bool {
        let mut present = 0u8;
        for item in &self.items {
            present |= 1 << item.class;
        }
        let is_present = |class: ProxyClass| present & (1 << class.code()) != 0;
        ProxyClass::ALL.iter().any(|&a| {
            ProxyClass::ALL
                .iter()
                .any(|&b| is_present(a) && is_present(b) && a.pairs_with(b))
        })
    }

    /// Copies the sorted items into their bands: a stable counting sort
    /// (count, prefix sums, copy), so each band's run in `banded` is in x
    /// order. Sets `band_start`.
    ///
    /// Cost: two passes over the items. With bands at least as tall as the
    /// median proxy, an item meets one band or two, both often (1.7 copies
    /// per item in `balls5000`), so both passes avoid branching on that: the count pass adds `+1` at the
    /// first band and `−1` after the last (a difference array, summed up
    /// afterwards), the copy pass always writes a second copy, into the
    /// last band or else into a spare slot past the end.
    fn fill_bands(&mut self) {
        let bands = Bands::choose(&self.items);
        let band_count = bands.band(bands.top) + 1;
        // Counts as differences: usize arithmetic modulo 2^bits, whose
        // running sums are the (non-negative) counts.
        self.band_cursor.clear();
        self.band_cursor.resize(band_count + 1, 0);
        for item in &self.items {
            let (low, high) = bands.range(item);
            self.band_cursor[low] = self.band_cursor[low].wrapping_add(1);
            self.band_cursor[high + 1] = self.band_cursor[high + 1].wrapping_sub(1);
        }
        self.band_start.clear();
        self.band_start.push(0);
        let mut total = 0usize;
        let mut count = 0usize;
        for cursor in &mut self.band_cursor[..band_count] {
            count = count.wrapping_add(*cursor);
            *cursor = total;
            total += count;
            self.band_start.push(total);
        }
        // Every slot below `total` is written next, and the spare slot at
        // `total` takes the discarded copies; what lies beyond is stale and
        // never read, so the buffer is only grown, never cleared.
        if self.banded.len() <= total {
            self.banded.resize(total + 1, Item::default());
        }
        for item in &self.items {
            let (low, high) = bands.range(item);
            let mut copy = *item;
            // At most MAX_BANDS − 1, so it fits.
            copy.band_min = bands.band(item.min_y) as u16;
            let at = self.band_cursor[low];
            self.banded[at] = copy;
            self.band_cursor[low] = at + 1;
            // Bands strictly inside the range: none for most items.
            for band in low + 1..high {
                let at = self.band_cursor[band];
                self.banded[at] = copy;
                self.band_cursor[band] = at + 1;
            }
            let spans = high > low;
            let at = if spans { self.band_cursor[high] } else { total };
            self.banded[at] = copy;
            self.band_cursor[high] += usize::from(spans);
        }
    }

    /// Sweeps each band along x, leaving the keys of the pairs in
    /// `keys[..key_count]`. Returns the bits of a slot index (the keys are
    /// `(a << bits) | b`).
    fn sweep_bands(&mut self) -> u32 {
        let max_index = self.items.iter().map(|item| item.index).max().unwrap_or(0);
        let index_bits = u32::BITS - max_index.leading_zeros();
        self.key_count = 0;
        for (band, window) in self.band_start.windows(2).enumerate() {
            sweep(
                &self.banded[window[0]..window[1]],
                band,
                index_bits,
                &mut self.keys,
                &mut self.key_count,
            );
        }
        index_bits
    }
}

/// The sweep of one band (items in `(min_x, index)` order): writes the key
/// of every pair whose reporting band is `band` at `keys[*count..]`,
/// advancing `count` (`keys` is used as a buffer beyond its logical length
/// `count`, grown here when it could fall short).
///
/// Cost: one step per x overlap inside the band. Whether an x overlap is a
/// pair is close to a coin toss (~0.45 in `balls5000`), which a branch
/// would mispredict often, so it is computed without branches: every
/// candidate's key is written and the count advances only on a pair.
#[inline]
fn sweep(items: &[Item], band: usize, index_bits: u32, keys: &mut Vec<u64>, count: &mut usize) {
    // Below MAX_BANDS, so it fits.
    let band = band as u16;
    let mut n = *count;
    for (i, p) in items.iter().enumerate() {
        let rest = &items[i + 1..];
        // Room for every candidate of p, so the writes below stay inside.
        // The buffer keeps its length between calls: no allocation in
        // steady state.
        if keys.len() < n + rest.len() {
            keys.resize(n + rest.len(), 0);
        }
        let row = PAIR_TABLE >> (p.class << 2);
        for q in rest {
            if q.min_x > p.max_x {
                break;
            }
            // The pair's reporting band is that of max(p.min_y, q.min_y),
            // which (bands being monotone) is the larger of their bands.
            let hit = (q.min_y <= p.max_y)
                & (p.min_y <= q.max_y)
                & (p.band_min.max(q.band_min) == band)
                & ((row >> q.class) & 1 != 0);
            let (a, b) = (p.index.min(q.index), p.index.max(q.index));
            keys[n] = (u64::from(a) << index_bits) | u64::from(b);
            n += usize::from(hit);
        }
    }
    *count = n;
}

/// The band layout of one call: band `k` holds y keys in
/// `[bottom + k·2^shift, bottom + (k+1)·2^shift)`.
#[derive(Clone, Copy, Debug)]
struct Bands {
    /// The lowest y key of any item.
    bottom: i64,
    /// The highest y key of any item.
    top: i64,
    /// `log2` of the band height in key units; 64 means one band.
    shift: u32,
}

impl Bands {
    /// Chooses the band height for `items`: the power of two just above
    /// the median proxy height (a proxy then meets one or two bands, and
    /// the sweep's work, ~(bands per proxy) × (B + h), is near its
    /// minimum at B ≈ h), raised if needed so that the copies stay below
    /// `4n` and the bands below [`MAX_BANDS`]. One pass, integers only.
    fn choose(items: &[Item]) -> Bands {
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
    fn band(&self, y: i64) -> usize {
        // y ≥ bottom, so the difference is exact as u64; the result is
        // below MAX_BANDS by the choice of shift.
        y.abs_diff(self.bottom).checked_shr(self.shift).unwrap_or(0) as usize
    }

    /// The first and last band an item's y range meets.
    #[inline]
    fn range(&self, item: &Item) -> (usize, usize) {
        let (low, high) = y_span(item);
        (self.band(low), self.band(high))
    }
}

/// An item's y range as `(low, high)`, also for an inverted proxy
/// (`min_y > max_y`, which the pair test treats asymmetrically: its pairs
/// have `max(p.min_y, q.min_y)` inside this range all the same).
#[inline]
fn y_span(item: &Item) -> (i64, i64) {
    (item.min_y.min(item.max_y), item.min_y.max(item.max_y))
}

/// The work item of a classed proxy.
#[inline]
fn item_of<S: Scalar>(proxy: &Proxy<S>) -> Item {
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
fn order_key<S: Scalar>(value: S) -> i64 {
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

/// Insertion sort by `(min_x, index)` that gives up once it has moved items
/// more than `budget` places in total (then returns `false`, leaving a
/// permutation of the input). Linear on a nearly sorted slice.
fn insertion_sort_bounded(items: &mut [Item], budget: usize) -> bool {
    let mut moves = 0usize;
    for i in 1..items.len() {
        let current = items[i];
        let key = (current.min_x, current.index);
        let mut j = i;
        while j > 0 && key < (items[j - 1].min_x, items[j - 1].index) {
            items[j] = items[j - 1];
            j -= 1;
        }
        items[j] = current;
        moves += i - j;
        if moves > budget {
            return false;
        }
    }
    true
}

#[cfg(test)]
#[path = "broad_phase_tests.rs"]
mod tests;
