//! The bounded sequence decoder shared by the snapshot and replay payloads.
//!
//! Serde's own `Vec` already caps its pre-allocation; this also caps the
//! total, so the memory a decode takes stays proportional to the table's
//! limit even when elements are tiny in the file and large in memory (an
//! empty body slot is 2 bytes in a file and over 100 in memory).

use std::marker::PhantomData;

use serde::Deserialize;
use serde::de::{Deserializer, SeqAccess, Visitor};

/// Deserialises a sequence of at most `MAX` elements; a longer one (by its
/// declared length or by what is actually read) is a decode error. Use it as
/// `#[serde(deserialize_with = "bounded::<_, _, MAX>")]` on a `Vec` field.
pub(crate) fn bounded<'de, D, T, const MAX: usize>(deserializer: D) -> Result<Vec<T>, D::Error>
where
    D: Deserializer<'de>,
    T: Deserialize<'de>,
{
    struct Bounded<T, const MAX: usize>(PhantomData<T>);

    impl<'de, T: Deserialize<'de>, const MAX: usize> Visitor<'de> for Bounded<T, MAX> {
        type Value = Vec<T>;

        fn expecting(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
            write!(f, "a sequence of at most {MAX} elements")
        }

        fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Vec<T>, A::Error> {
            let hint = seq.size_hint().unwrap_or(0);
            if hint > MAX {
                return Err(serde::de::Error::custom(format!(
                    "a table of {hint} entries is above the limit of {MAX}"
                )));
            }
            // Pre-allocate only a little: the length is untrusted until the
            // elements have actually been read.
            let mut out = Vec::with_capacity(hint.min(1024));
            while let Some(x) = seq.next_element()? {
                if out.len() >= MAX {
                    return Err(serde::de::Error::custom(format!(
                        "a table is above the limit of {MAX} entries"
                    )));
                }
                out.push(x);
            }
            Ok(out)
        }
    }

    deserializer.deserialize_seq(Bounded::<T, MAX>(PhantomData))
}
