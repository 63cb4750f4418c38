//! The hash table of the hash-based octrees (seed 000 §4.3.3, Eq. 4.8, Fig. 4.8).
//!
//! 2^n buckets, `hash(key) = key mod 2^n` (the key's low n bits), separate chaining with new
//! entries appended at the end of their bucket's chain. Entries live in one vector, chained by
//! index, so that a scan over every entry (global Marching Cubes) is a linear walk and a
//! lookup walks one short chain. The table is sized once, from the node count of the build
//! (the thesis sizes it "according to the resolution"; it gives no n).

use super::key::Key;
use crate::{Error, Result};

/// End of a chain.
const NIL: u32 = u32::MAX;

/// One node: its key, value (a cell's case byte, or 0 / 255 for a homogeneous leaf) and, for
/// the plain hash-based octree, whether it is an internal node.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Entry {
    /// The node's location key (§4.3.3, Fig. 4.1).
    pub key: Key,
    next: u32,
    /// A cell's case byte, or 0 / 255 for a homogeneous leaf.
    pub val: u8,
    /// An internal node (the plain hash-based octree only).
    pub internal: bool,
}

impl Entry {
    /// A node not linked to any chain yet.
    pub fn new(key: Key, val: u8, internal: bool) -> Entry {
        Entry {
            key,
            next: NIL,
            val,
            internal,
        }
    }
}

/// A chained hash table of octree nodes keyed by location key.
#[derive(Clone, Debug)]
pub struct KeyTable {
    heads: Vec<u32>,
    /// Last entry of each chain, kept while building in order (then freed).
    tails: Vec<u32>,
    entries: Vec<Entry>,
    mask: u64,
}

impl KeyTable {
    /// A table of 2^n ≥ `expected` buckets (at least 8, the thesis's Fig. 4.8 size).
    pub fn with_capacity(expected: usize) -> KeyTable {
        let buckets = expected.next_power_of_two().max(8);
        KeyTable {
            heads: vec![NIL; buckets],
            tails: vec![NIL; buckets],
            entries: Vec::with_capacity(expected),
            mask: buckets as u64 - 1,
        }
    }

    /// The sealed table of every entry of `lists`, taken in order, as [`KeyTable::push`] one
    /// by one would make it (the same buckets, each chain in the same order: seed 000
    /// §4.3.4's level-by-level insertion when `lists` runs from the deepest level up), but
    /// with each chain contiguous. A stable radix sort by bucket: one pass by the bucket's
    /// high bits from the lists into the table, then each of those segments by the low bits
    /// through a small scratch buffer, then one pass linking neighbours of one bucket. The
    /// build reads and writes the entries in sequence instead of touching a random bucket
    /// head and chain tail per insert.
    pub fn from_lists(lists: Vec<Vec<Entry>>) -> Result<KeyTable> {
        let n: usize = lists.iter().map(Vec::len).sum();
        if u32::try_from(n).map_or(true, |n| n == NIL) {
            return Err(Error::TooManyNodes);
        }
        let buckets = n.next_power_of_two().max(8);
        let mask = buckets as u64 - 1;
        let low = buckets.trailing_zeros() / 2;
        let high = |e: &Entry| ((e.key & mask) >> low) as usize;
        let mut next = offsets(lists.iter().flatten(), high, buckets >> low);
        let starts = next.clone();
        let mut entries = vec![Entry::new(0, 0, false); n];
        for e in lists.iter().flatten() {
            let d = high(e);
            entries[next[d] as usize] = *e;
            next[d] += 1;
        }
        drop(lists);
        sort_segments(&mut entries, &starts, (1 << low) - 1);
        Ok(KeyTable::linked(entries, mask))
    }

    /// The table of `entries` already sorted by bucket (stable): heads and links of each run.
    fn linked(mut entries: Vec<Entry>, mask: u64) -> KeyTable {
        let mut heads = Vec::with_capacity(mask as usize + 1);
        for i in 0..entries.len() {
            let b = (entries[i].key & mask) as usize;
            if b < heads.len() {
                entries[i - 1].next = i as u32;
            } else {
                heads.resize(b, NIL);
                heads.push(i as u32);
            }
        }
        heads.resize(mask as usize + 1, NIL);
        KeyTable {
            heads,
            tails: Vec::new(),
            entries,
            mask,
        }
    }

    /// Eq. 4.8: the bucket of a key.
    pub fn bucket(&self, key: Key) -> usize {
        (key & self.mask) as usize
    }

    /// Buckets (2^n).
    pub fn buckets(&self) -> usize {
        self.heads.len()
    }

