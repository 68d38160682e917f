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
//!    scalar's order ([`order_key`](item::order_key)): for fixed point that is the raw value,
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
//!    `4n` and the band count under [`MAX_BANDS`](bands::MAX_BANDS), which bounds time and
//!    memory for any input (a proxy spanning the world, saturated
//!    coordinates, everything in one spot).
//! 4. **Pair sort.** Pairs are packed into `u64` keys and sorted by an LSD
//!    radix sort ([`super::pair_sort`]): a few linear passes instead of
//!    `O(p log p)` comparisons.
//!
//! All buffers live in [`BroadPhase`], kept in the step context, so a world
//! in steady state allocates nothing here.

mod bands;
mod item;
mod proxy;

use self::bands::Bands;
use self::item::{Item, item_of};
use self::proxy::PAIR_TABLE;
pub(crate) use self::proxy::{Proxy, ProxyClass};
use super::pair_sort::sort_keys;
use crate::math::Scalar;

/// Marks a slot with no proxy in [`BroadPhase::slot_position`].
const ABSENT: u32 = u32::MAX;
/// Marks a slot whose proxy was already placed in the x order.
const TAKEN: u32 = u32::MAX - 1;

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
mod tests;
