//! Collision: broad phase, narrow-phase dispatch and the contact cache.

mod box_corner;
mod broad_phase;
mod coincident;
mod confined_pair;
mod contact_cache;
mod covered_corner;
mod deflected_sweep;
mod face_past_walls;
mod grazing_miss;
mod implied_rows;
mod level_seam;
mod narrow_phase;
mod narrow_scratch;
mod pair_sort;
mod rope_turn;
#[cfg(test)]
mod test_values;

pub(crate) use broad_phase::{BroadPhase, Proxy, ProxyClass};
pub(crate) use contact_cache::CachedContact;
pub(crate) use narrow_phase::{NarrowPhase, contact_between, shape_toi};
pub(crate) use narrow_scratch::NarrowScratch;