    /// Appends a node that is not in the table yet at the end of its chain (the build: no
    /// duplicate check). Refuses past 2^32 − 1 entries.
    pub fn push(&mut self, key: Key, val: u8, internal: bool) -> Result<()> {
        let i = u32::try_from(self.entries.len())
            .ok()
            .filter(|&i| i != NIL)
            .ok_or(Error::TooManyNodes)?;
        let b = self.bucket(key);
        let tail = match self.tails.get(b) {
            Some(&t) => t,
            None => self.chain_end(b),
        };
        match tail {
            NIL => self.heads[b] = i,
            t => self.entries[t as usize].next = i,
        }
        if let Some(t) = self.tails.get_mut(b) {
            *t = i;
        }
        self.entries.push(Entry {
            key,
            next: NIL,
            val,
            internal,
        });
        Ok(())
    }

    /// The last entry of bucket b's chain, walked (once the build's tail index is gone).
    fn chain_end(&self, b: usize) -> u32 {
        let (mut i, mut last) = (self.heads[b], NIL);
        while i != NIL {
            last = i;
            i = self.entries[i as usize].next;
        }
        last
    }

    /// Room for `more` entries without moving the entry vector (sculpting: splits insert
    /// nodes one step at a time, and a reallocation would stall that step).
    pub fn reserve(&mut self, more: usize) {
        self.entries.reserve(more);
    }

    /// Ends the build: frees the tail index and spare capacity.
    pub fn seal(&mut self) {
        self.tails = Vec::new();
        self.entries.shrink_to_fit();
    }

    fn index(&self, key: Key) -> Option<usize> {
        let mut i = self.heads[self.bucket(key)];
        while i != NIL {
            let e = &self.entries[i as usize];
            if e.key == key {
                return Some(i as usize);
            }
            i = e.next;
        }
        None
    }

    /// The node with this key.
    pub fn get(&self, key: Key) -> Option<&Entry> {
        self.index(key).map(|i| &self.entries[i])
    }

    /// The value of the node with this key, to change it.
    pub fn get_mut(&mut self, key: Key) -> Option<&mut u8> {
        self.index(key).map(|i| &mut self.entries[i].val)
    }

    /// Inserts a node at the end of its chain, or changes its value if it is there.
    pub fn insert(&mut self, key: Key, val: u8, internal: bool) -> Result<()> {
        match self.index(key) {
            Some(i) => {
                self.entries[i].val = val;
                self.entries[i].internal = internal;
                Ok(())
            }
            None => self.push(key, val, internal),
        }
    }

    /// Removes a node; the last entry moves into its slot (its chain link is rewritten).
    pub fn remove(&mut self, key: Key) -> Option<Entry> {
        let i = self.index(key)? as u32;
        self.unlink(i);
        let last = self.entries.len() as u32 - 1;
        if i != last {
            self.relink(last, i);
        }
        self.tails = Vec::new();
        Some(self.entries.swap_remove(i as usize))
    }

    /// Takes entry `i` out of its chain.
    fn unlink(&mut self, i: u32) {
        let b = self.bucket(self.entries[i as usize].key);
        let next = self.entries[i as usize].next;
        self.point(b, i, next);
    }

    /// Makes whatever links to entry `from` link to `to` instead.
    fn relink(&mut self, from: u32, to: u32) {
        let b = self.bucket(self.entries[from as usize].key);
        self.point(b, from, to);
    }

    /// In bucket b's chain, the link that holds `old` is set to `new`.
    fn point(&mut self, b: usize, old: u32, new: u32) {
        if self.heads[b] == old {
            self.heads[b] = new;
            return;
        }
        let mut j = self.heads[b];
        while j != NIL {
            let e = &mut self.entries[j as usize];
            if e.next == old {
                e.next = new;
                return;
            }
            j = e.next;
        }
    }

    /// Every entry, in insertion order (until something is removed).
    pub fn entries(&self) -> &[Entry] {
        &self.entries
    }

    /// Entries stored.
    pub fn len(&self) -> usize {
        self.entries.len()
    }

    /// No entry stored?
    pub fn is_empty(&self) -> bool {
        self.entries.is_empty()
    }

    /// Bytes held: bucket heads and entries (allocated capacity).
    pub fn bytes(&self) -> usize {
        self.heads.capacity() * 4
            + self.tails.capacity() * 4
            + self.entries.capacity() * std::mem::size_of::<Entry>()
    }

    /// Length of the longest chain (a measure of the hash's spread).
    pub fn longest_chain(&self) -> usize {
        let mut counts = vec![0usize; self.heads.len()];
        for e in &self.entries {
            counts[self.bucket(e.key)] += 1;
        }
        counts.into_iter().max().unwrap_or(0)
    }
}

/// Where each digit's entries start when `items` are sorted by `digit` (< `digits`).
fn offsets<'a>(
    items: impl Iterator<Item = &'a Entry>,
    digit: impl Fn(&Entry) -> usize,
    digits: usize,
) -> Vec<u32> {
    let mut at = vec![0u32; digits + 1];
    for e in items {
        at[digit(e) + 1] += 1;
    }
    for d in 1..at.len() {
        at[d] += at[d - 1];
    }
    at
}

