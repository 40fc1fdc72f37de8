//! A fast hash for the engine's own maps — nodes by their structure,
//! derivatives and temporaries by node id — whose keys no adversary
//! chooses: the multiply-and-rotate hash rustc uses for its own tables
//! (FxHash), several times faster than the default SipHash on such small
//! keys. Only lookups depend on it: nothing iterates these maps into an
//! order that shows.

use std::collections::HashMap;
#[cfg(feature = "syntax")]
use std::collections::HashSet;
use std::hash::{BuildHasherDefault, Hasher};

/// A `HashMap` with [`FxHasher`].
pub(crate) type FastMap<K, V> = HashMap<K, V, BuildHasherDefault<FxHasher>>;
/// A `HashSet` with [`FxHasher`] (the emitter's).
#[cfg(feature = "syntax")]
pub(crate) type FastSet<K> = HashSet<K, BuildHasherDefault<FxHasher>>;

/// The hash state: one word, each input word rotated in and multiplied.
#[derive(Default, Clone, Copy)]
pub(crate) struct FxHasher {
    hash: u64,
}

/// The multiplier (rustc's).
const MULTIPLIER: u64 = 0x51_7c_c1_b7_27_22_0a_95;

impl FxHasher {
    #[inline]
    fn add(&mut self, word: u64) {
        self.hash = (self.hash.rotate_left(5) ^ word).wrapping_mul(MULTIPLIER);
    }
}

impl Hasher for FxHasher {
    #[inline]
    fn write(&mut self, bytes: &[u8]) {
        let mut chunks = bytes.chunks_exact(8);
        for chunk in &mut chunks {
            let mut word = [0; 8];
            word.copy_from_slice(chunk);
            self.add(u64::from_le_bytes(word));
        }
        let rest = chunks.remainder();
        if !rest.is_empty() {
            let mut word = [0; 8];
            word[..rest.len()].copy_from_slice(rest);
            self.add(u64::from_le_bytes(word) ^ ((rest.len() as u64) << 59));
        }
    }

    #[inline]
    fn write_u8(&mut self, i: u8) {
        self.add(u64::from(i));
    }

    #[inline]
    fn write_u16(&mut self, i: u16) {
        self.add(u64::from(i));
    }

    #[inline]
    fn write_u32(&mut self, i: u32) {
        self.add(u64::from(i));
    }

    #[inline]
    fn write_u64(&mut self, i: u64) {
        self.add(i);
    }

    #[inline]
    fn write_usize(&mut self, i: usize) {
        self.add(i as u64);
    }

    #[inline]
    fn finish(&self) -> u64 {
        self.hash
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn equal_keys_hash_alike_and_different_ones_spread() {
        let hash = |bytes: &[u8]| {
            let mut h = FxHasher::default();
            h.write(bytes);
            h.finish()
        };
        assert_eq!(hash(b"theta3"), hash(b"theta3"));
        assert_ne!(hash(b"theta3"), hash(b"theta4"));
        // A shorter key is not a longer one padded with zeros.
        assert_ne!(hash(b"ab"), hash(b"ab\0"));
        let mut map: FastMap<u32, u32> = FastMap::default();
        for k in 0..10_000 {
            map.insert(k, k * 2);
        }
        assert!((0..10_000).all(|k| map[&k] == k * 2));
    }
}
