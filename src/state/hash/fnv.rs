//! FNV-1a hashers (64 and 128 bit) fed with canonical little-endian
//! values: the byte-level half of the state hash (see [`super`]).

use crate::math::{Scalar, Vec2};

const FNV_OFFSET: u64 = 0xcbf2_9ce4_8422_2325;
const FNV_PRIME: u64 = 0x0000_0100_0000_01b3;
const FNV128_OFFSET: u128 = 0x6c62_272e_07bb_0142_62b8_2175_6295_c58d;
const FNV128_PRIME: u128 = 0x0000_0000_0100_0000_0000_0000_0000_013b;

/// Something the canonical byte stream of the state can be fed into: the
/// 64-bit and the 128-bit FNV-1a hashers. The part digests are written once,
/// generically, so both hashes see exactly the same bytes.
pub trait StateSink {
    /// Feeds raw bytes.
    fn bytes(&mut self, bytes: &[u8]);
    /// Feeds one byte.
    fn u8(&mut self, v: u8) {
        self.bytes(&[v]);
    }
    /// Feeds a boolean as 0 or 1.
    fn bool(&mut self, v: bool) {
        self.u8(u8::from(v));
    }
    /// Feeds a `u32`, little endian.
    fn u32(&mut self, v: u32) {
        self.bytes(&v.to_le_bytes());
    }
    /// Feeds a `u64`, little endian.
    fn u64(&mut self, v: u64) {
        self.bytes(&v.to_le_bytes());
    }
    /// Feeds a scalar's canonical bits.
    fn scalar<S: Scalar>(&mut self, v: S) {
        self.u64(v.to_hash_bits());
    }
    /// Feeds a vector (x then y).
    fn vec2<S: Scalar>(&mut self, v: Vec2<S>) {
        self.scalar(v.x);
        self.scalar(v.y);
    }
}

/// An FNV-1a-64 hasher fed with canonical little-endian values.
#[derive(Clone, Copy, Debug)]
pub struct StateHasher(u64);

impl Default for StateHasher {
    fn default() -> Self {
        StateHasher(FNV_OFFSET)
    }
}

impl StateHasher {
    /// Feeds raw bytes.
    pub fn bytes(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.0 ^= u64::from(b);
            self.0 = self.0.wrapping_mul(FNV_PRIME);
        }
    }
    /// Feeds one byte.
    pub fn u8(&mut self, v: u8) {
        self.bytes(&[v]);
    }
    /// Feeds a boolean as 0 or 1.
    pub fn bool(&mut self, v: bool) {
        self.u8(u8::from(v));
    }
    /// Feeds a `u32`, little endian.
    pub fn u32(&mut self, v: u32) {
        self.bytes(&v.to_le_bytes());
    }
    /// Feeds a `u64`, little endian.
    pub fn u64(&mut self, v: u64) {
        self.bytes(&v.to_le_bytes());
    }
    /// Feeds a scalar's canonical bits.
    pub fn scalar<S: Scalar>(&mut self, v: S) {
        self.u64(v.to_hash_bits());
    }
    /// Feeds a vector (x then y).
    pub fn vec2<S: Scalar>(&mut self, v: Vec2<S>) {
        self.scalar(v.x);
        self.scalar(v.y);
    }
    /// The digest so far.
    #[must_use]
    pub fn finish(&self) -> u64 {
        self.0
    }
}

impl StateSink for StateHasher {
    fn bytes(&mut self, bytes: &[u8]) {
        StateHasher::bytes(self, bytes);
    }
}

/// An FNV-1a-128 hasher fed with canonical little-endian values (the
/// 128-bit twin of [`StateHasher`]).
#[derive(Clone, Copy, Debug)]
pub struct StateHasher128(u128);

impl Default for StateHasher128 {
    fn default() -> Self {
        StateHasher128(FNV128_OFFSET)
    }
}

impl StateHasher128 {
    /// The digest so far.
    #[must_use]
    pub fn finish(&self) -> u128 {
        self.0
    }
}

impl StateSink for StateHasher128 {
    fn bytes(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.0 ^= u128::from(b);
            self.0 = self.0.wrapping_mul(FNV128_PRIME);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fnv1a_matches_the_published_test_vectors() {
        // FNV-1a 64 of "" and of "a" (from the FNV reference test suite).
        let empty = StateHasher::default();
        assert_eq!(empty.finish(), 0xcbf2_9ce4_8422_2325);
        let mut a = StateHasher::default();
        a.bytes(b"a");
        assert_eq!(a.finish(), 0xaf63_dc4c_8601_ec8c);
    }

    #[test]
    fn fnv1a_128_matches_the_published_test_vectors() {
        // FNV-1a 128 of "", "a" and "foobar" (FNV reference test suite).
        assert_eq!(
            StateHasher128::default().finish(),
            0x6c62_272e_07bb_0142_62b8_2175_6295_c58d
        );
        let mut a = StateHasher128::default();
        StateSink::bytes(&mut a, b"a");
        assert_eq!(a.finish(), 0xd228_cb69_6f1a_8caf_7891_2b70_4e4a_8964);
        let mut f = StateHasher128::default();
        StateSink::bytes(&mut f, b"foobar");
        assert_eq!(f.finish(), 0x343e_1662_793c_64bf_6f0d_3597_ba44_6f18);
    }

    #[test]
    fn values_are_fed_little_endian() {
        let mut x = StateHasher::default();
        x.u32(0x0403_0201);
        let mut y = StateHasher::default();
        y.bytes(&[1, 2, 3, 4]);
        assert_eq!(x.finish(), y.finish());
    }
}
