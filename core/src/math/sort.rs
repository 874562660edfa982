//! One stable sort for the whole crate.
//!
//! `slice::sort_by` is generic over its comparator, so every call site with its own closure
//! compiles its own copy of the standard library's driftsort (quicksort, merges, small-sorts:
//! about 5–8 KB of wasm each). Twenty call sites made 104 functions and 116 KB of the npm
//! package's code (issue 10, wasm size). [`sort_by`] hands the comparator on as a trait object,
//! so the sort is compiled once per element type and shared by every caller.
//!
//! The order is the standard library's stable order (equal elements keep their order), so a
//! call site that used `sort_unstable*` on keys without ties gives the same result.

use core::cmp::Ordering;

/// Sorts `v` stably by `cmp` (the standard library's `sort_by`), compiled once per `T`.
pub fn sort_by<T>(v: &mut [T], mut cmp: impl FnMut(&T, &T) -> Ordering) {
    sort_dyn(v, &mut cmp);
}

/// Sorts floats ascending in IEEE 754 total order ([`f64::total_cmp`]).
pub fn sort_f64(v: &mut [f64]) {
    sort_dyn(v, &mut f64::total_cmp);
}

#[inline(never)]
fn sort_dyn<T>(v: &mut [T], cmp: &mut dyn FnMut(&T, &T) -> Ordering) {
    v.sort_by(cmp);
}

#[cfg(test)]
mod tests {
    use super::*;
    use alloc::vec::Vec;

    #[test]
    fn stable_and_total() {
        let mut v = [(2, 'a'), (1, 'b'), (2, 'c'), (0, 'd'), (1, 'e')];
        sort_by(&mut v, |a, b| a.0.cmp(&b.0));
        assert_eq!(v, [(0, 'd'), (1, 'b'), (1, 'e'), (2, 'a'), (2, 'c')]);
        let mut f = [3.0, -0.0, 0.0, f64::NEG_INFINITY, 1.5];
        sort_f64(&mut f);
        let bits: Vec<u64> = f.iter().map(|x| x.to_bits()).collect();
        let want: Vec<u64> = [f64::NEG_INFINITY, -0.0, 0.0, 1.5, 3.0]
            .iter()
            .map(|x| x.to_bits())
            .collect();
        assert_eq!(bits, want);
    }

    #[test]
    fn agrees_with_std_on_random_keys() {
        let mut state = 0x2545_f491_4f6c_dd1du64;
        for n in [0usize, 1, 2, 7, 20, 33, 500] {
            let v: Vec<(u32, usize)> = (0..n)
                .map(|i| {
                    state ^= state << 13;
                    state ^= state >> 7;
                    state ^= state << 17;
                    ((state % 16) as u32, i)
                })
                .collect();
            let mut ours = v.clone();
            sort_by(&mut ours, |a, b| a.0.cmp(&b.0));
            let mut std_sorted = v;
            std_sorted.sort_by_key(|a| a.0);
            assert_eq!(ours, std_sorted);
        }
    }
}
