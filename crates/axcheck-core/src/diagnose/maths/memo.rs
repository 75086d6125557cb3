//! Values of the diagnosis's pure numerical functions remembered by their exact inputs.
//!
//! What a plan can confirm (`detectable`) solves a noncentral F or an Imhof integral for
//! the size an effect needs: a third of a fleet's diagnosis time, and the same inputs come
//! back on every axis tested by the same plan. The value remembered is the one computed,
//! bit for bit, so every output stays the same; the table is cleared when it grows past
//! [`ENTRIES`], so its memory stays bounded whatever the campaign.

use std::collections::HashMap;
use std::sync::{LazyLock, Mutex, MutexGuard};

/// Entries kept before the table starts over (a few megabytes).
const ENTRIES: usize = 65_536;

/// A function's remembered values, keyed by the bits of its arguments.
pub(crate) struct Memo(LazyLock<Mutex<HashMap<Vec<u64>, f64>>>);

impl Memo {
    pub(crate) const fn new() -> Memo {
        Memo(LazyLock::new(|| Mutex::new(HashMap::new())))
    }

    fn table(&self) -> MutexGuard<'_, HashMap<Vec<u64>, f64>> {
        // A panic elsewhere never leaves a half-written entry: take the table as it is.
        self.0
            .lock()
            .unwrap_or_else(|poisoned| poisoned.into_inner())
    }

    /// `compute()`'s value for the arguments `key`, computed once (outside the lock, so
    /// two threads may both compute a new key; they store the same bits).
    pub(crate) fn get_or(&self, key: &[f64], compute: impl FnOnce() -> f64) -> f64 {
        let bits: Vec<u64> = key.iter().map(|x| x.to_bits()).collect();
        if let Some(&value) = self.table().get(&bits) {
            return value;
        }
        let value = compute();
        let mut table = self.table();
        if table.len() >= ENTRIES {
            table.clear();
        }
        table.insert(bits, value);
        value
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn remembers_by_exact_bits_and_stays_bounded() {
        static MEMO: Memo = Memo::new();
        let calls = std::cell::Cell::new(0);
        let f = |x: f64| {
            MEMO.get_or(&[x, 2.0], || {
                calls.set(calls.get() + 1);
                x * 2.0
            })
        };
        assert_eq!(f(1.5), 3.0);
        assert_eq!(f(1.5), 3.0);
        assert_eq!(calls.get(), 1);
        // -0.0 and 0.0 are different inputs to a function of bits.
        assert_eq!(f(0.0), 0.0);
        assert_eq!(f(-0.0), -0.0);
        assert_eq!(calls.get(), 3);
        for i in 0..(ENTRIES + 10) {
            f(i as f64 + 0.25);
        }
        assert!(MEMO.table().len() <= ENTRIES);
    }
}
