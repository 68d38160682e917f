//! Collision: broad phase, narrow-phase dispatch and the contact cache.

mod broad_phase;
mod contact_cache;
mod narrow_phase;
mod pair_sort;

pub(crate) use broad_phase::{BroadPhase, Proxy, ProxyClass, find_pairs};
pub(crate) use contact_cache::CachedContact;
pub(crate) use narrow_phase::{circles_out_of_reach, contact_between, shape_toi};
