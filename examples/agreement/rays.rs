//! Agreement of the ray and TOI queries (being written).
pub fn report() {}
