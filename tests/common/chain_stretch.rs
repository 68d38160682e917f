//! How far a chain of ropes is stretched: the measure of every rope-chain
//! test.
//!
//! A chain is an anchor point and links `x_1 … x_n`, rope `k` joining
//! `x_{k−1}` to `x_k` (`x_0` the anchor) with the rest length `ℓ`. A rope
//! may be slack but never longer than `ℓ`, so the measure is the largest
//! relative excess `(|x_k − x_{k−1}| − ℓ)/ℓ`, floored at 0 (a slack chain
//! reads 0, not a negative stretch).

use clockwork2d::prelude::*;

/// The worst relative stretch of the chain through `points` (in order,
/// starting from the one tied to `anchor`), each rope of rest length
/// `segment`; 0 when every rope is slack or exact.
pub fn worst_stretch_of_points(
    anchor: (f64, f64),
    points: impl IntoIterator<Item = (f64, f64)>,
    segment: f64,
) -> f64 {
    let mut previous = anchor;
    let mut worst = 0.0f64;
    for p in points {
        let length = (p.0 - previous.0).hypot(p.1 - previous.1);
        worst = worst.max((length - segment) / segment);
        previous = p;
    }
    worst
}

/// The worst relative stretch of the chain of bodies `links` hung from
/// `anchor` in `world` (see [`worst_stretch_of_points`]).
pub fn worst_stretch(world: &World, anchor: (f64, f64), links: &[BodyId], segment: f64) -> f64 {
    worst_stretch_of_points(
        anchor,
        links
            .iter()
            .map(|&id| world.body(id).expect("live link").position().to_f64()),
        segment,
    )
}
