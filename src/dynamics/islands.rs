//! Islands by union-find, in slot-index order.
//!
//! Each root is the smallest slot index of its island (union always makes the
//! smaller root the parent), so the result does not depend on the order in
//! which pairs are joined: the same on every machine.

/// Resets `parents` so every one of `count` slots is its own island.
pub(crate) fn reset(parents: &mut Vec<u32>, count: usize) {
    parents.clear();
    parents.extend((0..count).map(|i| u32::try_from(i).unwrap_or(u32::MAX)));
}

/// The root of `i`, halving the path on the way (each visited slot is
/// pointed at its grandparent: one pass, where full compression walks the
/// path twice). The root is the island's smallest slot whatever the
/// compression, so results do not depend on it.
pub(crate) fn find(parents: &mut [u32], i: u32) -> u32 {
    let mut node = i;
    loop {
        let parent = parents[node as usize];
        if parent == node {
            return node;
        }
        let grandparent = parents[parent as usize];
        parents[node as usize] = grandparent;
        node = grandparent;
    }
}

/// Points every slot straight at its root, in one forward pass; afterwards
/// `parents[i]` is the root of `i` (what [`find`] returns), with no walk.
///
/// Why one pass is enough: no slot's parent is above it. [`reset`] starts
/// with `parents[i] = i`, a union makes the lower root the parent of the
/// higher one, and compression points a slot at its root, which is the
/// smallest member of its island. So when slot `i` is reached, its parent
/// `p ≤ i` either is `i` (a root) or was already pointed at its root.
pub(crate) fn flatten(parents: &mut [u32]) {
    for i in 0..parents.len() {
        let parent = parents[i] as usize;
        // `parent <= i`: a root, or an earlier slot already flattened.
        parents[i] = parents[parent];
    }
}

/// Joins the islands of `a` and `b`; the smaller root becomes the parent.
pub(crate) fn union(parents: &mut [u32], a: u32, b: u32) {
    let (ra, rb) = (find(parents, a), find(parents, b));
    if ra < rb {
        parents[rb as usize] = ra;
    } else if rb < ra {
        parents[ra as usize] = rb;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn roots_are_smallest_members_whatever_the_union_order() {
        let mut p = Vec::new();
        reset(&mut p, 6);
        union(&mut p, 5, 3);
        union(&mut p, 3, 4);
        union(&mut p, 1, 2);
        assert_eq!(find(&mut p, 5), 3);
        assert_eq!(find(&mut p, 4), 3);
        assert_eq!(find(&mut p, 2), 1);
        union(&mut p, 4, 2);
        for i in 1..6 {
            assert_eq!(find(&mut p, i), 1);
        }
        assert_eq!(find(&mut p, 0), 0);
    }

    /// After any sequence of unions (deep chains included), `flatten`
    /// leaves every slot pointing at the root `find` reports.
    #[test]
    fn flatten_points_every_slot_at_its_root() {
        let mut p = Vec::new();
        reset(&mut p, 12);
        // A chain joined from the top down (each union hangs the old
        // root under a lower one), a pair, and singletons.
        for i in (1..8).rev() {
            union(&mut p, i, i + 1);
        }
        union(&mut p, 10, 9);
        let roots: Vec<u32> = (0..12).map(|i| find(&mut p.clone(), i)).collect();
        flatten(&mut p);
        assert_eq!(p, roots);
        assert_eq!(&p[..], &[0, 1, 1, 1, 1, 1, 1, 1, 1, 9, 9, 11]);
    }
}
