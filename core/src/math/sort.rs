//! One stable sort for the whole crate, compiled once.
//!
//! `slice::sort_by` is generic over its comparator, so every call site with its own closure
//! compiles its own copy of the standard library's driftsort (quicksort, merges, small-sorts:
//! about 5–8 KB of wasm each). Twenty call sites made 104 functions and 116 KB of the npm
//! package's code (issue 10, wasm size); handing the comparator on as a trait object still
//! left one driftsort per element type, 2–5 per wasm module and 92 KB of the six (issue 25,
//! wasm size). [`sort_by`] now finds the order of the indices with a merge sort of its own
//! (not generic: one copy per module, about 1 KB) and then moves the elements into it by the
//! permutation's cycles (a few instructions per element type): 3 KB per module in all.
//!
//! The order is the standard library's stable order (equal elements keep their order; for a
//! comparator that is a total preorder the stable order is unique), so the results are the
//! same bits as with `slice::sort_by`, and a call site that used `sort_unstable*` on keys
//! without ties, or on keys whose equal elements are identical, gives the same result. The
//! tests compare both with the standard library's sorts.

use alloc::vec::Vec;
use core::cmp::Ordering;

/// Sorts `v` stably by `cmp` (the standard library's `sort_by`, the same order), with the
/// crate's one merge sort; up to 12 elements by insertion in place.
pub fn sort_by<T>(v: &mut [T], mut cmp: impl FnMut(&T, &T) -> Ordering) {
    if v.len() <= RUN {
        insertion_sort(v, &mut cmp);
        return;
    }
    let order = stable_order(v.len(), &mut |i, j| cmp(&v[i], &v[j]));
    permute(v, order);
}

/// Sorts `v` stably by `cmp`, compiled for this call site with `cmp` inlined: for a sort in
/// a hot loop (the 2D MMUC sweep sorts a list of arc events per particle), at about 1 KB of
/// wasm per call site. The same order as [`sort_by`], which uses it on indices. Insertion
/// sort of runs of 12, then bottom-up merges between `v` and a copy, taking from the left run
/// on ties and copying a pair of runs already in order after one comparison: O(n log n)
/// comparisons, n extra elements of memory.
#[inline]
pub fn sort_copy_by<T: Copy, F: FnMut(&T, &T) -> Ordering>(v: &mut [T], mut cmp: F) {
    let n = v.len();
    let mut run_start = 0;
    while run_start < n {
        let hi = (run_start + RUN).min(n);
        for k in run_start + 1..hi {
            let x = v[k];
            let mut j = k;
            while j > run_start && cmp(&x, &v[j - 1]) == Ordering::Less {
                v[j] = v[j - 1];
                j -= 1;
            }
            v[j] = x;
        }
        run_start = hi;
    }
    if n <= RUN {
        return;
    }
    let mut buf = v.to_vec();
    let (mut src, mut dst): (&mut [T], &mut [T]) = (v, &mut buf);
    let mut in_v = true;
    let mut width = RUN;
    while width < n {
        let mut lo = 0;
        while lo < n {
            let mid = (lo + width).min(n);
            let hi = (lo + 2 * width).min(n);
            if mid == hi || cmp(&src[mid], &src[mid - 1]) != Ordering::Less {
                dst[lo..hi].copy_from_slice(&src[lo..hi]);
            } else {
                let (mut i, mut j, mut k) = (lo, mid, lo);
                while i < mid && j < hi {
                    if cmp(&src[j], &src[i]) == Ordering::Less {
                        dst[k] = src[j];
                        j += 1;
                    } else {
                        dst[k] = src[i];
                        i += 1;
                    }
                    k += 1;
                }
                dst[k..k + (mid - i)].copy_from_slice(&src[i..mid]);
                k += mid - i;
                dst[k..k + (hi - j)].copy_from_slice(&src[j..hi]);
            }
            lo = hi;
        }
        core::mem::swap(&mut src, &mut dst);
        in_v = !in_v;
        width *= 2;
    }
    if !in_v {
        dst.copy_from_slice(src);
    }
}

