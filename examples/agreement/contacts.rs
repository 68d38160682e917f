//! Agreement of the contact queries (being written).
pub fn report() {}