/// Sorts each segment `starts[i]..starts[i + 1]` of `entries` by the bits `low_mask` of the
/// key, stably (a counting sort through a scratch copy of the segment).
fn sort_segments(entries: &mut [Entry], starts: &[u32], low_mask: u64) {
    let mut scratch = Vec::new();
    for w in starts.windows(2) {
        let seg = &mut entries[w[0] as usize..w[1] as usize];
        if seg.len() < 2 {
            continue;
        }
        scratch.clear();
        scratch.extend_from_slice(seg);
        let low = |e: &Entry| (e.key & low_mask) as usize;
        let mut next = offsets(scratch.iter(), low, low_mask as usize + 1);
        for e in &scratch {
            let d = low(e);
            seg[next[d] as usize] = *e;
            next[d] += 1;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_thesis_bucket_of_key_100_in_a_table_of_8_is_4() {
        // seed 000 Fig. 4.8: hash(100) = 100 mod 8 = 4.
        let t = KeyTable::with_capacity(8);
        assert_eq!(t.buckets(), 8);
        assert_eq!(t.bucket(100), 4);
    }

    /// Every chain, head to tail, as keys.
    fn chains(t: &KeyTable) -> Vec<Vec<Key>> {
        (0..t.buckets())
            .map(|b| {
                let (mut i, mut keys) = (t.heads[b], vec![]);
                while i != NIL {
                    keys.push(t.entries[i as usize].key);
                    i = t.entries[i as usize].next;
                }
                keys
            })
            .collect()
    }

    #[test]
    fn the_radix_fill_makes_the_chains_of_inserting_one_by_one() {
        // Keys of mixed levels with many collisions, in several lists, sizes around the
        // powers of two where the bucket bits split differently.
        let mut seed = 0x2545_f491_4f6c_dd1du64;
        for n in [0usize, 1, 7, 8, 9, 100, 1000, 4097, 70_000] {
            let mut lists = vec![vec![]; 3];
            for i in 0..n {
                seed ^= seed << 13;
                seed ^= seed >> 7;
                seed ^= seed << 17;
                let level = 1 + seed % 7;
                let k = 1 << (3 * level) | (seed >> 8) & ((1 << (3 * level)) - 1);
                lists[i % 3].push(Entry::new(k, (seed >> 3) as u8, i % 5 == 0));
            }
            let mut one = KeyTable::with_capacity(n);
            for e in lists.iter().flatten() {
                one.push(e.key, e.val, e.internal).unwrap();
            }
            let fill = KeyTable::from_lists(lists.clone()).unwrap();
            assert_eq!(fill.buckets(), one.buckets(), "n = {n}");
            assert_eq!(chains(&fill), chains(&one), "n = {n}");
            for e in lists.iter().flatten() {
                let got = fill.get(e.key).map(|f| (f.val, f.internal));
                assert_eq!(got, one.get(e.key).map(|f| (f.val, f.internal)));
            }
        }
    }

    #[test]
    fn a_radix_filled_table_takes_pushes_and_removals() {
        let lists = vec![vec![Entry::new(4, 1, false), Entry::new(12, 2, false)]];
        let mut t = KeyTable::from_lists(lists).unwrap();
        t.push(20, 3, false).unwrap();
        t.push(5, 4, false).unwrap();
        assert_eq!(chains(&t)[4], vec![4, 12, 20]);
        assert_eq!(t.remove(4).map(|e| e.val), Some(1));
        assert_eq!(t.get(12).map(|e| e.val), Some(2));
        assert_eq!(t.get(20).map(|e| e.val), Some(3));
        assert_eq!(t.get(5).map(|e| e.val), Some(4));
    }

    #[test]
    fn chains_keep_insertion_order_and_survive_removal() {
        let mut t = KeyTable::with_capacity(8);
        // 4, 12, 20 share bucket 4; 5 is alone.
        for (k, v) in [(4, 1), (12, 2), (5, 3), (20, 4)] {
            t.push(k, v, false).unwrap();
        }
        assert_eq!(t.get(20).map(|e| e.val), Some(4));
        assert_eq!(t.remove(12).map(|e| e.val), Some(2));
        assert_eq!(t.get(12), None);
        assert_eq!(t.get(4).map(|e| e.val), Some(1));
        assert_eq!(t.get(20).map(|e| e.val), Some(4));
        assert_eq!(t.get(5).map(|e| e.val), Some(3));
        t.insert(28, 9, false).unwrap();
        t.insert(4, 7, false).unwrap();
        assert_eq!(t.len(), 4);
        assert_eq!(t.get(28).map(|e| e.val), Some(9));
        assert_eq!(t.get(4).map(|e| e.val), Some(7));
        assert_eq!(t.remove(5).map(|e| e.val), Some(3));
        assert_eq!(t.get(28).map(|e| e.val), Some(9));
        assert_eq!(t.get(20).map(|e| e.val), Some(4));
    }
}
