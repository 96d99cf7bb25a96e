//! The keys of recently keyed records, by the SHA-256 of their text: a
//! direct-mapped table of a fixed number of slots, so that a repeated
//! record is keyed (and charged) once while memory stays the same whatever
//! the input's length.
//!
//! Slot `s` holds the last record whose digest's first eight bytes are `s`
//! modulo the slot count (SHA-256 spreads records evenly over the slots).
//! A repeat is found while its slot has not been taken by another record
//! since: almost always for a repeat a few thousand records later, hardly
//! ever for one a few slot-counts later. A repeat not found is keyed again
//! and charged again (the work is done again), with the same key.

/// SHA-256 of a record's text.
pub(crate) type RecordHash = [u8; 32];

/// The slots of the bulk commands' table: 2¹⁶ (a few MB of keys).
pub(crate) const RECENT_SLOTS_LOG2: u32 = 16;

/// A direct-mapped table from record digests to keys (see the module).
pub(crate) struct RecentKeys<K> {
    slots: Vec<Option<(RecordHash, K)>>,
}

impl<K> RecentKeys<K> {
    /// An empty table of `2^log2` slots.
    pub fn new(log2: u32) -> RecentKeys<K> {
        RecentKeys {
            slots: std::iter::repeat_with(|| None).take(1 << log2).collect(),
        }
    }

    /// The slot of `h`: its first eight bytes modulo the slot count.
    fn slot(&self, h: &RecordHash) -> usize {
        let mut head = [0u8; 8];
        head.copy_from_slice(&h[..8]);
        (u64::from_le_bytes(head) as usize) & (self.slots.len() - 1)
    }

    /// The key of the record of digest `h`, if its slot still holds it.
    pub fn get(&self, h: &RecordHash) -> Option<&K> {
        match &self.slots[self.slot(h)] {
            Some((held, key)) if held == h => Some(key),
            _ => None,
        }
    }

    /// Keep `key` as the key of the record of digest `h`, in place of
    /// whatever its slot held.
    pub fn put(&mut self, h: RecordHash, key: K) {
        let s = self.slot(&h);
        self.slots[s] = Some((h, key));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn hash(k: u8, slot: u8) -> RecordHash {
        let mut h = [k; 32];
        h[0] = slot;
        h[1..8].fill(0);
        h
    }

    #[test]
    fn a_slot_keeps_the_last_record_put_in_it() {
        let mut t = RecentKeys::new(2);
        t.put(hash(1, 0), "a");
        t.put(hash(2, 1), "b");
        assert_eq!(
            (t.get(&hash(1, 0)), t.get(&hash(2, 1))),
            (Some(&"a"), Some(&"b"))
        );
        // Slot 4 is slot 0 of a 4-slot table: the first record is gone.
        t.put(hash(3, 4), "c");
        assert_eq!((t.get(&hash(1, 0)), t.get(&hash(3, 4))), (None, Some(&"c")));
        assert_eq!(t.get(&hash(9, 1)), None);
    }
}
