//! Generational handles: a slot index plus the generation of the slot.
//!
//! Bodies and constraints live in slot vectors with a free list. When an
//! entry is removed its slot's generation is bumped, so an old handle to
//! that slot is detected as stale instead of silently naming whatever took
//! the slot next. Both parts are `u32` (never `usize`, whose width differs
//! between targets), so a handle hashes and serialises the same everywhere.
//!
//! One type serves every kind of handle; the kind is a type parameter so a
//! body handle can never be passed where a constraint handle is expected.
//! The kinds: [`BodyId`](crate::dynamics::BodyId),
//! [`ConstraintId`](crate::constraints::ConstraintId).

use core::cmp::Ordering;
use core::fmt;
use core::hash::{Hash, Hasher};
use core::marker::PhantomData;

use serde::de::{self, MapAccess, SeqAccess, Visitor};
use serde::ser::SerializeStruct;
use serde::{Deserialize, Deserializer, Serialize, Serializer};

/// What a handle names: fixes the names it is printed and serialised under.
pub trait IdKind {
    /// The handle's type name (`Debug`, and the struct name for serde).
    const TYPE_NAME: &'static str;
    /// The noun `Display` starts with (`body 3 (gen 1)`).
    const NOUN: &'static str;
}

/// A handle: slot index plus the slot's generation when it was issued.
///
/// Ordered by index, then generation. Serialised as a struct named
/// [`IdKind::TYPE_NAME`] with the fields `index` and `generation`.
pub struct GenerationalId<K: IdKind> {
    index: u32,
    generation: u32,
    kind: PhantomData<fn() -> K>,
}

impl<K: IdKind> GenerationalId<K> {
    /// Builds a handle from its parts (for tools that store ids; the world
    /// validates every id it is given).
    #[must_use]
    pub const fn from_parts(index: u32, generation: u32) -> Self {
        GenerationalId {
            index,
            generation,
            kind: PhantomData,
        }
    }

    /// The slot index.
    #[must_use]
    pub const fn index(self) -> u32 {
        self.index
    }

    /// The slot's generation when this handle was issued.
    #[must_use]
    pub const fn generation(self) -> u32 {
        self.generation
    }
}

// The traits are written out rather than derived: a derive would demand
// them of the kind marker too, which is never instantiated.
impl<K: IdKind> Clone for GenerationalId<K> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<K: IdKind> Copy for GenerationalId<K> {}

impl<K: IdKind> PartialEq for GenerationalId<K> {
    fn eq(&self, other: &Self) -> bool {
        (self.index, self.generation) == (other.index, other.generation)
    }
}

impl<K: IdKind> Eq for GenerationalId<K> {}

impl<K: IdKind> PartialOrd for GenerationalId<K> {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl<K: IdKind> Ord for GenerationalId<K> {
    fn cmp(&self, other: &Self) -> Ordering {
        (self.index, self.generation).cmp(&(other.index, other.generation))
    }
}

impl<K: IdKind> Hash for GenerationalId<K> {
    fn hash<H: Hasher>(&self, state: &mut H) {
        self.index.hash(state);
        self.generation.hash(state);
    }
}

impl<K: IdKind> fmt::Debug for GenerationalId<K> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct(K::TYPE_NAME)
            .field("index", &self.index)
            .field("generation", &self.generation)
            .finish()
    }
}

impl<K: IdKind> fmt::Display for GenerationalId<K> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} {} (gen {})", K::NOUN, self.index, self.generation)
    }
}

impl<K: IdKind> Serialize for GenerationalId<K> {
    fn serialize<Ser: Serializer>(&self, serializer: Ser) -> Result<Ser::Ok, Ser::Error> {
        let mut s = serializer.serialize_struct(K::TYPE_NAME, 2)?;
        s.serialize_field("index", &self.index)?;
        s.serialize_field("generation", &self.generation)?;
        s.end()
    }
}

/// The field names, in order.
const FIELDS: &[&str] = &["index", "generation"];

impl<'de, K: IdKind> Deserialize<'de> for GenerationalId<K> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct Parts<K>(PhantomData<fn() -> K>);

        impl<'de, K: IdKind> Visitor<'de> for Parts<K> {
            type Value = GenerationalId<K>;

            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                write!(f, "struct {}", K::TYPE_NAME)
            }

            fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Self::Value, A::Error> {
                let index = seq
                    .next_element()?
                    .ok_or_else(|| de::Error::invalid_length(0, &self))?;
                let generation = seq
                    .next_element()?
                    .ok_or_else(|| de::Error::invalid_length(1, &self))?;
                Ok(GenerationalId::from_parts(index, generation))
            }

            fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Self::Value, A::Error> {
                let (mut index, mut generation) = (None, None);
                while let Some(key) = map.next_key::<&str>()? {
                    let slot = match key {
                        "index" => &mut index,
                        "generation" => &mut generation,
                        _ => {
                            map.next_value::<de::IgnoredAny>()?;
                            continue;
                        }
                    };
                    if slot.is_some() {
                        return Err(de::Error::custom(format!("duplicate field `{key}`")));
                    }
                    *slot = Some(map.next_value()?);
                }
                Ok(GenerationalId::from_parts(
                    index.ok_or_else(|| de::Error::missing_field("index"))?,
                    generation.ok_or_else(|| de::Error::missing_field("generation"))?,
                ))
            }
        }

        deserializer.deserialize_struct(K::TYPE_NAME, FIELDS, Parts(PhantomData))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dynamics::BodyId;

    /// The shape every handle had when it was a plain derived struct: the
    /// bytes of snapshots and replays written before must read the same.
    #[derive(Debug, PartialEq, Serialize, Deserialize)]
    struct DerivedTwin {
        index: u32,
        generation: u32,
    }

    fn encode<T: Serialize>(value: &T) -> Vec<u8> {
        bincode::serde::encode_to_vec(value, bincode::config::standard()).expect("encodes")
    }

    #[test]
    fn bytes_are_those_of_a_two_field_struct() {
        for (index, generation) in [(0, 0), (1, 7), (300, 70_000), (u32::MAX, u32::MAX)] {
            let id = BodyId::from_parts(index, generation);
            let twin = DerivedTwin { index, generation };
            assert_eq!(encode(&id), encode(&twin));
            let (back, used): (BodyId, usize) =
                bincode::serde::decode_from_slice(&encode(&twin), bincode::config::standard())
                    .expect("decodes");
            assert_eq!((back, used), (id, encode(&twin).len()));
        }
        let short = [5u8];
        assert!(
            bincode::serde::decode_from_slice::<BodyId, _>(&short, bincode::config::standard())
                .is_err()
        );
    }

    #[test]
    fn order_is_index_then_generation_and_kinds_print_their_names() {
        let a = BodyId::from_parts(1, 9);
        let b = BodyId::from_parts(2, 0);
        let c = BodyId::from_parts(2, 1);
        assert!(a < b && b < c);
        assert_eq!(format!("{b}"), "body 2 (gen 0)");
        assert_eq!(format!("{b:?}"), "BodyId { index: 2, generation: 0 }");
        let k = crate::constraints::ConstraintId::from_parts(4, 3);
        assert_eq!(format!("{k}"), "constraint 4 (gen 3)");
        assert_eq!(format!("{k:?}"), "ConstraintId { index: 4, generation: 3 }");
    }
}
