//! The broad-phase partners of the bodies a bounce moved, for the rebound
//! sweep (`World::sweep_rebounds`): one list per rebounding body, built
//! from the substep's candidate pairs.

use super::restitution::Rebound;
use crate::math::Scalar;

/// The broad-phase partners of each rebounding slot, into `out`: for the
/// `k`-th entry of `rebounds` (sorted by slot, without repeats),
/// `out.of(k)` lists the other slot of every pair in `pairs` that holds it,
/// ascending.
///
/// Why this order comes out without a sort: `pairs` is sorted by `(a, b)`
/// with `a < b` and without repeats (the broad phase's contract), so for a
/// slot `s` the pairs `(a, s)` (all `a < s`, ascending) come before the
/// pairs `(s, b)` (all `b > s`, ascending): appended in pair order, each
/// list is already ascending. Cost: two passes over the pairs with one
/// table look-up per end, instead of a binary search per end and a sort.
pub(crate) fn collect_rebound_partners<S: Scalar>(
    pairs: &[(u32, u32)],
    rebounds: &[Rebound<S>],
    slot_count: usize,
    out: &mut ReboundPartners,
) {
    let ReboundPartners {
        rebound_of_slot,
        starts,
        partners,
    } = out;
    rebound_of_slot.clear();
    rebound_of_slot.resize(slot_count, NOT_REBOUNDING);
    for (k, rebound) in rebounds.iter().enumerate() {
        if let Some(entry) = rebound_of_slot.get_mut(rebound.slot as usize) {
            // At most one entry per slot and far fewer than u32::MAX.
            *entry = u32::try_from(k).unwrap_or(NOT_REBOUNDING);
        }
    }
    let rebound = |slot: u32| {
        rebound_of_slot
            .get(slot as usize)
            .copied()
            .filter(|&k| k != NOT_REBOUNDING)
            .map(|k| k as usize)
    };
    // Counts, then exclusive prefix sums as each list's write cursor.
    // Room for every slot rebounding and every pair twice, so a step after
    // the warm-up does not allocate when more bodies rebound than before.
    starts.clear();
    starts.reserve(slot_count + 1);
    starts.resize(rebounds.len() + 1, 0);
    for &(a, b) in pairs {
        for k in [rebound(a), rebound(b)].into_iter().flatten() {
            starts[k + 1] += 1;
        }
    }
    for k in 1..starts.len() {
        starts[k] += starts[k - 1];
    }
    partners.clear();
    partners.reserve(pairs.len().saturating_mul(2));
    partners.resize(starts[rebounds.len()], 0);
    // `starts[k]` is advanced as list k fills; it ends at list k + 1's
    // start and is moved back below.
    for &(a, b) in pairs {
        for (k, other) in [(rebound(a), b), (rebound(b), a)] {
            if let Some(k) = k {
                partners[starts[k]] = other;
                starts[k] += 1;
            }
        }
    }
    for k in (1..starts.len()).rev() {
        starts[k] = starts[k - 1];
    }
    starts[0] = 0;
}

/// Marks a slot without a rebound in [`ReboundPartners`].
const NOT_REBOUNDING: u32 = u32::MAX;

/// The broad-phase partners of the rebounding slots, as lists in one buffer
/// ([`collect_rebound_partners`]); kept in the step context so that it
/// allocates nothing in steady state.
#[derive(Clone, Debug, Default)]
pub(crate) struct ReboundPartners {
    /// Per slot: its index in the rebound list, or [`NOT_REBOUNDING`].
    rebound_of_slot: Vec<u32>,
    /// List `k` is `partners[starts[k]..starts[k + 1]]`.
    starts: Vec<usize>,
    /// The lists, one after another.
    partners: Vec<u32>,
}

impl ReboundPartners {
    /// The partners of the `k`-th rebound, ascending.
    pub(crate) fn of(&self, k: usize) -> &[u32] {
        &self.partners[self.starts[k]..self.starts[k + 1]]
    }

    /// The index in the rebound list of `slot`'s rebound, if it has one.
    pub(crate) fn rebound_of(&self, slot: u32) -> Option<usize> {
        self.rebound_of_slot
            .get(slot as usize)
            .copied()
            .filter(|&k| k != NOT_REBOUNDING)
            .map(|k| k as usize)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::{Fx, Vec2};

    /// Every list equals the sorted partners of its slot found by brute
    /// force, for slots at the ends of the slot range, with no partners,
    /// and next to each other.
    #[test]
    fn lists_are_each_slots_partners_ascending() {
        let pairs = [
            (0, 3),
            (0, 7),
            (1, 2),
            (2, 3),
            (2, 9),
            (3, 4),
            (3, 9),
            (5, 9),
            (8, 9),
        ];
        let rebounds: Vec<Rebound<Fx>> = [0, 2, 3, 6, 9]
            .iter()
            .map(|&slot| Rebound {
                slot,
                start: Vec2::ZERO,
                time: Fx::ZERO,
                order: 0,
            })
            .collect();
        let mut out = ReboundPartners::default();
        // Twice: the buffers are reused.
        for _ in 0..2 {
            collect_rebound_partners(&pairs, &rebounds, 10, &mut out);
            for (k, rebound) in rebounds.iter().enumerate() {
                let slot = rebound.slot;
                let mut expected: Vec<u32> = pairs
                    .iter()
                    .filter_map(|&(a, b)| (a == slot).then_some(b).or((b == slot).then_some(a)))
                    .collect();
                expected.sort_unstable();
                assert_eq!(out.of(k), expected.as_slice(), "slot {slot}");
            }
        }
        assert_eq!(out.of(3), &[] as &[u32]);
        assert_eq!(out.of(4), &[2, 3, 5, 8]);
    }
}