/// Sorts floats ascending in IEEE 754 total order ([`f64::total_cmp`]).
pub fn sort_f64(v: &mut [f64]) {
    sort_by(v, f64::total_cmp);
}

/// Sorts `v` ascending by its [`Ord`] (equal elements are interchangeable, so this is also
/// `sort_unstable`'s result).
pub fn sort<T: Ord>(v: &mut [T]) {
    sort_by(v, T::cmp);
}

/// Runs shorter than this are sorted by insertion before the merges.
const RUN: usize = 12;

/// Stable insertion sort in place by swaps (no allocation): short slices.
fn insertion_sort<T>(v: &mut [T], cmp: &mut dyn FnMut(&T, &T) -> Ordering) {
    for k in 1..v.len() {
        let mut j = k;
        while j > 0 && cmp(&v[j], &v[j - 1]) == Ordering::Less {
            v.swap(j, j - 1);
            j -= 1;
        }
    }
}

/// The indices 0..n in the stable order of `cmp(i, j)` (which compares the elements at i and
/// j), by [`sort_copy_by`] compiled once here for indices.
#[inline(never)]
fn stable_order(n: usize, cmp: &mut dyn FnMut(usize, usize) -> Ordering) -> Vec<usize> {
    let mut order: Vec<usize> = (0..n).collect();
    sort_copy_by(&mut order, |&i, &j| cmp(i, j));
    order
}

/// Rearranges `v` so that its k-th element is the one that was at `order[k]` (`order` a
/// permutation), by swaps along the permutation's cycles.
fn permute<T>(v: &mut [T], mut order: Vec<usize>) {
    const DONE: usize = usize::MAX;
    for start in 0..v.len() {
        if order[start] == DONE || order[start] == start {
            continue;
        }
        let mut at = start;
        loop {
            let from = order[at];
            order[at] = DONE;
            if from == start {
                break;
            }
            v.swap(at, from);
            at = from;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
        for n in [
            0usize, 1, 2, 7, 11, 12, 13, 20, 24, 25, 33, 47, 96, 500, 4_099,
        ] {
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

    #[test]
    fn agrees_with_std_on_runs_ties_and_floats() {
        let mut state = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        };
        for n in (0usize..70).chain([128, 129, 1_000, 3_333]) {
            for shape in 0..4 {
                // Random keys with many ties, sorted, reversed, and sorted runs.
                let v: Vec<(u64, usize)> = (0..n)
                    .map(|i| {
                        let k = match shape {
                            0 => next() % 5,
                            1 => i as u64 / 3,
                            2 => (n - i) as u64 / 2,
                            _ => (i % 17) as u64 + next() % 2,
                        };
                        (k, i)
                    })
                    .collect();
                let mut ours = v.clone();
                sort_by(&mut ours, |a, b| a.0.cmp(&b.0));
                let mut want = v.clone();
                want.sort_by_key(|a| a.0);
                assert_eq!(ours, want, "n = {n}, shape {shape}");
                let mut copied = v.clone();
                sort_copy_by(&mut copied, |a, b| a.0.cmp(&b.0));
                assert_eq!(copied, want, "n = {n}, shape {shape}, sort_copy_by");
                let mut desc = v.clone();
                sort_by(&mut desc, |a, b| b.0.cmp(&a.0));
                want.sort_by_key(|a| core::cmp::Reverse(a.0));
                assert_eq!(desc, want, "n = {n}, shape {shape}, descending");
                let mut whole = v;
                sort(&mut whole);
                want.sort_unstable();
                assert_eq!(whole, want, "n = {n}, shape {shape}, Ord");
            }
            let f: Vec<f64> = (0..n)
                .map(|_| match next() % 6 {
                    0 => 0.0,
                    1 => -0.0,
                    2 => f64::NAN,
                    3 => -f64::INFINITY,
                    _ => f64::from_bits(next()),
                })
                .collect();
            let mut ours = f.clone();
            sort_f64(&mut ours);
            let mut want = f;
            want.sort_by(f64::total_cmp);
            let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
            assert_eq!(bits(&ours), bits(&want), "n = {n}, floats");
        }
    }
}
